#include "exact_best_search.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "asr_ism/coincident_poses.hpp"
#include "asr_ism/grid_cell.hpp"

namespace asr_ism_tree {
namespace {

// Sums of similarities are compared with this margin, so rounding never leaves out a result the
// exhaustive search would use.
constexpr double kMargin = 1e-9;
constexpr double kNothing = std::numeric_limits<double>::infinity();

}  // namespace

ExactBestSearch::ExactBestSearch(const IsmTree& tree, std::vector<bool> object_seen,
                                 Evaluate evaluate, BestObjective best, Start start,
                                 double known_best)
    : tree_(tree),
      object_seen_(std::move(object_seen)),
      evaluate_(std::move(evaluate)),
      best_(std::move(best)),
      start_(start),
      known_best_(known_best),
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
  const double bound = boundOf(ism);
  std::vector<double> member_from(tree_.isms[ism].members.size());
  for (std::size_t m = 0; m < member_from.size(); ++m) {
    const double others = bound - memberBound(ism, static_cast<int>(m));
    member_from[m] = searched_from_[ism] - others - kMargin;
  }
  evaluate_(ism, searched_from_[ism], member_from);
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
  const auto root_bar = [&] { return std::max(best_(0), known_best_); };
  if (root_bar() >= boundOf(0) - kMargin)
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
  if (root_bar() >= boundOf(0) - kMargin)
    return false;
  require(0, root_bar());
  // Parents of ISMs evaluated anew must follow their children's new results.
  for (int ism : bottom_up) {
    if (stale(ism))
      reevaluate(ism, searched_from_[ism]);
  }
  return true;
}

}  // namespace asr_ism_tree

namespace asr_ism_tree {
namespace {

using asr_common::Pose;

struct OutOfSteps {};

// The work of closing the pose gap, counted against its budget: each pose composed and each
// vote compared costs one step.
class Steps {
 public:
  explicit Steps(std::size_t& left) : left_(left) {}
  void spend(std::size_t count) {
    if (count > left_)
      throw OutOfSteps{};
    left_ -= count;
  }
  Pose compose(const Pose& a, const Pose& b) {
    spend(1);
    return asr_common::compose(a, b);
  }

 private:
  std::size_t& left_;
};

using Cell = std::array<std::int64_t, 3>;
struct CellHash {
  std::size_t operator()(const Cell& c) const {
    return static_cast<std::size_t>(c[0] * 73856093 ^ c[1] * 19349663 ^ c[2] * 83492791);
  }
};

// The votes of the inputs that can be part of a result reaching `from`, by cell of the support
// radius: what a hypothesis there can reach at most.
class EligibleVotes {
 public:
  EligibleVotes(const asr_ism::Ism& ism, const std::vector<asr_ism::IsmInput>& inputs,
                const std::vector<double>& member_from,
                const asr_ism::IsmRecognitionParameters& parameters, Steps& steps)
      : steps_(steps),
        radius_(parameters.supportRadius()),
        cos_half_max_angle_(std::cos(0.5 * parameters.max_angle_deviation)),
        best_(ism.members.size(), 0.0) {
    if (!inputs.empty()) {
      origin_ = inputs.front().pose.position;
      into_frame_ = inputs.front().pose.orientation.conjugate();
    }
    for (const asr_ism::IsmInput& input : inputs) {
      if (input.weight < member_from[input.member])
        continue;
      for (const auto& relative : ism.members[input.member].relative_poses) {
        const Pose vote = steps_.compose(input.pose, relative.reference_in_member);
        const Cell cell = cellOf(vote.position);
        if (cells_.count(cell) == 0) {
          steps_.spend(27);
          forEachNeighbour(cell, [&](const Cell& near) { near_.insert(near); });
        }
        cells_[cell].push_back(static_cast<int>(votes_.size()));
        votes_.push_back({vote, input.member, input.weight});
      }
    }
  }

  // The most any hypothesis can reach: per member, the highest weight of its votes.
  double mostReachable() const {
    std::vector<double> best(best_.size(), 0.0);
    for (const Vote& vote : votes_)
      best[vote.member] = std::max(best[vote.member], vote.weight);
    double sum = 0.0;
    for (double weight : best)
      sum += weight;
    return sum;
  }

  // The most a hypothesis at `pose` can reach: per member, the highest weight among the votes
  // within the support radius and the maximum angle deviation (with a margin for rounding).
  double reachableAt(const Pose& pose) {
    const Cell own = cellOf(pose.position);
    if (near_.count(own) == 0)
      return 0.0;  // no vote in the 27 cells around
    std::fill(best_.begin(), best_.end(), 0.0);
    steps_.spend(27);
    forEachNeighbour(own, [&](const Cell& cell) {
      const auto found = cells_.find(cell);
      if (found == cells_.end())
        return;
      steps_.spend(found->second.size());
      for (int v : found->second) {
        const Vote& vote = votes_[v];
        if ((vote.pose.position - pose.position).norm() > radius_ * (1.0 + 1e-9) ||
            std::abs(vote.pose.orientation.dot(pose.orientation)) <
                cos_half_max_angle_ * (1.0 - 1e-12))
          continue;
        best_[vote.member] = std::max(best_[vote.member], vote.weight);
      }
    });
    double sum = 0.0;
    for (double weight : best_)
      sum += weight;
    return sum;
  }

