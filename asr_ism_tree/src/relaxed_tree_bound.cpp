#include "relaxed_tree_bound.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "asr_ism/compliance.hpp"

namespace asr_ism_tree {
namespace {

using asr_common::Pose;
using Eigen::Quaterniond;
using Eigen::Vector3d;

struct OverBudget {};

// A set of poses (sub-ISM results or estimates) given by a centre and how far any of them may be
// from it; weight: the highest of theirs.
struct PoseCloud {
  Vector3d position;
  Quaterniond orientation;
  double position_slack = 0.0;
  double angle_slack = 0.0;
  double weight = 1.0;
};

// A set of votes of one member: besides the vote's pose, where its input is (`object`) and where
// the member stands in the reference's frame (`member_point`), each with its slack.
struct VoteCloud {
  PoseCloud vote;
  Vector3d object;
  double object_slack = 0.0;
  Vector3d member_point;
  double member_slack = 0.0;
};

using Cell = std::array<std::int64_t, 3>;

Cell cellOf(const Vector3d& p, double size) {
  return {static_cast<std::int64_t>(std::floor(p.x() / size)),
          static_cast<std::int64_t>(std::floor(p.y() / size)),
          static_cast<std::int64_t>(std::floor(p.z() / size))};
}

// How far rotating by at most `angle` moves a point at distance `length` from the axis' origin.
double chord(double angle, double length) {
  return 2.0 * std::sin(0.5 * std::min(angle, M_PI)) * length;
}

// Widens `group` so that it covers every pose of `pose` too.
void absorb(PoseCloud& group, const PoseCloud& pose) {
  group.position_slack =
      std::max(group.position_slack, (pose.position - group.position).norm() + pose.position_slack);
  group.angle_slack =
      std::max(group.angle_slack,
               asr_common::angleBetween(pose.orientation, group.orientation) + pose.angle_slack);
  group.weight = std::max(group.weight, pose.weight);
}

// The votes of every pose of `input` through one relative pose, as the ISM casts them.
VoteCloud castVote(const PoseCloud& input, const Pose& reference_in_member) {
  const Pose& t = reference_in_member;
  VoteCloud vote;
  vote.vote.position = input.position + input.orientation * t.position;
  vote.vote.orientation = input.orientation * t.orientation;
  vote.vote.position_slack = input.position_slack + chord(input.angle_slack, t.position.norm());
  vote.vote.angle_slack = input.angle_slack;
  vote.vote.weight = input.weight;
  vote.object = input.position;
  vote.object_slack = input.position_slack;
  vote.member_point = -(t.orientation.conjugate() * t.position);
  return vote;
}

class RelaxedEvaluation {
 public:
  RelaxedEvaluation(const IsmTree& tree, const RelaxedBoundParameters& parameters)
      : tree_(tree),
        parameters_(parameters),
        radius_(tree.parameters.supportRadius()),
        sin_half_squared_max_(
            asr_ism::sinHalfSquared(std::cos(0.5 * tree.parameters.max_angle_deviation))) {}

  // The relaxed results of `ism` from its members' clouds: one per candidate cloud, weighted by
  // the most any hypothesis in it could score.
  std::vector<PoseCloud> evaluate(int ism, const std::vector<std::vector<PoseCloud>>& inputs) {
    const auto& members = tree_.isms[ism].members;
    std::vector<std::vector<VoteCloud>> clouds(members.size());
    for (std::size_t m = 0; m < members.size(); ++m)
      clouds[m] = voteClouds(members[m], inputs[m]);
    double largest_slack = 0.0;
    for (const auto& of_member : clouds) {
      for (const VoteCloud& cloud : of_member)
        largest_slack = std::max(largest_slack, cloud.vote.position_slack);
    }
    // Clouds that can support one another lie within the radius plus both slacks.
    const double cell = radius_ + 2.0 * largest_slack;
    std::vector<std::map<Cell, std::vector<int>>> grid(members.size());
    for (std::size_t m = 0; m < members.size(); ++m) {
      for (std::size_t i = 0; i < clouds[m].size(); ++i)
        grid[m][cellOf(clouds[m][i].vote.position, cell)].push_back(static_cast<int>(i));
    }
    std::vector<PoseCloud> results;
    for (const auto& of_member : clouds) {
      for (const VoteCloud& candidate : of_member) {
        double objective = 0.0;
        for (std::size_t m = 0; m < members.size(); ++m) {
          double best = 0.0;
          forEachNear(grid[m], cellOf(candidate.vote.position, cell), [&](int v) {
            best = std::max(best, similarityBound(clouds[m][v], candidate));
            return false;
          });
          objective += best;
        }
        if (objective > 0.0) {
          PoseCloud result = candidate.vote;
          result.weight = objective;
          results.push_back(result);
        }
      }
    }
    return results;
  }

