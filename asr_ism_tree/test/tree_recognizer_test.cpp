#include "asr_ism_tree/tree_recognizer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

#include "asr_common/input_error.hpp"
#include "asr_ism_tree/tree_generation.hpp"
#include "instance_lookup.hpp"
#include "synthetic_scene.hpp"

namespace asr_ism_tree {
namespace {

using asr_common::Configuration;
using asr_common::InputError;
using asr_common::Pose;

constexpr double kDegree = M_PI / 180.0;

const std::vector<ObjectKey> kObjects = {
    {"Plate", "1"}, {"Cup", "1"}, {"Knife", "1"}, {"Fork", "1"}, {"Spoon", "1"}};
constexpr std::size_t kPlate = 0, kCup = 1, kKnife = 2, kFork = 3;

class TreeRecognizerTest : public ::testing::Test {
 protected:
  TreeRecognizerTest()
      : demonstration_(synthetic::demonstration("breakfast", kObjects, 6)),
        star_(generateIsmTree(demonstration_, RelationTopology::star(kObjects, kPlate), {})),
        complete_(generateIsmTree(demonstration_, RelationTopology::complete(kObjects), {})) {}

  // Step 2 with some objects off their demonstrated relations, so that compliances lie strictly
  // between 0 and 1 and the confidence is a sensitive number.
  Configuration perturbedStep() const {
    Configuration configuration = demonstration_.configuration(2);
    configuration[kCup].pose.position += Eigen::Vector3d(0.03, 0.0, 0.0);
    configuration[kKnife].pose.orientation =
        configuration[kKnife].pose.orientation *
        Eigen::Quaterniond(Eigen::AngleAxisd(12.0 * kDegree, Eigen::Vector3d::UnitZ()));
    configuration[kFork].pose.position += Eigen::Vector3d(0.02, -0.03, 0.01);
    return configuration;
  }

  asr_ism::Demonstration demonstration_;
  IsmTree star_;
  IsmTree complete_;
};

Configuration transformed(const Configuration& configuration, const Pose& transform) {
  Configuration result = configuration;
  for (auto& estimate : result)
    estimate.pose = asr_common::compose(transform, estimate.pose);
  return result;
}

// Exact equality of two recognitions; `estimate_in_a` maps an estimate index of b to a's.
void expectIdentical(const std::vector<SceneInstance>& a, const std::vector<SceneInstance>& b,
                     const std::vector<int>& estimate_in_a) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    SCOPED_TRACE("instance " + std::to_string(i));
    EXPECT_EQ(a[i].scene, b[i].scene);
    EXPECT_EQ(a[i].confidence, b[i].confidence);
    EXPECT_EQ(a[i].pose.position, b[i].pose.position);
    EXPECT_EQ(a[i].pose.orientation.coeffs(), b[i].pose.orientation.coeffs());
    EXPECT_EQ(a[i].missing, b[i].missing);
    ASSERT_EQ(a[i].objects.size(), b[i].objects.size());
    for (std::size_t o = 0; o < a[i].objects.size(); ++o) {
      const InstanceObject& x = a[i].objects[o];
      const InstanceObject& y = b[i].objects[o];
      EXPECT_EQ(x.key, y.key);
      EXPECT_EQ(x.estimate, estimate_in_a.at(y.estimate));
      EXPECT_EQ(x.pose.position, y.pose.position);
      EXPECT_EQ(x.similarity, y.similarity);
      EXPECT_EQ(x.position_compliance, y.position_compliance);
      EXPECT_EQ(x.orientation_compliance, y.orientation_compliance);
      EXPECT_EQ(x.appearances, y.appearances);
    }
    ASSERT_EQ(a[i].isms.size(), b[i].isms.size());
    for (std::size_t m = 0; m < a[i].isms.size(); ++m) {
      EXPECT_EQ(a[i].isms[m].name, b[i].isms[m].name);
      EXPECT_EQ(a[i].isms[m].objective, b[i].isms[m].objective);
      EXPECT_EQ(a[i].isms[m].recognized, b[i].isms[m].recognized);
      EXPECT_EQ(a[i].isms[m].reference_pose.position, b[i].isms[m].reference_pose.position);
    }
  }
}

std::vector<int> identityMapping(std::size_t size) {
  std::vector<int> mapping(size);
  std::iota(mapping.begin(), mapping.end(), 0);
  return mapping;
}

