// Relation topology selection: neighbours, the cost at its edges, test configurations and their
// storage, determinism, and a small real scene optimised end to end.

#include <gtest/gtest.h>

#include <string>

#include "asr_common/testing/input_error_of.hpp"
#include "asr_common/testing/recordings_skip.hpp"
#include "asr_common/testing/temp_dir.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism/synthetic_demonstration.hpp"
#include "asr_ism_tree/topology_selection/relation_violations.hpp"
#include "asr_ism_tree/topology_selection/topology_cost.hpp"
#include "asr_ism_tree/topology_selection/topology_neighbours.hpp"
#include "asr_ism_tree/topology_selection/topology_selection.hpp"
#include "asr_ism_tree/tree_generation.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"

namespace asr_ism_tree {
namespace {

using asr_common::testing::inputErrorOf;

std::vector<ObjectKey> objects(int count) {
  std::vector<ObjectKey> keys;
  for (int i = 0; i < count; ++i)
    keys.push_back({"object_" + std::to_string(i), "0"});
  return keys;
}

RelationTopology chain(int count) {
  RelationTopology topology(objects(count));
  for (int i = 0; i + 1 < count; ++i)
    topology.addRelation(i, i + 1);
  return topology;
}

TEST(TopologyNeighbours, AreConnectedDistinctAndOneChangeAway) {
  const RelationTopology start = chain(5);  // 4 of 10 pairs related
  const std::vector<RelationTopology> neighbours = topologyNeighbours(start, 0);
  // 6 additions; no removal keeps a chain connected; exchanges that keep it connected.
  std::size_t additions = 0;
  for (std::size_t i = 0; i < neighbours.size(); ++i) {
    const RelationTopology& neighbour = neighbours[i];
    EXPECT_TRUE(neighbour.isConnected());
    EXPECT_NE(neighbour, start);
    for (std::size_t j = 0; j < i; ++j)
      EXPECT_NE(neighbour, neighbours[j]) << i << " and " << j;
    std::size_t differing = 0;
    for (std::size_t a = 0; a < 5; ++a)
      for (std::size_t b = a + 1; b < 5; ++b)
        differing += neighbour.hasRelation(a, b) != start.hasRelation(a, b);
    EXPECT_TRUE(differing == 1 || differing == 2);
    additions += neighbour.relationCount() == 5 && differing == 1;
  }
  EXPECT_EQ(additions, 6u);
  EXPECT_GT(neighbours.size(), 6u);
}

TEST(TopologyNeighbours, RespectTheHeightLimit) {
  const RelationTopology star = RelationTopology::star(objects(5), 0);
  EXPECT_EQ(treeHeightOf(star), 1);
  EXPECT_EQ(treeHeightOf(chain(5)), 3);
  bool taller_without_limit = false;
  for (const RelationTopology& neighbour : topologyNeighbours(star, 0))
    taller_without_limit |= treeHeightOf(neighbour) > 1;
  EXPECT_TRUE(taller_without_limit);
  // A star has no neighbour of height 1: every change adds a relation between leaves.
  EXPECT_TRUE(topologyNeighbours(star, 1).empty());
  const auto limited = topologyNeighbours(chain(5), 2);
  EXPECT_FALSE(limited.empty());
  for (const RelationTopology& neighbour : limited)
    EXPECT_LE(treeHeightOf(neighbour), 2);
  EXPECT_LT(limited.size(), topologyNeighbours(chain(5), 0).size());
}

TopologyMeasures measures(double false_positives, double work, double valid = 1.0) {
  TopologyMeasures result;
  result.false_positive_rate = false_positives;
  result.mean_work = work;
  result.true_positive_rate = valid;
  return result;
}

TEST(TopologyCost, NormalisesBetweenStarAndComplete) {
  const TopologyCost cost(measures(0.4, 100), measures(0.0, 1100), 1.0, 1.0);
  EXPECT_DOUBLE_EQ(cost(measures(0.4, 100)), 1.0);   // the star: worst errors, least work
  EXPECT_DOUBLE_EQ(cost(measures(0.0, 1100)), 1.0);  // complete: no errors, most work
  EXPECT_DOUBLE_EQ(cost(measures(0.1, 350)), 0.25 + 0.25);
  // Rejected valid configurations count as errors too, by default as much as accepted invalid.
  EXPECT_DOUBLE_EQ(cost(measures(0.1, 350, 0.9)), 0.5 + 0.25);
  const TopologyCost weighted(measures(0.4, 100), measures(0.0, 1100), 3.0, 0.5);
  EXPECT_DOUBLE_EQ(weighted(measures(0.2, 600)), 1.5 + 0.25);
}

TEST(TopologyCost, EachTestConfigurationCountsOnce) {
  // A quarter of the configurations valid: a valid one rejected is as bad as an invalid one
  // accepted, so 10 % of the valid ones rejected weigh a third of 10 % of the invalid accepted.
  const TopologyCost cost(measures(0.4, 100), measures(0.0, 1100), 1.0, 1.0, 0.0, 0.25);
  EXPECT_DOUBLE_EQ(cost.errors(measures(0.4, 100)), 0.3);
  EXPECT_DOUBLE_EQ(cost.errors(measures(0.0, 100, 0.9)), 0.025);
  EXPECT_DOUBLE_EQ(cost(measures(0.1, 100, 0.9)), (0.075 + 0.025) / 0.3);
  // Rejecting everything is not free: all valid configurations are errors.
  EXPECT_DOUBLE_EQ(cost.errors(measures(0.0, 100, 0.0)), 0.25);
  for (const double share : {-0.1, 1.5}) {
    EXPECT_NE(inputErrorOf([&] {
                TopologyCost(measures(0.4, 100), measures(0.0, 1100), 1.0, 1.0, 0.0, share);
              }).find("share of valid"),
              std::string::npos);
  }
}

TEST(TopologyCost, EqualExtremesGiveZeroNotADivisionByZero) {
  EXPECT_EQ(TopologyCost::normalised(5.0, 5.0, 5.0), 0.0);
  const TopologyCost cost(measures(0.0, 500), measures(0.0, 500), 1.0, 1.0);
  EXPECT_EQ(cost(measures(0.0, 500)), 0.0);
  EXPECT_EQ(cost(measures(0.3, 900)), 0.0);  // nothing to tell topologies apart by
}

TEST(TopologyCost, RefusesNegativeOrZeroWeights) {
  EXPECT_NE(
      inputErrorOf([] { TopologyCost(measures(0, 1), measures(0, 2), -1.0, 1.0); }).find("alpha"),
      std::string::npos);
  EXPECT_NE(
      inputErrorOf([] { TopologyCost(measures(0, 1), measures(0, 2), 0.0, 0.0); }).find("alpha"),
      std::string::npos);
}

TEST(TopologyCost, AnythingOverTheWorkBudgetCostsMoreThanEverythingWithinIt) {
  const TopologyCost cost(measures(0.4, 100), measures(0.0, 1100), 1.0, 1.0, 500.0);
  EXPECT_DOUBLE_EQ(cost(measures(0.4, 100)), 1.0);  // within the budget: as without one
  EXPECT_DOUBLE_EQ(cost(measures(0.8, 500)), 2.0 + 0.4);
  const double over = cost(measures(0.0, 600));
  EXPECT_GE(over, TopologyCost::kOverBudget);
  EXPECT_GT(over, cost(measures(0.8, 500)));
  EXPECT_LT(over, cost(measures(0.0, 900)));  // over it, less work is better
  TopologyMeasures stopped_early = measures(0.0, 400);
  stopped_early.over_budget = true;
  EXPECT_GE(cost(stopped_early), TopologyCost::kOverBudget);
}

// Three objects in a row, 10 cm apart, demonstrated in five steps that move the whole row; object
// 2 also turns a little, as a recorded object would.
asr_ism::Demonstration rowOfThree() {
  asr_ism::Demonstration demonstration("row", objects(3));
  for (int step = 0; step < 5; ++step) {
    demonstration.addStep();
    for (int object = 0; object < 3; ++object) {
      const double turn = object == 2 ? 0.02 * step : 0.0;
      demonstration.setPose(
          step, object,
          {Eigen::Vector3d(0.5 * step + 0.1 * object, 0.0, 0.0),
           Eigen::Quaterniond(Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()))});
    }
  }
  return demonstration;
}

TEST(RelationViolations, AMovedObjectBreaksItsRelationsAndNoOthers) {
  const asr_ism::Demonstration demonstration = rowOfThree();
  asr_common::Configuration demonstrated = demonstration.configuration(3);
  asr_common::Configuration moved = demonstrated;
  moved[2].pose.position.y() += 0.3;  // object 2 pushed 30 cm aside
  asr_common::Configuration slightly = demonstrated;
  slightly[2].pose.position.y() += 0.01;  // 1 cm: within what the ISM tolerates
  asr_common::Configuration without = demonstrated;
  without.pop_back();  // object 2 absent
  const RelationViolations violations(demonstration, {demonstrated, moved, slightly, without}, {},
                                      0.05);
  ASSERT_EQ(violations.configurationCount(), 4u);
  for (std::size_t c : {0u, 2u, 3u}) {
    EXPECT_FALSE(violations.breaks(c, 0, 1)) << c;
    EXPECT_FALSE(violations.breaks(c, 0, 2)) << c;
    EXPECT_FALSE(violations.breaks(c, 1, 2)) << c;
  }
  EXPECT_FALSE(violations.breaks(1, 0, 1));
  EXPECT_TRUE(violations.breaks(1, 0, 2));
  EXPECT_TRUE(violations.breaks(1, 2, 1));  // either order names the pair

  RelationTopology star_at_0(objects(3));
  star_at_0.addRelation(0, 1);
  star_at_0.addRelation(0, 2);
  EXPECT_EQ(violations.predictedAccepted(star_at_0), 3u);
  EXPECT_EQ(violations.predictedAccepted(chain(3)), 3u);
  EXPECT_EQ(violations.predictedAccepted(RelationTopology(objects(3))), 4u);
}

TEST(RelationViolations, GrowingAddsOnlyTheRelationsThatCatchSomething) {
  const asr_ism::Demonstration demonstration = rowOfThree();
  asr_common::Configuration far = demonstration.configuration(2);
  far[2].pose.position.z() += 0.5;  // only relations to object 2 break
  const RelationViolations far_violations(demonstration, {far}, {}, 0.05);
  RelationTopology star_at_1(objects(3));
  star_at_1.addRelation(1, 0);
  star_at_1.addRelation(1, 2);
  EXPECT_EQ(withCatchingRelations(star_at_1, far_violations, 0), star_at_1);
  // A topology without relations to object 2 gets one that catches the raised object.
  RelationTopology only_01(objects(3));
  only_01.addRelation(0, 1);
  const RelationTopology caught = withCatchingRelations(only_01, far_violations, 0);
  EXPECT_EQ(caught.relationCount(), 2u);
  EXPECT_TRUE(caught.hasRelation(0, 2));  // the first pair in object order that catches it
  EXPECT_EQ(far_violations.predictedAccepted(caught), 0u);
}

TEST(TestConfigurations, ZeroRequestedIsAnError) {
  const asr_ism::Demonstration demonstration =
      asr_ism::makeSyntheticDemonstration(3, 10, 5, "shelf");
  const IsmTree complete =
      generateIsmTree(demonstration, RelationTopology::complete(demonstration.objects()), {});
  const std::string message =
      inputErrorOf([&] { generateTestConfigurations(demonstration, complete, 0, 1, 0.99); });
  EXPECT_NE(message.find("got 0"), std::string::npos) << message;
  EXPECT_NE(message.find("shelf"), std::string::npos) << message;
}

class TopologySelectionOnRecordings : public ::testing::Test {
 protected:
  void SetUp() override {
    REQUIRE_RECORDINGS();
    demonstration_ = asr_ism::sqlite::readDemonstration(
        asr_common::testing::recording("story_2.sqlite"), "Getraenke_Regal");
    options_.test_count = 120;
    options_.max_evaluations = 30;
    options_.seed = 7;
    options_.threads = 2;
  }
  asr_ism::Demonstration demonstration_;
  TopologySelectionOptions options_;
};

TEST_F(TopologySelectionOnRecordings, OptimisedIsNoWorseThanStarAndNoSlowerThanComplete) {
  std::size_t reports = 0;
  const TopologySelectionResult result =
      selectTopology(demonstration_, options_, [&](const TopologySelectionProgress& progress) {
        ++reports;
        EXPECT_LE(progress.best_cost, progress.current_cost + 1e-12);
        EXPECT_LE(progress.evaluated, options_.max_evaluations);
      });
  EXPECT_GT(reports, 0u);
  EXPECT_TRUE(result.topology.isConnected());
  EXPECT_LE(result.evaluated, options_.max_evaluations);
  EXPECT_EQ(result.complete_measures.false_positive_rate, 0.0);
  EXPECT_GT(result.star_measures.false_positive_rate, 0.0);
  EXPECT_LE(result.measures.false_positive_rate, result.star_measures.false_positive_rate);
  EXPECT_LE(result.measures.mean_work, result.complete_measures.mean_work);
}

TEST(TopologySelection, NothingMeasuredBeatsTheResultNotEvenTheCompleteTopology) {
  REQUIRE_RECORDINGS();
  // Spuelkorb_3 (10 objects): with the work not weighed, no sparser tree matches the complete
  // topology's zero errors, and a climb from the stars does not get there within the
  // evaluations; the search must still end on the best topology it measured.
  const asr_ism::Demonstration demonstration = asr_ism::sqlite::readDemonstration(
      asr_common::testing::recording("story_1.sqlite"), "Spuelkorb_3");
  TopologySelectionOptions options;
  options.test_count = 60;
  options.max_evaluations = 16;
  options.beta = 0.0;
  options.threads = 2;
  const TopologySelectionResult result = selectTopology(demonstration, options);
  EXPECT_EQ(result.cost, 0.0);
  EXPECT_EQ(result.measures.false_positive_rate, 0.0);
  EXPECT_EQ(result.measures.true_positive_rate, 1.0);
}

TEST_F(TopologySelectionOnRecordings, TheSameSeedGivesTheSameTopologyOnAnyThreadCount) {
  const TopologySelectionResult first = selectTopology(demonstration_, options_);
  options_.threads = 1;
  const TopologySelectionResult second = selectTopology(demonstration_, options_);
  EXPECT_EQ(first.topology, second.topology);
  EXPECT_EQ(first.evaluated, second.evaluated);
  EXPECT_EQ(first.cost, second.cost);
  options_.method = TopologySearchMethod::kSimulatedAnnealing;
  const TopologySelectionResult annealed = selectTopology(demonstration_, options_);
  options_.threads = 2;
  EXPECT_EQ(selectTopology(demonstration_, options_).topology, annealed.topology);
  EXPECT_LE(annealed.measures.false_positive_rate, annealed.star_measures.false_positive_rate);
}

TEST_F(TopologySelectionOnRecordings, TestConfigurationsAreLabelledStoredAndReadBackExactly) {
  const asr_ism::Demonstration& demonstration = demonstration_;
  const IsmTree complete =
      generateIsmTree(demonstration, RelationTopology::complete(demonstration.objects()), {});
  const TestConfigurations tests = generateTestConfigurations(demonstration, complete, 40, 3, 0.99);
  EXPECT_EQ(tests.size(), 40u);
  // The labels are the complete tree's verdicts.
  const TreeRecognizer recognizer(complete);
  for (const auto& configuration : tests.valid)
    EXPECT_GE(recognizer.recognize(configuration).at(0).confidence, 0.99);
  EXPECT_FALSE(tests.valid.empty());
  EXPECT_FALSE(tests.invalid.empty());
  const TestConfigurations again = generateTestConfigurations(demonstration, complete, 40, 3, 0.99);
  ASSERT_EQ(again.valid.size(), tests.valid.size());
  EXPECT_EQ(again.valid.front().front().pose.position, tests.valid.front().front().pose.position);

  asr_common::testing::TempDir dir("asr_topology_tests");
  const std::string path = dir.file("tests.sqlite");
  writeTestConfigurations(path, tests, demonstration.objects());
  const TestConfigurations read = readTestConfigurations(path, "Getraenke_Regal");
  ASSERT_EQ(read.valid.size(), tests.valid.size());
  ASSERT_EQ(read.invalid.size(), tests.invalid.size());
  for (std::size_t i = 0; i < tests.invalid.size(); ++i) {
    ASSERT_EQ(read.invalid[i].size(), tests.invalid[i].size());
    for (const asr_common::ObjectEstimate& estimate : tests.invalid[i]) {
      const auto found = std::find_if(read.invalid[i].begin(), read.invalid[i].end(),
                                      [&](const auto& e) { return e.key == estimate.key; });
      ASSERT_NE(found, read.invalid[i].end());
      EXPECT_EQ(found->pose.position, estimate.pose.position);
      EXPECT_EQ(found->pose.orientation.coeffs(), estimate.pose.orientation.coeffs());
    }
  }
  // Nothing is overwritten: a second write of the same scene is refused.
  const std::string twice =
      inputErrorOf([&] { writeTestConfigurations(path, tests, demonstration.objects()); });
  EXPECT_NE(twice.find("already holds"), std::string::npos) << twice;
  EXPECT_NE(inputErrorOf([&] { readTestConfigurations(path, "table"); }).find("table"),
            std::string::npos);
}

TEST_F(TopologySelectionOnRecordings, ATimeBudgetIsKeptOrTheLeastWorkIsChosen) {
  options_.max_evaluations = 20;
  // A fixed time per comparison, as if measured: the budget's conversion into work is exact and
  // the test does not depend on how fast or busy the machine is.
  options_.ms_per_comparison = 2e-5;
  const TopologySelectionResult free = selectTopology(demonstration_, options_);
  EXPECT_EQ(free.max_mean_work, 0.0);
  // A budget between the star's and the complete tree's times is converted into work, and the
  // selected topology's work stays within it.
  options_.max_duration_ms = 0.5 * (free.star_measures.mean_ms + free.complete_measures.mean_ms);
  const TopologySelectionResult budgeted = selectTopology(demonstration_, options_);
  EXPECT_GT(budgeted.max_mean_work, 0.0);
  EXPECT_LT(budgeted.cost, TopologyCost::kOverBudget);
  EXPECT_LE(budgeted.measures.mean_work, budgeted.max_mean_work);
  EXPECT_DOUBLE_EQ(budgeted.max_mean_work, options_.max_duration_ms / options_.ms_per_comparison);
  EXPECT_LE(budgeted.measures.mean_ms, options_.max_duration_ms);
  // A budget nothing meets: the result is over it, and no topology costs more work than the star
  // among those a search led by work alone would reach from it.
  options_.max_duration_ms = 1e-9;
  const TopologySelectionResult impossible = selectTopology(demonstration_, options_);
  EXPECT_GE(impossible.cost, TopologyCost::kOverBudget);
  EXPECT_LE(impossible.measures.mean_work, impossible.star_measures.mean_work * 1.5);
  options_.max_duration_ms = -1.0;
  EXPECT_NE(inputErrorOf([&] { selectTopology(demonstration_, options_); }).find("time budget"),
            std::string::npos);
}

TEST_F(TopologySelectionOnRecordings, EvaluationStopsEarlyOverTheWorkBudget) {
  const IsmTree complete =
      generateIsmTree(demonstration_, RelationTopology::complete(demonstration_.objects()), {});
  const TestConfigurations tests =
      generateTestConfigurations(demonstration_, complete, 40, 3, 0.99);
  const RelationTopology topology = RelationTopology::complete(demonstration_.objects());
  const TopologyMeasures full = evaluateTopology(demonstration_, topology, tests, {}, 0.99);
  EXPECT_FALSE(full.over_budget);
  EXPECT_EQ(full.false_positive_rate, 0.0);
  const TopologyMeasures stopped =
      evaluateTopology(demonstration_, topology, tests, {}, 0.99, full.mean_work / 4);
  EXPECT_TRUE(stopped.over_budget);
  // Within the budget nothing changes.
  const TopologyMeasures within =
      evaluateTopology(demonstration_, topology, tests, {}, 0.99, full.mean_work * 2);
  EXPECT_FALSE(within.over_budget);
  EXPECT_EQ(within.mean_work, full.mean_work);
}

TEST_F(TopologySelectionOnRecordings, ADisconnectedStartIsRefused) {
  RelationTopology start(demonstration_.objects());
  start.addRelation(0, 1);
  options_.start = &start;
  const std::string message = inputErrorOf([&] { selectTopology(demonstration_, options_); });
  EXPECT_NE(message.find("start topology"), std::string::npos) << message;
}

}  // namespace
}  // namespace asr_ism_tree
