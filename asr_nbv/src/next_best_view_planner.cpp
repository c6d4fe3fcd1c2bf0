#include "asr_nbv/next_best_view_planner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <queue>
#include <tuple>

#include "asr_robot_model/forward_kinematics.hpp"
#include "asr_robot_model/motion_model.hpp"

namespace asr_nbv {

using asr_robot_model::RobotState;

// A member a camera sees, occlusion aside: its slot among the position's nearby members (for
// the lines of sight cast from there), its index in the set and its utility.
struct NextBestViewPlanner::SeenMember {
  std::size_t index;
  std::size_t slot;
  double utility;
  bool operator<(const SeenMember& other) const { return index < other.index; }
};

// A view with something to see: where, which way, and its utility per type (sparse) by the
// first pass's bounds; the members it sees and their sum without occlusion (a tighter bound),
// the exact utility and the rating's bound once computed.
struct NextBestViewPlanner::Candidate {
  std::size_t position = 0;
  std::size_t orientation = 0;
  std::vector<std::pair<int, double>> per_type;
  double total = 0.0;
  std::vector<SeenMember> seen;    // in index order
  std::vector<double> unoccluded;  // per type
  double unoccluded_total = -1.0;  // < 0: not computed yet
  std::vector<double> exact;       // per type, occlusion included
  double exact_total = -1.0;       // < 0: not computed yet
  double bound = -1.0;             // of the rating; < 0: never chosen
};

struct NextBestViewPlanner::Step {
  bool found = false;
  PlannedView view;
};

// What the candidates of one step share while they are rated.
struct NextBestViewPlanner::StepState {
  StepState(const HypothesisGroups& grouped, const std::vector<Eigen::Vector2d>& at,
            const RobotState& from)
      : positions(at), current(from), groups(grouped) {}
  const std::vector<Eigen::Vector2d>& positions;
  const RobotState& current;
  const HypothesisGroups& groups;
  std::vector<std::vector<std::uint32_t>> nearby;  // groups
  std::vector<std::vector<Candidate>> candidates;  // per position, once expanded
  std::vector<char> expanded;                      // per position and tilt level
  // Lines of sight from a camera position (lattice point and tilt level's height) to its
  // nearby hypotheses, cast once for all the orientations rated there.
  std::vector<std::vector<signed char>> sight;
  std::size_t type_count = 0;  // types that still count
  double utility_max = 0.0;
  bool worth_moving = false;
};

namespace {

// Camera heights differ by tilt; IK must accept the heights this planner computes itself.
constexpr double kHeightTolerance = 1e-6;

// Hypotheses are grouped by type in cubes of this edge (HypothesisGroups): whole groups are
// found near a position, and skipped where none of their members can be seen (10 cm: measured
// 5-20 % faster on the benchmark than 2.5 or 5 cm, as fast as 15 or 25 cm).
constexpr double kGroupCell = 0.1;

// acos(q) rounded up to the table's resolution (never below it), for the heading windows: a
// window a little wider than needed only rates a few headings more, which the depth test
// rejects exactly.
double arcCosineUpperBound(double q) {
  constexpr int kEntries = 4096;
  static const std::vector<double> table = [] {
    std::vector<double> values(kEntries + 1);
    for (int i = 0; i <= kEntries; ++i)
      values[i] = std::acos(std::clamp(-1.0 + 2.0 * i / kEntries, -1.0, 1.0)) + 1e-9;
    return values;
  }();
  const double index = (q + 1.0) * (kEntries / 2.0);
  return table[std::clamp(static_cast<int>(index), 0, kEntries)];
}

// std::floor as a long without a library call (the heading windows' hot path).
long floorToLong(double x) {
  const long truncated = static_cast<long>(x);
  return x < static_cast<double>(truncated) ? truncated - 1 : truncated;
}

// atan2(y, x) within kAzimuthError radians (a polynomial of the octant's arc tangent, off by at
// most 2.1e-4 rad where sampled densely): the heading windows are widened by that margin, so they
// still hold every heading within the side angle, and the depth test rejects the few more.
constexpr double kAzimuthError = 1e-3;
double approximateAtan2(double y, double x) {
  const double ax = std::abs(x), ay = std::abs(y);
  const double largest = std::max(ax, ay);
  if (largest == 0.0)
    return 0.0;
  const double a = std::min(ax, ay) / largest, s = a * a;
  double angle = ((-0.0464964749 * s + 0.15931422) * s - 0.327622764) * s * a + a;
  if (ay > ax)
    angle = M_PI / 2.0 - angle;
  if (x < 0.0)
    angle = M_PI - angle;
  return y < 0.0 ? -angle : angle;
}

// Headings of a level whose axis lies within an angle (its cosine `cosine`) of a direction
// with this elevation (its sine and cosine) and azimuth: [first, first + count) modulo the
// level's headings. From cos(angle) = sin e1 sin e2 + cos e1 cos e2 cos(azimuth difference).
std::pair<long, long> headingWindow(const TiltLevel& level, double level_sine, double level_cosine,
                                    double sine, double cosine_elevation, double azimuth,
                                    double cosine) {
  const long all = static_cast<long>(level.headings);
  const double denominator = level_cosine * cosine_elevation;
  if (denominator < 1e-9)
    return {0, all};
  const double q = (cosine - level_sine * sine) / denominator;
  if (q > 1.0)
    return {0, 0};
  if (q <= -1.0)
    return {0, all};
  const double spread = (arcCosineUpperBound(q) + kAzimuthError) / level.heading_step;
  const double centre = (azimuth - level.first_heading) / level.heading_step;
  const long first = floorToLong(centre - spread);
  const long last = -floorToLong(-(centre + spread));  // the ceiling
  if (last - first + 1 >= all)
    return {0, all};
  return {first, last - first + 1};
}

}  // namespace

NextBestViewPlanner::NextBestViewPlanner(const asr_robot_model::RobotDescription& robot,
                                         const asr_robot_model::World& world,
                                         const asr_robot_model::WorldMap& map,
                                         NbvParameters parameters, asr_ism::ThreadPool* pool,
                                         unsigned seed, CandidateSearch search)
    : robot_(robot),
      kinematics_(robot, asr_robot_model::speedsOf(robot), kHeightTolerance),
      world_(world),
      map_(map),
      parameters_(std::move(parameters)),
      pool_(pool),
      orientations_(robot, parameters_.orientation_step, seed),
      orientation_bound_(parameters_.rating_angle),
      side_bound_(std::min(parameters_.frustum.fovx(), parameters_.frustum.fovy()) / 2.0),
      proximity_bound_((parameters_.frustum.far() - parameters_.frustum.near()) / 2.0),
      search_(search) {
  checkNbvParameters(parameters_);
  const asr_robot_model::Frustum& frustum = parameters_.frustum;
  const double side_angle = std::min(frustum.fovx(), frustum.fovy()) / 2.0;
  side_angle_ = side_angle;
  side_cosine_ = std::cos(side_angle);
  side_sine_ = std::sin(side_angle);
  reach_ = frustum.far() / side_cosine_;
  middle_ = (frustum.near() + frustum.far()) / 2.0;
  for (const TiltLevel& level : orientations_.levels()) {
    band_low_.push_back(std::tan(std::max(level.elevation - side_angle, -M_PI / 2 + 1e-6)));
    band_high_.push_back(std::tan(std::min(level.elevation + side_angle, M_PI / 2 - 1e-6)));
    level_sine_.push_back(std::sin(level.elevation));
    level_cosine_.push_back(std::cos(level.elevation));
    // How far the camera can be from the base's centre on the floor, over the pan range.
    for (int i = 0; i <= 64; ++i) {
      const double pan = robot.pan.lower + (robot.pan.upper - robot.pan.lower) * i / 64.0;
      camera_reach_ = std::max(
          camera_reach_,
          asr_robot_model::cameraInBase(robot, pan, level.tilt).translation().head<2>().norm());
    }
  }
  camera_reach_ += 0.01;  // the pan samples' margin
}

bool NextBestViewPlanner::groupLevels(const HypothesisGroups::Group& group,
                                      const Eigen::Vector2d& position,
                                      std::vector<char>& passing) const {
  const std::vector<TiltLevel>& levels = orientations_.levels();
  const double r = group.radius;
  const double horizontal = (group.centre.head<2>() - position).norm();
  // The members' rises and horizontal distances are within r of the centre's: each level's
  // slope band (see utilitiesAt) widened by that, and the clipping range's reach.
  const double near_run = std::max(0.0, horizontal - r), far_run = horizontal + r;
  const double closest = std::max(0.0, parameters_.frustum.near() - r), farthest = reach_ + r;
  bool any = false;
  for (std::size_t l = 0; l < levels.size(); ++l) {
    const double rise = group.centre.z() - levels[l].camera_height;
    const double low = band_low_[l], high = band_high_[l];
    const double squared = horizontal * horizontal + rise * rise;
    passing[l] = rise + r > (low >= 0.0 ? near_run * low : far_run * low) &&
                 rise - r < (high >= 0.0 ? far_run * high : near_run * high) &&
                 (closest == 0.0 || squared > closest * closest) && squared < farthest * farthest;
    any = any || passing[l];
  }
  return any;
}

void NextBestViewPlanner::utilitiesAt(const HypothesisSet& hypotheses,
                                      const HypothesisGroups& groups,
                                      const std::vector<std::uint32_t>& nearby,
                                      const Eigen::Vector2d& position, std::size_t position_index,
                                      const std::vector<char>& wanted,
                                      std::vector<Candidate>& candidates) const {
  const double near = parameters_.frustum.near();
  const std::size_t type_count = hypotheses.types().size();
  const std::vector<TiltLevel>& levels = orientations_.levels();
  thread_local std::vector<double> utility;  // orientation x type
  thread_local std::vector<char> touched;
  std::vector<char> passing(levels.size());
  // The wanted levels' orientations (each level's are consecutive).
  std::size_t first = orientations_.size(), end = 0;
  for (std::size_t l = 0; l < levels.size(); ++l) {
    if (wanted[l]) {
      first = std::min(first, levels[l].first_orientation);
      end = std::max(end, levels[l].first_orientation + levels[l].headings);
    }
  }
  // Only they are written and read: only they are cleared.
  utility.resize(orientations_.size() * type_count);
  touched.resize(orientations_.size());
  if (first < end) {
    std::fill(utility.begin() + static_cast<long>(first * type_count),
              utility.begin() + static_cast<long>(end * type_count), 0.0);
    std::fill(touched.begin() + static_cast<long>(first), touched.begin() + static_cast<long>(end),
              0);
  }
  for (std::uint32_t g : nearby) {
    const HypothesisGroups::Group& group = groups.groups()[g];
    // Levels none of the group's members can be seen from are skipped for all of them.
    if (!groupLevels(group, position, passing))
      continue;
    bool any = false;
    for (std::size_t l = 0; l < levels.size(); ++l) {
      passing[l] = passing[l] && wanted[l];
      any = any || passing[l];
    }
    if (!any)
      continue;
    double* const row = utility.data() + group.type;
    for (std::uint32_t m = group.begin; m < group.end; ++m) {
      const Eigen::Vector3d& point = groups.point(m);
      const Eigen::Vector2d across = point.head<2>() - position;
      const double horizontal_squared = across.squaredNorm();
      const double horizontal = std::sqrt(horizontal_squared);
      double azimuth = std::numeric_limits<double>::quiet_NaN();  // when a level needs it
      for (std::size_t l = 0; l < levels.size(); ++l) {
        if (!passing[l])
          continue;
        const TiltLevel& level = levels[l];
        // Only levels whose axis elevation lies within the side angle of the hypothesis' can
        // see it: a slope test, no arc function.
        const double rise = point.z() - level.camera_height;
        if (rise <= horizontal * band_low_[l] || rise >= horizontal * band_high_[l])
          continue;
        const Eigen::Vector3d offset(across.x(), across.y(), rise);
        const double distance = std::sqrt(horizontal_squared + rise * rise);
        if (distance <= near || distance >= reach_)
          continue;
        const double inverse_distance = 1.0 / distance;
        const double orientation = orientationBound(groups, m, -inverse_distance * offset);
        if (orientation == 0.0)
          continue;
        if (std::isnan(azimuth))
          azimuth = approximateAtan2(across.y(), across.x());
        const auto [first, count] =
            headingWindow(level, level_sine_[l], level_cosine_[l], rise * inverse_distance,
                          horizontal * inverse_distance, azimuth, side_cosine_);
        const long headings = static_cast<long>(level.headings);
        long h = first;  // within a few turns of the circle: no division needed
        while (h < 0)
          h += headings;
        while (h >= headings)
          h -= headings;
        for (long k = 0; k < count; ++k, h = (h + 1 == headings) ? 0 : h + 1) {
          const std::size_t o = level.first_orientation + static_cast<std::size_t>(h);
          // Bounds of sideProximity's terms, as the orientation's above.
          const double depth = orientations_.axis(o).dot(offset);
          if (depth <= side_cosine_ * distance)
            continue;
          const double terms = proximity_bound_.ofDistance(std::abs(depth - middle_)) *
                               side_bound_.ofCosine(depth * inverse_distance);
          if (terms > 0.0) {
            row[o * type_count] += orientation * terms;
            touched[o] = 1;
          }
        }
      }
    }
  }
  for (std::size_t o = first; o < end; ++o) {
    if (!touched[o])
      continue;
    Candidate candidate;
    candidate.position = position_index;
    candidate.orientation = o;
    for (std::size_t t = 0; t < type_count; ++t) {
      const double u = utility[o * type_count + t];
      if (u > 0.0) {
        candidate.per_type.emplace_back(static_cast<int>(t), u);
        candidate.total += u;
      }
    }
    candidates.push_back(std::move(candidate));
  }
}

asr_common::Pose NextBestViewPlanner::cameraOf(
    const Candidate& candidate, const std::vector<Eigen::Vector2d>& positions) const {
  const TiltLevel& level = orientations_.levels()[orientations_.levelOf(candidate.orientation)];
  const Eigen::Vector2d& xy = positions[candidate.position];
  asr_common::Pose camera;
  camera.position = Eigen::Vector3d(xy.x(), xy.y(), level.camera_height);
  camera.orientation = Eigen::Quaterniond(orientations_.rotation(candidate.orientation));
  return camera;
}

void NextBestViewPlanner::visibleMembers(const HypothesisSet& hypotheses,
                                         const HypothesisGroups& groups,
                                         const std::vector<std::uint32_t>& nearby,
                                         const asr_common::Pose& camera,
                                         std::vector<SeenMember>& seen) const {
  const Eigen::Vector3d axis = camera.orientation * Eigen::Vector3d::UnitZ();
  const asr_robot_model::Frustum& frustum = parameters_.frustum;
  seen.clear();
  std::size_t slot = 0;  // of the group's first member among the nearby groups' members
  for (std::uint32_t g : nearby) {
    const HypothesisGroups::Group& group = groups.groups()[g];
    const std::size_t first_slot = slot;
    slot += group.end - group.begin;
    // A group whose members all lie outside the side angle or the clipping range is skipped.
    const Eigen::Vector3d offset = group.centre - camera.position;
    const double depth = axis.dot(offset), distance = offset.norm();
    const double r = group.radius;
    if (depth + r <= frustum.near() || depth - r >= frustum.far())
      continue;
    if (distance > r) {
      const double x = r / distance;
      if (depth <
          distance * (side_cosine_ * std::sqrt(1.0 - x * x) - side_sine_ * x) - 1e-9 * distance)
        continue;
    }
    for (std::uint32_t m = group.begin; m < group.end; ++m) {
      const std::size_t index = groups.memberIndex(m);
      const double u = hypothesisUtility(camera, hypotheses.hypotheses()[index], parameters_);
      if (u > 0.0)
        seen.push_back({index, first_slot + (m - group.begin), u});
    }
  }
  // Summed in index order, as without groups.
  std::sort(seen.begin(), seen.end());
}

void NextBestViewPlanner::positionBound(const HypothesisSet& hypotheses,
                                        const HypothesisGroups& groups,
                                        const std::vector<std::uint32_t>& nearby,
                                        const Eigen::Vector2d& position,
                                        std::vector<double>& per_level_type) const {
  // Covers the rounding of the sums (the tables' margins cover that of the terms).
  constexpr double kMargin = 1.0 + 1e-6;
  // Covers the rounding of the cosine of the elevation difference.
  constexpr double kCosineMargin = 1e-9;
  const double near = parameters_.frustum.near();
  const std::size_t type_count = hypotheses.types().size();
  const std::vector<TiltLevel>& levels = orientations_.levels();
  std::vector<char> passing(levels.size());
  per_level_type.assign(levels.size() * type_count, 0.0);
  for (std::uint32_t g : nearby) {
    const HypothesisGroups::Group& group = groups.groups()[g];
    if (!groupLevels(group, position, passing))
      continue;
    double* const row = per_level_type.data() + group.type;
    for (std::uint32_t m = group.begin; m < group.end; ++m) {
      const Eigen::Vector3d& point = groups.point(m);
      const Eigen::Vector2d across = point.head<2>() - position;
      const double horizontal_squared = across.squaredNorm();
      const double horizontal = std::sqrt(horizontal_squared);
      for (std::size_t l = 0; l < levels.size(); ++l) {
        if (!passing[l])
          continue;
        // As in utilitiesAt: the levels that can see the hypothesis at all.
        const double rise = point.z() - levels[l].camera_height;
        if (rise <= horizontal * band_low_[l] || rise >= horizontal * band_high_[l])
          continue;
        const double distance = std::sqrt(horizontal_squared + rise * rise);
        if (distance <= near || distance >= reach_)
          continue;
        // Every axis of the level is at least the elevation difference away from the
        // hypothesis, whatever its heading: that bounds the side term, and the depth
        // (distance x the cosine of that angle) from above.
        const double inverse_distance = 1.0 / distance;
        const double cosine = std::min(
            1.0, (level_cosine_[l] * horizontal + level_sine_[l] * rise) * inverse_distance +
                     kCosineMargin);
        const double low = side_cosine_ * distance, high = cosine * distance;
        const double gap = middle_ < low ? low - middle_ : std::max(0.0, middle_ - high);
        const double terms =
            side_bound_.ofCosine(cosine) * proximity_bound_.ofDistance(std::max(0.0, gap - 1e-9));
        if (terms > 0.0)
          row[l * type_count] +=
              kMargin *
              orientationBound(groups, m,
                               -inverse_distance * Eigen::Vector3d(across.x(), across.y(), rise)) *
              terms;
      }
    }
  }
}

namespace {

// Level l's bounds per type in a level x type table.
std::vector<double> levelSlice(const std::vector<double>& table, std::size_t l, std::size_t types) {
  return {table.begin() + static_cast<long>(l * types),
          table.begin() + static_cast<long>((l + 1) * types)};
}
double levelTotal(const std::vector<double>& table, std::size_t l, std::size_t types) {
  return std::accumulate(table.begin() + static_cast<long>(l * types),
                         table.begin() + static_cast<long>((l + 1) * types), 0.0);
}

// Indices of `values` >= 0 in falling order of value, ties in index order.
std::vector<std::size_t> fallingOrder(const std::vector<double>& values) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < values.size(); ++i)
    if (values[i] >= 0.0)
      order.push_back(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return values[a] > values[b]; });
  return order;
}

}  // namespace

