#include "asr_ism/ism_recognizer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include <Eigen/Geometry>

#include "asr_ism/coincident_poses.hpp"
#include "asr_ism/common_types.hpp"
#include "asr_ism/compliance.hpp"
#include "asr_ism/grid_cell.hpp"
#include "asr_ism/voting_space.hpp"

namespace asr_ism {
namespace {

// Bounds are compared with this margin so that rounding can never prune a hypothesis that an
// exhaustive search would have kept.
constexpr double kBoundMargin = 1e-9;
constexpr double kNoThreshold = -std::numeric_limits<double>::infinity();
// How far below the best similarity a member's vote may score and still be compared: with this
// 1,000 times the bound margin, near-equal votes (within kBoundMargin, decided by key) are all
// compared unless a thousand of them chain down (Search::bestVote).
constexpr double kLikelyMargin = 1e-6;

// Objectives are ranked at this resolution (the bound margin), not bit for bit: a rigid motion of
// the input changes sums in their last bits, and equal hypotheses (in a two-member ISM the
// reference's own vote and the member's vote score 1 + c each) must stay equal, so that the tie
// goes to the same hypothesis wherever the bin grid falls.
std::int64_t objectiveLevel(double objective) {
  return std::llround(objective / kBoundMargin);
}

// Whether `value` falls short of `bar` by more than the bound margin, judged by level: callers
// often ask for objectives above one they have (the tree's exact search asks for results better
// than its best by the margin), so that a hypothesis at that objective lies exactly on the
// margin, and an exact comparison would let the last bits of its sum, which differ from frame to
// frame, decide. Prunes only what `value < bar - kBoundMargin` prunes.
bool fallsShort(double value, double bar) {
  if (!std::isfinite(bar))
    return bar > 0.0;
  if (value < bar - 2.0 * kBoundMargin)
    return true;
  if (value >= bar - 0.5 * kBoundMargin)
    return false;
  return objectiveLevel(value) < objectiveLevel(bar) - 1;
}

// Votes as parallel arrays in bin order, so that a bin's neighbourhood is a few contiguous ranges.
// Besides the vote's pose, each vote keeps where its input is (ox, oy, oz) and where the member
// stands in the reference's frame (mx, my, mz), so a hypothesis can be carried back to the object.
struct Votes {
  std::vector<double> px, py, pz, qw, qx, qy, qz, weight, ox, oy, oz, mx, my, mz;
  std::vector<int> member, input, relative;

