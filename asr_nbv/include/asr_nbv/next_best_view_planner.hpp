#pragma once

#include <algorithm>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "asr_common/pose.hpp"
#include "asr_ism/thread_pool.hpp"
#include "asr_nbv/candidate_views.hpp"
#include "asr_nbv/hypotheses.hpp"
#include "asr_nbv/hypothesis_groups.hpp"
#include "asr_nbv/nbv_documents.hpp"
#include "asr_nbv/nbv_parameters.hpp"
#include "asr_nbv/raised_cosine_bound.hpp"
#include "asr_nbv/view_rating.hpp"
#include "asr_robot_model/inverse_kinematics.hpp"
#include "asr_robot_model/world.hpp"
#include "asr_robot_model/world_map.hpp"

namespace asr_nbv {

/// A candidate view the planner rated in full (utility with occlusion, inverse kinematics,
/// costs), for display: the camera as reached and its rating.
struct RatedCandidate {
  asr_common::Pose camera;
  double rating = 0.0;
};

/// The view chosen (or none: nothing left to see from anywhere the robot can go).
struct PlannedView {
  bool found = false;
  asr_common::Pose camera;            // camera_optical_frame in map
  asr_robot_model::RobotState state;  // the state that takes it (inverse kinematics)
  std::vector<std::string> types;     // to search there
  double utility = 0.0;               // of the searched types
  double utility_max = 0.0;           // the best utility of the last step (normaliser)
  double rating = 0.0;
  InverseCosts costs;
  double motion_seconds = 0.0;       // from the current state, by the motion model
  std::size_t candidates_rated = 0;  // positions x orientations over all steps
  std::size_t steps = 0;
  std::vector<RatedCandidate> rated;  // every candidate rated in full, over all steps
};

/// A given view rated as the planner rates its candidates (NextBestViewPlanner::rateViews).
struct RatedView {
  bool reachable = false;
  std::string refusal;                // the inverse kinematics' explanation if not reachable
  asr_common::Pose camera;            // as reached (the head cannot roll the camera)
  asr_robot_model::RobotState state;  // that takes it
  std::vector<std::string> types;     // rated: as given, or the best subset if none were
  double utility = 0.0;               // of `types`, occluded hypotheses excluded
  double rating = 0.0;                // 0 if not reachable
  InverseCosts costs;
  double motion_seconds = 0.0;
};
struct RatedViews {
  std::vector<RatedView> views;
  double utility_max = 0.0;  // the largest utility (all types) among the views
};

/// The bounds the bounded search rates by at one camera floor position, per type (for tests:
/// neither may fall below the utility, occlusion aside, of any view they bound).
struct PositionBounds {
  std::vector<double> position;            // >= every level's
  std::vector<std::vector<double>> level;  // per tilt level, >= its orientations'

  std::vector<std::vector<double>> orientation;  // the first pass's, per candidate orientation
  /// Per candidate orientation, the utility without occlusion as the planner sums it before
  /// casting lines of sight (groups of hypotheses that cannot be in view skipped): must equal
  /// viewUtility's without a map.
  std::vector<std::vector<double>> unoccluded;
};

/// How a step's candidates are rated. `bounded`: branch and bound over lattice positions (the
/// default); `exhaustive`: every position and orientation rated in full, the reference the
/// bounded search must equal (tests; far slower).
enum class CandidateSearch { bounded, exhaustive };

/// Next-best-view search: candidate camera positions on a hexagonal lattice over the room,
/// refined around the best view step by step; at each, the orientations of
/// CandidateOrientations; utility per type from the hypotheses (occluded ones excluded); the
/// types to search by bestTypeSubset; costs from inverse kinematics and the motion model. The
/// candidates are rated in parallel on `pool`; the answer is the same for a seed whatever the
/// number of threads.
class NextBestViewPlanner {
 public:
  /// `world` gives the room; `map` free space and lines of sight (both must outlive the
  /// planner, as must `pool`; a null pool rates on the calling thread).
  NextBestViewPlanner(const asr_robot_model::RobotDescription& robot,
                      const asr_robot_model::World& world, const asr_robot_model::WorldMap& map,
                      NbvParameters parameters, asr_ism::ThreadPool* pool, unsigned seed = 0,
                      CandidateSearch search = CandidateSearch::bounded);

  /// The best view from `current` (checked finite: asr_common::InputError otherwise).
  PlannedView plan(const HypothesisSet& hypotheses,
                   const asr_robot_model::RobotState& current) const;