// A candidate waiting to be rated, in the order of the exhaustive search over bounds: falling
// bound, then position, then its index at the position.
// `key`: the candidate's orientation, or kLevelKey + l for a tilt level not yet expanded (so
// the order does not depend on the order candidates were found in); `index`: the candidate's
// among its position's.
constexpr std::size_t kLevelKey = std::numeric_limits<std::size_t>::max() / 2;
struct NextBestViewPlanner::Queued {
  double bound;
  std::size_t position, key, index;
  bool operator<(const Queued& other) const {  // "rated after" for std::priority_queue
    if (bound != other.bound)
      return bound < other.bound;
    return std::tie(position, key) > std::tie(other.position, other.key);
  }
  bool isLevel() const { return key >= kLevelKey; }
  std::size_t level() const { return key - kLevelKey; }
};

NextBestViewPlanner::Step NextBestViewPlanner::rateStep(
    const HypothesisSet& hypotheses, const HypothesisGroups& groups,
    const std::vector<Eigen::Vector2d>& positions, const RobotState& current) const {
  if (search_ == CandidateSearch::exhaustive)
    return rateStepExhaustively(hypotheses, groups, positions, current);
  StepState state = startStep(hypotheses, groups, positions, current);
  // Branch and bound over the positions: a bound per position and type first (cheap, one term
  // per hypothesis), then the first pass (every orientation) only where the bound can still win.
  const std::vector<std::vector<double>> level_bound =
      positionBounds(hypotheses, groups, state, positions);
  findUtilityMax(hypotheses, state, level_bound);
  Step step;
  if (state.utility_max <= 0.0)
    return step;
  state.worth_moving = state.utility_max > parameters_.min_utility_for_moving;
  rateBestFirst(hypotheses, state, positions, level_bound, step);
  return step;
}

