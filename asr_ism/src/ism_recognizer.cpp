#include "asr_ism/ism_recognizer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>
#include <unordered_map>

#include "asr_ism/common_types.hpp"
#include "asr_ism/compliance.hpp"
#include "asr_ism/voting_space.hpp"

namespace asr_ism {
namespace {

// Bounds are compared with this margin so that rounding can never prune a hypothesis that an
// exhaustive search would have kept.
constexpr double kBoundMargin = 1e-9;
constexpr double kNoThreshold = -std::numeric_limits<double>::infinity();

// Objectives are ranked at this resolution (the bound margin), not bit for bit: a rigid motion of
// the input changes sums in their last bits, and equal hypotheses (in a two-member ISM the
// reference's own vote and the member's vote score 1 + c each) must stay equal, so that the tie
// goes to the same hypothesis wherever the bin grid falls.
std::int64_t objectiveLevel(double objective) {
  return std::llround(objective / kBoundMargin);
}

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

  // The order in which equally good hypotheses are preferred: by member (the reference first),
  // input and relative pose. It comes from the model and the inputs, not from where votes fall.
  bool keyLess(std::size_t a, std::size_t b) const {
    return std::tie(member[a], input[a], relative[a]) < std::tie(member[b], input[b], relative[b]);
  }
};

// One evaluated reference hypothesis: a vote taken as the reference pose and the best vote of each
// member around it.
struct Hypothesis {
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
  std::vector<std::uint32_t> candidates;  // the bin's own votes, in key order
  double upper_bound = 0.0;
  std::vector<int> atoms;  // sorted estimates that inputs with votes here stand for
  // Every member here votes from a single input, so a hypothesis that matches all of them fully
  // uses every estimate here, and anything else in the bin would only repeat part of it.
  bool one_input_per_member = false;
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
    n.one_input_per_member = inputs_here_.size() == n.members.size();
    // Sum in member order, as evaluate() does, so a perfect hypothesis meets the bound exactly.
    n.upper_bound = 0.0;
    for (double w : n.max_weight)
      n.upper_bound += w;
    const auto& own = space.bins()[bin];
    n.candidates.resize(own.end - own.begin);
    std::iota(n.candidates.begin(), n.candidates.end(), own.begin);
    // In key order, so that among equally good hypotheses the first found is the one the model
    // itself prefers (the reference's own vote first), not the one the bin layout puts first.
    std::sort(n.candidates.begin(), n.candidates.end(),
              [&](std::uint32_t a, std::uint32_t b) { return votes_.keyLess(a, b); });
  }

