// Real-data tests: ISM trees learned from the kitchen recordings of the original ASR system
// (see ../shared/data/asr_recordings/README.md), with the default parameters (bin 0.1 m, 30 deg).

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <ostream>
#include <string>

#include "asr_common/testing/recordings_skip.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism_tree/star_center.hpp"
#include "asr_ism_tree/tree_generation.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"
#include "instance_lookup.hpp"

namespace asr_ism_tree {
namespace {

using asr_common::Configuration;
using asr_common::Pose;

constexpr double kAccepted = 0.99;

using asr_common::testing::recording;

struct KitchenSceneInfo {
  const char* file;
  const char* scene;
  std::size_t sets;     // from the README's table
  std::size_t objects;  // from the README's table
};

// The ten kitchen scene categories of the paper's evaluation.
const KitchenSceneInfo kKitchenScenes[] = {
    {"story_1.sqlite", "gedeck", 112, 8},           {"story_1.sqlite", "Gedeck_Ende", 220, 8},
    {"story_1.sqlite", "Gedeck_Schrank_2", 103, 9}, {"story_1.sqlite", "Spuelkorb_3", 117, 10},
    {"story_2.sqlite", "Brot_Gedeck_2", 92, 5},     {"story_2.sqlite", "Brot_Regal", 98, 6},
    {"story_2.sqlite", "Getraenke_Gedeck", 23, 3},  {"story_2.sqlite", "Getraenke_Regal", 44, 4},
    {"story_2.sqlite", "Muesli_Gedeck", 26, 4},     {"story_2.sqlite", "Muesli_Regal", 98, 5}};

// Readable test names in failure messages instead of the struct's bytes.
void PrintTo(const KitchenSceneInfo& info, std::ostream* out) {
  *out << info.file << ", " << info.scene;
}

// A scene's demonstration and its trees from the star (centre by chooseStarCenter) and the
// complete topology; learned once per test program.
struct LearnedScene {
  asr_ism::Demonstration demonstration;
  std::size_t star_center = 0;
  IsmTree star;
  IsmTree complete;

