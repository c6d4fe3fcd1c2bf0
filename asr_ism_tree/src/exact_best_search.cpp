#include "exact_best_search.hpp"

#include <algorithm>
#include <limits>
#include <utility>

namespace asr_ism_tree {
namespace {

// Sums of similarities are compared with this margin, so rounding never leaves out a result the
// exhaustive search would use.
constexpr double kMargin = 1e-9;
constexpr double kNothing = std::numeric_limits<double>::infinity();

}  // namespace

ExactBestSearch::ExactBestSearch(const IsmTree& tree, std::vector<bool> object_seen,
                                 Evaluate evaluate, BestObjective best, Start start)
    : tree_(tree),
      object_seen_(std::move(object_seen)),
      evaluate_(std::move(evaluate)),
      best_(std::move(best)),
      start_(start),
      maximum_(tree.isms.size(), kNothing),
      searched_from_(tree.isms.size(), kNothing),
      stamp_(tree.isms.size(), 0) {}

double ExactBestSearch::memberBound(int ism, int member) const {
  const auto& m = tree_.isms[ism].members[member];
  if (m.isPlaceholder())
    return maximum_[m.child_ism];
  return object_seen_[tree_.topology.indexOf(m.object)] ? 1.0 : 0.0;
}

double ExactBestSearch::boundOf(int ism) const {
  double bound = 0.0;
  for (std::size_t m = 0; m < tree_.isms[ism].members.size(); ++m)
    bound += memberBound(ism, static_cast<int>(m));
  return bound;
}

bool ExactBestSearch::hasSubIsm(int ism) const {
  const auto& members = tree_.isms[ism].members;
  return std::any_of(members.begin(), members.end(),
                     [](const auto& member) { return member.isPlaceholder(); });
}

bool ExactBestSearch::stale(int ism) const {
  for (const auto& member : tree_.isms[ism].members) {
    if (member.isPlaceholder() && stamp_[member.child_ism] > stamp_[ism])
      return true;
  }
  return false;
}

void ExactBestSearch::reevaluate(int ism, double from) {
  searched_from_[ism] = std::min(searched_from_[ism], from);
  evaluate_(ism, searched_from_[ism]);
  stamp_[ism] = ++clock_;
}

void ExactBestSearch::require(int ism, double from) {
  const double bound = boundOf(ism);
  const auto& members = tree_.isms[ism].members;
  for (std::size_t m = 0; m < members.size(); ++m) {
    if (members[m].isPlaceholder()) {
      const double others = bound - memberBound(ism, static_cast<int>(m));
      require(members[m].child_ism, from - others - kMargin);
    }
  }
  if (from < searched_from_[ism] || stale(ism))
    reevaluate(ism, from);
}

bool ExactBestSearch::run(const std::vector<int>& bottom_up) {
  // With every sub-ISM worth its number of seen leaves, a first best that reaches the bound is
  // exact, and nothing need be searched.
  for (int ism : bottom_up)
    maximum_[ism] = boundOf(ism);
  if (best_(0) >= boundOf(0) - kMargin)
    return false;
  for (int ism : bottom_up) {
    if (ism == 0)
      continue;
    // A sub-ISM over objects only searched all its hypotheses (unless its results are lower
    // bounds); one whose best reaches the bound cannot do better. Otherwise its maximum is that
    // of its exact search, which the lower bound its best is makes exact.
    const bool searched_all = !hasSubIsm(ism) && start_ == Start::kFirstEvaluation;
    if (!searched_all && best_(ism) < boundOf(ism) - kMargin)
      require(ism, best_(ism));
    maximum_[ism] = best_(ism);
  }
  if (best_(0) >= boundOf(0) - kMargin)
    return false;
  require(0, best_(0));
  // Parents of ISMs evaluated anew must follow their children's new results.
  for (int ism : bottom_up) {
    if (stale(ism))
      reevaluate(ism, searched_from_[ism]);
  }
  return true;
}

}  // namespace asr_ism_tree