  std::size_t work() const { return work_; }

  // Poses within the radii of a group's first one (the heaviest first) join it.
  std::vector<PoseCloud> grouped(std::vector<PoseCloud> poses) {
    std::sort(poses.begin(), poses.end(),
              [](const PoseCloud& a, const PoseCloud& b) { return a.weight > b.weight; });
    std::vector<PoseCloud> groups;
    std::map<Cell, std::vector<int>> grid;
    const double cell = std::max(parameters_.position_radius, 1e-9);
    for (const PoseCloud& pose : poses) {
      spend(1);
      const int joined = nearbyGroup(
          grid, groups, cell, [&](const PoseCloud& group) { return withinRadii(pose, group); },
          pose.position);
      if (joined < 0) {
        grid[cellOf(pose.position, cell)].push_back(static_cast<int>(groups.size()));
        groups.push_back(pose);
        continue;
      }
      absorb(groups[joined], pose);
    }
    return groups;
  }

 private:
  bool withinRadii(const PoseCloud& pose, const PoseCloud& group) const {
    return (pose.position - group.position).norm() <= parameters_.position_radius &&
           asr_common::angleBetween(pose.orientation, group.orientation) <=
               parameters_.angle_radius;
  }

  // The votes of one member's inputs, grouped like results.
  std::vector<VoteCloud> voteClouds(const asr_ism::IsmMember& member,
                                    const std::vector<PoseCloud>& inputs) {
    std::vector<VoteCloud> clouds;
    std::map<Cell, std::vector<int>> grid;
    const double cell = std::max(parameters_.position_radius, 1e-9);
    for (const PoseCloud& input : inputs) {
      for (const auto& relative : member.relative_poses) {
        spend(1);
        const VoteCloud vote = castVote(input, relative.reference_in_member);
        const auto near = [&](const VoteCloud& group) {
          return withinRadii(vote.vote, group.vote) &&
                 (vote.object - group.object).norm() <= parameters_.position_radius &&
                 (vote.member_point - group.member_point).norm() <= parameters_.position_radius;
        };
        const int joined = nearbyGroup(grid, clouds, cell, near, vote.vote.position);
        if (joined < 0) {
          grid[cellOf(vote.vote.position, cell)].push_back(static_cast<int>(clouds.size()));
          clouds.push_back(vote);
          continue;
        }
        VoteCloud& group = clouds[joined];
        absorb(group.vote, vote.vote);
        group.object_slack =
            std::max(group.object_slack, (vote.object - group.object).norm() + vote.object_slack);
        group.member_slack =
            std::max(group.member_slack, (vote.member_point - group.member_point).norm());
      }
    }
    return clouds;
  }

  // The first group near `position` (in its cell or the 26 around it) that `near` accepts, -1.
  template <typename Group, typename Near>
  int nearbyGroup(const std::map<Cell, std::vector<int>>& grid, const std::vector<Group>& groups,
                  double cell, Near near, const Vector3d& position) {
    int found = -1;
    forEachNear(grid, cellOf(position, cell), [&](int g) {
      spend(1);
      found = near(groups[g]) ? g : -1;
      return found >= 0;
    });
    return found;
  }

