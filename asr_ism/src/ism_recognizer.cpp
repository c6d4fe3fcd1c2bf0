#include "asr_ism/ism_recognizer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <unordered_map>

#include "asr_ism/compliance.hpp"
#include "asr_ism/input_error.hpp"
#include "asr_ism/voting_space.hpp"

namespace asr_ism {
namespace {

// Bounds are compared with this margin so that rounding can never prune a hypothesis that an
// exhaustive search would have kept.
constexpr double kBoundMargin = 1e-9;
constexpr double kNoThreshold = -std::numeric_limits<double>::infinity();

// Votes as parallel arrays in bin order, so that a bin's neighbourhood is a few contiguous ranges.
struct Votes {
  std::vector<double> px, py, pz, qw, qx, qy, qz, weight;
  std::vector<int> member, input, relative;

  void resize(std::size_t n) {
    for (auto* column : {&px, &py, &pz, &qw, &qx, &qy, &qz, &weight})
      column->resize(n);
    for (auto* column : {&member, &input, &relative})
      column->resize(n);
  }
};

struct Range {
  std::uint32_t begin;
  std::uint32_t end;
};

// A bin's best hypothesis.
struct BinResult {
  std::size_t bin = 0;
  int candidate = -1;
  double objective = 0.0;
  std::vector<int> votes;  // per member, the matched vote or -1
  std::vector<double> position_compliance;
  std::vector<double> orientation_compliance;
  std::vector<int> assignment;  // per member, the matched input or -1
};

// The neighbourhood of one bin, regrouped by member so a hypothesis can be abandoned as soon as
// the members left cannot lift it above the bar.
struct Neighbourhood {
  std::vector<int> members;          // members with votes here, fewest votes first
  std::vector<std::uint32_t> begin;  // per entry of `members`, range in `votes`
  std::vector<std::uint32_t> end;
  std::vector<double> max_weight;         // per entry of `members`
  std::vector<std::uint32_t> votes;       // vote indices grouped by member
  std::vector<std::uint32_t> candidates;  // the bin's own votes, fewest-vote members first
  double upper_bound = 0.0;
  std::vector<int> atoms;  // sorted estimates that inputs with votes here stand for
};

// The estimates each input stands for; an input without any stands for itself, as -(index + 1).
std::vector<std::vector<int>> atomsOfInputs(const std::vector<IsmInput>& inputs) {
  std::vector<std::vector<int>> atoms(inputs.size());
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    atoms[i] = inputs[i].estimates.empty() ? std::vector<int>{-static_cast<int>(i) - 1}
                                           : inputs[i].estimates;
    std::sort(atoms[i].begin(), atoms[i].end());
  }
  return atoms;
}

std::vector<int> unionOfAtoms(const std::vector<int>& input_indices,
                              const std::vector<std::vector<int>>& atoms_of_input) {
  std::vector<int> atoms;
  for (int input : input_indices) {
    if (input >= 0) {
      atoms.insert(atoms.end(), atoms_of_input[input].begin(), atoms_of_input[input].end());
    }
  }
  std::sort(atoms.begin(), atoms.end());
  atoms.erase(std::unique(atoms.begin(), atoms.end()), atoms.end());
  return atoms;
}

class Search {
 public:
  Search(const Ism& ism, const Votes& votes, const std::vector<std::vector<int>>& atoms_of_input,
         const IsmRecognitionParameters& parameters, IsmRecognitionStats& stats)
      : votes_(votes),
        atoms_of_input_(atoms_of_input),
        member_count_(ism.members.size()),
        stats_(stats),
        bin_size_squared_(parameters.bin_size * parameters.bin_size),
        cos_half_max_angle_(std::cos(0.5 * parameters.max_angle_deviation)),
        sin_half_squared_max_angle_(sinHalfSquared(cos_half_max_angle_)) {
    vote_.resize(member_count_);
    per_member_.resize(member_count_);
    slot_.resize(member_count_);
    rank_.resize(member_count_);
    input_stamp_.assign(atoms_of_input.size(), 0);
    position_.resize(member_count_);
    orientation_.resize(member_count_);
  }

