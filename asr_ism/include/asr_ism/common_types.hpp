// The suite's shared types (package asr_common) by the names asr_ism's code uses unqualified:
// an ISM is made of poses, object keys and estimates, and reports bad input as InputError.
#pragma once

#include "asr_common/input_error.hpp"
#include "asr_common/object.hpp"
#include "asr_common/pose.hpp"

namespace asr_ism {

using asr_common::angleBetween;
using asr_common::approximatelyEqual;
using asr_common::canonicalQuaternion;
using asr_common::compose;
using asr_common::Configuration;
using asr_common::InputError;
using asr_common::inverse;
using asr_common::ObjectEstimate;
using asr_common::ObjectKey;
using asr_common::Pose;
using asr_common::relativePose;
using asr_common::validatedPose;

}  // namespace asr_ism