std::vector<std::vector<double>> NextBestViewPlanner::positionBounds(
    const HypothesisSet& hypotheses, const HypothesisGroups& groups, const StepState& state,
    const std::vector<Eigen::Vector2d>& positions) const {
  std::vector<std::vector<double>> level_bound(positions.size());
  forEachPosition(positions.size(), [&](std::size_t p) {
    if (!state.nearby[p].empty())
      positionBound(hypotheses, groups, state.nearby[p], positions[p], level_bound[p]);
  });
  return level_bound;
}

void NextBestViewPlanner::findUtilityMax(
    const HypothesisSet& hypotheses, StepState& state,
    const std::vector<std::vector<double>>& level_bound) const {
  // Occlusion only lowers utilities, so the first pass bounds them: best first, positions (by
  // their bound) and their candidates (by the first pass's, then without occlusion) from one
  // queue, until no bound exceeds the largest exact utility found; lines of sight are cast only
  // for the candidates taken from it. The best few entries are worked on at a time, in parallel:
  // the maximum does not depend on the order, so neither does the answer.
  const std::size_t count = level_bound.size();
  const std::size_t levels = orientations_.levels().size(), types = hypotheses.types().size();
  double& utility_max = state.utility_max;
  std::priority_queue<Queued> best_first;
  for (std::size_t p = 0; p < count; ++p)
    for (std::size_t l = 0; !state.nearby[p].empty() && l < levels; ++l)
      if (const double total = levelTotal(level_bound[p], l, types); total > 0.0)
        best_first.push({total, p, kLevelKey + l, 0});
  // Candidates cost several positions' first pass each: fewer of them per batch.
  const std::size_t most_candidates = pool_ != nullptr ? pool_->threadCount() : 1;
  std::vector<Queued> batch;
  std::vector<char> exact;  // per entry of the batch: a candidate's exact utility is wanted
  while (!best_first.empty() && best_first.top().bound > utility_max) {
    batch.clear();
    std::size_t candidates = 0;
    while (batch.size() < batchSize() && candidates < most_candidates && !best_first.empty() &&
           best_first.top().bound > utility_max) {
      candidates += best_first.top().isLevel() ? 0 : 1;
      batch.push_back(best_first.top());
      best_first.pop();
    }
    // A candidate taken for the first time gets its utility without occlusion (no line of
    // sight cast) and waits again by it; taken again, its exact utility, unless the lines of
    // sight show that it cannot exceed the maximum (it is then dropped).
    exact.clear();
    for (const Queued& item : batch)
      exact.push_back(!item.isLevel() &&
                      state.candidates[item.position][item.index].unoccluded_total >= 0.0);
    work(hypotheses, state, batch, utility_max, false);
    for (const Queued& item : batch)
      if (!item.isLevel())
        utility_max =
            std::max(utility_max, state.candidates[item.position][item.index].exact_total);
    for (std::size_t i = 0; i < batch.size(); ++i) {
      const Queued& item = batch[i];
      if (!item.isLevel()) {
        const Candidate& candidate = state.candidates[item.position][item.index];
        if (!exact[i] && candidate.unoccluded_total > utility_max)
          best_first.push({candidate.unoccluded_total, item.position, item.key, item.index});
        continue;
      }
      for (std::size_t k = 0; k < state.candidates[item.position].size(); ++k) {
        const Candidate& candidate = state.candidates[item.position][k];
        if (orientations_.levelOf(candidate.orientation) == item.level() &&
            candidate.total > utility_max)
          best_first.push({candidate.total, item.position, candidate.orientation, k});
      }
    }
  }
}

