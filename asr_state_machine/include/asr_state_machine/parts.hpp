#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "asr_common/object.hpp"
#include "asr_ism_tree/scene_instance.hpp"
#include "asr_nbv/hypotheses.hpp"
#include "asr_nbv/next_best_view_planner.hpp"
#include "asr_robot_model/robot_state.hpp"
#include "asr_state_machine/world_model.hpp"

// The parts the search executive talks to. Each is an interface with an in-process
// implementation on the suite's libraries (in_process_parts.hpp: experiments, tests,
// `asr search`); a ROS client of the part's node implements the same interface, so the
// executive's decisions are written once.
namespace asr_state_machine {

using asr_ism_tree::SceneInstance;
using asr_nbv::PlannedView;
using asr_nbv::PredictedCloud;
using asr_robot_model::RobotState;

/// A part that failed: it stopped answering, refused a request it should take, or broke. The
/// search ends `aborted`, naming the part.
class PartFailure : public std::runtime_error {
 public:
  PartFailure(const std::string& part, const std::string& reason)
      : std::runtime_error(part + ": " + reason), part_(part) {}
  const std::string& part() const { return part_; }

 private:
  std::string part_;
};

struct MoveResult {
  RobotState reached;
  Pose camera;           // camera_optical_frame in map where the robot stopped
  double seconds = 0.0;  // simulated time the motion took
};

/// The mobile base with its pan-tilt camera head.
class Robot {
 public:
  virtual ~Robot() = default;
  virtual RobotState state() = 0;
  /// Moves base and head to `goal`; throws PartFailure if it cannot.
  virtual MoveResult moveTo(const RobotState& goal) = 0;
};

struct DetectionResult {
  std::vector<ObjectEstimate> estimates;  // in map
  double seconds = 0.0;                   // simulated time the detection took
};

/// Object detection for some types from the camera's current pose (given, for detectors that
/// do not read it themselves).
class Detector {
 public:
  virtual ~Detector() = default;
  virtual DetectionResult detect(const Pose& camera, const std::vector<std::string>& types) = 0;
};

/// Scene recognition over the scene models.
class Recognizer {
 public:
  virtual ~Recognizer() = default;
  /// The objects of every scene model searched for.
  virtual std::map<std::string, std::vector<ObjectKey>> sceneObjects() = 0;
  /// Instances of the scenes in the configuration, best first.
  virtual std::vector<SceneInstance> recognize(const asr_common::Configuration& found) = 0;
};

/// Where the missing objects may be.
class Predictor {
 public:
  virtual ~Predictor() = default;
  /// Predicted poses of the `missing` objects (only those), from `instances` (best first);
  /// empty if nothing can be predicted.
  virtual std::vector<PredictedCloud> predict(const std::vector<SceneInstance>& instances,
                                              const std::vector<ObjectKey>& missing,
                                              std::uint32_t seed) = 0;
};

/// Next-best-view planning over the hypotheses of the predicted poses.
class ViewPlanner {
 public:
  virtual ~ViewPlanner() = default;
  /// New hypotheses, with every view already taken (and its types) replayed on them; returns
  /// how many hypotheses still count.
  virtual std::size_t setHypotheses(const std::vector<PredictedCloud>& clouds,
                                    const std::vector<VisitedView>& visited) = 0;
  virtual PlannedView next(const RobotState& current) = 0;
  /// After a view: deactivates what it has seen of `types`; returns how much.
  virtual std::size_t update(const Pose& camera, const std::vector<std::string>& types) = 0;
  /// Found objects are no longer searched.
  virtual void removeObjects(const std::vector<ObjectKey>& objects) = 0;
};

/// A view of the direct search.
struct SearchView {
  RobotState state;
  Pose camera;
  bool informed = false;  // chosen because a searched object was demonstrated there
};

/// The direct search's views: where the searched objects were demonstrated first, then a
/// sweep over the furniture, nearest first; none near a visited view.
class DirectSearch {
 public:
  virtual ~DirectSearch() = default;
  virtual std::optional<SearchView> next(const RobotState& current,
                                         const std::vector<std::string>& types,
                                         const std::vector<VisitedView>& visited) = 0;
};

}  // namespace asr_state_machine