  void resize(std::size_t n) {
    for (auto* column : {&px, &py, &pz, &qw, &qx, &qy, &qz, &weight, &ox, &oy, &oz, &mx, &my, &mz})
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

// The objective a hypothesis of a bin must reach to be selected: `any` for every hypothesis,
// `full` (never below `any`) for one with the bin's full assignment, which a result found before
// may already hold at a higher objective (Bar::forBin).
struct Thresholds {
  double any = kNoThreshold;
  double full = kNoThreshold;
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
  // Matches every input around it fully, one per member: nothing else can explain them better.
  bool perfect = false;
};

// The neighbourhood of one bin, regrouped by member so a hypothesis can be abandoned as soon as
// the members left cannot lift it above the bar.
struct Neighbourhood {
  std::vector<int> members;          // members with votes here, fewest votes first
  std::vector<std::uint32_t> begin;  // per entry of `members`, range in `votes`
  std::vector<std::uint32_t> end;
  std::vector<double> max_weight;    // per entry of `members`
  std::vector<std::uint32_t> votes;  // vote indices grouped by member
  // Each member's votes split by bin: ranges in `votes` sorted by x (VotingSpace::order), those
  // of entry i of `members` from first_run[i] to first_run[i + 1].
  std::vector<std::pair<std::uint32_t, std::uint32_t>> runs;
  std::vector<std::uint32_t> first_run;
  // Per run, the box its votes span: a run farther from a hypothesis than a vote may be is
  // skipped without a look at its votes. Its squared exterior distance never exceeds a vote's
  // squared distance, also in floating point (each axis' difference is one of a vote's, or 0,
  // summed in the same order).
  std::vector<Eigen::AlignedBox3d> run_box;
  std::vector<std::uint32_t> candidates;  // the bin's own votes, in key order
  double upper_bound = 0.0;
  std::vector<int> atoms;  // sorted estimates that inputs with votes here stand for
  // Every member here votes from a single input, so a hypothesis that matches all of them fully
  // uses every estimate here, and anything else in the bin would only repeat part of it.
  bool one_input_per_member = false;
  // With one input per member: per member of the ISM, that input or -1; the assignment of every
  // hypothesis here that matches each member here. Empty otherwise.
  std::vector<int> full_assignment;
  // lightest_from[i]: the smallest max_weight of entries i.. of `members` (infinity past the
  // last); a hypothesis that leaves one of them unmatched loses at least that much of its bound.
  std::vector<double> lightest_from;
  // Some hypothesis here may be perfect: one input per member, and a candidate with a vote of
  // every member on it (CoincidentVotes).
  bool may_hold_perfect = false;
  // The bin holds a vote of the ISM's reference object, which votes where it is: where a scene is
  // seen fully, a perfect result is found in such a bin.
  bool holds_reference_vote = false;
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

// The member that is the ISM's reference object, or -1.
int referenceMember(const Ism& ism) {
  for (std::size_t m = 0; m < ism.members.size(); ++m) {
    if (!ism.members[m].isPlaceholder() && ism.members[m].object == ism.reference)
      return static_cast<int>(m);
  }
  return -1;
}

// Which votes coincide. A perfect hypothesis matches a vote of every member with similarity 1 up
// to the objective's resolution: each such vote lies within `reach` of the hypothesis. Where no
// candidate has every member's vote that close (detections with noise, clutter), no perfect
// result can be found, and the search need not wait for one (Bar).
class CoincidentVotes {
 public:
  CoincidentVotes(const Votes& votes, double support_radius, std::size_t member_count)
      : votes_(votes), member_stamp_(member_count, 0) {
    double min_weight = std::numeric_limits<double>::infinity();
    for (double w : votes.weight)
      min_weight = std::min(min_weight, w);
    // position compliance 1 - d^2 / r^2 may miss 1 by at most 2 levels / weight
    reach_ = support_radius * std::sqrt(2.0 * kBoundMargin / min_weight);
    usable_ = reach_ < 0.01 * support_radius;
  }

  // Whether every member in `members` has a vote within reach of vote c.
  bool allMembersOn(std::uint32_t c, const std::vector<int>& members) {
    if (!usable_)
      return true;
    if (cells_.empty())
      indexCells();
    ++stamp_;
    std::size_t found = 0;
    const double x = votes_.px[c], y = votes_.py[c], z = votes_.pz[c];
    const Cell own = cellOf(x, y, z);
    // Within reach of a point lies at most the nearer neighbour cell per axis.
    const Cell step = {lowerHalf(x, own[0]) ? -1 : 1, lowerHalf(y, own[1]) ? -1 : 1,
                       lowerHalf(z, own[2]) ? -1 : 1};
    for (int corner = 0; corner < 8; ++corner) {
      const Cell cell = {own[0] + ((corner & 1) ? step[0] : 0),
                         own[1] + ((corner & 2) ? step[1] : 0),
                         own[2] + ((corner & 4) ? step[2] : 0)};
      const auto [first, last] =
          std::equal_range(cells_.begin(), cells_.end(), std::make_pair(cell, std::uint32_t{0}),
                           [](const auto& a, const auto& b) { return a.first < b.first; });
      for (auto it = first; it != last; ++it) {
        const std::uint32_t v = it->second;
        const double dx = votes_.px[v] - x, dy = votes_.py[v] - y, dz = votes_.pz[v] - z;
        const int m = votes_.member[v];
        if (dx * dx + dy * dy + dz * dz <= reach_ * reach_ && member_stamp_[m] != stamp_) {
          member_stamp_[m] = stamp_;
          ++found;
        }
      }
    }
    return found >= members.size();
  }

 private:
  using Cell = std::array<std::int64_t, 3>;

  // Every vote by its cell, sorted: one allocation, built only where a bin asks (an index per
  // call of the recogniser cost more than the search of a small ISM).
  void indexCells() {
    cells_.reserve(votes_.px.size());
    for (std::uint32_t v = 0; v < votes_.px.size(); ++v)
      cells_.emplace_back(cellOf(votes_.px[v], votes_.py[v], votes_.pz[v]), v);
    std::sort(cells_.begin(), cells_.end());
  }

  Cell cellOf(double x, double y, double z) const {
    return {gridCell(x, reach_), gridCell(y, reach_), gridCell(z, reach_)};
  }
  bool lowerHalf(double coordinate, std::int64_t cell) const {
    return gridCell(coordinate - static_cast<double>(cell) * reach_, 0.5 * reach_) < 1;
  }

  const Votes& votes_;
  double reach_ = 0.0;
  bool usable_ = false;
  std::vector<std::pair<Cell, std::uint32_t>> cells_;
  std::vector<std::uint32_t> member_stamp_;
  std::uint32_t stamp_ = 0;
};

class Search {
 public:
  Search(const Ism& ism, const Votes& votes, const std::vector<std::vector<int>>& atoms_of_input,
         const IsmRecognitionParameters& parameters, const IsmResultSelection& selection,
         IsmRecognitionStats& stats)
      : votes_(votes),
        coincident_(votes, parameters.supportRadius(), ism.members.size()),
        atoms_of_input_(atoms_of_input),
        member_count_(ism.members.size()),
        reference_member_(referenceMember(ism)),
        stats_(stats),
        max_comparisons_(selection.max_comparisons),
        perfect_results_matter_(selection.best_count > 0),
        compare_every_vote_(selection.compare_every_vote),
        bin_size_(parameters.bin_size),
        support_radius_squared_(parameters.supportRadius() * parameters.supportRadius()),
        cos_half_max_angle_(std::cos(0.5 * parameters.max_angle_deviation)),
        sin_half_squared_max_angle_(sinHalfSquared(cos_half_max_angle_)) {
    vote_.resize(member_count_);
    seed_similarity_.resize(member_count_);
    last_best_vote_.assign(member_count_, -1);
    best_.resize(member_count_);
    per_member_.resize(member_count_);
    slot_.resize(member_count_);
    rank_.resize(member_count_);
    input_stamp_.assign(atoms_of_input.size(), 0);
    input_member_.assign(atoms_of_input.size(), -1);
    position_.resize(member_count_);
    orientation_.resize(member_count_);
    x_order_.resize(votes.px.size());
    for (std::size_t v = 0; v < x_order_.size(); ++v)
      x_order_[v] = VotingSpace::xOrder(votes.px[v], parameters.bin_size);
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
          input_member_[input] = m;
          inputs_here_.push_back(input);
        }
      }
    }
    splitIntoRuns(space, n);
    n.atoms = unionOfAtoms(inputs_here_, atoms_of_input_);
    n.one_input_per_member = inputs_here_.size() == n.members.size();
    n.full_assignment.clear();
    if (n.one_input_per_member) {
      n.full_assignment.assign(member_count_, -1);
      for (int input : inputs_here_)
        n.full_assignment[input_member_[input]] = input;
    }
    n.lightest_from.assign(n.members.size() + 1, std::numeric_limits<double>::infinity());
    for (std::size_t i = n.members.size(); i-- > 0;)
      n.lightest_from[i] = std::min(n.max_weight[i], n.lightest_from[i + 1]);
    // Sum in member order, as evaluate() does, so a perfect hypothesis meets the bound exactly.
    n.upper_bound = 0.0;
    for (double w : n.max_weight)
      n.upper_bound += w;
    const auto& own = space.bins()[bin];
    n.candidates.resize(own.end - own.begin);
    std::iota(n.candidates.begin(), n.candidates.end(), own.begin);
    n.holds_reference_vote =
        std::any_of(n.candidates.begin(), n.candidates.end(),
                    [&](std::uint32_t v) { return votes_.member[v] == reference_member_; });
    // In key order, so that among equally good hypotheses the first found is the one the model
    // itself prefers (the reference's own vote first), not the one the bin layout puts first.
    std::sort(n.candidates.begin(), n.candidates.end(),
              [&](std::uint32_t a, std::uint32_t b) { return votes_.keyLess(a, b); });
    // Only a sub-ISM's bar waits for perfect results; at the root the test would be wasted.
    n.may_hold_perfect =
        n.one_input_per_member &&
        (!perfect_results_matter_ ||
         std::any_of(n.candidates.begin(), n.candidates.end(),
                     [&](std::uint32_t c) { return coincident_.allMembersOn(c, n.members); }));
  }

