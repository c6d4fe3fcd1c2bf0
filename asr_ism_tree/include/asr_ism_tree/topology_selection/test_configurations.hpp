#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "asr_ism/demonstration.hpp"
#include "asr_ism_tree/ism_tree.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"

namespace asr_ism_tree {

/// Object configurations on which relation topologies are compared: valid ones (recognised by
/// the tree of the complete topology with confidence >= the threshold) and invalid ones.
struct TestConfigurations {
  std::string scene;
  std::vector<asr_common::Configuration> valid;
  std::vector<asr_common::Configuration> invalid;
  std::size_t size() const { return valid.size() + invalid.size(); }
};

/// How topology selection recognises (labelling test configurations, evaluating topologies): the
/// first evaluation only, without the exact search (TreeRecognitionParameters::exact_best). It
/// recognises thousands of configurations, most of them invalid ones far from every demonstrated
/// pose, where the exact search's bound is loosest; and the false positives it counts are those
/// of the best few results per sub-ISM, as the paper's selection measured them.
TreeRecognitionParameters selectionRecognitionParameters();

/// Generates `count` configurations from the demonstration (seeded, the same on every platform):
/// each keeps one random object at its pose of a random time step and places every other object
/// by its pose relative to that object at another random time step where both were seen. Every
/// object's relation to the kept one was demonstrated, but the relations among the others
/// usually were not. Each is labelled by `complete_tree` (the tree of the complete topology):
/// valid if its best instance's confidence >= `threshold`. Throws InputError for count 0 or a
/// demonstration without a time step that shows two objects.
TestConfigurations generateTestConfigurations(const asr_ism::Demonstration& demonstration,
                                              const IsmTree& complete_tree, std::size_t count,
                                              std::uint32_t seed, double threshold);

/// Stores the configurations in `path` (the original ASR demonstration schema, as the scenes
/// `<scene>.valid` and `<scene>.invalid`), so a run can be repeated exactly and any configuration
/// inspected with `asr ism recognize --demo path --set K`. Throws InputError if the file already
/// holds test configurations of the scene. `objects` are the scene's objects.
void writeTestConfigurations(const std::string& path, const TestConfigurations& tests,
                             const std::vector<asr_common::ObjectKey>& objects);

/// Reads what writeTestConfigurations stored. Throws InputError naming the file if it has no
/// test configurations of `scene`.
TestConfigurations readTestConfigurations(const std::string& path, const std::string& scene);

}  // namespace asr_ism_tree