  const IsmTree& tree(bool complete_topology) const { return complete_topology ? complete : star; }
};

const LearnedScene& learned(const std::string& file, const std::string& scene) {
  static std::map<std::string, std::unique_ptr<LearnedScene>> cache;
  std::unique_ptr<LearnedScene>& entry = cache[file + "/" + scene];
  if (!entry) {
    entry = std::make_unique<LearnedScene>();
    entry->demonstration = asr_ism::sqlite::readDemonstration(recording(file), scene);
    const auto& objects = entry->demonstration.objects();
    entry->star_center = chooseStarCenter(entry->demonstration);
    entry->star = generateIsmTree(entry->demonstration,
                                  RelationTopology::star(objects, entry->star_center), {});
    entry->complete =
        generateIsmTree(entry->demonstration, RelationTopology::complete(objects), {});
  }
  return *entry;
}

const char* topologyName(bool complete_topology) {
  return complete_topology ? "complete" : "star";
}

class KitchenScene : public ::testing::TestWithParam<KitchenSceneInfo> {
 protected:
  void SetUp() override { REQUIRE_RECORDINGS(); }
  const LearnedScene& scene() const { return learned(GetParam().file, GetParam().scene); }
};

TEST_P(KitchenScene, RecordingMatchesTheReadme) {
  const LearnedScene& s = scene();
  EXPECT_EQ(s.demonstration.stepCount(), GetParam().sets);
  EXPECT_EQ(s.demonstration.objectCount(), GetParam().objects);
  EXPECT_EQ(s.star.isms.size(), 1u);
  EXPECT_EQ(s.star.leafCount(), GetParam().objects);
  EXPECT_EQ(s.complete.topology.relationCount(), GetParam().objects * (GetParam().objects - 1) / 2);
}

TEST_P(KitchenScene, EveryRecordedSetIsRecognised) {
  const LearnedScene& s = scene();
  for (bool complete_topology : {false, true}) {
    const TreeRecognizer recognizer(s.tree(complete_topology));
    for (std::size_t step = 0; step < s.demonstration.stepCount(); ++step) {
      const auto instances = recognizer.recognize(s.demonstration.configuration(step));
      EXPECT_GE(bestConfidence(instances), kAccepted)
          << topologyName(complete_topology) << " tree, recorded set " << step;
    }
  }
}

TEST_P(KitchenScene, StarTreeWithOneObjectLeftOutGivesNMinusOneOverN) {
  const LearnedScene& s = scene();
  const TreeRecognizer recognizer(s.star);
  const double n = static_cast<double>(s.demonstration.objectCount());
  for (std::size_t step = 0; step < s.demonstration.stepCount(); ++step) {
    const Configuration full = s.demonstration.configuration(step);
    for (std::size_t left_out = 0; left_out < full.size(); ++left_out) {
      Configuration configuration = full;
      configuration.erase(configuration.begin() + left_out);
      const auto instances = recognizer.recognize(configuration);
      ASSERT_FALSE(instances.empty());
      EXPECT_NEAR(instances[0].confidence, (n - 1.0) / n, 0.02)
          << "recorded set " << step << " without " << full[left_out].key.toString()
          << (left_out == s.star_center ? " (the centre)" : "");
      EXPECT_EQ(instances[0].missing, std::vector<ObjectKey>{full[left_out].key});
    }
  }
}

// Recorded set 5, every object in turn moved by 0.3 m along the map's y axis or turned by 90 deg
// about its own z axis. (Objects move during the demonstrations, so other moves can land on a
// learned relation: in Gedeck_Schrank_2, set 0, marker_2 moved 0.3 m along -x is within 5.5 cm
// and 6 deg of a relation to PlateDeep demonstrated in set 9.)
TEST_P(KitchenScene, MovedOrTurnedObjectIsRejected) {
  const LearnedScene& s = scene();
  constexpr std::size_t kStep = 5;
  const Configuration recorded = s.demonstration.configuration(kStep);
  const Eigen::Quaterniond quarter_turn(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  for (bool complete_topology : {false, true}) {
    const TreeRecognizer recognizer(s.tree(complete_topology));
    ASSERT_GE(bestConfidence(recognizer.recognize(recorded)), kAccepted);
    for (std::size_t object = 0; object < recorded.size(); ++object) {
      const ObjectKey& key = recorded[object].key;
      if (complete_topology && std::string(GetParam().scene) == "Getraenke_Gedeck" &&
          key.type == "Sprudelflasche") {
        continue;  // a tie of two instances: see LoneObjectInTwoLeavesTiesWithTheOtherTwo
      }
      for (bool turn : {false, true}) {
        Configuration changed = recorded;
        if (turn) {
          changed[object].pose.orientation = changed[object].pose.orientation * quarter_turn;
        } else {
          changed[object].pose.position.y() += 0.3;
        }
        const auto instances = recognizer.recognize(changed);
        ASSERT_FALSE(instances.empty());
        const InstanceObject* rated = find(instances[0], key);
        ASSERT_NE(rated, nullptr);
        const std::string what = std::string(topologyName(complete_topology)) + " tree, " +
                                 key.toString() + (turn ? " turned" : " moved");
        EXPECT_EQ(rated->similarity, 0.0) << what;
        EXPECT_LT(instances[0].confidence, kAccepted) << what;
      }
    }
  }
}

// Moving the whole configuration rigidly must move the instances with it and change no
// confidence, also where equally good hypotheses compete (the bin grid falls differently on the
// moved votes). Every 7th recorded set with two objects pushed off by up to 4 cm and 11 degrees,
// so that compliances lie strictly between 0 and 1, under three motions.
TEST_P(KitchenScene, ConfidenceIsInvariantUnderRigidMotions) {
  const LearnedScene& s = scene();
  const Pose motions[] = {
      Pose(Eigen::Vector3d(2.5, -1.3, 0.4),
           Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()))),
      Pose(Eigen::Vector3d(-7.77, 3.1, -0.05),
           Eigen::Quaterniond(Eigen::AngleAxisd(2.9, Eigen::Vector3d::UnitZ()))),
      Pose(Eigen::Vector3d(0.049, 0.051, 0.0),
           Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX())))};
  int partly_recognised = 0;
  for (bool complete_topology : {false, true}) {
    const TreeRecognizer recognizer(s.tree(complete_topology));
    for (std::size_t step = 0; step < s.demonstration.stepCount(); step += 7) {
      Configuration configuration = s.demonstration.configuration(step);
      for (std::size_t k = 0; k < 2 && k < configuration.size(); ++k) {
        Pose& pose = configuration[(step + 3 * k) % configuration.size()].pose;
        const double phase = 0.37 * static_cast<double>(step + k);
        pose.position += Eigen::Vector3d(0.04 * std::sin(phase), 0.04 * std::cos(phase), 0.0);
        pose.orientation *= Eigen::Quaterniond(
            Eigen::AngleAxisd(0.2 * std::sin(2.0 * phase), Eigen::Vector3d::UnitZ()));
      }
      const auto original = recognizer.recognize(configuration);
      ASSERT_FALSE(original.empty());
      partly_recognised += original[0].confidence > 0.5 && original[0].confidence < kAccepted;
      for (const Pose& motion : motions) {
        Configuration moved = configuration;
        for (auto& estimate : moved)
          estimate.pose = asr_common::compose(motion, estimate.pose);
        const auto instances = recognizer.recognize(moved);
        const std::string what =
            std::string(topologyName(complete_topology)) + " tree, set " + std::to_string(step);
        ASSERT_EQ(instances.size(), original.size()) << what;
        for (std::size_t i = 0; i < original.size(); ++i)
          EXPECT_NEAR(instances[i].confidence, original[i].confidence, 1e-9) << what;
        EXPECT_TRUE(asr_common::approximatelyEqual(
            instances[0].pose, asr_common::compose(motion, original[0].pose), 1e-9, 1e-9))
            << what;
      }
    }
  }
  // The pushed objects must matter in many sets, or the test would prove little.
  EXPECT_GE(partly_recognised, 4);
}

