#pragma once

#include <functional>
#include <vector>

#include "asr_ism_tree/ism_tree.hpp"

namespace asr_ism_tree {

/// Makes the root's best result that of the exhaustive search (every sub-ISM passing every result
/// up), after a first evaluation that passed up a few results per sub-ISM.
///
/// An instance through result h of sub-ISM s scores at most h's objective plus what the other
/// members of s's ancestors can add: a seen object 1, a sibling sub-ISM its own maximum. So with
/// L a result already found, only results of s reaching L minus that can be part of a better
/// instance; every sub-ISM asked for all of them (recursively, down its subtree) makes the best
/// instance exact. Each sub-ISM's maximum is made exact the same way first, bottom-up, so that the
/// bound counts what a sibling can really add, not its number of leaves: where an object is seen
/// badly, the siblings that hold it are worth what they really reach, and the search asks for
/// little beyond what the first evaluation passed up. Where the first evaluation already reached
/// the bound nothing is asked at all.
class ExactBestSearch {
 public:
  /// What the ISMs' current results are when the search starts.
  enum class Start {
    /// A first evaluation over the same estimates: a sub-ISM over objects only has tried every
    /// hypothesis, so its best is its maximum.
    kFirstEvaluation,
    /// Results over a subset of the estimates (the representatives of repeated detections): each
    /// ISM's best is only a lower bound of its maximum over these estimates, as the exhaustive
    /// search's best cannot fall when estimates are added, so every ISM is evaluated anew.
    kLowerBounds,
  };
  /// Re-evaluates one ISM from its children's current results. `from`: a sub-ISM passes up every
  /// result reaching it besides its few best; the root returns only the results reaching it.
  using Evaluate = std::function<void(int ism, double from)>;
  /// The best objective an ISM's current results reach, 0 if none.
  using BestObjective = std::function<double(int ism)>;

  /// `object_seen`: per object of the tree, whether any estimate may stand for it.
  ExactBestSearch(const IsmTree& tree, std::vector<bool> object_seen, Evaluate evaluate,
                  BestObjective best, Start start = Start::kFirstEvaluation);

  /// `bottom_up`: every ISM, children before parents. True if the root was evaluated anew: its
  /// best result is then that of the exhaustive search, and every sub-ISM's results are those its
  /// parent's links refer to. False: the first evaluation's best already was (with
  /// Start::kLowerBounds: the starting results' best reaches the bound, so it is the maximum).
  bool run(const std::vector<int>& bottom_up);

 private:
  double memberBound(int ism, int member) const;
  double boundOf(int ism) const;
  bool hasSubIsm(int ism) const;
  bool stale(int ism) const;
  // Makes every result of `ism` reaching `from` exact and passed up; re-evaluates its subtree as
  // far as needed.
  void require(int ism, double from);
  void reevaluate(int ism, double from);

  const IsmTree& tree_;
  const std::vector<bool> object_seen_;
  const Evaluate evaluate_;
  const BestObjective best_;
  const Start start_;
  std::vector<double> maximum_;        // exact maximum objective per sub-ISM, once known
  std::vector<double> searched_from_;  // every result reaching it is passed up
  std::vector<unsigned> stamp_;        // when each ISM was last evaluated
  unsigned clock_ = 0;
};

}  // namespace asr_ism_tree
