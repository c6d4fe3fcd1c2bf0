#pragma once

#include <string>

#include "asr_robot_model/frustum.hpp"

namespace asr_nbv {

/// Weights of the rating's terms (docs/next_best_view.md).
struct RatingWeights {
  double utility = 60.0;
  double base = 135.0;
  double rotation = 10.0;
  double pan_tilt = 1.0;
  double recognition = 10.0;

  double sum() const { return utility + base + rotation + pan_tilt + recognition; }
};

/// Everything the planner is configured with; angles in radians, distances in metres.
struct NbvParameters {
  asr_robot_model::Frustum frustum = asr_robot_model::Frustum::defaults();
  RatingWeights weights;
  double rating_angle = 45.0 * M_PI / 180.0;
  double update_angle = 45.0 * M_PI / 180.0;
  double base_distance_sigma = 2.0;
  double lattice_radius = 0.15;
  double orientation_step = 8.0 * M_PI / 180.0;
  int max_steps = 20;
  double rating_epsilon = 0.01;
  double min_utility_for_moving = 0.1;
  double occlusion_resolution = 0.03;
};

/// Reads config/next_best_view.yaml (or a file of that format; absent fields keep their
/// defaults). Throws asr_common::InputError naming the file and the field if a value is
/// malformed or out of range.
NbvParameters loadNbvParameters(const std::string& path);

/// Throws asr_common::InputError naming the field if a value is out of range.
void checkNbvParameters(const NbvParameters& parameters);

/// The shipped parameters (asr_nbv/config/next_best_view.yaml).
std::string defaultNbvParameters();

}  // namespace asr_nbv
