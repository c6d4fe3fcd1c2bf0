#include "asr_ism/demonstration.hpp"

#include <algorithm>
#include <stdexcept>

#include "asr_ism/common_types.hpp"

namespace asr_ism {

Demonstration::Demonstration(std::string scene, std::vector<ObjectKey> objects)
    : scene_(std::move(scene)), objects_(std::move(objects)) {}

int Demonstration::indexOf(const ObjectKey& key) const {
  const auto found = std::find(objects_.begin(), objects_.end(), key);
  return found == objects_.end() ? -1 : static_cast<int>(found - objects_.begin());
}

std::size_t Demonstration::addStep() {
  steps_.emplace_back(objects_.size());
  return steps_.size() - 1;
}

void Demonstration::setPose(std::size_t step, std::size_t object, const Pose& pose) {
  steps_.at(step).at(object) = pose;
}

const std::optional<Pose>& Demonstration::pose(std::size_t step, std::size_t object) const {
  return steps_.at(step).at(object);
}

Trajectory Demonstration::trajectory(std::size_t object) const {
  Trajectory result;
  result.reserve(steps_.size());
  for (const auto& step : steps_) {
    result.push_back(step.at(object));
  }
  return result;
}

Configuration Demonstration::configuration(std::size_t step) const {
  Configuration result;
  const auto& poses = steps_.at(step);
  for (std::size_t object = 0; object < objects_.size(); ++object) {
    if (poses[object]) {
      result.push_back({objects_[object], *poses[object]});
    }
  }
  return result;
}

void Demonstration::validate(const std::string& source) const {
  const std::string what = source + ", scene '" + scene_ + "'";
  if (objects_.empty()) {
    throw InputError(what + ": the demonstration contains no object");
  }
  if (steps_.empty()) {
    throw InputError(what + ": the demonstration contains no time step");
  }
  for (std::size_t object = 0; object < objects_.size(); ++object) {
    const bool observed = std::any_of(steps_.begin(), steps_.end(), [object](const auto& step) {
      return step[object].has_value();
    });
    if (!observed) {
      throw InputError(what + ": object " + objects_[object].toString() + " is never observed");
    }
  }
}

}  // namespace asr_ism