void NextBestViewPlanner::rateBestFirst(const HypothesisSet& hypotheses, StepState& state,
                                        const std::vector<Eigen::Vector2d>& positions,
                                        const std::vector<std::vector<double>>& level_bound,
                                        Step& step) const {
  // Candidates in falling order of their bound (motion free, no occlusion) until none can beat
  // the best; a position's bound (its types' bounds) is at least its candidates', so a position
  // is expanded only once its bound reaches the best candidate waiting.
  const std::size_t count = positions.size();
  const std::size_t levels = orientations_.levels().size(), types = hypotheses.types().size();
  std::vector<double> level_rating(count * levels, -1.0);  // position x level
  forEachPosition(count, [&](std::size_t p) {
    for (std::size_t l = 0; l < levels && !state.nearby[p].empty(); ++l) {
      const double total = levelTotal(level_bound[p], l, types);
      if (total > 0.0 && !(state.worth_moving && total <= parameters_.min_utility_for_moving))
        level_rating[p * levels + l] =
            ratingBound(bestTypeSubset(levelSlice(level_bound[p], l, types), state.utility_max,
                                       state.type_count, parameters_.weights),
                        positions[p], state);
    }
  });
  const std::vector<std::size_t> by_rating = fallingOrder(level_rating);
  std::priority_queue<Queued> queue;
  std::vector<Queued> batch;
  double best_rating = -1.0;
  std::size_t next = 0;
  for (;;) {
    auto wanted = [&](std::size_t i) {
      return level_rating[i] > best_rating &&
             (queue.empty() || level_rating[i] >= queue.top().bound);
    };
    while (next < by_rating.size() && wanted(by_rating[next])) {
      batch.clear();
      for (; next < by_rating.size() && batch.size() < batchSize() && wanted(by_rating[next]);
           ++next)
        batch.push_back({0.0, by_rating[next] / levels, kLevelKey + by_rating[next] % levels, 0});
      work(hypotheses, state, batch, -std::numeric_limits<double>::infinity(), true);
      for (const Queued& item : batch)
        for (std::size_t k = 0; k < state.candidates[item.position].size(); ++k) {
          const Candidate& candidate = state.candidates[item.position][k];
          if (orientations_.levelOf(candidate.orientation) == item.level() &&
              candidate.bound >= 0.0)
            queue.push({candidate.bound, item.position, candidate.orientation, k});
        }
    }
    if (queue.empty() || queue.top().bound <= best_rating)
      return;
    const Queued top = queue.top();
    queue.pop();
    rateCandidate(hypotheses, state, state.candidates[top.position][top.index], true, best_rating,
                  step);
  }
}