  // Evaluates the hypotheses of one bin in key order and passes each that may still be selected
  // to `emit`; `bar_now()` says what objective that takes, and may rise with every result emitted.
  // A bin keeps every combination of inputs it finds, not only its best: which distinct results
  // exist then does not depend on how the bin grid groups the votes, so the answer is that of an
  // exhaustive search over all votes (a rigid motion of the input cannot change it).
  // `every_from`: every hypothesis reaching it is wanted, so none may be skipped for a perfect one.
  template <typename BarNow, typename Emit>
  void searchBin(const Neighbourhood& n, double every_from, BarNow bar_now, Emit emit) {
    const bool every_here_wanted = n.upper_bound >= every_from - kBoundMargin;
    // The reference (compare_every_vote) skips nothing for the full assignment's best either.
    const auto thresholds_now = [&] {
      Thresholds now = bar_now();
      if (compare_every_vote_)
        now.full = now.any;
      return now;
    };
    Thresholds threshold = thresholds_now();
    for (std::uint32_t c : n.candidates) {
      if (fallsShort(n.upper_bound, threshold.any) ||
          cannotBeSelected(n.upper_bound, n.lightest_from[0], threshold))
        return;  // nothing in this bin can be selected any more
      ++stats_.candidates;
      double objective;
      const bool scored = evaluate(c, n, threshold, objective);
      if (stats_.comparisons > max_comparisons_)
        throw IsmWorkLimitExceeded();
      if (!scored || objective <= 0.0)
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
      // Later candidates come later in key order, and none can score more, so with one input per
      // member they could only give a result with this one's inputs or fewer. This one matches
      // every input here perfectly: its pose serves a parent as well as theirs would.
      hypothesis.perfect =
          n.one_input_per_member && objectiveLevel(objective) >= objectiveLevel(n.upper_bound) &&
          std::all_of(n.members.begin(), n.members.end(), [&](int m) { return vote_[m] >= 0; });
      const bool perfect = hypothesis.perfect;
      emit(std::move(hypothesis));
      if (perfect && !every_here_wanted)
        return;
      threshold = thresholds_now();
    }
  }

 private:
  void splitIntoRuns(const VotingSpace& space, Neighbourhood& n) {
    if (bin_of_vote_.empty()) {
      bin_of_vote_.resize(votes_.px.size());
      for (std::uint32_t b = 0; b < space.bins().size(); ++b)
        std::fill(bin_of_vote_.begin() + space.bins()[b].begin,
                  bin_of_vote_.begin() + space.bins()[b].end, b);
    }
    n.runs.clear();
    n.run_box.clear();
    n.first_run.clear();
    for (std::size_t i = 0; i < n.members.size(); ++i) {
      n.first_run.push_back(static_cast<std::uint32_t>(n.runs.size()));
      for (std::uint32_t k = n.begin[i]; k < n.end[i]; ++k) {
        const std::uint32_t v = n.votes[k];
        if (k == n.begin[i] || bin_of_vote_[v] != bin_of_vote_[n.votes[k - 1]]) {
          n.runs.emplace_back(k, k);
          n.run_box.emplace_back();
        }
        n.runs.back().second = k + 1;
        n.run_box.back().extend(Eigen::Vector3d(votes_.px[v], votes_.py[v], votes_.pz[v]));
      }
    }
    n.first_run.push_back(static_cast<std::uint32_t>(n.runs.size()));
  }

  // Whether a hypothesis bounded by `bound`, all of whose members matched so far, can reach
  // neither `full` (matching every member left) nor `any` (leaving one of them, the lightest at
  // best, unmatched: it then loses at least `lightest_left`).
  static bool cannotBeSelected(double bound, double lightest_left, const Thresholds& threshold) {
    return fallsShort(bound, threshold.full) && fallsShort(bound - lightest_left, threshold.any);
  }

  // Scores hypothesis `c`; false once the members left cannot lift it to what it must reach.
  bool evaluate(std::uint32_t c, const Neighbourhood& n, const Thresholds& threshold,
                double& objective) {
    std::fill(vote_.begin(), vote_.end(), -1);
    // Where every member has a vote scoring above 0 here, the hypothesis will match each, so it
    // has the full assignment and must beat that assignment's best.
    const bool seeded = threshold.full > threshold.any;
    const double must_reach =
        seeded && seedsMatchEveryMember(c, n) ? threshold.full : threshold.any;
    double achieved = 0.0;
    double still_possible = n.upper_bound;
    bool all_matched = true;
    for (std::size_t i = 0; i < n.members.size(); ++i) {
      const int m = n.members[i];
      stats_.neighbourhood_votes += n.end[i] - n.begin[i];
      // What member i must add for the hypothesis to reach must_reach, less a margin that makes
      // the bound below fall short wherever the member's best similarity is below it.
      const double need =
          must_reach - 3.0 * kBoundMargin - (achieved + still_possible - n.max_weight[i]);
      if (compare_every_vote_ || !bestVoteAmongLikely(c, n, i, seeded, need))
        bestVote(c, n, i, 0.0, std::numeric_limits<double>::infinity());
      achieved += best_[m];
      still_possible -= n.max_weight[i];
      all_matched = all_matched && vote_[m] >= 0;
      const double bound = achieved + still_possible;
      if (fallsShort(bound, must_reach) ||
          (all_matched && cannotBeSelected(bound, n.lightest_from[i + 1], threshold)))
        return false;
    }
    objective = achieved;
    return true;
  }

