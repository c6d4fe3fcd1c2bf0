// The trainer node: learns ISM trees for the scenes of a demonstration file and stores them in a
// model file, then exits (0 on success, 1 on bad input). Parameters (private):
// demonstration_file and model_file (required), scenes (list or one; empty: every scene of the
// file), topology (star | complete | optimised, default optimised), and for optimised:
// tests, seed, alpha, beta, max_duration_ms (0: no time budget) and max_evaluations, whose
// defaults are TopologySelectionOptions' (topology_selection.hpp). A model file is added to:
// other scenes and tables in it stay; a scene learned again replaces its previous tree.
#include <ros/ros.h>

#include "asr_common/ros/node_main.hpp"
#include "asr_common/ros/node_parameters.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism_tree/sqlite/model_store.hpp"
#include "asr_ism_tree/star_center.hpp"
#include "asr_ism_tree/topology_selection/topology_selection.hpp"
#include "asr_ism_tree/tree_generation.hpp"

namespace {

using namespace asr_common::ros_interface;
using namespace asr_ism_tree;

// The search's parameters, checked against the suite's limits; unset ones keep
// TopologySelectionOptions' defaults.
TopologySelectionOptions selectionParameters(const ros::NodeHandle& parameters) {
  TopologySelectionOptions selection;
  selection.test_count = static_cast<std::size_t>(integerParameter(
      parameters, "tests", static_cast<long long>(selection.test_count), 1, kMaxTestCount));
  selection.seed =
      static_cast<std::uint32_t>(integerParameter(parameters, "seed", selection.seed, 0, kMaxSeed));
  selection.alpha = numberParameter(parameters, "alpha", selection.alpha, 0.0, 1e6);
  selection.beta = numberParameter(parameters, "beta", selection.beta, 0.0, 1e6);
  checkParameter(parameters, "alpha", selection.alpha + selection.beta > 0, "> 0 if beta is 0");
  selection.max_duration_ms =
      numberParameter(parameters, "max_duration_ms", selection.max_duration_ms, 0.0, 1e6);
  selection.max_evaluations = static_cast<std::size_t>(
      integerParameter(parameters, "max_evaluations",
                       static_cast<long long>(selection.max_evaluations), 2, kMaxEvaluations));
  return selection;
}

// An optimised topology for `demonstration`, with progress and the result on the log.
RelationTopology optimisedTopology(const asr_ism::Demonstration& demonstration,
                                   const TopologySelectionOptions& selection) {
  const std::string& scene = demonstration.scene();
  const TopologySelectionResult result =
      selectTopology(demonstration, selection, [&](const TopologySelectionProgress& progress) {
        ROS_INFO_THROTTLE(2.0,
                          "trainer: '%s': %zu/%zu topologies, best cost %.4f, about %.0f s "
                          "left",
                          scene.c_str(), progress.evaluated, progress.max_evaluations,
                          progress.best_cost, progress.seconds_left_estimate);
      });
  ROS_INFO(
      "trainer: '%s': %zu relations selected; numFPs %.2f %% (star %.2f %%), %.3f ms "
      "per recognition (complete %.3f ms)",
      scene.c_str(), result.topology.relationCount(), 100 * result.measures.false_positive_rate,
      100 * result.star_measures.false_positive_rate, result.measures.mean_ms,
      result.complete_measures.mean_ms);
  return result.topology;
}

void train(const ros::NodeHandle& parameters) {
  const auto demonstration_file = requiredParameter<std::string>(parameters, "demonstration_file");
  const auto model_file = requiredParameter<std::string>(parameters, "model_file");
  std::vector<std::string> scenes = stringListParameter(parameters, "scenes");
  const auto topology = optionalParameter<std::string>(parameters, "topology", "optimised");
  checkParameter(parameters, "topology",
                 topology == "star" || topology == "complete" || topology == "optimised",
                 "star, complete or optimised");
  const TopologySelectionOptions selection = selectionParameters(parameters);
  if (scenes.empty())
    scenes = asr_ism::sqlite::listRecordedScenes(demonstration_file);

  for (std::size_t k = 0; k < scenes.size() && ros::ok(); ++k) {
    const std::string& scene = scenes[k];
    ROS_INFO("trainer: scene %zu of %zu: '%s' (%s topology)", k + 1, scenes.size(), scene.c_str(),
             topology.c_str());
    const asr_ism::Demonstration demonstration =
        asr_ism::sqlite::readDemonstration(demonstration_file, scene);
    RelationTopology relations;
    if (topology == "star") {
      relations = RelationTopology::star(demonstration.objects(), chooseStarCenter(demonstration));
    } else if (topology == "complete") {
      relations = RelationTopology::complete(demonstration.objects());
    } else {
      relations = optimisedTopology(demonstration, selection);
    }
    const IsmTree tree = generateIsmTree(demonstration, relations, {});
    sqlite::saveIsmTree(
        model_file, tree,
        "demonstration " + demonstration_file + ", " + topology + " topology (trainer)");
    ROS_INFO("trainer: '%s': %zu ISMs, height %d, stored in %s", scene.c_str(), tree.isms.size(),
             tree.height(), model_file.c_str());
  }
}

}  // namespace

int main(int argc, char** argv) {
  return asr_common::ros_interface::runNodeMain(argc, argv, "trainer",
                                                [] { train(ros::NodeHandle("~")); });
}