  void gather(const VotingSpace& space, std::size_t bin, Neighbourhood& n) {
    std::array<int, 27> neighbours;
    const int count = space.neighbourBins(bin, neighbours);
    std::fill(per_member_.begin(), per_member_.end(), 0);
    std::size_t total = 0;
    for (int i = 0; i < count; ++i) {
      const auto& b = space.bins()[neighbours[i]];
      for (std::uint32_t v = b.begin; v < b.end; ++v)
        ++per_member_[votes_.member[v]];
      total += b.end - b.begin;
    }
    n.members.clear();
    for (std::size_t m = 0; m < member_count_; ++m) {
      if (per_member_[m] > 0)
        n.members.push_back(static_cast<int>(m));
    }
    std::stable_sort(n.members.begin(), n.members.end(),
                     [&](int a, int b) { return per_member_[a] < per_member_[b]; });
    std::fill(rank_.begin(), rank_.end(), -1);
    n.begin.resize(n.members.size());
    n.end.resize(n.members.size());
    n.max_weight.assign(n.members.size(), 0.0);
    std::uint32_t offset = 0;
    for (std::size_t i = 0; i < n.members.size(); ++i) {
      rank_[n.members[i]] = static_cast<int>(i);
      n.begin[i] = slot_[n.members[i]] = offset;
      offset += per_member_[n.members[i]];
      n.end[i] = offset;
    }
    n.votes.resize(total);
    inputs_here_.clear();
    ++stamp_;
    for (int i = 0; i < count; ++i) {
      const auto& b = space.bins()[neighbours[i]];
      for (std::uint32_t v = b.begin; v < b.end; ++v) {
        const int m = votes_.member[v];
        n.votes[slot_[m]++] = v;
        double& max_weight = n.max_weight[rank_[m]];
        max_weight = std::max(max_weight, votes_.weight[v]);
        const int input = votes_.input[v];
        if (input_stamp_[input] != stamp_) {
          input_stamp_[input] = stamp_;
          inputs_here_.push_back(input);
        }
      }
    }
    n.atoms = unionOfAtoms(inputs_here_, atoms_of_input_);
    // Sum in member order, as evaluate() does, so a perfect hypothesis meets the bound exactly.
    n.upper_bound = 0.0;
    for (double w : n.max_weight)
      n.upper_bound += w;
    const auto& own = space.bins()[bin];
    n.candidates.resize(own.end - own.begin);
    std::iota(n.candidates.begin(), n.candidates.end(), own.begin);
    std::stable_sort(n.candidates.begin(), n.candidates.end(),
                     [&](std::uint32_t a, std::uint32_t b) {
                       return rank_[votes_.member[a]] < rank_[votes_.member[b]];
                     });
  }

  // The best hypothesis of a bin that reaches `bar`; false if none does.
  bool searchBin(const Neighbourhood& n, double bar, BinResult& result) {
    result.candidate = -1;
    result.objective = 0.0;
    double best_in_bin = 0.0;
    for (std::uint32_t c : n.candidates) {
      ++stats_.candidates;
      const double threshold = std::max(bar, best_in_bin);
      double objective;
      if (!evaluate(c, n, threshold, objective) || objective <= best_in_bin)
        continue;
      best_in_bin = objective;
      result.candidate = static_cast<int>(c);
      result.objective = objective;
      result.votes.assign(vote_.begin(), vote_.end());
      result.position_compliance.assign(position_.begin(), position_.end());
      result.orientation_compliance.assign(orientation_.begin(), orientation_.end());
      if (objective >= n.upper_bound)
        break;  // nothing in this bin can do better
    }
    if (result.candidate < 0)
      return false;
    result.assignment.assign(member_count_, -1);
    for (std::size_t m = 0; m < member_count_; ++m) {
      if (result.votes[m] >= 0)
        result.assignment[m] = votes_.input[result.votes[m]];
    }
    return true;
  }

