// The executive's states and transitions against scripted parts (no libraries, no ROS).
#include "asr_state_machine/search_executive.hpp"

#include <gtest/gtest.h>

#include <map>

namespace asr_state_machine {
namespace {

Pose at(double x) {
  return Pose(Eigen::Vector3d(x, 0, 1), Eigen::Quaterniond::Identity());
}

// Views are told apart by the base's x; the camera is at the same x.
struct ScriptedRobot : Robot {
  RobotState current;
  double seconds_per_move = 10.0;
  int moves = 0;
  RobotState state() override { return current; }
  MoveResult moveTo(const RobotState& goal) override {
    ++moves;
    current = goal;
    return {goal, at(goal.x), seconds_per_move};
  }
};

struct ScriptedDetector : Detector {
  std::map<int, std::vector<ObjectEstimate>> objects_at_x;  // what each view shows
  bool fails = false;
  DetectionResult detect(const Pose& camera, const std::vector<std::string>& types) override {
    if (fails)
      throw PartFailure("object_detector", "no answer within 30 s");
    DetectionResult result;
    result.seconds = 3.0 * types.size();
    for (const ObjectEstimate& estimate : objects_at_x[static_cast<int>(camera.position.x())]) {
      if (std::count(types.begin(), types.end(), estimate.key.type)) {
        result.estimates.push_back(estimate);
      }
    }
    return result;
  }
};

// Scene "s" of objects A and B; confidence = share of them found.
struct ScriptedRecognizer : Recognizer {
  std::map<std::string, std::vector<ObjectKey>> sceneObjects() override {
    return {{"s", {{"A", "0"}, {"B", "0"}}}};
  }
  std::vector<SceneInstance> recognize(const asr_common::Configuration& found) override {
    SceneInstance instance;
    instance.scene = "s";
    instance.confidence = found.size() / 2.0;
    return {instance};
  }
};

struct ScriptedPredictor : Predictor {
  int calls = 0;
  std::vector<PredictedCloud> predict(const std::vector<SceneInstance>&,
                                      const std::vector<ObjectKey>& missing,
                                      std::uint32_t) override {
    ++calls;
    std::vector<PredictedCloud> clouds;
    for (const ObjectKey& key : missing)
      clouds.push_back({key, {at(7.0)}});
    return clouds;
  }
};

// Proposes the view at x = 7 while it has not been looked at.
struct ScriptedPlanner : ViewPlanner {
  bool seen = false;
  std::size_t setHypotheses(const std::vector<PredictedCloud>& clouds,
                            const std::vector<VisitedView>& visited) override {
    seen = std::any_of(visited.begin(), visited.end(),
                       [](const VisitedView& v) { return v.camera.position.x() == 7.0; });
    return clouds.empty() || seen ? 0 : 1;
  }
  PlannedView next(const RobotState&) override {
    PlannedView view;
    view.found = !seen;
    view.state.x = 7.0;
    view.camera = at(7.0);
    view.types = {"B"};
    view.utility = 1.0;
    return view;
  }
  std::size_t update(const Pose& camera, const std::vector<std::string>&) override {
    if (camera.position.x() == 7.0)
      seen = true;
    return 1;
  }
  void removeObjects(const std::vector<ObjectKey>&) override {}
};

// Views at x = 1, 2, ..., `count`, each once.
struct ScriptedDirectSearch : DirectSearch {
  int count = 3;
  std::optional<SearchView> next(const RobotState&, const std::vector<std::string>&,
                                 const std::vector<VisitedView>& visited) override {
    for (int x = 1; x <= count; ++x) {
      const bool taken = std::any_of(visited.begin(), visited.end(), [&](const VisitedView& v) {
        return v.camera.position.x() == x;
      });
      if (!taken) {
        SearchView view;
        view.state.x = x;
        view.camera = at(x);
        return view;
      }
    }
    return std::nullopt;
  }
};

struct Rig {
  ScriptedRobot robot;
  ScriptedDetector detector;
  ScriptedRecognizer recognizer;
  ScriptedPredictor predictor;
  ScriptedPlanner planner;
  ScriptedDirectSearch direct;
  SearchConfig config;