  // Member i's best vote for hypothesis c, compared only with the votes that may come within
  // kLikelyMargin of the best similarity: a vote at distance d scores at most (1 - d^2 / r^2) x
  // the member's largest weight here, and the best similarity is at least that of the member's
  // best vote for the previous hypothesis, usually a neighbour of this one. False where that
  // cannot be shown to give the result of comparing every vote (see bestVote).
  // `seeded`: seed_similarity_[i] holds it already (seedsMatchEveryMember). Votes that cannot
  // reach `need` are skipped too: where the best does, it is found as before; where it does not,
  // the hypothesis falls short whatever this member adds, so its best need not be exact.
  bool bestVoteAmongLikely(std::uint32_t c, const Neighbourhood& n, std::size_t i, bool seeded,
                           double need) {
    const double seed_similarity = seeded ? seed_similarity_[i] : seedSimilarity(c, n.members[i]);
    return bestVote(c, n, i, std::max({0.0, seed_similarity, need}), kLikelyMargin);
  }

  // The similarity to hypothesis c of member m's last best vote (-1 where it has none or that
  // vote fails the support test).
  double seedSimilarity(std::uint32_t c, int m) {
    const int seed = last_best_vote_[m];
    if (seed < 0)
      return -1.0;
    ++stats_.comparisons;
    return similarityOf(static_cast<std::uint32_t>(seed), c);
  }

  // Fills seed_similarity_ for the members here; whether each seed scores above 0. A vote within
  // the support radius of c lies in c's neighbourhood, so the member is then matched here.
  bool seedsMatchEveryMember(std::uint32_t c, const Neighbourhood& n) {
    bool every = true;
    for (std::size_t i = 0; i < n.members.size(); ++i) {
      seed_similarity_[i] = seedSimilarity(c, n.members[i]);
      every = every && seed_similarity_[i] > 0.0;
    }
    return every;
  }

  // Compares hypothesis c with member i's votes in order, keeping the best (ties by key, as
  // votes near-equal within kBoundMargin go by key, not by where the bin layout put them), but
  // skips a vote whose bound (1 - d^2 / r^2) x largest weight falls more than `margin` below
  // both `floor` (a similarity some vote reaches) and the best so far. Skipping never changes the
  // answer: each vote skipped scores more than `margin` below the best M, and the votes that
  // decide among near-equals lie within a chain of kBoundMargin steps below M; with fewer than
  // margin / kBoundMargin votes compared at or above floor - margin, that chain cannot reach the
  // skipped ones, so they are ignored by the scan of every vote too. False if that count is
  // reached (the caller then compares every vote).
  bool bestVote(std::uint32_t c, const Neighbourhood& n, std::size_t i, double floor,
                double margin) {
    const int m = n.members[i];
    const double cx = votes_.px[c], cy = votes_.py[c], cz = votes_.pz[c];
    const double max_weight = n.max_weight[i];
    // Two margins of slack for rounding in the skip test (see above).
    const std::size_t chain_limit = std::isfinite(margin)
                                        ? static_cast<std::size_t>(margin / kBoundMargin) - 2
                                        : std::numeric_limits<std::size_t>::max();
    std::size_t near_floor = 0;
    double best = 0.0;
    int best_vote = -1;
    // Beyond this squared distance a vote's bound falls below max(floor, best) - margin.
    const auto skipBeyond = [&](double best_so_far) {
      const double bar = std::max(floor, best_so_far) - margin;
      return bar <= 0.0 ? support_radius_squared_
                        : support_radius_squared_ * std::max(0.0, 1.0 - bar / max_weight);
    };
    double skip_beyond_squared = skipBeyond(best);
    // A run's votes are sorted by x: only those within the skip distance in x are looked at.
    for (std::uint32_t run = n.first_run[i]; run < n.first_run[i + 1]; ++run) {
      if (n.run_box[run].squaredExteriorDistance(Eigen::Vector3d(cx, cy, cz)) >=
          skip_beyond_squared)
        continue;  // every vote of it would be skipped below
      // Runs are sorted by x at VotingSpace::xOrder's resolution: one step more either side.
      const double reach = std::sqrt(skip_beyond_squared) * (1.0 + 1e-9);
      const std::int64_t lowest = VotingSpace::xOrder(cx - reach, bin_size_) - 1;
      const std::int64_t highest = VotingSpace::xOrder(cx + reach, bin_size_) + 1;
      const auto [first, last] = n.runs[run];
      std::uint32_t k = static_cast<std::uint32_t>(
          std::lower_bound(n.votes.begin() + first, n.votes.begin() + last, lowest,
                           [&](std::uint32_t v, std::int64_t x) { return x_order_[v] < x; }) -
          n.votes.begin());
      for (; k < last && x_order_[n.votes[k]] <= highest; ++k) {
        const std::uint32_t v = n.votes[k];
        const double vote_distance_squared = squaredDistance(v, cx, cy, cz);
        if (vote_distance_squared >= skip_beyond_squared ||
            vote_distance_squared >= support_radius_squared_)
          continue;
        ++stats_.comparisons;
        double position, orientation;
        const double similarity = similarityOf(
            v, c, vote_distance_squared, std::max(floor, best) - margin, position, orientation);
        if (similarity < 0.0)
          continue;  // fails the support test or scores too little
        if (similarity >= floor - margin && ++near_floor >= chain_limit)
          return false;
        const bool better = best_vote < 0
                                ? similarity > 0.0
                                : similarity > best + kBoundMargin ||
                                      (similarity >= best - kBoundMargin &&
                                       votes_.keyLess(v, static_cast<std::size_t>(best_vote)));
        if (better) {
          best = similarity;
          best_vote = static_cast<int>(v);
          position_[m] = position;
          orientation_[m] = orientation;
          skip_beyond_squared = skipBeyond(best);
        }
      }
    }
    vote_[m] = best_vote;
    best_[m] = best;
    if (best_vote >= 0)
      last_best_vote_[m] = best_vote;
    return true;
  }

