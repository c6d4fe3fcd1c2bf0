#pragma once

#include <cstddef>

#include "asr_ism/demonstration.hpp"

namespace asr_ism_tree {

/// The object a star topology is centred on when the user names none: the object observed in
/// the most time steps (relations exist only where the reference is observed); among those, the
/// one with the smallest mean distance to the other objects observed with it (short relations
/// turn orientation noise of the reference into small position errors); then the lower index.
std::size_t chooseStarCenter(const asr_ism::Demonstration& demonstration);

}  // namespace asr_ism_tree
