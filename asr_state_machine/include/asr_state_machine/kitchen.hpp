#pragma once

#include <string>
#include <vector>

#include "asr_ism/demonstration.hpp"

// The simulated kitchen of the search: three scenes of the real recordings (the breakfast
// setting `gedeck` on the table, `Brot_Regal` and `Muesli_Regal` on the shelf and the table),
// placed as in a recorded set their models were not learned from, moved rigidly into a room
// with a table, a shelf, a counter and a cupboard, plus clutter of other types.
namespace asr_state_machine::kitchen {

struct KitchenScene {
  std::string file;  // in the recordings folder
  std::string scene;
};

/// gedeck (story_1), Brot_Regal and Muesli_Regal (story_2).
std::vector<KitchenScene> kitchenScenes();

/// The step held out of learning and used to place the scene: the `placement`-th from the end
/// (0: the last) of the steps in which every object of the scene was observed. Throws
/// InputError naming the scene if there are not that many.
std::size_t heldOutStep(const asr_ism::Demonstration& demonstration, std::size_t placement = 0);

/// The demonstration without one of its steps.
asr_ism::Demonstration withoutStep(const asr_ism::Demonstration& demonstration, std::size_t step);

/// Learns a star-topology ISM tree of every kitchen scene from its demonstration without the
/// held-out step of `placement` and stores them in `model_path` (created, or its scenes
/// replaced). Returns one line per scene saying what was learned.
std::vector<std::string> learnKitchenModels(const std::string& recordings,
                                            const std::string& model_path,
                                            std::size_t placement = 0);

/// The kitchen world (asr_robot_model's YAML format): the furniture, the objects of every scene
/// at their held-out step of `placement` moved by the recordings-to-kitchen transform (an object
/// two scenes share is placed once, as the first scene has it), the clutter and the robot's start.
std::string kitchenWorldYaml(const std::string& recordings, std::size_t placement = 0);

}  // namespace asr_state_machine::kitchen