TEST_F(TreeRecognizerTest, EveryDemonstratedStepIsRecognisedFully) {
  for (const IsmTree* tree : {&star_, &complete_}) {
    const TreeRecognizer recognizer(*tree);
    for (std::size_t step = 0; step < demonstration_.stepCount(); ++step) {
      const auto instances = recognizer.recognize(demonstration_.configuration(step));
      ASSERT_FALSE(instances.empty());
      EXPECT_NEAR(instances[0].confidence, 1.0, 1e-9) << tree->isms.size() << " ISMs, " << step;
      EXPECT_TRUE(instances[0].missing.empty());
      EXPECT_EQ(instances[0].objects.size(), kObjects.size());
      EXPECT_EQ(instances[0].scene, "breakfast");
      // The instance sits where the root's reference (the plate) is.
      EXPECT_TRUE(asr_common::approximatelyEqual(
          instances[0].pose,
          *demonstration_.pose(step, tree->topology.indexOf(tree->isms[0].reference)), 1e-9, 1e-9));
      for (const InstanceIsm& ism : instances[0].isms)
        EXPECT_TRUE(ism.recognized) << ism.name;
    }
  }
}

const Pose kRigidTransforms[] = {
    Pose(Eigen::Vector3d(2.5, -1.3, 0.4),
         Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()))),
    Pose(Eigen::Vector3d(-7.77, 3.1, -0.05),
         Eigen::Quaterniond(Eigen::AngleAxisd(2.9, Eigen::Vector3d::UnitZ()))),
    Pose(Eigen::Vector3d(0.049, 0.051, 0.0),
         Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX())))};

// Recognises `configuration` as given and rigidly moved; the best instance must move along and
// keep its confidence and per-object similarities.
void expectInvariantUnderRigidTransforms(const IsmTree& tree, const Configuration& configuration) {
  const TreeRecognizer recognizer(tree);
  const auto original = recognizer.recognize(configuration);
  const double confidence = bestConfidence(original);
  ASSERT_GT(confidence, 0.5);
  ASSERT_LT(confidence, 0.99);  // the perturbation must matter, or the test proves nothing
  for (const Pose& transform : kRigidTransforms) {
    const auto moved = recognizer.recognize(transformed(configuration, transform));
    ASSERT_FALSE(moved.empty());
    EXPECT_NEAR(moved[0].confidence, confidence, 1e-9);
    EXPECT_TRUE(asr_common::approximatelyEqual(
        moved[0].pose, asr_common::compose(transform, original[0].pose), 1e-9, 1e-9));
    for (const InstanceObject& object : original[0].objects) {
      const InstanceObject* moved_object = find(moved[0], object.key);
      ASSERT_NE(moved_object, nullptr);
      EXPECT_NEAR(moved_object->similarity, object.similarity, 1e-9) << object.key.toString();
    }
  }
}

TEST_F(TreeRecognizerTest, ConfidenceIsInvariantUnderARigidTransform) {
  SCOPED_TRACE("star tree");
  expectInvariantUnderRigidTransforms(star_, perturbedStep());
}

TEST_F(TreeRecognizerTest, ConfidenceOfACompleteTreeIsInvariantUnderARigidTransform) {
  // Only the cup and the knife are off; the two-member ISM breakfast_sub2 sees an exact pair.
  Configuration configuration = demonstration_.configuration(2);
  const Configuration perturbed = perturbedStep();
  configuration[kCup] = perturbed[kCup];
  configuration[kKnife] = perturbed[kKnife];
  ASSERT_EQ(complete_.isms[3].members.size(), 2u);
  expectInvariantUnderRigidTransforms(complete_, configuration);
}

// In the two-member ISM breakfast_sub2 (reference Fork, member Spoon) a fork a few centimetres
// off gives two hypotheses with the same objective 1 + c: the fork's own vote and the spoon's
// vote (compliance is symmetric). The tie must go to the same one however the bin grid falls
// relative to the moved configuration, or the pose passed up to the root, and with it the
// confidence, would change (0.904782 vs 0.908279 when ties went by bin order).
TEST_F(TreeRecognizerTest, SubIsmTiesDoNotDependOnTheBinGrid) {
  ASSERT_EQ(complete_.isms[3].members.size(), 2u);
  expectInvariantUnderRigidTransforms(complete_, perturbedStep());
}