  // The similarity of vote v to hypothesis c (x weight), -1 if it fails the support test.
  double similarityOf(std::uint32_t v, std::uint32_t c) {
    double position, orientation;
    return similarityOf(v, c, squaredDistance(v, votes_.px[c], votes_.py[c], votes_.pz[c]),
                        kNoThreshold, position, orientation);
  }

  // Also -1 where the vote, by its distance and orientation alone, scores below `skip_below`.
  double similarityOf(std::uint32_t v, std::uint32_t c, double vote_distance_squared,
                      double skip_below, double& position, double& orientation) const {
    if (vote_distance_squared >= support_radius_squared_)
      return -1.0;
    const double cos_half = std::abs(votes_.qw[v] * votes_.qw[c] + votes_.qx[v] * votes_.qx[c] +
                                     votes_.qy[v] * votes_.qy[c] + votes_.qz[v] * votes_.qz[c]);
    if (cos_half <= cos_half_max_angle_)
      return -1.0;
    orientation = orientationCompliance(cos_half, sin_half_squared_max_angle_);
    if (positionCompliance(vote_distance_squared, support_radius_squared_) * orientation *
            votes_.weight[v] <
        skip_below)
      return -1.0;
    const double object_distance_squared = objectDistanceSquared(v, c);
    if (object_distance_squared >= support_radius_squared_)
      return -1.0;
    position = positionCompliance(std::max(vote_distance_squared, object_distance_squared),
                                  support_radius_squared_);
    return position * orientation * votes_.weight[v];
  }

  double squaredDistance(std::uint32_t v, double x, double y, double z) const {
    const double dx = votes_.px[v] - x;
    const double dy = votes_.py[v] - y;
    const double dz = votes_.pz[v] - z;
    return dx * dx + dy * dy + dz * dz;
  }

  // The support test at the object: hypothesis c carried through vote v's relative pose puts the
  // member at c * inverse(relative pose); how far is that from where the member's input is? A
  // small turn of the vote against the hypothesis moves this point by the turn times the
  // relation's length, which the vote's own distance does not see.
  double objectDistanceSquared(std::uint32_t v, std::uint32_t c) const {
    const Eigen::Quaterniond hypothesis(votes_.qw[c], votes_.qx[c], votes_.qy[c], votes_.qz[c]);
    const Eigen::Vector3d member =
        Eigen::Vector3d(votes_.px[c], votes_.py[c], votes_.pz[c]) +
        hypothesis * Eigen::Vector3d(votes_.mx[v], votes_.my[v], votes_.mz[v]);
    return (member - Eigen::Vector3d(votes_.ox[v], votes_.oy[v], votes_.oz[v])).squaredNorm();
  }

  const Votes& votes_;
  CoincidentVotes coincident_;
  const std::vector<std::vector<int>>& atoms_of_input_;
  const std::size_t member_count_;
  const int reference_member_;
  IsmRecognitionStats& stats_;
  const std::size_t max_comparisons_;
  const bool perfect_results_matter_;
  const bool compare_every_vote_;
  const double bin_size_;
  const double support_radius_squared_;
  const double cos_half_max_angle_;
  const double sin_half_squared_max_angle_;
  std::vector<int> vote_;                // per member, the matched vote or -1
  std::vector<double> seed_similarity_;  // per entry of a neighbourhood's members
  std::vector<double> best_;
  std::vector<int> last_best_vote_;  // per member, its last matched vote or -1
  std::vector<std::uint32_t> bin_of_vote_;
  std::vector<std::uint32_t> per_member_;
  std::vector<std::uint32_t> slot_;
  std::vector<int> rank_;
  std::vector<std::uint32_t> input_stamp_;
  std::vector<int> input_member_;  // per input seen in a neighbourhood, its member
  std::uint32_t stamp_ = 0;
  std::vector<int> inputs_here_;
  std::vector<double> position_;
  std::vector<double> orientation_;
  std::vector<std::int64_t> x_order_;  // per vote, VotingSpace::xOrder of its x
};

struct AssignmentHash {
  std::size_t operator()(const std::vector<int>& assignment) const {
    std::size_t hash = 1469598103934665603ULL;
    for (int input : assignment)
      hash = (hash ^ static_cast<std::size_t>(input + 1)) * 1099511628211ULL;
    return hash;
  }
};

// What the results found so far rule out. At the root (every result is returned), a result that
// uses only estimates a better result uses too is dropped as redundant, so a bin whose votes all
// come from such estimates need only be searched for results that beat the better one. Below the
// root (the n best are passed up), a result is dropped only if a better one has the same
// assignment: one at another pose is another placeholder for the parent, even if it explains no
// new estimate, and dropping it lets a badly seen object pull the hypothesis away from where the
// parent needs it. There the bar is the n-th best objective of distinct assignments found so far,
// and a perfect result (every input around it matched fully) rules out others that use only its
// estimates, as at the root: they could only offer a parent a pose that fits those inputs worse.
class Bar {
 public:
  Bar(const std::vector<std::vector<int>>& atoms_of_input, const IsmResultSelection& selection)
      : atoms_of_input_(atoms_of_input),
        best_count_(selection.best_count),
        every_result_from_(selection.every_result_from),
        at_least_(selection.at_least) {}

  bool dropsSubsets() const { return best_count_ == 0; }