NextBestViewPlanner::Step NextBestViewPlanner::rateStepExhaustively(
    const HypothesisSet& hypotheses, const HypothesisGroups& groups,
    const std::vector<Eigen::Vector2d>& positions, const RobotState& current) const {
  StepState state = startStep(hypotheses, groups, positions, current);
  for (std::size_t p = 0; p < positions.size(); ++p) {
    for (std::size_t o = 0; o < orientations_.size(); ++o) {
      Candidate candidate;
      candidate.position = p;
      candidate.orientation = o;
      state.utility_max = std::max(state.utility_max, exactUtility(hypotheses, state, candidate));
      state.candidates[p].push_back(std::move(candidate));
    }
  }
  Step step;
  if (state.utility_max <= 0.0)
    return step;
  state.worth_moving = state.utility_max > parameters_.min_utility_for_moving;
  double best_rating = -1.0;
  for (auto& at_position : state.candidates)
    for (Candidate& candidate : at_position)
      rateCandidate(hypotheses, state, candidate, false, best_rating, step);
  return step;
}

NextBestViewPlanner::StepState NextBestViewPlanner::startStep(
    const HypothesisSet& hypotheses, const HypothesisGroups& groups,
    const std::vector<Eigen::Vector2d>& positions, const RobotState& current) const {
  StepState state(groups, positions, current);
  state.type_count = hypotheses.countingTypes();
  state.nearby.resize(positions.size());
  forEachPosition(positions.size(),
                  [&](std::size_t p) { state.nearby[p] = groups.near(positions[p]); });
  state.candidates.resize(positions.size());
  state.expanded.assign(positions.size() * orientations_.levels().size(), 0);
  state.sight.resize(positions.size() * orientations_.levels().size());
  return state;
}

