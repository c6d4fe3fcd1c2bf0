#include "asr_ism/ism.hpp"

namespace asr_ism {

std::size_t Ism::relativePoseCount() const {
  std::size_t count = 0;
  for (const auto& member : members) {
    count += member.relative_poses.size();
  }
  return count;
}

}  // namespace asr_ism