 private:
  // Scores hypothesis `c`; false once the members left cannot lift it to `threshold`.
  bool evaluate(std::uint32_t c, const Neighbourhood& n, double threshold, double& objective) {
    std::fill(vote_.begin(), vote_.end(), -1);
    const double cx = votes_.px[c], cy = votes_.py[c], cz = votes_.pz[c];
    const double cw = votes_.qw[c], cqx = votes_.qx[c], cqy = votes_.qy[c], cqz = votes_.qz[c];
    double achieved = 0.0;
    double still_possible = n.upper_bound;
    for (std::size_t i = 0; i < n.members.size(); ++i) {
      const int m = n.members[i];
      double best = 0.0;
      stats_.comparisons += n.end[i] - n.begin[i];
      for (std::uint32_t k = n.begin[i]; k < n.end[i]; ++k) {
        const std::uint32_t v = n.votes[k];
        const double dx = votes_.px[v] - cx;
        const double dy = votes_.py[v] - cy;
        const double dz = votes_.pz[v] - cz;
        const double distance_squared = dx * dx + dy * dy + dz * dz;
        if (distance_squared >= bin_size_squared_)
          continue;
        const double cos_half = std::abs(votes_.qw[v] * cw + votes_.qx[v] * cqx +
                                         votes_.qy[v] * cqy + votes_.qz[v] * cqz);
        if (cos_half <= cos_half_max_angle_)
          continue;
        const double position = positionCompliance(distance_squared, bin_size_squared_);
        const double orientation = orientationCompliance(cos_half, sin_half_squared_max_angle_);
        const double similarity = position * orientation * votes_.weight[v];
        if (similarity > best) {
          best = similarity;
          vote_[m] = static_cast<int>(v);
          position_[m] = position;
          orientation_[m] = orientation;
        }
      }
      achieved += best;
      still_possible -= n.max_weight[i];
      if (achieved + still_possible < threshold - kBoundMargin)
        return false;
    }
    objective = achieved;
    return true;
  }

  const Votes& votes_;
  const std::vector<std::vector<int>>& atoms_of_input_;
  const std::size_t member_count_;
  IsmRecognitionStats& stats_;
  const double bin_size_squared_;
  const double cos_half_max_angle_;
  const double sin_half_squared_max_angle_;
  std::vector<int> vote_;
  std::vector<std::uint32_t> per_member_;
  std::vector<std::uint32_t> slot_;
  std::vector<int> rank_;
  std::vector<std::uint32_t> input_stamp_;
  std::uint32_t stamp_ = 0;
  std::vector<int> inputs_here_;
  std::vector<double> position_;
  std::vector<double> orientation_;
};

struct AssignmentHash {
  std::size_t operator()(const std::vector<int>& assignment) const {
    std::size_t hash = 1469598103934665603ULL;
    for (int input : assignment)
      hash = (hash ^ static_cast<std::size_t>(input + 1)) * 1099511628211ULL;
    return hash;
  }
};

// What the results found so far rule out, for the two kinds of selection.
class Bar {
 public:
  Bar(const IsmResultSelection& selection, const std::vector<std::vector<int>>& atoms_of_input)
      : best_count_(selection.best_count), atoms_of_input_(atoms_of_input) {}

  // The objective a result of a bin with this neighbourhood must reach to be selected.
  double forBin(const Neighbourhood& n) const {
    if (best_count_ > 0) {
      return best_.size() < best_count_ ? kNoThreshold : best_.back().first;
    }
    // A result using only estimates of a better result would be dropped as its subset.
    double bar = kNoThreshold;
    for (const auto& [objective, atoms] : dominators_) {
      if (objective > bar &&
          std::includes(atoms.begin(), atoms.end(), n.atoms.begin(), n.atoms.end())) {
        bar = objective;
      }
    }
    return bar;
  }

