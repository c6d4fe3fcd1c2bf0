#pragma once

#include <vector>

#include "asr_common/pose.hpp"
#include "asr_nbv/hypotheses.hpp"
#include "asr_nbv/nbv_parameters.hpp"
#include "asr_robot_model/motion_model.hpp"
#include "asr_robot_model/robot_description.hpp"
#include "asr_robot_model/world_map.hpp"

namespace asr_nbv {

/// The shaping function of every utility term: 0.5 + 0.5 cos(pi d / threshold) for
/// d < threshold, else 0 (1 at d = 0, falling smoothly to 0 at the threshold).
double raisedCosine(double d, double threshold);

/// True if `point` (in map) lies in the frustum of a camera_optical_frame pose (in map).
bool inFrustum(const asr_common::Pose& camera, const Eigen::Vector3d& point,
               const asr_robot_model::Frustum& frustum);

/// The largest raised cosine over the active normals of the angle between each and the
/// direction from the hypothesis to the camera; 1 for a hypothesis recognisable from every side.
double orientationUtility(const Hypothesis& hypothesis, const Eigen::Vector3d& camera_position,
                          double rating_angle);

/// Side x proximity of a point at `offset` from the camera, whose optical axis is `axis`
/// (unit): side from the angle between them (threshold half the smaller field of view),
/// proximity from the depth's distance to the middle of the clipping range (threshold half the
/// range). Non-zero only inside the frustum: within that cone the frustum's sides are never
/// reached, and the proximity term vanishes outside the clipping range.
double sideProximity(const Eigen::Vector3d& axis, const Eigen::Vector3d& offset,
                     const asr_robot_model::Frustum& frustum);

/// How well a camera sees one hypothesis, occlusion aside: 0 outside the frustum or for a
/// hypothesis that no longer counts, else orientationUtility x sideProximity.
double hypothesisUtility(const asr_common::Pose& camera, const Hypothesis& hypothesis,
                         const NbvParameters& parameters);

/// Utility of a view per type (indices of HypothesisSet::types()) and in total: the sum of
/// hypothesisUtility over the hypotheses whose line of sight from the camera is free in `map`
/// (no occlusion check without a map).
struct ViewUtility {
  std::vector<double> per_type;
  double total = 0.0;
};
ViewUtility viewUtility(const asr_common::Pose& camera, const HypothesisSet& hypotheses,
                        const NbvParameters& parameters, const asr_robot_model::WorldMap* map);

/// Inverse costs in [0, 1] (1: free) of going to a view and searching it.
struct InverseCosts {
  double base = 1.0;         // exp(-d^2 / (2 sigma^2)), d the distance driven
  double rotation = 1.0;     // 1 - radians turned on the spot / (2 pi)
  double pan_tilt = 1.0;     // the smaller of 1 - |pan change| / pan range, likewise tilt
  double recognition = 1.0;  // 1 - searched types / types to search
};

/// Costs of the base and head motion (from the robot model's motion model) and of searching
/// `searched_types` of `type_count` types.
InverseCosts inverseCosts(const asr_robot_model::Motion& motion,
                          const asr_robot_model::RobotState& from,
                          const asr_robot_model::RobotState& to,
                          const asr_robot_model::RobotDescription& robot,
                          std::size_t searched_types, std::size_t type_count,
                          const NbvParameters& parameters);

/// The rating in [0, 1]: weighted mean of utility / utility_max and the inverse costs.
double rating(double utility, double utility_max, const InverseCosts& costs,
              const RatingWeights& weights);

/// The types to search in a view: those maximising w_utility U(S) / utility_max
/// + w_recognition (1 - |S| / type_count). U adds up over types and the detection cost depends
/// on |S| alone, so for each k the best S is the k types of highest utility: one sort, not the
/// power set. Types with no utility are never chosen; ties go to fewer types.
struct TypeChoice {
  std::vector<int> types;  // indices, by falling utility
  double utility = 0.0;    // U(S)
};
TypeChoice bestTypeSubset(const std::vector<double>& per_type_utility, double utility_max,
                          std::size_t type_count, const RatingWeights& weights);

/// Deactivates, for every hypothesis of a searched type seen from `camera` (in its frustum, line
/// of sight free in `map` if given), the active normals within update_angle of the direction to
/// the camera (a hypothesis recognisable from every side: its single entry). Returns how many
/// were deactivated. `types` are names; unknown names are ignored.
std::size_t updateAfterView(HypothesisSet& hypotheses, const asr_common::Pose& camera,
                            const std::vector<std::string>& types, const NbvParameters& parameters,
                            const asr_robot_model::WorldMap* map);

}  // namespace asr_nbv
