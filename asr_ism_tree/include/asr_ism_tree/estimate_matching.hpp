#pragma once

#include <cstddef>
#include <vector>

#include "asr_common/object.hpp"

namespace asr_ism_tree {

using asr_common::ObjectKey;

/// Which of a scene's objects each estimate of a configuration may stand for. An estimate whose
/// type and id name a scene object stands for that object. One without an id, or with an id the
/// scene does not know for its type, is matched by type: it may stand for any object of its type
/// (most detectors report types only). Estimates of types the scene does not have are clutter.
struct EstimateMatching {
  /// Per estimate: the objects it may stand for (indices into the scene's objects); empty for
  /// clutter, one entry when the key or a unique type decides.
  std::vector<std::vector<int>> candidates;
  /// True if some estimate that is not clutter was matched by type.
  bool ids_ignored = false;

  /// How many ways there are to give every estimate one of its candidates.
  std::size_t labellingCount() const;
  /// Labelling `index` (0 <= index < labellingCount()): per object, the estimates that stand for
  /// it, in the order of `estimate_order` (every estimate, once), which also orders the digits
  /// of `index`.
  std::vector<std::vector<int>> estimatesOfObjects(std::size_t index, std::size_t object_count,
                                                   const std::vector<int>& estimate_order) const;
};

EstimateMatching matchEstimates(const std::vector<ObjectKey>& scene_objects,
                                const asr_common::Configuration& configuration);

}  // namespace asr_ism_tree