  void add(const BinResult& result) {
    if (best_count_ > 0) {
      // Keep the best_count best distinct assignments seen so far; their worst is the bar.
      auto same = std::find_if(best_.begin(), best_.end(), [&](const auto& entry) {
        return entry.second == result.assignment;
      });
      if (same != best_.end()) {
        same->first = std::max(same->first, result.objective);
      } else {
        best_.emplace_back(result.objective, result.assignment);
      }
      std::stable_sort(best_.begin(), best_.end(),
                       [](const auto& a, const auto& b) { return a.first > b.first; });
      if (best_.size() > best_count_)
        best_.resize(best_count_);
      return;
    }
    std::vector<int> atoms = unionOfAtoms(result.assignment, atoms_of_input_);
    for (const auto& [objective, other] : dominators_) {
      if (objective >= result.objective &&
          std::includes(other.begin(), other.end(), atoms.begin(), atoms.end())) {
        return;  // the better result rules out everything this one would
      }
    }
    dominators_.emplace_back(result.objective, std::move(atoms));
  }

 private:
  const std::size_t best_count_;
  const std::vector<std::vector<int>>& atoms_of_input_;
  std::vector<std::pair<double, std::vector<int>>> best_;
  std::vector<std::pair<double, std::vector<int>>> dominators_;
};

}  // namespace

