#include "asr_state_machine/kitchen.hpp"

#include <cstdio>
#include <set>
#include <sstream>

#include "asr_common/input_error.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism_tree/relation_topology.hpp"
#include "asr_ism_tree/sqlite/model_store.hpp"
#include "asr_ism_tree/star_center.hpp"
#include "asr_ism_tree/tree_generation.hpp"

namespace asr_state_machine::kitchen {

namespace {

// The recordings' room moved into the kitchen: their table (around (-1.5, 0.6)) becomes the
// kitchen's table, their shelf (objects at x about 2.1) the kitchen's shelf on the east wall.
const Eigen::Vector3d kRecordingsToKitchen(3.2, 1.95, 0.0);

struct Block {
  const char* name;
  Eigen::Vector3d centre;
  Eigen::Vector3d size;
};

// A 6 x 5 m room: the table in the middle of the west half; the open shelf (three boards and a
// back panel, no sides) on the east wall, its boards just below the recorded objects; the
// counter along the north wall; a tall cupboard between counter and shelf, hiding the shelf
// from the north-west.
const Block kFurniture[] = {
    {"table", {1.6, 2.55, 0.35}, {1.2, 0.8, 0.70}},
    {"shelf_board_low", {5.375, 1.9, 0.89}, {0.35, 1.2, 0.02}},
    {"shelf_board_middle", {5.375, 1.9, 1.21}, {0.35, 1.2, 0.02}},
    {"shelf_board_high", {5.375, 1.9, 1.69}, {0.35, 1.2, 0.02}},
    {"shelf_back", {5.57, 1.9, 1.0}, {0.04, 1.2, 2.0}},
    {"counter", {2.2, 4.7, 0.45}, {2.4, 0.6, 0.9}},
    {"cupboard", {4.6, 4.5, 1.0}, {1.0, 0.6, 2.0}},
};

struct Clutter {
  const char* type;
  Eigen::Vector3d position;
  double yaw;
};

// Objects of types no kitchen scene holds.
const Clutter kClutter[] = {
    {"CoffeeBox", {1.5, 4.65, 1.0}, 0.3},
    {"MultivitaminJuice", {2.9, 4.6, 1.025}, 0.0},
    {"Smacks", {2.05, 2.3, 0.84}, 1.2},
    {"MeasuringCup", {5.35, 1.45, 0.96}, 0.0},
};

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.4f", value);
  return text;
}

std::string poseYaml(const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
  return "{position: {x: " + number(p.x()) + ", y: " + number(p.y()) + ", z: " + number(p.z()) +
         "}, orientation: {x: " + number(q.x()) + ", y: " + number(q.y()) +
         ", z: " + number(q.z()) + ", w: " + number(q.w()) + "}}";
}

std::string recordingPath(const std::string& recordings, const KitchenScene& scene) {
  return recordings + "/" + scene.file;
}

}  // namespace

std::vector<KitchenScene> kitchenScenes() {
  return {{"story_1.sqlite", "gedeck"},
          {"story_2.sqlite", "Brot_Regal"},
          {"story_2.sqlite", "Muesli_Regal"}};
}

std::size_t heldOutStep(const asr_ism::Demonstration& demonstration, std::size_t placement) {
  std::size_t complete = 0;
  for (std::size_t step = demonstration.stepCount(); step-- > 0;) {
    if (demonstration.configuration(step).size() != demonstration.objectCount())
      continue;
    if (complete++ == placement)
      return step;
  }
  throw asr_common::InputError(
      "scene '" + demonstration.scene() + "' has " + std::to_string(complete) +
      " steps in which every object was observed, not " + std::to_string(placement + 1));
}

asr_ism::Demonstration withoutStep(const asr_ism::Demonstration& demonstration, std::size_t step) {
  asr_ism::Demonstration kept(demonstration.scene(), demonstration.objects());
  for (std::size_t s = 0; s < demonstration.stepCount(); ++s) {
    if (s == step)
      continue;
    const std::size_t added = kept.addStep();
    for (std::size_t o = 0; o < demonstration.objectCount(); ++o) {
      if (const auto& pose = demonstration.pose(s, o))
        kept.setPose(added, o, *pose);
    }
  }
  return kept;
}