TEST_F(TreeRecognizerTest, InputOrderDoesNotChangeTheResult) {
  // A scene with several instances: a perturbed copy, a partial copy elsewhere, and clutter.
  Configuration configuration = perturbedStep();
  for (std::size_t object : {kPlate, kCup, kFork}) {
    auto estimate = demonstration_.configuration(4)[object];
    estimate.pose.position += Eigen::Vector3d(3.0, 0.0, 0.0);
    configuration.push_back(estimate);
  }
  configuration.push_back({{"Teapot", "1"}, synthetic::yawPose(1.0, 1.0, 0.8, 0.2)});
  std::mt19937 random(7);
  for (const IsmTree* tree : {&star_, &complete_}) {
    const TreeRecognizer recognizer(*tree);
    const auto original = recognizer.recognize(configuration);
    ASSERT_GE(original.size(), 2u);
    for (int trial = 0; trial < 5; ++trial) {
      std::vector<int> permutation = identityMapping(configuration.size());
      std::shuffle(permutation.begin(), permutation.end(), random);
      Configuration permuted;
      for (int index : permutation)
        permuted.push_back(configuration[index]);
      // permuted[i] is configuration[permutation[i]].
      expectIdentical(original, recognizer.recognize(permuted), permutation);
    }
  }
}

// Binary-exact coordinates and identity orientations make two cup estimates exactly equally
// good: 1/32 m on either side of where the cup belongs, with their votes in one bin.
struct TiedCups {
  ObjectKey plate{"Plate", "1"};
  ObjectKey cup{"Cup", "1"};
  IsmTree tree;
  Configuration configuration;
};

TiedCups tiedCups() {
  TiedCups tied;
  const Eigen::Quaterniond identity = Eigen::Quaterniond::Identity();
  asr_ism::Demonstration demonstration("pair", {tied.plate, tied.cup});
  demonstration.addStep();
  demonstration.setPose(0, 0, Pose(Eigen::Vector3d(0.5, 0.5625, 0.5), identity));
  demonstration.setPose(0, 1, Pose(Eigen::Vector3d(0.75, 0.5625, 0.5), identity));
  asr_ism::IsmRecognitionParameters parameters;
  parameters.bin_size = 0.125;
  tied.tree =
      generateIsmTree(demonstration, RelationTopology::star({tied.plate, tied.cup}, 0), parameters);
  tied.configuration = {{tied.plate, Pose(Eigen::Vector3d(0.5, 0.5625, 0.5), identity)},
                        {tied.cup, Pose(Eigen::Vector3d(0.75, 0.5625 - 0.03125, 0.5), identity)},
                        {tied.cup, Pose(Eigen::Vector3d(0.75, 0.5625 + 0.03125, 0.5), identity)}};
  return tied;
}

TEST(TreeRecognizer, ExactTiesAreBrokenIndependentlyOfTheInputOrder) {
  // Neither plate-and-cup combination uses only estimates of the other, so both are instances,
  // equally confident. Whichever order the estimates come in, the result must be the same.
  const TiedCups cups = tiedCups();
  const ObjectKey& cup = cups.cup;
  const IsmTree& tree = cups.tree;
  const Configuration& configuration = cups.configuration;
  // The two cups are repeated detections of one; the search's own tie-break is under test here.
  TreeRecognitionParameters exhaustive;
  exhaustive.merge_repeated_detections = false;
  const TreeRecognizer recognizer(tree, exhaustive);
  const auto original = recognizer.recognize(configuration);
  ASSERT_EQ(original.size(), 2u);
  // 1/32 m against the support radius sqrt(3)/2 x 1/8 m: compliance 1 - (1/1024) / (3/256).
  const double tied = (1.0 + (1.0 - 1.0 / 12.0)) / 2.0;
  EXPECT_NEAR(original[0].confidence, tied, 1e-12);
  EXPECT_EQ(original[1].confidence, original[0].confidence);
  // The tie goes to the plate's own vote: the first instance sits exactly at the plate.
  EXPECT_EQ(original[0].pose.position, configuration[0].pose.position);
  const auto cup_of = [&](const SceneInstance& instance) { return find(instance, cup)->estimate; };
  EXPECT_NE(cup_of(original[0]), cup_of(original[1]));
  std::vector<int> permutation = {0, 1, 2};
  do {
    Configuration permuted;
    for (int index : permutation)
      permuted.push_back(configuration[index]);
    expectIdentical(original, recognizer.recognize(permuted), permutation);
  } while (std::next_permutation(permutation.begin(), permutation.end()));
}