std::string sceneName(const ::testing::TestParamInfo<KitchenSceneInfo>& info) {
  return info.param.scene;
}

INSTANTIATE_TEST_SUITE_P(Recordings, KitchenScene, ::testing::ValuesIn(kKitchenScenes), sceneName);

// Surprising but documented: an object counts once per leaf it appears in. In the complete
// (triangle) tree of Drinks - Setting, Sprudelflasche appears in two of the four leaves, so the
// bottle alone, moved away from the others, scores 2 of 4, exactly as much as the cup and the
// juice together. Which of the two tied instances comes first is decided by the tie rule of
// recognizeIsm (the lower member's hypothesis), not tested here.
TEST(Recordings, LoneObjectInTwoLeavesTiesWithTheOtherTwo) {
  REQUIRE_RECORDINGS();
  const LearnedScene& s = learned("story_2.sqlite", "Getraenke_Gedeck");
  ASSERT_EQ(s.complete.leafCount(), 4u);
  Configuration configuration = s.demonstration.configuration(5);
  const ObjectKey bottle{"Sprudelflasche", "0"};
  std::size_t bottle_index = 0;
  while (configuration[bottle_index].key != bottle)
    ++bottle_index;
  configuration[bottle_index].pose.position.y() += 0.3;
  const auto instances = TreeRecognizer(s.complete).recognize(configuration);
  ASSERT_EQ(instances.size(), 2u);
  EXPECT_NEAR(instances[0].confidence, 0.5, 1e-9);
  EXPECT_NEAR(instances[1].confidence, 0.5, 1e-9);
  int bottle_alone = 0;
  int bottle_rejected = 0;
  for (const SceneInstance& instance : instances) {
    double others = 0.0;
    for (const InstanceObject& object : instance.objects) {
      if (object.key != bottle)
        others += object.similarity;
    }
    const double bottle_similarity = find(instance, bottle)->similarity;
    bottle_alone += bottle_similarity > 0.99 && others == 0.0;
    bottle_rejected += bottle_similarity == 0.0 && others > 1.9;
  }
  EXPECT_EQ(bottle_alone, 1);
  EXPECT_EQ(bottle_rejected, 1);
}

