#include "asr_ism/input_limits.hpp"

#include <cmath>
#include <sstream>

#include "asr_ism/common_types.hpp"
#include "asr_ism/voting_space.hpp"

namespace asr_ism {

void checkRecognitionParameters(const IsmRecognitionParameters& parameters,
                                const std::string& what) {
  if (!(parameters.bin_size >= kMinBinSize && parameters.bin_size <= kMaxBinSize)) {
    std::ostringstream message;
    message << what << ": bin_size " << parameters.bin_size << " m is outside [" << kMinBinSize
            << ", " << kMaxBinSize << "] m";
    throw InputError(message.str());
  }
  if (!(parameters.max_angle_deviation > 0.0 && parameters.max_angle_deviation <= M_PI)) {
    std::ostringstream message;
    message << what << ": max_angle_deviation " << parameters.max_angle_deviation
            << " rad is outside (0, pi]";
    throw InputError(message.str());
  }
}

void checkVotingExtent(double bin_size, int height, double longest_relation,
                       const std::string& what) {
  // Leaf votes land within one relation of an estimate; every level up adds one more relation.
  // Estimates lie within the cube of kMaxCoordinate, so two votes of one ISM lie at most this far
  // apart, along any axis of the frame the recogniser bins them in (ism_recognizer.hpp).
  const double spread = 2.0 * (std::sqrt(3.0) * kMaxCoordinate + height * longest_relation);
  if (!(spread <= VotingSpace::maxSpread(bin_size))) {
    std::ostringstream message;
    message << what << ": votes of " << height << " levels with relations up to "
            << longest_relation << " m can spread over " << spread << " m, beyond the "
            << VotingSpace::maxSpread(bin_size) << " m bins of " << bin_size << " m can hold";
    throw InputError(message.str());
  }
}

}  // namespace asr_ism