// The same tie with objects the scene does not know added on either side: clutter must not
// decide it (the scene_recognizer reuses a scene's answer while the estimates it can match stay
// the same). The estimates' canonical order, which breaks such ties, once measured distances
// from the centroid of every estimate, clutter included.
TEST(TreeRecognizer, ExactTiesDoNotDependOnClutter) {
  const TiedCups tied = tiedCups();
  const IsmTree& tree = tied.tree;
  const Configuration& configuration = tied.configuration;
  TreeRecognitionParameters exhaustive;
  exhaustive.merge_repeated_detections = false;
  for (const TreeRecognitionParameters& recognition : {TreeRecognitionParameters{}, exhaustive}) {
    const TreeRecognizer recognizer(tree, recognition);
    const auto original = recognizer.recognize(configuration);
    ASSERT_FALSE(original.empty());
    for (double side : {-10.0, 10.0}) {
      Configuration cluttered = configuration;
      cluttered.push_back(
          {{"Vase", "1"}, Pose(Eigen::Vector3d(0.6, side, 0.5), Eigen::Quaterniond::Identity())});
      expectIdentical(original, recognizer.recognize(cluttered), {0, 1, 2});
    }
  }
}

TEST_F(TreeRecognizerTest, ResultsDoNotDependOnThePoolSize) {
  Configuration configuration = perturbedStep();
  const auto second_copy =
      transformed(demonstration_.configuration(1), synthetic::yawPose(0.0, 4.0, 0.0, 1.0));
  configuration.insert(configuration.end(), second_copy.begin(), second_copy.end());
  asr_ism::ThreadPool one(1);
  asr_ism::ThreadPool two(2);
  for (const IsmTree* tree : {&star_, &complete_}) {
    const auto without_pool = TreeRecognizer(*tree).recognize(configuration);
    const auto with_one = TreeRecognizer(*tree, {}, &one).recognize(configuration);
    const auto with_two = TreeRecognizer(*tree, {}, &two).recognize(configuration);
    ASSERT_GE(without_pool.size(), 2u);
    expectIdentical(without_pool, with_one, identityMapping(configuration.size()));
    expectIdentical(without_pool, with_two, identityMapping(configuration.size()));
  }
}

TEST_F(TreeRecognizerTest, ClutterIsIgnored) {
  const Configuration configuration = perturbedStep();
  Configuration cluttered = configuration;
  // Unknown objects right on the scene's objects, beside them, and far away.
  for (const auto& estimate : configuration)
    cluttered.push_back({{"Teapot", estimate.key.type}, estimate.pose});
  cluttered.push_back({{"Plate", "2"}, configuration[kPlate].pose});  // known type, unknown id
  cluttered.push_back({{"Vase", ""}, synthetic::yawPose(0.3, 0.2, 0.75, 1.0)});
  for (const IsmTree* tree : {&star_, &complete_}) {
    const TreeRecognizer recognizer(*tree);
    const auto clean = recognizer.recognize(configuration);
    const auto with_clutter = recognizer.recognize(cluttered);
    // The scene is recognised, every object of it found (an empty result would be "identical"
    // too); the cup, knife and fork are a little off, so the confidence is below 1.
    ASSERT_FALSE(with_clutter.empty());
    EXPECT_TRUE(with_clutter[0].missing.empty());
    EXPECT_GT(with_clutter[0].confidence, 0.75);
    expectIdentical(clean, with_clutter, identityMapping(cluttered.size()));
    for (const SceneInstance& instance : with_clutter) {
      for (const InstanceObject& object : instance.objects)
        EXPECT_LT(object.estimate, static_cast<int>(configuration.size()));
    }
  }
}

TEST_F(TreeRecognizerTest, MissingObjectLowersTheConfidenceOfAStarTree) {
  const TreeRecognizer recognizer(star_);
  const double n = static_cast<double>(kObjects.size());
  for (std::size_t left_out = 0; left_out < kObjects.size(); ++left_out) {
    SCOPED_TRACE("without " + kObjects[left_out].toString());
    Configuration configuration = demonstration_.configuration(3);
    configuration.erase(configuration.begin() + left_out);
    const auto instances = recognizer.recognize(configuration);
    ASSERT_FALSE(instances.empty());
    // Also when the left-out object is the plate, the star's centre and ISM reference.
    EXPECT_NEAR(instances[0].confidence, (n - 1.0) / n, 1e-9);
    EXPECT_EQ(instances[0].missing, std::vector<ObjectKey>{kObjects[left_out]});
    EXPECT_EQ(instances[0].objects.size(), kObjects.size() - 1);
    EXPECT_EQ(find(instances[0], kObjects[left_out]), nullptr);
  }
}

TEST_F(TreeRecognizerTest, MissingObjectIsListedByACompleteTree) {
  const TreeRecognizer recognizer(complete_);
  for (std::size_t left_out = 0; left_out < kObjects.size(); ++left_out) {
    Configuration configuration = demonstration_.configuration(3);
    configuration.erase(configuration.begin() + left_out);
    const auto instances = recognizer.recognize(configuration);
    ASSERT_FALSE(instances.empty());
    EXPECT_LT(instances[0].confidence, 1.0 - 1e-6) << kObjects[left_out].toString();
    EXPECT_GT(instances[0].confidence, 0.5) << kObjects[left_out].toString();
    EXPECT_EQ(instances[0].missing, std::vector<ObjectKey>{kObjects[left_out]});
  }
}

