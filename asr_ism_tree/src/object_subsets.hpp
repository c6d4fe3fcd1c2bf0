#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "asr_ism_tree/ism_tree.hpp"

namespace asr_ism_tree {

/// A set of a scene's objects, one bit per object of the tree (at most 64).
using ObjectSet = std::uint64_t;

/// Where a recognition's search gave up, its best instance may fall short of the exhaustive
/// search's, and then possibly of the best instance with some object left out: seeing an object
/// badly could score lower than not seeing it. Recognising with seen objects left out as well
/// and keeping the best closes that: the answer is the best over every subset of the seen
/// objects, so it is at least the answer with any object removed, whatever the budgets.
///
/// Most subsets need no recognition: one whose bound cannot beat the best found is skipped,
/// and so is one within a subset whose search completed (the exhaustive best cannot fall when
/// objects are added). The rest are visited by falling bound, so the search stops at the first
/// subset that cannot beat the best.
class ObjectSubsetSearch {
 public:
  /// An upper bound of the exhaustive search's best root objective over a subset's estimates.
  using Bound = std::function<double(ObjectSet)>;

  /// `seen`: the objects estimates may stand for; `best`: the objective the recognition over
  /// `seen` reached, `completed`: whether its search completed.
  ObjectSubsetSearch(Bound bound, ObjectSet seen, double best, bool completed);

  /// The next subset worth recognising, or none. After each, report() what it reached.
  std::optional<ObjectSet> next();
  void report(ObjectSet subset, double best, bool completed);

  double best() const { return best_; }

 private:
  double bar() const;
  bool covered(ObjectSet subset) const;
  void pushSubsetsOf(ObjectSet subset);

  const Bound bound_;
  double best_;
  // By falling bound (at 1e-9, so that rounding, which differs with where the world frame
  // lies, cannot reorder them), then by set; with the bound itself.
  std::set<std::tuple<std::int64_t, ObjectSet, double>, std::greater<>> pending_;
  std::set<ObjectSet> queued_;
  std::vector<ObjectSet> completed_;
};

/// The bound of a tree's root objective over the estimates of a subset of its objects: each
/// seen leaf adds at most 1, and no ISM exceeds its maximum over every estimate (its best over
/// a subset cannot be higher), where that is known.
class SubsetBound {
 public:
  /// `maximum`: per ISM, its best over every estimate if that is its maximum, else infinity.
  SubsetBound(const IsmTree& tree, std::vector<double> maximum);
  double operator()(ObjectSet subset) const { return boundOf(0, subset); }

 private:
  double boundOf(int ism, ObjectSet subset) const;

  const IsmTree& tree_;
  const std::vector<double> maximum_;
};

}  // namespace asr_ism_tree