void NextBestViewPlanner::forEachPosition(std::size_t count,
                                          const std::function<void(std::size_t)>& task) const {
  if (pool_ != nullptr)
    pool_->parallelFor(count, task);
  else
    for (std::size_t i = 0; i < count; ++i)
      task(i);
}

std::size_t NextBestViewPlanner::batchSize() const {
  return pool_ != nullptr ? 4 * pool_->threadCount() : 1;
}

void NextBestViewPlanner::work(const HypothesisSet& hypotheses, StepState& state,
                               const std::vector<Queued>& batch, double floor,
                               bool bound_candidates) const {
  const std::size_t levels = orientations_.levels().size();
  std::vector<std::size_t> at;                       // the positions, each once
  std::vector<std::vector<char>> masks;              // their levels to expand
  std::vector<std::vector<std::size_t>> candidates;  // their candidates to evaluate
  for (const Queued& item : batch) {
    const std::size_t p = item.position;
    const std::size_t i = std::find(at.begin(), at.end(), p) - at.begin();
    if (i == at.size()) {
      at.push_back(p);
      masks.emplace_back(levels, 0);
      candidates.emplace_back();
    }
    if (item.isLevel()) {
      masks[i][item.level()] = !state.expanded[p * levels + item.level()];
      state.expanded[p * levels + item.level()] = 1;
    } else {
      candidates[i].push_back(item.index);
    }
  }
  // One task per position: a position's candidates and lines of sight are its task's alone.
  forEachPosition(at.size(), [&](std::size_t i) {
    for (std::size_t k : candidates[i]) {
      Candidate& candidate = state.candidates[at[i]][k];
      if (candidate.unoccluded_total < 0.0)
        unoccludedUtility(hypotheses, state, candidate);
      else
        exactUtility(hypotheses, state, candidate, floor);
    }
    // Expanded after (the candidates are held by reference, the expansion appends).
    if (std::find(masks[i].begin(), masks[i].end(), 1) != masks[i].end())
      utilitiesAt(hypotheses, state.groups, state.nearby[at[i]], state.positions[at[i]], at[i],
                  masks[i], state.candidates[at[i]]);
    if (bound_candidates)
      boundCandidates(hypotheses, state, at[i]);
  });
}

double NextBestViewPlanner::unoccludedUtility(const HypothesisSet& hypotheses, StepState& state,
                                              Candidate& candidate) const {
  if (candidate.unoccluded_total < 0.0) {
    visibleMembers(hypotheses, state.groups, state.nearby[candidate.position],
                   cameraOf(candidate, state.positions), candidate.seen);
    // Summed as the exact utility is (per type, then over types), so that it is never below it.
    std::vector<double>& per_type = candidate.unoccluded;
    per_type.assign(hypotheses.types().size(), 0.0);
    for (const SeenMember& member : candidate.seen)
      per_type[hypotheses.hypotheses()[member.index].type] += member.utility;
    candidate.unoccluded_total = std::accumulate(per_type.begin(), per_type.end(), 0.0);
  }
  return candidate.unoccluded_total;
}

double NextBestViewPlanner::exactUtility(const HypothesisSet& hypotheses, StepState& state,
                                         Candidate& candidate, double floor) const {
  // Covers the rounding of the sums: given up only where the exact utility is surely <= floor.
  constexpr double kSlack = 1e-9;
  if (candidate.exact_total < 0.0) {
    unoccludedUtility(hypotheses, state, candidate);
    const std::size_t level = orientations_.levelOf(candidate.orientation);
    std::vector<signed char>& sight =
        state.sight[candidate.position * orientations_.levels().size() + level];
    if (sight.empty()) {
      std::size_t members = 0;
      for (std::uint32_t g : state.nearby[candidate.position])
        members += state.groups.groups()[g].end - state.groups.groups()[g].begin;
      sight.assign(members, -1);
    }
    const Eigen::Vector3d eye = cameraOf(candidate, state.positions).position;
    candidate.exact.assign(hypotheses.types().size(), 0.0);
    const double give_up = floor - kSlack * candidate.unoccluded_total;
    double occluded = 0.0;
    for (const SeenMember& member : candidate.seen) {
      const Hypothesis& hypothesis = hypotheses.hypotheses()[member.index];
      signed char& free = sight[member.slot];
      if (free < 0)
        free = map_.lineOfSight(eye, hypothesis.box) ? 1 : 0;
      if (free == 1) {
        candidate.exact[hypothesis.type] += member.utility;
      } else {
        occluded += member.utility;
        if (candidate.unoccluded_total - occluded <= give_up)
          return -1.0;  // the lines of sight cast so far stay cast
      }
    }
    candidate.exact_total = std::accumulate(candidate.exact.begin(), candidate.exact.end(), 0.0);
  }
  return candidate.exact_total;
}

