#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "asr_common/pose.hpp"
#include "asr_ism/ism_recognizer.hpp"
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
///
/// The bound covers what a result *contributes*, not where hypotheses are: a parent's hypotheses
/// sit at the votes of its inputs, so a child result below its bound, never passed up, could
/// still be the *pose* of a better parent hypothesis. The evaluation closes that gap with
/// poseGapCandidates() (below): each ISM is also given, as pose-only inputs, the child results
/// (of the exhaustive search) at whose votes a hypothesis reaching `from` could lie.
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
  /// `member_from`, per member: what an input of it must reach to be part of such a result.
  using Evaluate =
      std::function<void(int ism, double from, const std::vector<double>& member_from)>;
  /// The best objective an ISM's current results reach, 0 if none.
  using BestObjective = std::function<double(int ism)>;

  /// `object_seen`: per object of the tree, whether any estimate may stand for it.
  /// `known_best`: an objective some instance is known to reach (one found over other
  /// estimates): the root seeks only results beyond it, as it does beyond its own current best.
  ExactBestSearch(const IsmTree& tree, std::vector<bool> object_seen, Evaluate evaluate,
                  BestObjective best, Start start = Start::kFirstEvaluation,
                  double known_best = 0.0);

  /// `bottom_up`: every ISM, children before parents. True if the root was evaluated anew: its
  /// best result, if it has one, is then that of the exhaustive search (none: nothing beats
  /// `known_best`), and every sub-ISM's results are those its parent's links refer to. False:
  /// the first evaluation's best (or `known_best`) already was at least the exhaustive search's
  /// (with Start::kLowerBounds: the starting results' best reaches the bound, so it is the
  /// maximum).
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
  const double known_best_;
  std::vector<double> maximum_;        // exact maximum objective per sub-ISM, once known
  std::vector<double> searched_from_;  // every result reaching it is passed up
  std::vector<unsigned> stamp_;        // when each ISM was last evaluated
  unsigned clock_ = 0;
};

/// A child result of the exhaustive search given to its parent as a pose-only input: a
/// hypothesis of the parent may sit at one of its votes.
struct PoseOnlyInput {
  int member = -1;  // the parent's placeholder member
  asr_common::Pose pose;
  int estimate = -1;  // the estimate its chain of votes starts at
};

/// The pose gap, closed. A hypothesis of ISM `ism` reaching `from` matches only inputs reaching
/// their `member_from` (what else the other members can add does not suffice otherwise), and
/// each matched vote lies within the support radius and the maximum angle deviation of the
/// hypothesis' pose. That pose is a vote of some input: an estimate (always an input), a child
/// result passed up, or a child result of the exhaustive search not passed up; the latter's
/// votes must then lie that close to votes of inputs reaching their `member_from` whose weights
/// add up to `from`. The exhaustive search's child results are at every vote of the child's
/// inputs (each vote is a hypothesis there, matching at least itself), so its result poses are
/// the chains estimate * relative pose * relative pose ... up the subtree, composed as the
/// recogniser composes votes. Each such pose that `inputs` lacks and one of whose votes passes
/// that test is returned. Its objective there is at least its chain's estimate's (1): the
/// caller gives it a lower weight, so it can be no better instance's match, only its pose.
/// Holds for every ISM the search evaluates, whatever its inputs were found from, so for
/// ExactBestSearch::Start::kFirstEvaluation and kLowerBounds alike. Chains multiply by the number
/// of relative poses per level: false where more than `steps_left` compositions would be needed
/// (the gap then stays open), `steps_left` reduced by those made.
bool poseGapCandidates(const IsmTree& tree, int ism, double from,
                       const std::vector<asr_ism::IsmInput>& inputs,
                       const std::vector<double>& member_from,
                       const std::vector<asr_common::Pose>& poses,
                       const std::vector<std::vector<int>>& estimates_of_object,
                       std::size_t& steps_left, std::vector<PoseOnlyInput>& candidates);

}  // namespace asr_ism_tree
