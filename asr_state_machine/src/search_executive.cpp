#include "asr_state_machine/search_executive.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <set>
#include <sstream>

#include "asr_common/input_error.hpp"

namespace asr_state_machine {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string joined(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& word : words)
    text += (text.empty() ? "" : ",") + word;
  return text;
}

std::string fixed(double value, int digits = 2) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", digits, value);
  return text;
}

}  // namespace

const char* modeName(SearchMode mode) {
  switch (mode) {
    case SearchMode::kAsr:
      return "asr";
    case SearchMode::kDirect:
      return "direct";
    case SearchMode::kBoundingBox:
      return "bbox";
  }
  return "?";
}

SearchMode parseMode(const std::string& text) {
  for (SearchMode mode : {SearchMode::kAsr, SearchMode::kDirect, SearchMode::kBoundingBox}) {
    if (text == modeName(mode))
      return mode;
  }
  throw asr_common::InputError("unknown search mode '" + text + "' (asr, direct or bbox)");
}

const char* outcomeName(Outcome outcome) {
  switch (outcome) {
    case Outcome::kFoundAllObjects:
      return "found_all_objects";
    case Outcome::kFoundAllRequiredScenes:
      return "found_all_required_scenes";
    case Outcome::kNowhereLeftToSearch:
      return "nowhere_left_to_search";
    case Outcome::kAborted:
      return "aborted";
  }
  return "?";
}

const char* SearchExecutive::stateName(State state) {
  switch (state) {
    case State::kInit:
      return "INIT";
    case State::kDirectSearch:
      return "DIRECT_SEARCH";
    case State::kSceneRecognition:
      return "SCENE_RECOGNITION";
    case State::kObjectPosePrediction:
      return "OBJECT_POSE_PREDICTION";
    case State::kNbvSetHypotheses:
      return "NBV_SET_HYPOTHESES";
    case State::kRelationBasedSearch:
      return "RELATION_BASED_SEARCH";
    case State::kDone:
      return "DONE";
  }
  return "?";
}

SearchExecutive::SearchExecutive(SearchParts parts, SearchConfig config)
    : parts_(parts), config_(std::move(config)) {}

SearchResult SearchExecutive::run() {
  state_ = State::kInit;
  while (state_ != State::kDone) {
    if (result_.sim_seconds > config_.max_sim_seconds) {
      state_ = finish(Outcome::kAborted, "the time budget of " +
                                             fixed(config_.max_sim_seconds / 60.0, 1) +
                                             " simulated minutes ran out");
      break;
    }
    try {
      state_ = run(state_);
    } catch (const PartFailure& failure) {
      state_ = finish(Outcome::kAborted, failure.what());
    }
  }
  return result_;
}

SearchExecutive::State SearchExecutive::run(State state) {
  switch (state) {
    case State::kInit:
      return init();
    case State::kDirectSearch:
      return directSearch();
    case State::kSceneRecognition:
      return sceneRecognition();
    case State::kObjectPosePrediction:
      return objectPosePrediction();
    case State::kNbvSetHypotheses:
      return nbvSetHypotheses();
    case State::kRelationBasedSearch:
      return relationBasedSearch();
    case State::kDone:
      return State::kDone;
  }
  return State::kDone;
}

SearchExecutive::State SearchExecutive::init() {
  result_ = SearchResult();
  result_.start = parts_.robot.state();
  result_.world.setSceneObjects(parts_.recognizer.sceneObjects());
  log("start", std::string("mode ") + modeName(config_.mode) + ", " +
                   std::to_string(result_.world.missingObjects().size()) + " objects to find");
  if (config_.mode == SearchMode::kBoundingBox)
    return State::kObjectPosePrediction;
  return State::kDirectSearch;
}

SearchExecutive::State SearchExecutive::directSearch() {
  const std::vector<std::string> types = result_.world.missingTypes();
  if (types.empty())
    return finish(Outcome::kFoundAllObjects, "");
  // The direct search's views are precomputed: choosing one is no decision of the executive.
  const std::optional<SearchView> view =
      parts_.direct_search.next(parts_.robot.state(), types, result_.world.visitedViews());
  if (!view) {
    return finish(Outcome::kNowhereLeftToSearch, "no direct-search view is left");
  }
  log(view->informed ? "demonstrated_view" : "sweep_view", joined(types));
  const ViewTaken taken = takeView(view->state, types);
  return taken.new_objects > 0 ? State::kSceneRecognition : State::kDirectSearch;
}

SearchExecutive::State SearchExecutive::sceneRecognition() {
  if (result_.world.missingObjects().empty())
    return finish(Outcome::kFoundAllObjects, "");
  const auto start = Clock::now();
  instances_ = parts_.recognizer.recognize(result_.world.configuration());
  const double compute = secondsSince(start);
  decided(compute);
  std::map<std::string, double> best;
  for (const SceneInstance& instance : instances_) {
    best[instance.scene] = std::max(best[instance.scene], instance.confidence);
  }
  std::string detail;
  for (const auto& [scene, confidence] : best) {
    result_.world.setSceneConfidence(scene, confidence);
    detail += (detail.empty() ? "" : ", ") + scene + " " + fixed(confidence);
  }
  log("recognised", detail.empty() ? "no scene" : detail, compute);
  if (requiredScenesComplete()) {
    return finish(Outcome::kFoundAllRequiredScenes, "every required scene reached its confidence");
  }
  if (config_.mode == SearchMode::kDirect)
    return State::kDirectSearch;
  worthless_predictions_ = 0;
  return State::kObjectPosePrediction;
}

