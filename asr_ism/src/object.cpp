#include "asr_ism/object.hpp"

namespace asr_ism {

std::string ObjectKey::toString() const {
  return id.empty() ? type : type + ":" + id;
}

}  // namespace asr_ism