double NextBestViewPlanner::ratingBound(const TypeChoice& choice, const Eigen::Vector2d& camera,
                                        const StepState& state) const {
  // The base must carry the camera at least this far: the rating's base term is bounded.
  const Eigen::Vector2d base(state.current.x, state.current.y);
  const double sigma = parameters_.base_distance_sigma;
  InverseCosts best_motion;
  const double drive = std::max(0.0, (camera - base).norm() - camera_reach_);
  best_motion.base = std::exp(-drive * drive / (2.0 * sigma * sigma));
  best_motion.recognition =
      1.0 - static_cast<double>(choice.types.size()) / static_cast<double>(state.type_count);
  return rating(choice.utility, state.utility_max, best_motion, parameters_.weights);
}

void NextBestViewPlanner::boundCandidates(const HypothesisSet& hypotheses, StepState& state,
                                          std::size_t position) const {
  std::vector<double> dense(hypotheses.types().size());
  for (Candidate& candidate : state.candidates[position]) {
    if (candidate.bound >= 0.0 ||
        (state.worth_moving && candidate.total <= parameters_.min_utility_for_moving))
      continue;
    std::fill(dense.begin(), dense.end(), 0.0);
    for (const auto& [type, u] : candidate.per_type)
      dense[type] = u;
    candidate.bound =
        ratingBound(bestTypeSubset(dense, state.utility_max, state.type_count, parameters_.weights),
                    state.positions[position], state);
  }
}

void NextBestViewPlanner::rateCandidate(const HypothesisSet& hypotheses, StepState& state,
                                        Candidate& candidate, bool prune, double& best_rating,
                                        Step& step) const {
  // Covers the rounding of the sums (a bound's types may be summed in another order).
  constexpr double kMargin = 1.0 + 1e-9;
  auto cannot_count = [&](double utility) {
    return utility <= 0.0 || (state.worth_moving && utility <= parameters_.min_utility_for_moving);
  };
  if (prune && candidate.exact_total < 0.0) {
    // Without occlusion first: no line of sight is cast for a view that cannot win anyway.
    if (cannot_count(unoccludedUtility(hypotheses, state, candidate) * kMargin))
      return;
    const TypeChoice bound = bestTypeSubset(candidate.unoccluded, state.utility_max,
                                            state.type_count, parameters_.weights);
    if (ratingBound(bound, state.positions[candidate.position], state) * kMargin <= best_rating)
      return;
  }
  const double total = exactUtility(hypotheses, state, candidate);
  if (cannot_count(total))
    return;
  const TypeChoice choice =
      bestTypeSubset(candidate.exact, state.utility_max, state.type_count, parameters_.weights);
  if (prune && ratingBound(choice, state.positions[candidate.position], state) <= best_rating)
    return;
  const asr_common::Pose camera = cameraOf(candidate, state.positions);
  const asr_robot_model::BaseIsFree base_is_free = [this](double x, double y, double) {
    return map_.baseIsFree(x, y);
  };
  const asr_robot_model::IkResult ik =
      kinematics_.solve(camera.position, camera.orientation, state.current, base_is_free);
  if (!ik.reachable)
    return;
  const asr_robot_model::Motion motion =
      asr_robot_model::motionBetween(state.current, ik.state, kinematics_.speeds());
  const InverseCosts costs = inverseCosts(motion, state.current, ik.state, robot_,
                                          choice.types.size(), state.type_count, parameters_);
  const double value = rating(choice.utility, state.utility_max, costs, parameters_.weights);
  step.view.rated.push_back({ik.camera, value});
  if (value <= best_rating)
    return;
  best_rating = value;
  PlannedView& view = step.view;
  view.found = step.found = true;
  view.camera = ik.camera;
  view.state = ik.state;
  view.types.clear();
  for (int type : choice.types)
    view.types.push_back(hypotheses.types()[type]);
  view.utility = choice.utility;
  view.utility_max = state.utility_max;
  view.rating = value;
  view.costs = costs;
  view.motion_seconds = motion.seconds;
}

PositionBounds NextBestViewPlanner::boundsAt(const HypothesisSet& hypotheses,
                                             const Eigen::Vector2d& position) const {
  const std::vector<Eigen::Vector2d> positions{position};
  const HypothesisGroups groups(hypotheses, kGroupCell, reach_);
  StepState state = startStep(hypotheses, groups, positions, RobotState{});
  PositionBounds bounds;
  std::vector<double> level_bound;
  positionBound(hypotheses, groups, state.nearby[0], position, level_bound);
  const std::size_t types = hypotheses.types().size();
  bounds.position.assign(types, 0.0);
  for (std::size_t l = 0; l < orientations_.levels().size(); ++l) {
    bounds.level.push_back(levelSlice(level_bound, l, types));
    for (std::size_t t = 0; t < types; ++t)
      bounds.position[t] = std::max(bounds.position[t], bounds.level[l][t]);
  }
  utilitiesAt(hypotheses, groups, state.nearby[0], position, 0,
              std::vector<char>(orientations_.levels().size(), 1), state.candidates[0]);
  bounds.orientation.assign(orientations_.size(),
                            std::vector<double>(hypotheses.types().size(), 0.0));
  for (const Candidate& candidate : state.candidates[0])
    for (const auto& [type, u] : candidate.per_type)
      bounds.orientation[candidate.orientation][type] = u;
  for (std::size_t o = 0; o < orientations_.size(); ++o) {
    Candidate candidate;
    candidate.orientation = o;
    unoccludedUtility(hypotheses, state, candidate);
    bounds.unoccluded.push_back(candidate.unoccluded);
  }
  return bounds;
}