std::vector<std::string> learnKitchenModels(const std::string& recordings,
                                            const std::string& model_path, std::size_t placement) {
  std::vector<std::string> lines;
  for (const KitchenScene& scene : kitchenScenes()) {
    const std::string file = recordingPath(recordings, scene);
    const asr_ism::Demonstration all = asr_ism::sqlite::readDemonstration(file, scene.scene);
    const std::size_t held_out = heldOutStep(all, placement);
    const asr_ism::Demonstration training = withoutStep(all, held_out);
    const auto topology = asr_ism_tree::RelationTopology::star(
        training.objects(), asr_ism_tree::chooseStarCenter(training));
    const asr_ism_tree::IsmTree tree =
        asr_ism_tree::generateIsmTree(training, topology, asr_ism::IsmRecognitionParameters{});
    asr_ism_tree::sqlite::saveIsmTree(
        model_path, tree,
        "demonstration " + file + " without set " + std::to_string(held_out) + ", star topology");
    lines.push_back(scene.scene + ": " + std::to_string(training.stepCount()) + " of " +
                    std::to_string(all.stepCount()) + " sets (set " + std::to_string(held_out) +
                    " held out), " + std::to_string(training.objectCount()) + " objects");
  }
  return lines;
}

std::string kitchenWorldYaml(const std::string& recordings, std::size_t placement) {
  std::ostringstream yaml;
  yaml << "# The search's kitchen, written by learn_kitchen_models (asr_state_machine/src/"
          "kitchen.cpp):\n"
          "# the scenes gedeck, Brot_Regal and Muesli_Regal of the recordings, each as in the set\n"
          "# its model was not learned from, moved by ("
       << kRecordingsToKitchen.x() << ", " << kRecordingsToKitchen.y() << ", "
       << kRecordingsToKitchen.z()
       << ") into this room; clutter of other types.\n"
          "version: 1\nframe: map\nroom: {min: [0.0, 0.0], max: [6.0, 5.0]}\nfurniture:\n";
  for (const Block& block : kFurniture) {
    yaml << "  - name: " << block.name
         << "\n    pose: " << poseYaml(block.centre, Eigen::Quaterniond::Identity())
         << "\n    size: [" << number(block.size.x()) << ", " << number(block.size.y()) << ", "
         << number(block.size.z()) << "]\n";
  }
  yaml << "objects:\n";
  std::set<asr_common::ObjectKey> placed;
  for (const KitchenScene& scene : kitchenScenes()) {
    const asr_ism::Demonstration all =
        asr_ism::sqlite::readDemonstration(recordingPath(recordings, scene), scene.scene);
    const std::size_t held_out = heldOutStep(all, placement);
    yaml << "  # " << scene.scene << ", set " << held_out << "\n";
    for (const asr_common::ObjectEstimate& object : all.configuration(held_out)) {
      if (!placed.insert(object.key).second)
        continue;
      yaml << "  - type: " << object.key.type << "\n    id: \"" << object.key.id << "\"\n    pose: "
           << poseYaml(object.pose.position + kRecordingsToKitchen, object.pose.orientation)
           << "\n";
    }
  }
  yaml << "  # clutter\n";
  for (const Clutter& clutter : kClutter) {
    yaml << "  - type: " << clutter.type << "\n    id: \"0\"\n    pose: "
         << poseYaml(clutter.position,
                     Eigen::Quaterniond(Eigen::AngleAxisd(clutter.yaw, Eigen::Vector3d::UnitZ())))
         << "\n";
  }
  yaml << "robot: {x: 0.7, y: 0.7, yaw: 0.6, pan: 0.0, tilt: -0.3}\n";
  return yaml.str();
}

}  // namespace asr_state_machine::kitchen
