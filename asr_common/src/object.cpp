#include "asr_common/object.hpp"

namespace asr_common {

std::string ObjectKey::toString() const {
  return id.empty() ? type : type + ":" + id;
}

}  // namespace asr_common