  // The objective a result of a bin with this neighbourhood must reach to be selected. One with
  // the bin's full assignment must also beat the best found with it: below that it is neither
  // the assignment's best nor (short of every_result_from) wanted for its pose.
  Thresholds forBin(const Neighbourhood& n) const {
    Thresholds threshold;
    threshold.any = std::max(std::min(bestOrDominatorBar(n), every_result_from_), at_least_);
    threshold.full = threshold.any;
    if (!n.full_assignment.empty()) {
      const auto found = best_of_assignment_.find(n.full_assignment);
      if (found != best_of_assignment_.end())
        threshold.full = std::max(threshold.any, std::min(found->second, every_result_from_));
    }
    return threshold;
  }

  // The highest objective a perfect result of the bins not yet searched could have: the upper
  // bound of the best such bin with one input per member (perfect results need one).
  void setPerfectBound(double bound) { perfect_bound_ = bound; }

  void add(const Hypothesis& result) {
    const auto [entry, inserted] = best_of_assignment_.emplace(result.assignment, result.objective);
    if (!inserted)
      entry->second = std::max(entry->second, result.objective);
    std::vector<int> atoms = unionOfAtoms(result.assignment, atoms_of_input_);
    if (dominated(result.objective, atoms))
      return;  // a better result rules out everything this one would
    if (!dropsSubsets()) {
      addToBest(result, atoms);
      if (!result.perfect)
        return;
      best_.erase(std::remove_if(best_.begin(), best_.end(),
                                 [&](const BestEntry& entry) {
                                   return entry.objective <= result.objective &&
                                          entry.assignment != result.assignment &&
                                          std::includes(atoms.begin(), atoms.end(),
                                                        entry.atoms.begin(), entry.atoms.end());
                                 }),
                  best_.end());
    }
    dominators_.emplace_back(result.objective, std::move(atoms));
  }

 private:
  struct BestEntry {
    double objective;
    std::vector<int> assignment;
    std::vector<int> atoms;
  };

  double bestOrDominatorBar(const Neighbourhood& n) const {
    double bar = kNoThreshold;
    if (!dropsSubsets()) {
      // Only results better than any perfect result still possible are sure to stay; a perfect
      // result found later could drop the others.
      std::size_t sure = 0;
      for (const auto& entry : best_)
        sure += entry.objective > perfect_bound_ + kBoundMargin ? 1 : 0;
      if (sure >= best_count_)
        return best_[best_count_ - 1].objective;
    }
    for (const auto& [objective, atoms] : dominators_) {
      if (objective > bar &&
          std::includes(atoms.begin(), atoms.end(), n.atoms.begin(), n.atoms.end())) {
        bar = objective;
      }
    }
    return bar;
  }

  bool dominated(double objective, const std::vector<int>& atoms) const {
    return std::any_of(dominators_.begin(), dominators_.end(), [&](const auto& dominator) {
      return dominator.first >= objective &&
             std::includes(dominator.second.begin(), dominator.second.end(), atoms.begin(),
                           atoms.end());
    });
  }

  // Keeps the best_count_ best objectives of distinct assignments, best first.
  void addToBest(const Hypothesis& result, const std::vector<int>& atoms) {
    auto same = std::find_if(best_.begin(), best_.end(), [&](const BestEntry& entry) {
      return entry.assignment == result.assignment;
    });
    if (same != best_.end()) {
      same->objective = std::max(same->objective, result.objective);
    } else if (best_.size() < best_count_) {
      best_.push_back({result.objective, result.assignment, atoms});
    } else if (result.objective > best_.back().objective) {
      best_.back() = {result.objective, result.assignment, atoms};
    }
    std::sort(best_.begin(), best_.end(),
              [](const BestEntry& a, const BestEntry& b) { return a.objective > b.objective; });
  }

  const std::vector<std::vector<int>>& atoms_of_input_;
  const std::size_t best_count_;
  const double every_result_from_;
  const double at_least_;
  std::vector<std::pair<double, std::vector<int>>> dominators_;
  std::vector<BestEntry> best_;
  std::unordered_map<std::vector<int>, double, AssignmentHash> best_of_assignment_;
  double perfect_bound_ = std::numeric_limits<double>::infinity();
};

void checkInputs(const Ism& ism, const std::vector<IsmInput>& inputs,
                 const IsmRecognitionParameters& parameters) {
  if (!(parameters.bin_size > 0.0) || !(parameters.max_angle_deviation > 0.0)) {
    throw InputError("ISM '" + ism.name + "': bin size and maximum angle deviation must be > 0");
  }
  for (const IsmInput& input : inputs) {
    if (input.member < 0 || static_cast<std::size_t>(input.member) >= ism.members.size()) {
      throw InputError("ISM '" + ism.name + "': an input names member " +
                       std::to_string(input.member) + " of " + std::to_string(ism.members.size()));
    }
    if (!(input.weight > 0.0)) {
      throw InputError("ISM '" + ism.name + "': input weights must be > 0");
    }
  }
}

void setVote(Votes& votes, std::size_t v, const Pose& input, double weight, const Pose& relative) {
  const Eigen::Vector3d position = input.position + input.orientation * relative.position;
  const Eigen::Quaterniond orientation = input.orientation * relative.orientation;
  // Where the member stands in the reference's frame: the position of inverse(relative).
  const Eigen::Vector3d member = -(relative.orientation.conjugate() * relative.position);
  votes.px[v] = position.x();
  votes.py[v] = position.y();
  votes.pz[v] = position.z();
  votes.qw[v] = orientation.w();
  votes.qx[v] = orientation.x();
  votes.qy[v] = orientation.y();
  votes.qz[v] = orientation.z();
  votes.weight[v] = weight;
  votes.ox[v] = input.position.x();
  votes.oy[v] = input.position.y();
  votes.oz[v] = input.position.z();
  votes.mx[v] = member.x();
  votes.my[v] = member.y();
  votes.mz[v] = member.z();
}

// The frame the search works in, derived from the inputs alone, so that a rigid motion of all
// inputs moves it with them: the bins, and with them every work count, stay the same (up to
// rounding of the coordinates, which matters only where a vote or a compared value lies within
// it of a bin border or a threshold). Its axes are those of an anchor input, its origin half a
// bin from the anchor along each axis, so that the anchor, which is usually the reference object
// voting where it is, lies at the centre of its bin. The anchor is the input of the lowest member
// (the reference first) with the largest weight, nearest the inputs' centroid, then the first
// in input order; weights and distances within 1e-9 count as equal, so that rounding does not
// decide. Not covered: inputs whose weights or distances differ by about 1e-9 (rounding can
// pick either anchor), and ties left to input order when the inputs come reordered.
class SearchFrame {
 public:
  SearchFrame(const Ism& ism, const std::vector<IsmInput>& inputs, double bin_size)
      : centre_offset_(Eigen::Vector3d::Constant(0.5 * bin_size)) {
    if (inputs.empty())
      return;
    const Pose& anchor = inputs[anchorInput(ism, inputs)].pose;
    origin_ = anchor.position;
    axes_ = anchor.orientation;
  }