  Rig() {
    detector.objects_at_x[2] = {{{"A", "0"}, at(2.0)}};
    detector.objects_at_x[7] = {{{"B", "0"}, at(7.0)}};
  }
  SearchResult run() {
    return SearchExecutive({robot, detector, recognizer, predictor, planner, direct}, config).run();
  }
};

std::vector<std::string> events(const SearchResult& result) {
  std::vector<std::string> out;
  for (const LogEntry& entry : result.log)
    out.push_back(entry.state + ":" + entry.event);
  return out;
}

TEST(SearchExecutive, DirectSearchFindsOneObjectAndTheRelationBasedSearchTheOther) {
  Rig rig;
  const SearchResult result = rig.run();
  EXPECT_EQ(result.outcome, Outcome::kFoundAllObjects);
  ASSERT_EQ(result.world.foundObjects().size(), 2u);
  EXPECT_EQ(result.world.foundObjects()[1].key.type, "B");
  EXPECT_EQ(result.world.visitedViews().size(), 3u);  // x = 1, 2 (A), then 7 (B)
  // Moves of 10 s, detection of 2 missing types, then of 1: 3 x 10 + 6 + 6 + 3.
  EXPECT_DOUBLE_EQ(result.sim_seconds, 45.0);
  const std::vector<std::string> log = events(result);
  const auto has = [&](const std::string& e) {
    return std::find(log.begin(), log.end(), e) != log.end();
  };
  EXPECT_TRUE(has("SCENE_RECOGNITION:recognised"));
  EXPECT_TRUE(has("OBJECT_POSE_PREDICTION:predicted"));
  EXPECT_TRUE(has("RELATION_BASED_SEARCH:next_best_view"));
  EXPECT_EQ(log.back(), "SCENE_RECOGNITION:found_all_objects");
  EXPECT_EQ(result.world.sceneConfidence("s"), 0.5);
}

TEST(SearchExecutive, EndsNowhereLeftToSearchWhenAnObjectIsAbsent) {
  Rig rig;
  rig.detector.objects_at_x.erase(7);  // B is not where it is predicted, nor anywhere else
  const SearchResult result = rig.run();
  EXPECT_EQ(result.outcome, Outcome::kNowhereLeftToSearch);
  EXPECT_EQ(result.world.foundObjects().size(), 1u);
  EXPECT_EQ(result.world.visitedViews().size(), 4u);  // every direct view and the predicted one
}

TEST(SearchExecutive, EndsWhenTheRequiredScenesAreConfidentEnough) {
  Rig rig;
  rig.config.required_scenes = {{"s", 0.5}};
  const SearchResult result = rig.run();
  EXPECT_EQ(result.outcome, Outcome::kFoundAllRequiredScenes);
  EXPECT_EQ(result.world.foundObjects().size(), 1u);
}

TEST(SearchExecutive, AFailingPartAbortsTheSearchNamingIt) {
  Rig rig;
  rig.detector.fails = true;
  const SearchResult result = rig.run();
  EXPECT_EQ(result.outcome, Outcome::kAborted);
  EXPECT_NE(result.reason.find("object_detector"), std::string::npos) << result.reason;
  EXPECT_EQ(rig.robot.moves, 1);
}

TEST(SearchExecutive, TheTimeBudgetAbortsTheSearch) {
  Rig rig;
  rig.robot.seconds_per_move = 100.0;
  rig.config.max_sim_seconds = 150.0;
  const SearchResult result = rig.run();
  EXPECT_EQ(result.outcome, Outcome::kAborted);
  EXPECT_NE(result.reason.find("time budget"), std::string::npos) << result.reason;
  EXPECT_LE(result.world.visitedViews().size(), 2u);
}

TEST(SearchExecutive, DirectModeNeverPredicts) {
  Rig rig;
  rig.config.mode = SearchMode::kDirect;
  rig.direct.count = 8;  // the sweep reaches x = 7 itself
  const SearchResult result = rig.run();
  EXPECT_EQ(result.outcome, Outcome::kFoundAllObjects);
  EXPECT_EQ(rig.predictor.calls, 0);
  EXPECT_EQ(result.world.visitedViews().size(), 7u);
}

TEST(SearchExecutive, BoundingBoxModeStartsWithTheViewPlanner) {
  Rig rig;
  rig.config.mode = SearchMode::kBoundingBox;
  const SearchResult result = rig.run();
  EXPECT_EQ(result.outcome, Outcome::kFoundAllObjects);
  EXPECT_EQ(result.world.visitedViews().front().camera.position.x(), 7.0);
}

TEST(SearchExecutive, ModesAndOutcomesHaveTheirNames) {
  EXPECT_EQ(parseMode("bbox"), SearchMode::kBoundingBox);
  EXPECT_THROW(parseMode("random"), std::exception);
  EXPECT_STREQ(outcomeName(Outcome::kNowhereLeftToSearch), "nowhere_left_to_search");
}

}  // namespace
}  // namespace asr_state_machine