  // Calls `visit` with every entry of `cell` and the 26 cells around it until it returns true.
  template <typename Visit>
  static void forEachNear(const std::map<Cell, std::vector<int>>& grid, const Cell& cell,
                          Visit visit) {
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto found = grid.find({cell[0] + dx, cell[1] + dy, cell[2] + dz});
          if (found == grid.end())
            continue;
          for (int entry : found->second) {
            if (visit(entry))
              return;
          }
        }
  }

  // The most any vote of `cloud` can score for any hypothesis in `candidate` (the support test
  // at the vote and at the object, and the orientation test, each shortened by the slacks).
  double similarityBound(const VoteCloud& cloud, const VoteCloud& candidate) {
    spend(1);
    const PoseCloud& v = cloud.vote;
    const PoseCloud& c = candidate.vote;
    const double vote_distance =
        std::max(0.0, (v.position - c.position).norm() - v.position_slack - c.position_slack);
    if (vote_distance >= radius_)
      return 0.0;
    const double angle = std::max(0.0, asr_common::angleBetween(v.orientation, c.orientation) -
                                           v.angle_slack - c.angle_slack);
    const double sin_half = std::sin(0.5 * std::min(angle, M_PI));
    if (sin_half * sin_half >= sin_half_squared_max_)
      return 0.0;
    // Where a hypothesis of the candidate cloud puts the member, against where its input is.
    const double member_reach = cloud.member_point.norm() + cloud.member_slack;
    const Vector3d member = c.position + c.orientation * cloud.member_point;
    const double object_distance = std::max(0.0, (member - cloud.object).norm() - c.position_slack -
                                                     chord(c.angle_slack, member_reach) -
                                                     cloud.member_slack - cloud.object_slack);
    const double distance = std::max(vote_distance, object_distance);
    if (distance >= radius_)
      return 0.0;
    const double position = 1.0 - distance * distance / (radius_ * radius_);
    const double orientation = 1.0 - sin_half * sin_half / sin_half_squared_max_;
    return v.weight * position * orientation;
  }

  void spend(std::size_t amount) {
    work_ += amount;
    if (work_ > parameters_.max_work)
      throw OverBudget{};
  }

 private:
  const IsmTree& tree_;
  const RelaxedBoundParameters parameters_;
  const double radius_;
  const double sin_half_squared_max_;
  std::size_t work_ = 0;
};

}  // namespace

std::optional<double> relaxedRootBound(const IsmTree& tree, const std::vector<int>& bottom_up,
                                       const std::vector<Pose>& poses,
                                       const std::vector<std::vector<int>>& estimates_of_object,
                                       const RelaxedBoundParameters& parameters,
                                       std::size_t* work) {
  RelaxedEvaluation evaluation(tree, parameters);
  std::vector<std::vector<PoseCloud>> passed_up(tree.isms.size());
  std::optional<double> bound;
  try {
    for (int ism : bottom_up) {
      const auto& members = tree.isms[ism].members;
      std::vector<std::vector<PoseCloud>> inputs(members.size());
      for (std::size_t m = 0; m < members.size(); ++m) {
        if (members[m].isPlaceholder()) {
          inputs[m] = passed_up[members[m].child_ism];
          continue;
        }
        for (int estimate : estimates_of_object[tree.topology.indexOf(members[m].object)])
          inputs[m].push_back({poses[estimate].position, poses[estimate].orientation});
      }
      std::vector<PoseCloud> results = evaluation.evaluate(ism, inputs);
      if (ism == 0) {
        double best = 0.0;
        for (const PoseCloud& result : results)
          best = std::max(best, result.weight);
        bound = best;
      } else {
        passed_up[ism] = evaluation.grouped(std::move(results));
      }
    }
  } catch (const OverBudget&) {
    bound.reset();
  }
  if (work != nullptr)
    *work = evaluation.work();
  return bound;
}

}  // namespace asr_ism_tree