SearchExecutive::State SearchExecutive::objectPosePrediction() {
  if (worthless_predictions_ >= config_.max_worthless_predictions) {
    log("predictions_ran_out",
        std::to_string(worthless_predictions_) + " predictions in a row gave no view worth taking");
    worthless_predictions_ = 0;
    return State::kDirectSearch;
  }
  const std::vector<ObjectKey> missing = result_.world.missingObjects();
  if (missing.empty())
    return finish(Outcome::kFoundAllObjects, "");
  const auto start = Clock::now();
  clouds_ = parts_.predictor.predict(instances_, missing, config_.seed + prediction_round_++);
  const double compute = secondsSince(start);
  decided(compute);
  std::size_t poses = 0;
  for (const PredictedCloud& cloud : clouds_)
    poses += cloud.poses.size();
  log("predicted", std::to_string(clouds_.size()) + " objects, " + std::to_string(poses) + " poses",
      compute);
  if (clouds_.empty()) {
    worthless_predictions_ = 0;
    return State::kDirectSearch;
  }
  return State::kNbvSetHypotheses;
}

SearchExecutive::State SearchExecutive::nbvSetHypotheses() {
  const auto start = Clock::now();
  const std::size_t counting =
      parts_.view_planner.setHypotheses(clouds_, result_.world.visitedViews());
  const double compute = secondsSince(start);
  decided(compute);
  log("hypotheses", std::to_string(counting) + " still count after the views taken", compute);
  stale_updates_ = 0;
  if (counting == 0) {
    ++worthless_predictions_;
    return State::kObjectPosePrediction;
  }
  return State::kRelationBasedSearch;
}

SearchExecutive::State SearchExecutive::relationBasedSearch() {
  const auto start = Clock::now();
  const PlannedView planned = parts_.view_planner.next(parts_.robot.state());
  const double compute = secondsSince(start);
  decided(compute);
  if (!planned.found || planned.utility < config_.min_utility) {
    log("no_view_worth_taking",
        planned.found ? "utility " + fixed(planned.utility, 3) : "nothing left to see", compute);
    ++worthless_predictions_;
    return State::kObjectPosePrediction;
  }
  const std::vector<std::string> missing_types = result_.world.missingTypes();
  std::vector<std::string> types;
  for (const std::string& type : planned.types) {
    if (std::binary_search(missing_types.begin(), missing_types.end(), type))
      types.push_back(type);
  }
  log("next_best_view", joined(types) + ", utility " + fixed(planned.utility, 3), compute);
  if (types.empty()) {
    const std::size_t deactivated = parts_.view_planner.update(planned.camera, planned.types);
    if (deactivated == 0 && ++stale_updates_ >= config_.max_stale_updates) {
      ++worthless_predictions_;
      return State::kObjectPosePrediction;
    }
    return State::kRelationBasedSearch;
  }
  const ViewTaken taken = takeView(planned.state, types);
  if (taken.new_objects > 0) {
    std::vector<ObjectKey> found;
    for (const FoundObject& object : result_.world.foundObjects())
      found.push_back(object.key);
    parts_.view_planner.removeObjects(found);
    return State::kSceneRecognition;
  }
  const std::size_t deactivated = parts_.view_planner.update(taken.camera, types);
  if (deactivated == 0 && ++stale_updates_ >= config_.max_stale_updates) {
    ++worthless_predictions_;
    return State::kObjectPosePrediction;
  }
  return State::kRelationBasedSearch;
}

SearchExecutive::ViewTaken SearchExecutive::takeView(const RobotState& goal,
                                                     const std::vector<std::string>& types) {
  const MoveResult moved = parts_.robot.moveTo(goal);
  result_.sim_seconds += moved.seconds;
  const int view = result_.world.addView({moved.camera, types, result_.sim_seconds, moved.reached});
  log("moved", "view " + std::to_string(view) + " after " + fixed(moved.seconds, 1) + " s");
  const DetectionResult detection = parts_.detector.detect(moved.camera, types);
  result_.sim_seconds += detection.seconds;
  ViewTaken taken;
  taken.camera = moved.camera;
  for (const ObjectEstimate& estimate : detection.estimates) {
    if (!std::count(types.begin(), types.end(), estimate.key.type))
      continue;
    const WorldModel::Added added = result_.world.addEstimate(estimate, result_.sim_seconds, view);
    if (added.is_new) {
      ++taken.new_objects;
      log("found", estimate.key.toString() + " in view " + std::to_string(view));
    }
  }
  log("detected", std::to_string(detection.estimates.size()) + " estimates of " +
                      std::to_string(types.size()) + " types, " +
                      std::to_string(taken.new_objects) + " new");
  return taken;
}

bool SearchExecutive::requiredScenesComplete() const {
  if (config_.required_scenes.empty())
    return false;
  for (const auto& [scene, threshold] : config_.required_scenes) {
    if (result_.world.sceneConfidence(scene) < threshold)
      return false;
  }
  return true;
}

SearchExecutive::State SearchExecutive::finish(Outcome outcome, const std::string& reason) {
  result_.outcome = outcome;
  result_.reason = reason;
  log(outcomeName(outcome), reason);
  return State::kDone;
}

void SearchExecutive::log(const std::string& event, const std::string& detail,
                          double compute_seconds) {
  result_.log.push_back({result_.sim_seconds, stateName(state_), event, detail, compute_seconds});
  if (log_listener_)
    log_listener_(result_.log.back(), result_.world);
}

void SearchExecutive::decided(double compute_seconds) {
  result_.compute_seconds += compute_seconds;
  result_.decision_compute_seconds.push_back(compute_seconds);
}

}  // namespace asr_state_machine