 private:
  struct Vote {
    Pose pose;
    int member;
    double weight;
  };

  template <typename Visit>
  static void forEachNeighbour(const Cell& cell, Visit visit) {
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dz = -1; dz <= 1; ++dz)
          visit(Cell{cell[0] + dx, cell[1] + dy, cell[2] + dz});
      }
    }
  }

  // Cells in the frame of the first input (the inputs come in an order the world frame does not
  // change), so that the steps spent do not depend on where the world frame lies; that input at
  // the centre of its cell, as votes often coincide with it (child results at their reference
  // object's estimate) and rounding would put them on either side of a border.
  Cell cellOf(const Eigen::Vector3d& world) const {
    const Eigen::Vector3d p =
        into_frame_ * (world - origin_) + Eigen::Vector3d::Constant(0.5 * radius_);
    return {asr_ism::gridCell(p.x(), radius_), asr_ism::gridCell(p.y(), radius_),
            asr_ism::gridCell(p.z(), radius_)};
  }

  Steps& steps_;
  const double radius_;
  const double cos_half_max_angle_;
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  Eigen::Quaterniond into_frame_ = Eigen::Quaterniond::Identity();
  std::vector<Vote> votes_;
  std::unordered_map<Cell, std::vector<int>, CellHash> cells_;
  std::unordered_set<Cell, CellHash> near_;  // the cells within one of a vote's
  std::vector<double> best_;
};

// Every result pose of ISM `ism` in the exhaustive search, with the estimate its chain starts
// at: every vote of its inputs, the child results' poses found recursively.
class ChainPoses {
 public:
  using Visit = std::function<void(const Pose& pose, int estimate)>;

  ChainPoses(const IsmTree& tree, const std::vector<Pose>& poses,
             const std::vector<std::vector<int>>& estimates_of_object, Steps& steps)
      : tree_(tree), poses_(poses), estimates_of_object_(estimates_of_object), steps_(steps) {}

  void forEach(int ism, const Visit& visit) {
    for (const auto& member : tree_.isms[ism].members) {
      const auto voteFrom = [&](const Pose& input, int estimate) {
        for (const auto& relative : member.relative_poses)
          visit(steps_.compose(input, relative.reference_in_member), estimate);
      };
      if (member.isPlaceholder()) {
        forEach(member.child_ism, voteFrom);
        continue;
      }
      for (int estimate : estimates_of_object_[tree_.topology.indexOf(member.object)])
        voteFrom(poses_[estimate], estimate);
    }
  }

 private:
  const IsmTree& tree_;
  const std::vector<Pose>& poses_;
  const std::vector<std::vector<int>>& estimates_of_object_;
  Steps& steps_;
};

}  // namespace

bool poseGapCandidates(const IsmTree& tree, int ism, double from,
                       const std::vector<asr_ism::IsmInput>& inputs,
                       const std::vector<double>& member_from, const std::vector<Pose>& poses,
                       const std::vector<std::vector<int>>& estimates_of_object,
                       std::size_t& steps_left, std::vector<PoseOnlyInput>& candidates) {
  candidates.clear();
  if (!std::isfinite(from))
    return true;
  const asr_ism::Ism& model = tree.isms[ism];
  if (std::none_of(model.members.begin(), model.members.end(),
                   [](const auto& member) { return member.isPlaceholder(); }))
    return true;
  Steps steps(steps_left);
  try {
    EligibleVotes eligible(model, inputs, member_from, tree.parameters, steps);
    if (eligible.mostReachable() < from - kMargin)
      return true;  // no hypothesis anywhere reaches `from`
    // Poses a member's inputs already have, and those found.
    // A pose counts as known within rounding (asr_ism/coincident_poses.hpp), so that the same
    // pose composed along another route or in another frame is not added twice.
    std::vector<asr_ism::CoincidentPoses> known(model.members.size());
    for (const asr_ism::IsmInput& input : inputs)
      known[input.member].insert(input.pose);
    ChainPoses chains(tree, poses, estimates_of_object, steps);
    for (std::size_t m = 0; m < model.members.size(); ++m) {
      const auto& member = model.members[m];
      if (!member.isPlaceholder())
        continue;
      chains.forEach(member.child_ism, [&](const Pose& pose, int estimate) {
        if (known[m].contains(pose))
          return;
        for (const auto& relative : member.relative_poses) {
          const Pose vote = steps.compose(pose, relative.reference_in_member);
          if (eligible.reachableAt(vote) >= from - kMargin) {
            known[m].insert(pose);
            candidates.push_back({static_cast<int>(m), pose, estimate});
            return;
          }
        }
      });
    }
  } catch (const OutOfSteps&) {
    candidates.clear();
    return false;
  }
  return true;
}

}  // namespace asr_ism_tree
