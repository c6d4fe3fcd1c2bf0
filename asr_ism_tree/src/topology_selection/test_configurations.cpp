#include "asr_ism_tree/topology_selection/test_configurations.hpp"

#include <algorithm>
#include <filesystem>

#include "asr_common/input_error.hpp"
#include "asr_ism/portable_random.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism/sqlite/demonstration_writer.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"

namespace asr_ism_tree {
namespace {

using asr_common::Configuration;
using asr_common::InputError;
using asr_ism::Demonstration;

std::string validScene(const std::string& scene) {
  return scene + ".valid";
}
std::string invalidScene(const std::string& scene) {
  return scene + ".invalid";
}

// One configuration: `anchor` at its pose of `step`, every other object placed by its relation
// to the anchor at a random step in which both were seen.
Configuration drawConfiguration(const Demonstration& demonstration, std::size_t step,
                                std::size_t anchor, asr_ism::PortableRandom& random) {
  const asr_common::Pose& anchor_pose = *demonstration.pose(step, anchor);
  Configuration configuration;
  configuration.push_back({demonstration.objects()[anchor], anchor_pose});
  for (std::size_t object = 0; object < demonstration.objectCount(); ++object) {
    if (object == anchor)
      continue;
    std::vector<std::uint32_t> together;
    for (std::size_t other = 0; other < demonstration.stepCount(); ++other) {
      if (demonstration.pose(other, anchor) && demonstration.pose(other, object))
        together.push_back(static_cast<std::uint32_t>(other));
    }
    if (together.empty())
      continue;  // never seen with the anchor: no relation to place it by
    const std::uint32_t source =
        together[random.below(static_cast<std::uint32_t>(together.size()))];
    const asr_common::Pose relative = asr_common::relativePose(*demonstration.pose(source, anchor),
                                                               *demonstration.pose(source, object));
    asr_common::Pose pose = asr_common::compose(anchor_pose, relative);
    pose.orientation = asr_common::canonicalQuaternion(pose.orientation);
    configuration.push_back({demonstration.objects()[object], pose});
  }
  return configuration;
}

}  // namespace

TreeRecognitionParameters selectionRecognitionParameters() {
  TreeRecognitionParameters parameters;
  parameters.exact_best = false;
  return parameters;
}

TestConfigurations generateTestConfigurations(const Demonstration& demonstration,
                                              const IsmTree& complete_tree, std::size_t count,
                                              std::uint32_t seed, double threshold) {
  if (count == 0)
    throw InputError("scene '" + demonstration.scene() +
                     "': at least one test configuration must be requested (got 0)");
  // Steps with at least two objects, and for each the objects seen in it.
  std::vector<std::uint32_t> usable_steps;
  for (std::size_t step = 0; step < demonstration.stepCount(); ++step) {
    if (demonstration.configuration(step).size() >= 2)
      usable_steps.push_back(static_cast<std::uint32_t>(step));
  }
  if (usable_steps.empty())
    throw InputError("scene '" + demonstration.scene() +
                     "': no time step shows two objects, so no test configuration can be made");

  asr_ism::PortableRandom random(seed);
  const TreeRecognizer recognizer(complete_tree, selectionRecognitionParameters());
  TestConfigurations tests;
  tests.scene = demonstration.scene();
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint32_t step =
        usable_steps[random.below(static_cast<std::uint32_t>(usable_steps.size()))];
    std::vector<std::size_t> seen;
    for (std::size_t object = 0; object < demonstration.objectCount(); ++object) {
      if (demonstration.pose(step, object))
        seen.push_back(object);
    }
    const std::size_t anchor = seen[random.below(static_cast<std::uint32_t>(seen.size()))];
    Configuration configuration = drawConfiguration(demonstration, step, anchor, random);
    const auto instances = recognizer.recognize(configuration);
    const bool valid = !instances.empty() && instances.front().confidence >= threshold;
    (valid ? tests.valid : tests.invalid).push_back(std::move(configuration));
  }
  return tests;
}

void writeTestConfigurations(const std::string& path, const TestConfigurations& tests,
                             const std::vector<asr_common::ObjectKey>& objects) {
  if (std::filesystem::exists(path)) {
    const std::vector<std::string> scenes = asr_ism::sqlite::listRecordedScenes(path);
    for (const std::string& existing : {validScene(tests.scene), invalidScene(tests.scene)}) {
      if (std::find(scenes.begin(), scenes.end(), existing) != scenes.end())
        throw InputError(path + " already holds test configurations of scene '" + tests.scene +
                         "'; choose another file");
    }
  }
  for (const auto& [scene, configurations] :
       {std::pair{validScene(tests.scene), &tests.valid},
        std::pair{invalidScene(tests.scene), &tests.invalid}}) {
    if (configurations->empty())
      continue;
    // One demonstration per label, written in one transaction.
    Demonstration stored(scene, objects);
    for (const Configuration& configuration : *configurations) {
      const std::size_t step = stored.addStep();
      for (const asr_common::ObjectEstimate& estimate : configuration)
        stored.setPose(step, static_cast<std::size_t>(stored.indexOf(estimate.key)), estimate.pose);
    }
    asr_ism::sqlite::appendDemonstration(path, stored);
  }
}

TestConfigurations readTestConfigurations(const std::string& path, const std::string& scene) {
  const std::vector<std::string> scenes = asr_ism::sqlite::listRecordedScenes(path);
  TestConfigurations tests;
  tests.scene = scene;
  bool found = false;
  for (const auto& [name, configurations] : {std::pair{validScene(scene), &tests.valid},
                                             std::pair{invalidScene(scene), &tests.invalid}}) {
    if (std::find(scenes.begin(), scenes.end(), name) == scenes.end())
      continue;
    found = true;
    const Demonstration stored = asr_ism::sqlite::readDemonstration(path, name);
    for (std::size_t step = 0; step < stored.stepCount(); ++step)
      configurations->push_back(stored.configuration(step));
  }
  if (!found)
    throw InputError(path + " holds no test configurations of scene '" + scene + "'");
  return tests;
}

}  // namespace asr_ism_tree