  Pose fromWorld(const Pose& pose) const {
    return Pose(axes_.conjugate() * (pose.position - origin_) + centre_offset_,
                axes_.conjugate() * pose.orientation);
  }
  Pose toWorld(const Pose& pose) const {
    return Pose(axes_ * (pose.position - centre_offset_) + origin_, axes_ * pose.orientation);
  }

 private:
  static std::size_t anchorInput(const Ism& ism, const std::vector<IsmInput>& inputs) {
    constexpr double kTie = 1e-9;
    const int reference = referenceMember(ism);
    // The reference member ranks first, the others by index.
    const auto rank = [&](int member) { return member == reference ? -1 : member; };
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const IsmInput& input : inputs)
      centroid += input.pose.position;
    centroid /= static_cast<double>(inputs.size());
    std::size_t anchor = 0;
    double anchor_distance = (inputs[0].pose.position - centroid).norm();
    for (std::size_t i = 1; i < inputs.size(); ++i) {
      const IsmInput& input = inputs[i];
      const IsmInput& best = inputs[anchor];
      const double distance = (input.pose.position - centroid).norm();
      const bool better =
          rank(input.member) != rank(best.member)       ? rank(input.member) < rank(best.member)
          : std::abs(input.weight - best.weight) > kTie ? input.weight > best.weight
                                                        : distance < anchor_distance - kTie;
      if (better) {
        anchor = i;
        anchor_distance = distance;
      }
    }
    return anchor;
  }

  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  Eigen::Quaterniond axes_ = Eigen::Quaterniond::Identity();
  Eigen::Vector3d centre_offset_;
};

// Every input (at its pose in the search frame) combined with every relative pose of its member.
Votes castVotes(const Ism& ism, const std::vector<IsmInput>& inputs,
                const std::vector<Pose>& poses) {
  std::size_t vote_count = 0;
  for (const IsmInput& input : inputs)
    vote_count += ism.members[input.member].relative_poses.size();
  Votes cast;
  cast.resize(vote_count);
  std::size_t v = 0;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const auto& relative_poses = ism.members[inputs[i].member].relative_poses;
    for (std::size_t r = 0; r < relative_poses.size(); ++r, ++v) {
      setVote(cast, v, poses[i], inputs[i].weight, relative_poses[r].reference_in_member);
      cast.member[v] = inputs[i].member;
      cast.input[v] = static_cast<int>(i);
      cast.relative[v] = static_cast<int>(r);
    }
  }
  return cast;
}

// The votes in the space's bin order.
Votes sortedByBin(const Votes& cast, const VotingSpace& space) {
  const std::size_t count = cast.member.size();
  Votes votes;
  votes.resize(count);
  const auto copy = [&](auto member) {
    for (std::size_t sorted = 0; sorted < count; ++sorted)
      (votes.*member)[sorted] = (cast.*member)[space.order()[sorted]];
  };
  for (auto column :
       {&Votes::px, &Votes::py, &Votes::pz, &Votes::qw, &Votes::qx, &Votes::qy, &Votes::qz,
        &Votes::weight, &Votes::ox, &Votes::oy, &Votes::oz, &Votes::mx, &Votes::my, &Votes::mz})
    copy(column);
  for (auto column : {&Votes::member, &Votes::input, &Votes::relative})
    copy(column);
  return votes;
}

// Every hypothesis that may be selected, bins with the highest upper bound first: their results
// raise the bar for the rest.
std::vector<Hypothesis> searchBins(const VotingSpace& space, Search& search, Bar& bar,
                                   double every_result_from) {
  const std::size_t bin_count = space.bins().size();
  std::vector<Neighbourhood> neighbourhoods(bin_count);
  for (std::size_t b = 0; b < bin_count; ++b)
    search.gather(space, b, neighbourhoods[b]);
  std::vector<std::size_t> bin_order(bin_count);
  std::iota(bin_order.begin(), bin_order.end(), 0);
  // Among equal bounds, bins with a vote of the reference first: a perfect result found early
  // prunes the rest. The order changes the speed only, never the answer. Bounds are compared by
  // level: weights that are child ISMs' objectives differ in their last bits from frame to
  // frame, and bins with equal bounds must keep their order (by cell) in every frame.
  std::stable_sort(bin_order.begin(), bin_order.end(), [&](std::size_t a, std::size_t b) {
    const Neighbourhood& x = neighbourhoods[a];
    const Neighbourhood& y = neighbourhoods[b];
    const std::int64_t level_x = objectiveLevel(x.upper_bound);
    const std::int64_t level_y = objectiveLevel(y.upper_bound);
    if (level_x != level_y)
      return level_x > level_y;
    return x.holds_reference_vote && !y.holds_reference_vote;
  });
  // perfect_bound[i]: the highest bound of a bin with one input per member from position i on.
  std::vector<double> perfect_bound(bin_count + 1, kNoThreshold);
  for (std::size_t i = bin_count; i-- > 0;) {
    const Neighbourhood& n = neighbourhoods[bin_order[i]];
    // The running maximum: bounds within one level may come in either order.
    perfect_bound[i] =
        n.may_hold_perfect ? std::max(n.upper_bound, perfect_bound[i + 1]) : perfect_bound[i + 1];
  }
  std::vector<Hypothesis> found;
  for (std::size_t i = 0; i < bin_count; ++i) {
    const Neighbourhood& n = neighbourhoods[bin_order[i]];
    bar.setPerfectBound(perfect_bound[i]);
    search.searchBin(
        n, every_result_from, [&] { return bar.forBin(n); },
        [&](Hypothesis&& hypothesis) {
          bar.add(hypothesis);
          found.push_back(std::move(hypothesis));
        });
  }
  return found;
}