std::vector<IsmResult> recognizeIsm(const Ism& ism, const std::vector<IsmInput>& inputs,
                                    const IsmRecognitionParameters& parameters,
                                    const IsmResultSelection& selection,
                                    IsmRecognitionStats* stats) {
  if (!(parameters.bin_size > 0.0) || !(parameters.max_angle_deviation > 0.0)) {
    throw InputError("ISM '" + ism.name + "': bin size and maximum angle deviation must be > 0");
  }
  const std::size_t member_count = ism.members.size();

  // Cast the votes: every input combined with every relative pose of its member.
  std::size_t vote_count = 0;
  for (const IsmInput& input : inputs) {
    if (input.member < 0 || static_cast<std::size_t>(input.member) >= member_count) {
      throw InputError("ISM '" + ism.name + "': an input names member " +
                       std::to_string(input.member) + " of " + std::to_string(member_count));
    }
    if (!(input.weight > 0.0)) {
      throw InputError("ISM '" + ism.name + "': input weights must be > 0");
    }
    vote_count += ism.members[input.member].relative_poses.size();
  }
  Votes cast;
  cast.resize(vote_count);
  std::size_t v = 0;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const IsmInput& input = inputs[i];
    const auto& relative_poses = ism.members[input.member].relative_poses;
    for (std::size_t r = 0; r < relative_poses.size(); ++r, ++v) {
      const Pose& relative = relative_poses[r].reference_in_member;
      const Eigen::Vector3d position =
          input.pose.position + input.pose.orientation * relative.position;
      const Eigen::Quaterniond orientation = input.pose.orientation * relative.orientation;
      cast.px[v] = position.x();
      cast.py[v] = position.y();
      cast.pz[v] = position.z();
      cast.qw[v] = orientation.w();
      cast.qx[v] = orientation.x();
      cast.qy[v] = orientation.y();
      cast.qz[v] = orientation.z();
      cast.weight[v] = input.weight;
      cast.member[v] = input.member;
      cast.input[v] = static_cast<int>(i);
      cast.relative[v] = static_cast<int>(r);
    }
  }

  const VotingSpace space(parameters.bin_size, cast.px.data(), cast.py.data(), cast.pz.data(),
                          vote_count);
  Votes votes;
  votes.resize(vote_count);
  for (std::size_t sorted = 0; sorted < vote_count; ++sorted) {
    const std::uint32_t from = space.order()[sorted];
    votes.px[sorted] = cast.px[from];
    votes.py[sorted] = cast.py[from];
    votes.pz[sorted] = cast.pz[from];
    votes.qw[sorted] = cast.qw[from];
    votes.qx[sorted] = cast.qx[from];
    votes.qy[sorted] = cast.qy[from];
    votes.qz[sorted] = cast.qz[from];
    votes.weight[sorted] = cast.weight[from];
    votes.member[sorted] = cast.member[from];
    votes.input[sorted] = cast.input[from];
    votes.relative[sorted] = cast.relative[from];
  }

  IsmRecognitionStats local_stats;
  local_stats.votes = vote_count;
  local_stats.bins = space.bins().size();
  const std::vector<std::vector<int>> atoms_of_input = atomsOfInputs(inputs);
  Search search(ism, votes, atoms_of_input, parameters, local_stats);

  // Search bins with the highest upper bound first: their results raise the bar for the rest.
  const std::size_t bin_count = space.bins().size();
  std::vector<Neighbourhood> neighbourhoods(bin_count);
  for (std::size_t b = 0; b < bin_count; ++b)
    search.gather(space, b, neighbourhoods[b]);
  std::vector<std::size_t> bin_order(bin_count);
  std::iota(bin_order.begin(), bin_order.end(), 0);
  std::stable_sort(bin_order.begin(), bin_order.end(), [&](std::size_t a, std::size_t b) {
    return neighbourhoods[a].upper_bound > neighbourhoods[b].upper_bound;
  });

  Bar bar(selection, atoms_of_input);
  std::vector<BinResult> found;
  for (std::size_t b : bin_order) {
    const Neighbourhood& n = neighbourhoods[b];
    const double bin_bar = bar.forBin(n);
    if (n.upper_bound < bin_bar - kBoundMargin)
      continue;
    BinResult result;
    result.bin = b;
    if (!search.searchBin(n, bin_bar, result))
      continue;
    bar.add(result);
    found.push_back(std::move(result));
  }
  if (stats != nullptr) {
    stats->votes += local_stats.votes;
    stats->bins += local_stats.bins;
    stats->candidates += local_stats.candidates;
    stats->comparisons += local_stats.comparisons;
  }

  // Best first; equal objectives in bin order, so the result does not depend on search order.
  std::sort(found.begin(), found.end(), [](const BinResult& a, const BinResult& b) {
    if (a.objective != b.objective)
      return a.objective > b.objective;
    return a.bin < b.bin;
  });
  std::vector<IsmResult> results;
  std::unordered_map<std::vector<int>, bool, AssignmentHash> seen;
  std::vector<std::vector<int>> kept_atoms;
  for (BinResult& bin_result : found) {
    if (!seen.emplace(bin_result.assignment, true).second)
      continue;
    std::vector<int> atoms = unionOfAtoms(bin_result.assignment, atoms_of_input);
    if (selection.best_count > 0) {
      if (results.size() >= selection.best_count)
        break;
    } else {
      const bool dominated =
          std::any_of(kept_atoms.begin(), kept_atoms.end(), [&](const std::vector<int>& better) {
            return std::includes(better.begin(), better.end(), atoms.begin(), atoms.end());
          });
      if (dominated)
        continue;
      kept_atoms.push_back(atoms);
    }
    const int c = bin_result.candidate;
    IsmResult result;
    result.reference_pose =
        Pose(Eigen::Vector3d(votes.px[c], votes.py[c], votes.pz[c]),
             Eigen::Quaterniond(votes.qw[c], votes.qx[c], votes.qy[c], votes.qz[c]));
    result.objective = bin_result.objective;
    // Inputs that stand for themselves (negative atoms) sort first; report real estimates only.
    result.estimates.assign(std::lower_bound(atoms.begin(), atoms.end(), 0), atoms.end());
    result.matches.resize(member_count);
    for (std::size_t m = 0; m < member_count; ++m) {
      const int vote = bin_result.votes[m];
      if (vote < 0)
        continue;
      result.matches[m] = {votes.input[vote], votes.relative[vote],
                           bin_result.position_compliance[m], bin_result.orientation_compliance[m]};
    }
    results.push_back(std::move(result));
  }
  return results;
}

}  // namespace asr_ism