// The key weakness of star topologies (the paper's motivation for ISM trees): a star only checks
// each object against the centre. Place one object Y where it stood relative to the centre at
// another time step t2, keep everything else as at t1: every star relation is one that was
// demonstrated, but Y's relations to the other objects are not. The star tree accepts the
// configuration, the complete tree rejects it. Cases found by a search over all scenes, objects
// and pairs of time steps (a throwaway program, not part of the repository).
struct StarOnlyCase {
  const char* file;
  const char* scene;
  ObjectKey center;  // what chooseStarCenter picks; checked, since the case depends on it
  ObjectKey moved;   // Y
  std::size_t t1;
  std::size_t t2;
  double complete_confidence;  // found by the search, for the message only
};

const std::vector<StarOnlyCase>& starOnlyCases() {
  static const std::vector<StarOnlyCase> cases = {
      // Sandwich - Setting: the knife (marker_5) 0.45 m from where it lies at t1, on the other
      // side of the marmalade and turned by 173 deg, as it lay relative to the marmalade at t2.
      // Star 1.0; complete 0.727 (the knife fits only its relation to the marmalade).
      {"story_2.sqlite",
       "Brot_Gedeck_2",
       {"OrangeMarmelade", "0"},
       {"marker_5", "052052051100"},
       10,
       59,
       0.727273},
      // Setting - Ready for Breakfast, the paper's example: a piece of cutlery 4.6 cm off and
      // turned by 21 deg. Star 1.0; complete 0.927.
      {"story_1.sqlite",
       "gedeck",
       {"PlateDeep", "018054024100"},
       {"marker_6", "052052051100"},
       10,
       98,
       0.926562},
  };
  return cases;
}

// Set t1 with object y where it lay relative to the centre at t2.
Configuration withMovedObject(const asr_ism::Demonstration& demonstration, std::size_t center,
                              const StarOnlyCase& c) {
  const int y = demonstration.indexOf(c.moved);
  Configuration configuration = demonstration.configuration(c.t1);
  const Pose placed = asr_common::compose(
      *demonstration.pose(c.t1, center),
      asr_common::relativePose(*demonstration.pose(c.t2, center), *demonstration.pose(c.t2, y)));
  for (auto& estimate : configuration) {
    if (estimate.key == c.moved)
      estimate.pose = placed;
  }
  return configuration;
}

TEST(Recordings, StarTreeAcceptsWhatTheCompleteTreeRejects) {
  REQUIRE_RECORDINGS();
  for (const StarOnlyCase& c : starOnlyCases()) {
    SCOPED_TRACE(std::string(c.scene) + ", " + c.moved.toString());
    const LearnedScene& s = learned(c.file, c.scene);
    const asr_ism::Demonstration& demonstration = s.demonstration;
    ASSERT_EQ(demonstration.objects()[s.star_center], c.center);
    ASSERT_GE(demonstration.indexOf(c.moved), 0);
    const Configuration configuration = withMovedObject(demonstration, s.star_center, c);
    // Both trees accept the recorded set t1 itself; only Y's new place makes the difference.
    ASSERT_GE(bestConfidence(TreeRecognizer(s.star).recognize(demonstration.configuration(c.t1))),
              kAccepted);
    ASSERT_GE(
        bestConfidence(TreeRecognizer(s.complete).recognize(demonstration.configuration(c.t1))),
        kAccepted);

    const auto star_instances = TreeRecognizer(s.star).recognize(configuration);
    const auto complete_instances = TreeRecognizer(s.complete).recognize(configuration);
    EXPECT_GE(bestConfidence(star_instances), kAccepted);
    EXPECT_LT(bestConfidence(complete_instances), kAccepted)
        << "the search found " << c.complete_confidence;
    ASSERT_FALSE(complete_instances.empty());
    EXPECT_NE(find(complete_instances[0], c.moved), nullptr);
  }
}

}  // namespace
}  // namespace asr_ism_tree
