#include "asr_pose_prediction/prediction_accuracy.hpp"

#include <algorithm>
#include <limits>

#include "asr_common/input_error.hpp"

namespace asr_pose_prediction {

NearestPoseError nearestPoseError(const Pose& truth, const std::vector<Pose>& predictions) {
  if (predictions.empty())
    throw asr_common::InputError("no predicted pose to compare with the true pose");
  NearestPoseError error;
  error.distance = std::numeric_limits<double>::infinity();
  error.smallest_angle = std::numeric_limits<double>::infinity();
  for (const Pose& prediction : predictions) {
    const double distance = (prediction.position - truth.position).norm();
    const double angle = asr_common::angleBetween(prediction.orientation, truth.orientation);
    if (distance < error.distance) {
      error.distance = distance;
      error.angle_at_nearest = angle;
    }
    error.smallest_angle = std::min(error.smallest_angle, angle);
  }
  return error;
}

LeftOutPrediction predictLeftOutObject(const asr_ism_tree::TreeRecognizer& recognizer,
                                       const PosePredictor& predictor,
                                       const asr_common::Configuration& configuration,
                                       std::size_t left_out, std::size_t samples,
                                       std::uint32_t seed) {
  const asr_common::ObjectEstimate& truth = configuration.at(left_out);
  const std::size_t object = predictor.objectIndex(truth.key);
  asr_common::Configuration rest = configuration;
  rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(left_out));

  LeftOutPrediction outcome;
  const std::vector<SceneInstance> instances = recognizer.recognize(rest);
  if (instances.empty())
    return outcome;
  outcome.instance_found = true;
  outcome.confidence = instances.front().confidence;
  outcome.error = nearestPoseError(
      truth.pose, predictor.predictObject(instances.front().pose, object, samples, seed));
  return outcome;
}

}  // namespace asr_pose_prediction
