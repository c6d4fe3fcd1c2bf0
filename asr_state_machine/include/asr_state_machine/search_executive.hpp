#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "asr_state_machine/parts.hpp"
#include "asr_state_machine/world_model.hpp"

namespace asr_state_machine {

/// asr: direct and indirect search; direct: direct search only; bbox: next-best-view on
/// hypotheses spread over the furniture (no scene knowledge), then direct search.
enum class SearchMode { kAsr, kDirect, kBoundingBox };
/// "asr", "direct", "bbox".
const char* modeName(SearchMode mode);
/// Throws asr_common::InputError naming the text if it is no mode.
SearchMode parseMode(const std::string& text);

enum class Outcome { kFoundAllObjects, kFoundAllRequiredScenes, kNowhereLeftToSearch, kAborted };
/// "found_all_objects", "found_all_required_scenes", "nowhere_left_to_search", "aborted".
const char* outcomeName(Outcome outcome);

struct SearchConfig {
  SearchMode mode = SearchMode::kAsr;
  /// Scenes that end the search once recognised with at least this confidence (all of them).
  std::map<std::string, double> required_scenes;
  double max_sim_seconds = 3600.0;
  std::uint32_t seed = 0;
  /// A view is worth moving to if the planner's utility of its types reaches this.
  double min_utility = 0.1;
  /// Predictions in a row that lead to no worthwhile view before the direct search resumes.
  int max_worthless_predictions = 3;
  /// Views after which nothing was deactivated in a row before predicting again.
  int max_stale_updates = 2;
};

/// One decision or event of the search, with the simulated time it happened at.
struct LogEntry {
  double t = 0.0;  // simulated seconds
  std::string state;
  std::string event;
  std::string detail;
  double compute_seconds = 0.0;  // measured compute of the decision (0 for robot events)
};

struct SearchResult {
  Outcome outcome = Outcome::kAborted;
  std::string reason;
  double sim_seconds = 0.0;
  double compute_seconds = 0.0;  // recognition + prediction + next-best-view, measured
  /// Per decision of recognition, prediction or next-best-view (what compute_seconds sums).
  std::vector<double> decision_compute_seconds;
  WorldModel world;
  std::vector<LogEntry> log;
  RobotState start;  // where the robot began (the path goes on through the visited views)
};

struct SearchParts {
  Robot& robot;
  Detector& detector;
  Recognizer& recognizer;
  Predictor& predictor;  // scene-based (asr) or over the furniture (bbox)
  ViewPlanner& view_planner;
  DirectSearch& direct_search;
};

/// The search: an explicit state machine, one function per state; the transitions are the
/// functions' return values (docs/search.md draws the graph).
///
///   INIT -> DIRECT_SEARCH (bbox: OBJECT_POSE_PREDICTION)
///   DIRECT_SEARCH: next direct view, move, detect the missing types;
///     found something -> SCENE_RECOGNITION; nothing -> DIRECT_SEARCH;
///     no view left -> nowhere_left_to_search
///   SCENE_RECOGNITION: all objects found -> found_all_objects; required scenes complete ->
///     found_all_required_scenes; else OBJECT_POSE_PREDICTION (direct mode: DIRECT_SEARCH)
///   OBJECT_POSE_PREDICTION: predictions ran out or are empty -> DIRECT_SEARCH;
///     else NBV_SET_HYPOTHESES
///   NBV_SET_HYPOTHESES: nothing counts -> OBJECT_POSE_PREDICTION; else RELATION_BASED_SEARCH
///   RELATION_BASED_SEARCH: next best view; worthless -> OBJECT_POSE_PREDICTION; move, detect,
///     update; found something -> SCENE_RECOGNITION; else RELATION_BASED_SEARCH
///
/// A PartFailure or an exhausted time budget ends it `aborted` with the reason.
class SearchExecutive {
 public:
  SearchExecutive(SearchParts parts, SearchConfig config);

  SearchResult run();

  /// Called with every log entry as it is made and the world model as it is then (a node
  /// publishes the search as it goes).
  using LogListener = std::function<void(const LogEntry&, const WorldModel&)>;
  void onLog(LogListener listener) { log_listener_ = std::move(listener); }

 private:
  enum class State {
    kInit,
    kDirectSearch,
    kSceneRecognition,
    kObjectPosePrediction,
    kNbvSetHypotheses,
    kRelationBasedSearch,
    kDone
  };
  static const char* stateName(State state);

  State init();
  State directSearch();
  State sceneRecognition();
  State objectPosePrediction();
  State nbvSetHypotheses();
  State relationBasedSearch();
  State run(State state);

  State finish(Outcome outcome, const std::string& reason);
  /// Moves to `goal`, detects `types`, updates the world model; returns how many objects were
  /// new and where the camera was.
  struct ViewTaken {
    int new_objects = 0;
    Pose camera;
  };
  ViewTaken takeView(const RobotState& goal, const std::vector<std::string>& types);
  bool requiredScenesComplete() const;
  void log(const std::string& event, const std::string& detail, double compute_seconds = 0.0);
  void decided(double compute_seconds);

  SearchParts parts_;
  SearchConfig config_;
  LogListener log_listener_;
  SearchResult result_;
  State state_ = State::kInit;
  std::vector<SceneInstance> instances_;
  std::vector<PredictedCloud> clouds_;
  int worthless_predictions_ = 0;
  int stale_updates_ = 0;
  std::uint32_t prediction_round_ = 0;
};

}  // namespace asr_state_machine
