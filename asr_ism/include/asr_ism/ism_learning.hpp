#pragma once

#include <string>
#include <vector>

#include "asr_ism/demonstration.hpp"
#include "asr_ism/ism.hpp"

namespace asr_ism {

/// What a member of an ISM to be learned is, and the trajectory it was demonstrated with.
struct MemberTrajectory {
  ObjectKey object;
  int child_ism = -1;
  Trajectory trajectory;
};

/// Learns one ISM: for every member and every time step in which both the member and the
/// reference are observed, the pose of the reference in the member's frame. Equal relative poses
/// (within 1e-9 m and 1e-9 rad) are stored once with their step count, which changes no vote.
/// Throws InputError if trajectories differ in length, a member never co-occurs with the
/// reference, or is ever more than kMaxRelationLength from it (an outlier pose).
Ism learnIsm(const std::string& name, const ObjectKey& reference,
             const Trajectory& reference_trajectory, const std::vector<MemberTrajectory>& members);

}  // namespace asr_ism