  /// Rates `views` (camera poses with types to search; no types: the best subset) from
  /// `current`, the utility normalised by the largest among them. A camera pose that is not
  /// finite or not unit-length is an asr_common::InputError naming the view.
  RatedViews rateViews(const HypothesisSet& hypotheses, const std::vector<VisitedView>& views,
                       const asr_robot_model::RobotState& current) const;

  /// The bounds at `position` (camera floor point) for `hypotheses`.
  PositionBounds boundsAt(const HypothesisSet& hypotheses, const Eigen::Vector2d& position) const;
  /// The candidate orientations (camera_optical_frame in map) and the camera height of each.
  const CandidateOrientations& orientations() const { return orientations_; }

  const NbvParameters& parameters() const { return parameters_; }
  const asr_robot_model::InverseKinematics& kinematics() const { return kinematics_; }

 private:
  struct SeenMember;
  struct Candidate;
  struct Step;
  struct StepState;
  struct Queued;
  Step rateStep(const HypothesisSet& hypotheses, const HypothesisGroups& groups,
                const std::vector<Eigen::Vector2d>& positions,
                const asr_robot_model::RobotState& current) const;
  Step rateStepExhaustively(const HypothesisSet& hypotheses, const HypothesisGroups& groups,
                            const std::vector<Eigen::Vector2d>& positions,
                            const asr_robot_model::RobotState& current) const;
  /// Per position, positionBound (empty where no hypothesis is near), in parallel.
  std::vector<std::vector<double>> positionBounds(
      const HypothesisSet& hypotheses, const HypothesisGroups& groups, const StepState& state,
      const std::vector<Eigen::Vector2d>& positions) const;
  /// The step's normaliser, its largest exact utility, into state.utility_max: best first over
  /// the positions' level bounds and their candidates' utilities.
  void findUtilityMax(const HypothesisSet& hypotheses, StepState& state,
                      const std::vector<std::vector<double>>& level_bound) const;
  /// The best rated view of the step into `step`: candidates best first by their rating
  /// bounds, positions expanded only once their level bound can still win.
  void rateBestFirst(const HypothesisSet& hypotheses, StepState& state,
                     const std::vector<Eigen::Vector2d>& positions,
                     const std::vector<std::vector<double>>& level_bound, Step& step) const;
  /// Per tilt level and type (level x type), >= the first pass's utility of every orientation
  /// of the level at `position` (so >= the exact utility of every view from there): each
  /// nearby hypothesis counted once, with the best orientation, side and proximity terms the
  /// level can give it (the side term from the elevation difference to the level's axis, which
  /// no heading can undercut). A view has one level: the largest level's bound is its
  /// position's, tighter than each hypothesis at its best level would give.
  void positionBound(const HypothesisSet& hypotheses, const HypothesisGroups& groups,
                     const std::vector<std::uint32_t>& nearby, const Eigen::Vector2d& position,
                     std::vector<double>& per_level_type) const;
  /// passing[l]: whether a member of `group` may be seen from `position` at tilt level l;
  /// false if none can at any.
  bool groupLevels(const HypothesisGroups::Group& group, const Eigen::Vector2d& position,
                   std::vector<char>& passing) const;
  StepState startStep(const HypothesisSet& hypotheses, const HypothesisGroups& groups,
                      const std::vector<Eigen::Vector2d>& positions,
                      const asr_robot_model::RobotState& current) const;
  /// task(0 .. count - 1), on the pool if there is one.
  void forEachPosition(std::size_t count, const std::function<void(std::size_t)>& task) const;
  /// Queue entries worked on at a time: a few per thread (more are expanded than needed at the
  /// end, none twice).
  std::size_t batchSize() const;
  /// The entries of `batch` worked on, in parallel over their positions: each (position, tilt
  /// level) not expanded yet gets the first pass (utilitiesAt), each candidate its utility
  /// without occlusion if not known yet, else its exact utility (which gives up below `floor`);
  /// then, if `bound_candidates`, the positions' candidates their rating bounds
  /// (boundCandidates), in the same task.
  void work(const HypothesisSet& hypotheses, StepState& state, const std::vector<Queued>& batch,
            double floor, bool bound_candidates) const;
  /// The candidate's utility without occlusion (computed once): the sum over the members it
  /// sees, >= its exact utility.
  double unoccludedUtility(const HypothesisSet& hypotheses, StepState& state,
                           Candidate& candidate) const;
  /// The candidate's utility per type with occlusion (computed once): lines of sight cast
  /// from its camera position to the members it sees (once per position and tilt level). Gives
  /// up (-1, nothing kept but the lines of sight) as soon as the hypotheses found occluded show
  /// that it cannot exceed `floor`.
  double exactUtility(const HypothesisSet& hypotheses, StepState& state, Candidate& candidate,
                      double floor = -std::numeric_limits<double>::infinity()) const;
  /// >= the rating of any view from a camera at `camera` (floor) searching `choice`: motion
  /// free but for the base's least drive, utility as given.
  double ratingBound(const TypeChoice& choice, const Eigen::Vector2d& camera,
                     const StepState& state) const;
  /// Each candidate's rating bound at `position` (-1: it cannot be chosen).
  void boundCandidates(const HypothesisSet& hypotheses, StepState& state,
                       std::size_t position) const;
  /// The rating of a candidate (exact utility, inverse kinematics, costs) into `step` if it beats
  /// `best_rating`, which it then raises; `prune`: skipped without inverse kinematics if its
  /// bound with the exact utility cannot beat it.
  void rateCandidate(const HypothesisSet& hypotheses, StepState& state, Candidate& candidate,
                     bool prune, double& best_rating, Step& step) const;
  /// The first pass at `position`, for the tilt levels `wanted`: per candidate orientation that
  /// may see something, a bound
  /// of its utility per type (each hypothesis adds its terms, by table look-up, to the few
  /// orientations whose axis passes within the side angle of it).
  void utilitiesAt(const HypothesisSet& hypotheses, const HypothesisGroups& groups,
                   const std::vector<std::uint32_t>& nearby, const Eigen::Vector2d& position,
                   std::size_t position_index, const std::vector<char>& wanted,
                   std::vector<Candidate>& candidates) const;
  /// >= orientationUtility of the member seen from a camera in the unit direction
  /// `to_camera` from it, by table look-up.
  double orientationBound(const HypothesisGroups& groups, std::uint32_t member,
                          const Eigen::Vector3d& to_camera) const {
    const std::uint32_t begin = groups.normalsBegin(member), end = groups.normalsBegin(member + 1);
    if (begin == end)
      return 1.0;  // recognisable from every side (only counting hypotheses are grouped)
    double best = 0.0;
    for (std::uint32_t n = begin; n < end; ++n)
      best = std::max(best, orientation_bound_.ofCosine(groups.normal(n).dot(to_camera)));
    return best;
  }
  /// False if no base position within camera_reach_ of the camera's floor point (sampled on
  /// its circle) is free: the camera cannot be carried there.
  bool reachable(const Eigen::Vector2d& camera) const;
  asr_common::Pose cameraOf(const Candidate& candidate,
                            const std::vector<Eigen::Vector2d>& positions) const;
  /// The members of the groups `nearby` that `camera` sees, occlusion aside, in index order
  /// (groups wholly outside the frustum's side angle or depth skipped).
  void visibleMembers(const HypothesisSet& hypotheses, const HypothesisGroups& groups,
                      const std::vector<std::uint32_t>& nearby, const asr_common::Pose& camera,
                      std::vector<SeenMember>& seen) const;

  asr_robot_model::RobotDescription robot_;
  asr_robot_model::InverseKinematics kinematics_;
  const asr_robot_model::World& world_;
  const asr_robot_model::WorldMap& map_;
  NbvParameters parameters_;
  asr_ism::ThreadPool* pool_;
  CandidateOrientations orientations_;
  // Per tilt level, the slopes (rise / run) between which a hypothesis can be within the side
  // angle of the level's axis elevation.
  std::vector<double> band_low_, band_high_;
  std::vector<double> level_sine_, level_cosine_;  // of each level's axis elevation
  // The first pass's bounds of the orientation, side and proximity terms.
  RaisedCosineBound orientation_bound_, side_bound_, proximity_bound_;
  double camera_reach_ = 0.0;
  // Half the smaller field of view, its cosine and sine; the farthest a visible point can be
  // (far plane / that cosine); the middle of the clipping range.
  double side_angle_ = 0.0, side_cosine_ = 1.0, side_sine_ = 0.0, reach_ = 0.0,
         middle_ = 0.0;  // metres from the base's centre to the camera, on the floor
  CandidateSearch search_;
};

}  // namespace asr_nbv