// Candidate c's pose in the search frame.
Pose poseOf(const Votes& votes, int c) {
  return Pose(Eigen::Vector3d(votes.px[c], votes.py[c], votes.pz[c]),
              Eigen::Quaterniond(votes.qw[c], votes.qx[c], votes.qy[c], votes.qz[c]));
}

IsmResult resultOf(const Hypothesis& hypothesis, const Votes& votes, const SearchFrame& frame,
                   std::vector<int> atoms) {
  IsmResult result;
  result.reference_pose = frame.toWorld(poseOf(votes, hypothesis.candidate));
  result.objective = hypothesis.objective;
  // Inputs that stand for themselves (negative atoms) sort first; report real estimates only.
  result.estimates.assign(std::lower_bound(atoms.begin(), atoms.end(), 0), atoms.end());
  result.matches.resize(hypothesis.votes.size());
  for (std::size_t m = 0; m < hypothesis.votes.size(); ++m) {
    const int vote = hypothesis.votes[m];
    if (vote >= 0) {
      result.matches[m] = {votes.input[vote], votes.relative[vote],
                           hypothesis.position_compliance[m], hypothesis.orientation_compliance[m]};
    }
  }
  return result;
}

// Best level first, ties by the hypothesis' key (unique per vote), so neither the search order
// nor the bin grid decides between equally good results; then one result per assignment, and none
// whose estimates a better result uses too: at the root any better result, below it a perfect
// one (see Bar). Besides, every hypothesis reaching `every_result_from`, one per pose.
std::vector<IsmResult> selectResults(std::vector<Hypothesis>& found, const Votes& votes,
                                     const SearchFrame& frame,
                                     const std::vector<std::vector<int>>& atoms_of_input,
                                     const IsmResultSelection& selection) {
  std::sort(found.begin(), found.end(), [&](const Hypothesis& a, const Hypothesis& b) {
    const std::int64_t level_a = objectiveLevel(a.objective);
    const std::int64_t level_b = objectiveLevel(b.objective);
    if (level_a != level_b)
      return level_a > level_b;
    return votes.keyLess(a.candidate, b.candidate);
  });

  std::vector<IsmResult> results;
  std::size_t best_taken = 0;
  std::unordered_map<std::vector<int>, bool, AssignmentHash> seen;
  std::vector<std::vector<int>> kept_atoms;
  asr_ism::CoincidentPoses poses_taken;
  const bool wants_every = std::isfinite(selection.every_result_from);
  for (Hypothesis& hypothesis : found) {
    const bool capped = selection.best_count > 0 && best_taken >= selection.best_count;
    const bool reaches_every_from = !fallsShort(hypothesis.objective, selection.every_result_from);
    if ((capped && !reaches_every_from) || fallsShort(hypothesis.objective, selection.at_least))
      break;  // sorted: nothing later is wanted
    std::vector<int> atoms = unionOfAtoms(hypothesis.assignment, atoms_of_input);
    bool as_best = false;
    if (seen.emplace(hypothesis.assignment, true).second && !capped) {
      as_best = std::none_of(kept_atoms.begin(), kept_atoms.end(), [&](const auto& better) {
        return std::includes(better.begin(), better.end(), atoms.begin(), atoms.end());
      });
    }
    // Poses matter only where every result reaching every_result_from is wanted.
    const bool pose_new =
        wants_every && poses_taken.insertIfNew(poseOf(votes, hypothesis.candidate));
    if (!as_best && !(reaches_every_from && pose_new))
      continue;
    if (as_best) {
      ++best_taken;
      if (selection.best_count == 0 || hypothesis.perfect)
        kept_atoms.push_back(atoms);
    }
    results.push_back(resultOf(hypothesis, votes, frame, std::move(atoms)));
  }
  return results;
}

}  // namespace

std::vector<IsmResult> recognizeIsm(const Ism& ism, const std::vector<IsmInput>& inputs,
                                    const IsmRecognitionParameters& parameters,
                                    const IsmResultSelection& selection,
                                    IsmRecognitionStats* stats) {
  checkInputs(ism, inputs, parameters);
  const SearchFrame frame(ism, inputs, parameters.bin_size);
  std::vector<Pose> poses;
  poses.reserve(inputs.size());
  for (const IsmInput& input : inputs)
    poses.push_back(frame.fromWorld(input.pose));
  const Votes cast = castVotes(ism, inputs, poses);
  const VotingSpace space(parameters.bin_size, cast.px.data(), cast.py.data(), cast.pz.data(),
                          cast.px.size());
  const Votes votes = sortedByBin(cast, space);

  IsmRecognitionStats local_stats;
  local_stats.votes = votes.px.size();
  local_stats.bins = space.bins().size();
  const std::vector<std::vector<int>> atoms_of_input = atomsOfInputs(inputs);
  Search search(ism, votes, atoms_of_input, parameters, selection, local_stats);
  Bar bar(atoms_of_input, selection);
  std::vector<Hypothesis> found = searchBins(space, search, bar, selection.every_result_from);
  if (stats != nullptr) {
    stats->votes += local_stats.votes;
    stats->bins += local_stats.bins;
    stats->candidates += local_stats.candidates;
    stats->comparisons += local_stats.comparisons;
    stats->neighbourhood_votes += local_stats.neighbourhood_votes;
  }
  return selectResults(found, votes, frame, atoms_of_input, selection);
}

}  // namespace asr_ism