  // Evaluates the hypotheses of one bin in key order and passes each that may still be selected
  // to `emit`; `bar_now()` says what objective that takes, and may rise with every result emitted.
  // A bin keeps every combination of inputs it finds, not only its best: which distinct results
  // exist then does not depend on how the bin grid groups the votes, so the answer is that of an
  // exhaustive search over all votes (a rigid motion of the input cannot change it).
  template <typename BarNow, typename Emit>
  void searchBin(const Neighbourhood& n, BarNow bar_now, Emit emit) {
    double threshold = bar_now();
    for (std::uint32_t c : n.candidates) {
      if (n.upper_bound < threshold - kBoundMargin)
        return;  // nothing in this bin can be selected any more
      ++stats_.candidates;
      double objective;
      if (!evaluate(c, n, threshold, objective) || objective <= 0.0)
        continue;
      Hypothesis hypothesis;
      hypothesis.candidate = static_cast<int>(c);
      hypothesis.objective = objective;
      hypothesis.votes.assign(vote_.begin(), vote_.end());
      hypothesis.position_compliance.assign(position_.begin(), position_.end());
      hypothesis.orientation_compliance.assign(orientation_.begin(), orientation_.end());
      hypothesis.assignment.assign(member_count_, -1);
      for (std::size_t m = 0; m < member_count_; ++m) {
        if (vote_[m] >= 0)
          hypothesis.assignment[m] = votes_.input[vote_[m]];
      }
      emit(std::move(hypothesis));
      // Later candidates come later in key order, and none can score more, so with one input per
      // member they could only give a result this one makes redundant.
      if (n.one_input_per_member && objectiveLevel(objective) >= objectiveLevel(n.upper_bound) &&
          std::all_of(n.members.begin(), n.members.end(), [&](int m) { return vote_[m] >= 0; }))
        return;
      threshold = bar_now();
    }
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
        // Near-equal votes go by key, not by where the bin layout put them.
        const bool better = vote_[m] < 0
                                ? similarity > 0.0
                                : similarity > best + kBoundMargin ||
                                      (similarity >= best - kBoundMargin &&
                                       votes_.keyLess(v, static_cast<std::size_t>(vote_[m])));
        if (better) {
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

// What the results found so far rule out: a result that uses only estimates a better result uses
// too would be dropped as redundant, so a bin whose votes all come from such estimates need only
// be searched for results that beat the better one.
class Bar {
 public:
  explicit Bar(const std::vector<std::vector<int>>& atoms_of_input)
      : atoms_of_input_(atoms_of_input) {}

  // The objective a result of a bin with this neighbourhood must reach to be selected.
  double forBin(const Neighbourhood& n) const {
    double bar = kNoThreshold;
    for (const auto& [objective, atoms] : dominators_) {
      if (objective > bar &&
          std::includes(atoms.begin(), atoms.end(), n.atoms.begin(), n.atoms.end())) {
        bar = objective;
      }
    }
    return bar;
  }

  void add(const Hypothesis& result) {
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
  const std::vector<std::vector<int>>& atoms_of_input_;
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

  Bar bar(atoms_of_input);
  std::vector<Hypothesis> found;
  for (std::size_t b : bin_order) {
    const Neighbourhood& n = neighbourhoods[b];
    search.searchBin(
        n, [&] { return bar.forBin(n); },
        [&](Hypothesis&& hypothesis) {
          bar.add(hypothesis);
          found.push_back(std::move(hypothesis));
        });
  }
  if (stats != nullptr) {
    stats->votes += local_stats.votes;
    stats->bins += local_stats.bins;
    stats->candidates += local_stats.candidates;
    stats->comparisons += local_stats.comparisons;
  }

  // Best level first, ties by the hypothesis' key (unique per vote), so neither the search order
  // nor the bin grid decides between equally good results.
  std::sort(found.begin(), found.end(), [&](const Hypothesis& a, const Hypothesis& b) {
    const std::int64_t level_a = objectiveLevel(a.objective);
    const std::int64_t level_b = objectiveLevel(b.objective);
    if (level_a != level_b)
      return level_a > level_b;
    return votes.keyLess(a.candidate, b.candidate);
  });
  std::vector<IsmResult> results;
  std::unordered_map<std::vector<int>, bool, AssignmentHash> seen;
  std::vector<std::vector<int>> kept_atoms;
  for (Hypothesis& hypothesis : found) {
    if (!seen.emplace(hypothesis.assignment, true).second)
      continue;
    std::vector<int> atoms = unionOfAtoms(hypothesis.assignment, atoms_of_input);
    const bool dominated =
        std::any_of(kept_atoms.begin(), kept_atoms.end(), [&](const std::vector<int>& better) {
          return std::includes(better.begin(), better.end(), atoms.begin(), atoms.end());
        });
    if (dominated)
      continue;
    if (selection.best_count > 0 && results.size() >= selection.best_count)
      break;
    kept_atoms.push_back(atoms);
    const int c = hypothesis.candidate;
    IsmResult result;
    result.reference_pose =
        Pose(Eigen::Vector3d(votes.px[c], votes.py[c], votes.pz[c]),
             Eigen::Quaterniond(votes.qw[c], votes.qx[c], votes.qy[c], votes.qz[c]));
    result.objective = hypothesis.objective;
    // Inputs that stand for themselves (negative atoms) sort first; report real estimates only.
    result.estimates.assign(std::lower_bound(atoms.begin(), atoms.end(), 0), atoms.end());
    result.matches.resize(member_count);
    for (std::size_t m = 0; m < member_count; ++m) {
      const int vote = hypothesis.votes[m];
      if (vote < 0)
        continue;
      result.matches[m] = {votes.input[vote], votes.relative[vote],
                           hypothesis.position_compliance[m], hypothesis.orientation_compliance[m]};
    }
    results.push_back(std::move(result));
  }
  return results;
}

}  // namespace asr_ism