bool NextBestViewPlanner::reachable(const Eigen::Vector2d& camera) const {
  constexpr int kSamples = 16;
  if (map_.baseIsFree(camera.x(), camera.y()))
    return true;
  for (int i = 0; i < kSamples; ++i) {
    const double angle = 2.0 * M_PI * i / kSamples;
    if (map_.baseIsFree(camera.x() + camera_reach_ * std::cos(angle),
                        camera.y() + camera_reach_ * std::sin(angle)))
      return true;
  }
  return false;
}

PlannedView NextBestViewPlanner::plan(const HypothesisSet& hypotheses,
                                      const RobotState& current) const {
  asr_robot_model::checkFinite(current, "current robot state");
  PlannedView result;
  if (hypotheses.countingHypotheses() == 0)
    return result;
  const Eigen::Vector2d low = world_.room_min, high = world_.room_max;
  Eigen::Vector2d centre = asr_robot_model::cameraPose(robot_, current).position.head<2>();
  double reach = (high - low).norm();
  double scale = 1.0, previous_rating = 0.0;
  std::size_t rated = 0;
  std::vector<RatedCandidate> rated_views;
  const HypothesisGroups groups(hypotheses, kGroupCell, reach_);
  for (int k = 0; k < parameters_.max_steps; ++k) {
    const double radius = std::pow(scale, 0.382) * parameters_.lattice_radius;
    std::vector<Eigen::Vector2d> positions = hexagonalLattice(centre, radius, reach, low, high);
    // Like the original's costmap: drop positions the base cannot carry the camera to (the
    // lattice's centre, where the camera is or was chosen, stays).
    positions.erase(std::remove_if(positions.begin() + 1, positions.end(),
                                   [this](const Eigen::Vector2d& xy) { return !reachable(xy); }),
                    positions.end());
    rated += positions.size() * orientations_.size();
    Step step = rateStep(hypotheses, groups, positions, current);
    if (!step.found)
      break;
    rated_views.insert(rated_views.end(), step.view.rated.begin(), step.view.rated.end());
    result = step.view;
    result.steps = static_cast<std::size_t>(k) + 1;
    if (k > 0 && std::abs(step.view.rating - previous_rating) <= parameters_.rating_epsilon)
      break;
    previous_rating = step.view.rating;
    centre = step.view.camera.position.head<2>();
    // The next lattice, finer, covers the neighbourhood of this step's spacing.
    reach = 2.0 * 2.0 * radius * std::cos(M_PI / 6.0);
    scale /= 2.0;
  }
  result.candidates_rated = rated;
  result.rated = std::move(rated_views);
  return result;
}

RatedViews NextBestViewPlanner::rateViews(const HypothesisSet& hypotheses,
                                          const std::vector<VisitedView>& views,
                                          const RobotState& current) const {
  asr_robot_model::checkFinite(current, "current robot state");
  std::vector<ViewUtility> utilities;
  RatedViews rated;
  for (std::size_t v = 0; v < views.size(); ++v) {
    const asr_common::Pose& camera = views[v].camera;
    asr_common::validatedPose(camera.position, camera.orientation,
                              "view " + std::to_string(v) + " camera");
    utilities.push_back(viewUtility(camera, hypotheses, parameters_, &map_));
    rated.utility_max = std::max(rated.utility_max, utilities.back().total);
  }
  const std::size_t type_count = hypotheses.countingTypes();
  const asr_robot_model::BaseIsFree base_is_free = [this](double x, double y, double) {
    return map_.baseIsFree(x, y);
  };
  for (std::size_t v = 0; v < views.size(); ++v) {
    const VisitedView& given = views[v];
    RatedView view;
    if (given.types.empty()) {
      const TypeChoice choice =
          bestTypeSubset(utilities[v].per_type, rated.utility_max, type_count, parameters_.weights);
      for (int type : choice.types)
        view.types.push_back(hypotheses.types()[type]);
      view.utility = choice.utility;
    } else {
      view.types = given.types;
      for (const std::string& name : given.types) {
        const int type = hypotheses.typeIndex(name);
        view.utility += type >= 0 ? utilities[v].per_type[type] : 0.0;
      }
    }
    const asr_robot_model::IkResult ik =
        kinematics_.solve(given.camera.position, given.camera.orientation, current, base_is_free);
    view.reachable = ik.reachable;
    view.refusal = ik.explanation;
    view.camera = ik.reachable ? ik.camera : given.camera;
    if (ik.reachable) {
      const asr_robot_model::Motion motion =
          asr_robot_model::motionBetween(current, ik.state, kinematics_.speeds());
      view.state = ik.state;
      view.costs = inverseCosts(motion, current, ik.state, robot_, view.types.size(),
                                std::max(type_count, view.types.size()), parameters_);
      view.motion_seconds = motion.seconds;
      view.rating = rating(view.utility, rated.utility_max, view.costs, parameters_.weights);
    }
    rated.views.push_back(std::move(view));
  }
  return rated;
}

}  // namespace asr_nbv
