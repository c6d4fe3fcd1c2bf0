#pragma once

#include <cstddef>
#include <limits>
#include <stdexcept>
#include <vector>

#include "asr_ism/ism.hpp"

namespace asr_ism {

struct IsmRecognitionParameters {
  /// Edge of the accumulator's cubic bins in metres.
  double bin_size = 0.1;
  /// Orientation deviation in radians at which a vote's orientation compliance reaches 0.
  double max_angle_deviation = 0.5235987755982988;  // 30 degrees

  /// The position deviation at which position compliance reaches 0: half the diagonal of a bin,
  /// sqrt(3)/2 x bin_size (0.087 m for bins of 0.1 m), the farthest a point of a bin is from its
  /// centre. It bounds both the vote's distance from the hypothesis and the member's distance
  /// from where the hypothesis puts it.
  double supportRadius() const { return 0.8660254037844386 * bin_size; }
};

/// An estimate given to one ISM: a real object or a child ISM's result, already assigned to the
/// member it stands for.
struct IsmInput {
  int member = -1;
  Pose pose;
  /// 1 for a real object; the objective of the child ISM's result for a placeholder, so that a
  /// placeholder counts as many objects as its sub-tree matched.
  double weight = 1.0;
  /// The real object estimates this input stands for: the estimate itself for a real object,
  /// every estimate the child result matched for a placeholder. A result whose estimates are a
  /// subset of a better result's is redundant. Empty: the input stands for itself alone.
  std::vector<int> estimates;
};

/// How one member of an ISM takes part in a recognition result.
struct MemberMatch {
  int input = -1;          // index into the inputs, -1 if the member is not matched
  int relative_pose = -1;  // the member's relative pose whose vote matched
  double position_compliance = 0.0;
  double orientation_compliance = 0.0;

  bool matched() const { return input >= 0; }
  double similarity() const { return position_compliance * orientation_compliance; }
};

/// One recognition result of an ISM: a reference pose (where consistent votes met) and the most
/// consistent combination of votes there, one per member.
struct IsmResult {
  Pose reference_pose;
  /// Sum over matched members of similarity x input weight.
  double objective = 0.0;
  std::vector<MemberMatch> matches;  // indexed by member
  /// Union of the `estimates` of the matched inputs, sorted.
  std::vector<int> estimates;
};

/// Which results of an ISM the caller needs; the search skips bins and hypotheses that cannot
/// change them, so the answer is the same as with an exhaustive search, only faster.
struct IsmResultSelection {
  /// 0 (for a root ISM): every result whose estimates are not all used by a better result too (it
  /// would add nothing the better one does not explain). n > 0 (for a sub-ISM whose results go up
  /// the tree): the n best, dropping only results whose estimates a better *perfect* result uses
  /// (one that matches every input around it, one per member, fully); a result at another pose is
  /// another placeholder for the parent even if it explains no new estimate.
  std::size_t best_count = 0;
  /// Also return every hypothesis whose objective reaches this, however many, each with its exact
  /// objective; of hypotheses at one pose (within 1e-12) only the best, since it serves a parent
  /// at least as well. An exact search over a tree asks a sub-ISM for every result that could
  /// still be part of a better instance (tree_recognizer.cpp). Infinity: none beyond the above.
  double every_result_from = std::numeric_limits<double>::infinity();
  /// Only results whose objective reaches this (the search skips everything below it).
  double at_least = -std::numeric_limits<double>::infinity();
  /// The search stops with IsmWorkLimitExceeded once it has made more vote-to-hypothesis
  /// comparisons than this (IsmRecognitionStats::comparisons): a caller that can do without the
  /// answer (the tree's exact search) bounds its cost by a count, not by the clock, so the
  /// outcome does not depend on the machine.
  std::size_t max_comparisons = std::numeric_limits<std::size_t>::max();
  /// Compare every vote near each hypothesis instead of only those whose distance lets them
  /// come near the best, and score in full every hypothesis that reaches the bar, even one that
  /// will match the same inputs as a better result found before (so can only be dropped): the
  /// same results, more work. The tests' reference.
  bool compare_every_vote = false;
};

/// Thrown by recognizeIsm where IsmResultSelection::max_comparisons is exceeded.
struct IsmWorkLimitExceeded : std::runtime_error {
  IsmWorkLimitExceeded() : std::runtime_error("ISM recognition: work limit exceeded") {}
};

/// Work counts of a recognition, comparable across machines.
struct IsmRecognitionStats {
  std::size_t votes = 0;
  std::size_t bins = 0;
  std::size_t candidates = 0;  // reference hypotheses evaluated
  /// Vote-to-hypothesis comparisons: votes whose similarity to a hypothesis was computed. Votes
  /// whose distance alone shows they score too little to matter are not counted.
  std::size_t comparisons = 0;
  /// Votes of each member evaluated in the 27 bins around each hypothesis evaluated: what a
  /// search comparing every vote near a hypothesis would compare. Topology selection's work
  /// measure, which does not depend on how the best vote is found.
  std::size_t neighbourhood_votes = 0;
};

/// Recognises the scene an ISM models in its inputs. Every input casts one vote per relative pose
/// of its member (a hypothesis of the reference pose); votes are binned by position. In each bin,
/// every vote is tried as the reference pose, and each member contributes its best vote that
/// passes the support test: within `supportRadius()` of it, the member carried back through the
/// vote's relative pose within `supportRadius()` of its input, and within `max_angle_deviation`
/// (so only the 27 surrounding bins matter): similarity = position compliance x orientation
/// compliance. The hypothesis with the highest
/// objective is the bin's result. Of results that match the same inputs to the same members only
/// the best is kept; `selection` says which of the rest are returned. Results come sorted by
/// objective, best first. Objectives within 1e-9 of each other count as equal; such ties go to
/// the hypothesis cast by the lower member (the reference first), then the lower input and
/// relative pose, so that where the bin grid falls does not change which hypothesis wins. Bins
/// are searched in order of their objective's upper bound, and bins and hypotheses whose bound
/// shows they cannot be selected are skipped (below the bar, or, where a hypothesis will match
/// every member around it, below the best result found with those inputs). The bin grid is laid in
/// a frame taken from one of the inputs (ism_recognizer.cpp, SearchFrame), so a rigid motion of all
/// inputs moves the grid with them: the results move with the inputs, and every work count
/// (IsmRecognitionStats, and so whether `max_comparisons` is exceeded) stays the same.
/// Deterministic.
std::vector<IsmResult> recognizeIsm(const Ism& ism, const std::vector<IsmInput>& inputs,
                                    const IsmRecognitionParameters& parameters,
                                    const IsmResultSelection& selection = {},
                                    IsmRecognitionStats* stats = nullptr);

}  // namespace asr_ism
