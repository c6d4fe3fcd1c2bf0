#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "asr_common/object.hpp"
#include "asr_common/pose.hpp"
#include "asr_robot_model/robot_state.hpp"

namespace asr_state_machine {

using asr_common::ObjectEstimate;
using asr_common::ObjectKey;
using asr_common::Pose;

/// One object the search has found: the mean of the estimates that were merged into it.
struct FoundObject {
  ObjectKey key;
  Pose pose;
  int estimates = 0;        // merged into `pose`
  double found_at_s = 0.0;  // simulated seconds since the search began
  int view = -1;            // index of the visited view that first saw it
};

/// A camera view the robot has taken and the object types it searched there.
struct VisitedView {
  Pose camera;  // camera_optical_frame in map
  std::vector<std::string> types;
  double at_s = 0.0;
  asr_robot_model::RobotState base;  // where the robot stood (the path of the search)
};

/// When two estimates are one object.
struct MergeTolerance {
  /// Estimates of one type closer than this are one object when an id does not tell them
  /// apart (an estimate without id, or two estimates with the same id).
  double distance = 0.1;
};

/// What the search knows: the objects found (repeated estimates of one object merged into one
/// pose; several objects of one type kept apart by id and distance), the views visited with the
/// types searched there, which objects each scene model still misses, and the scenes recognised
/// with their confidence.
class WorldModel {
 public:
  explicit WorldModel(MergeTolerance tolerance = {});

  /// The objects every scene model holds, per scene (what "missing" is measured against).
  void setSceneObjects(const std::map<std::string, std::vector<ObjectKey>>& scene_objects);

  /// Adds one estimate. An estimate with an id joins the found object with its key; without
  /// one it joins the nearest found object of its type within the tolerance. Otherwise it is a
  /// new object. Returns the index of the object it joined or created and whether
  /// it was new. Throws asr_common::InputError for a non-finite pose.
  struct Added {
    std::size_t object;
    bool is_new;
  };
  Added addEstimate(const ObjectEstimate& estimate, double at_s, int view);

  /// Records a view; returns its index.
  int addView(const VisitedView& view);

  const std::vector<FoundObject>& foundObjects() const { return found_; }
  const std::vector<VisitedView>& visitedViews() const { return views_; }
  /// The found objects as a configuration for scene recognition.
  asr_common::Configuration configuration() const;

  /// The objects of `scene` no found object stands for: a found object stands for the scene
  /// object with its key; one whose id the scene does not know (or without id) for one object
  /// of its type that no other found object stands for. Throws InputError for a scene not set.
  std::vector<ObjectKey> missingObjects(const std::string& scene) const;
  /// Missing objects over all scenes, each once, sorted.
  std::vector<ObjectKey> missingObjects() const;
  /// The types of missingObjects(), sorted, each once.
  std::vector<std::string> missingTypes() const;
  bool isMissing(const ObjectKey& key) const;

  /// The best confidence each scene was recognised with so far (kept: later recognition
  /// replaces it, so it always reflects every object found).
  void setSceneConfidence(const std::string& scene, double confidence);
  const std::map<std::string, double>& sceneConfidences() const { return confidences_; }
  /// The confidence of `scene`, 0 if never recognised.
  double sceneConfidence(const std::string& scene) const;

  const std::map<std::string, std::vector<ObjectKey>>& sceneObjects() const {
    return scene_objects_;
  }

  /// Back to nothing found and nothing visited (the scene objects stay).
  void clear();

 private:
  std::optional<std::size_t> matchingObject(const ObjectEstimate& estimate) const;

  MergeTolerance tolerance_;
  std::map<std::string, std::vector<ObjectKey>> scene_objects_;
  std::vector<FoundObject> found_;
  std::vector<VisitedView> views_;
  std::map<std::string, double> confidences_;
};

}  // namespace asr_state_machine
