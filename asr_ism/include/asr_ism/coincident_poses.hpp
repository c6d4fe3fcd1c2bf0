#pragma once

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "asr_common/pose.hpp"

namespace asr_ism {

/// A set of poses in which a pose counts as present when one lies within rounding of it (1e-9 m,
/// orientations within 1e-12 of their dot product): the same pose composed along another route,
/// or in another frame, differs in its last bits only, by more than any fixed quantisation
/// tolerates where coordinates are large (3e-14 m at 300 m), so keys of rounded coordinates
/// would call it new in one frame and known in another.
class CoincidentPoses {
 public:
  bool contains(const asr_common::Pose& pose) const;
  void insert(const asr_common::Pose& pose);
  /// Inserts `pose` unless it is present; true if it was new.
  bool insertIfNew(const asr_common::Pose& pose);

 private:
  using Cell = std::array<std::int64_t, 3>;
  struct CellHash {
    std::size_t operator()(const Cell& c) const;
  };
  std::unordered_map<Cell, std::vector<asr_common::Pose>, CellHash> cells_;
};

}  // namespace asr_ism