TEST_F(TreeRecognizerTest, TwoCopiesFarApartAreTwoInstances) {
  const Eigen::Vector3d offset(6.0, -4.0, 0.0);
  const Configuration first = demonstration_.configuration(1);
  Configuration configuration = first;
  for (auto estimate : first) {
    estimate.pose.position += offset;
    configuration.push_back(estimate);  // the same object keys again
  }
  for (const IsmTree* tree : {&star_, &complete_}) {
    SCOPED_TRACE(std::to_string(tree->isms.size()) + " ISMs");
    const auto instances = TreeRecognizer(*tree).recognize(configuration);
    ASSERT_EQ(instances.size(), 2u);
    int copies_seen[2] = {0, 0};
    for (const SceneInstance& instance : instances) {
      EXPECT_NEAR(instance.confidence, 1.0, 1e-9);
      ASSERT_EQ(instance.objects.size(), kObjects.size());
      // All estimates of one instance come from one copy.
      const int copy = instance.objects[0].estimate < static_cast<int>(first.size()) ? 0 : 1;
      ++copies_seen[copy];
      for (const InstanceObject& object : instance.objects) {
        EXPECT_EQ(object.estimate / static_cast<int>(first.size()), copy);
        EXPECT_NEAR(object.similarity, 1.0, 1e-9);
      }
      const Pose expected_pose =
          copy == 0 ? first[kPlate].pose
                    : Pose(first[kPlate].pose.position + offset, first[kPlate].pose.orientation);
      EXPECT_TRUE(asr_common::approximatelyEqual(instance.pose, expected_pose, 1e-9, 1e-9));
    }
    EXPECT_EQ(copies_seen[0], 1);
    EXPECT_EQ(copies_seen[1], 1);
  }
}

TEST_F(TreeRecognizerTest, InstancesAreSortedByConfidence) {
  // The perturbed scene, and three objects of another step 5 m away: a weaker instance.
  Configuration configuration = perturbedStep();
  auto partial = demonstration_.configuration(0);
  partial.resize(3);
  for (auto& estimate : partial)
    estimate.pose.position.y() += 5.0;
  configuration.insert(configuration.end(), partial.begin(), partial.end());
  TreeRecognitionStats stats;
  const auto instances = TreeRecognizer(complete_).recognize(configuration, &stats);
  ASSERT_GE(instances.size(), 2u);
  for (std::size_t i = 1; i < instances.size(); ++i)
    EXPECT_GE(instances[i - 1].confidence, instances[i].confidence);
  EXPECT_EQ(stats.root_results, instances.size());
  EXPECT_GT(stats.isms.votes, 0u);
}

TEST_F(TreeRecognizerTest, NonFinitePoseIsAnInputError) {
  const TreeRecognizer recognizer(star_);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double infinity = std::numeric_limits<double>::infinity();
  Configuration nan_position = demonstration_.configuration(0);
  nan_position[kCup].pose.position.y() = nan;
  EXPECT_THROW(recognizer.recognize(nan_position), InputError);
  Configuration nan_orientation = demonstration_.configuration(0);
  nan_orientation[kKnife].pose.orientation.coeffs()[2] = nan;
  EXPECT_THROW(recognizer.recognize(nan_orientation), InputError);
  Configuration infinite = demonstration_.configuration(0);
  infinite[kPlate].pose.position.x() = infinity;
  EXPECT_THROW(recognizer.recognize(infinite), InputError);
  // Even when the bad estimate is clutter the scene would ignore.
  Configuration bad_clutter = demonstration_.configuration(0);
  bad_clutter.push_back({{"Teapot", ""}, Pose::identity()});
  bad_clutter.back().pose.position.z() = nan;
  EXPECT_THROW(recognizer.recognize(bad_clutter), InputError);
}

TEST_F(TreeRecognizerTest, EmptyConfigurationHasNoInstance) {
  EXPECT_TRUE(TreeRecognizer(star_).recognize({}).empty());
  EXPECT_TRUE(TreeRecognizer(complete_).recognize({}).empty());
}

TEST_F(TreeRecognizerTest, ZeroResultsPassedUpIsRefused) {
  TreeRecognitionParameters parameters;
  parameters.results_passed_up = 0;
  EXPECT_THROW(TreeRecognizer(complete_, parameters), InputError);
}

}  // namespace
}  // namespace asr_ism_tree
