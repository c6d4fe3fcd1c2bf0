#include "asr_nbv/next_best_view_planner.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

#include "asr_robot_model/forward_kinematics.hpp"
#include "asr_robot_model/motion_model.hpp"

namespace asr_nbv {

using asr_robot_model::RobotState;

// A view with something to see: where, which way, and its utility per type (sparse).
struct NextBestViewPlanner::Candidate {
  std::size_t position = 0;
  std::size_t orientation = 0;
  std::vector<std::pair<int, double>> per_type;
  double total = 0.0;
};

struct NextBestViewPlanner::Step {
  bool found = false;
  PlannedView view;
};

namespace {

// Camera heights differ by tilt; IK must accept the heights this planner computes itself.
constexpr double kHeightTolerance = 1e-6;

// Counting hypotheses bucketed by floor cells of the far plane's size, so the ones a position
// can see are found in the 3 x 3 cells around it.
class HypothesisGrid {
 public:
  HypothesisGrid(const HypothesisSet& hypotheses, double cell) : cell_(cell) {
    const auto& all = hypotheses.hypotheses();
    for (std::size_t i = 0; i < all.size(); ++i) {
      if (all[i].counts())
        cells_[keyOf(all[i].box.pose.position.head<2>())].push_back(i);
    }
  }

  // Counting hypotheses within `reach` of `point` on the floor, in index order.
  std::vector<std::size_t> near(const HypothesisSet& hypotheses, const Eigen::Vector2d& point,
                                double reach) const {
    std::vector<std::size_t> found;
    const auto [cx, cy] = keyOf(point);
    for (long dx = -1; dx <= 1; ++dx) {
      for (long dy = -1; dy <= 1; ++dy) {
        const auto cell = cells_.find({cx + dx, cy + dy});
        if (cell == cells_.end())
          continue;
        for (std::size_t i : cell->second) {
          if ((hypotheses.hypotheses()[i].box.pose.position.head<2>() - point).norm() <= reach)
            found.push_back(i);
        }
      }
    }
    std::sort(found.begin(), found.end());
    return found;
  }

 private:
  std::pair<long, long> keyOf(const Eigen::Vector2d& point) const {
    return {static_cast<long>(std::floor(point.x() / cell_)),
            static_cast<long>(std::floor(point.y() / cell_))};
  }
  double cell_;
  std::map<std::pair<long, long>, std::vector<std::size_t>> cells_;
};

// Headings of a level whose axis lies within `angle` of a direction with this elevation and
// azimuth: [first, first + count) modulo the level's headings.
std::pair<long, long> headingWindow(const TiltLevel& level, double elevation, double azimuth,
                                    double angle) {
  const long all = static_cast<long>(level.headings);
  const double denominator = std::cos(level.elevation) * std::cos(elevation);
  if (denominator < 1e-9)
    return {0, all};
  const double q =
      (std::cos(angle) - std::sin(level.elevation) * std::sin(elevation)) / denominator;
  if (q > 1.0)
    return {0, 0};
  if (q <= -1.0)
    return {0, all};
  const double spread = std::acos(q) / level.heading_step;
  const double centre = (azimuth - level.first_heading) / level.heading_step;
  const long first = static_cast<long>(std::floor(centre - spread));
  const long last = static_cast<long>(std::ceil(centre + spread));
  if (last - first + 1 >= all)
    return {0, all};
  return {first, last - first + 1};
}

}  // namespace

NextBestViewPlanner::NextBestViewPlanner(const asr_robot_model::RobotDescription& robot,
                                         const asr_robot_model::World& world,
                                         const asr_robot_model::WorldMap& map,
                                         NbvParameters parameters, asr_ism::ThreadPool* pool,
                                         unsigned seed)
    : robot_(robot),
      kinematics_(robot, asr_robot_model::speedsOf(robot), kHeightTolerance),
      world_(world),
      map_(map),
      parameters_(std::move(parameters)),
      pool_(pool),
      orientations_(robot, parameters_.orientation_step, seed) {
  checkNbvParameters(parameters_);
}

void NextBestViewPlanner::utilitiesAt(const HypothesisSet& hypotheses,
                                      const std::vector<std::size_t>& nearby,
                                      const Eigen::Vector2d& position, std::size_t position_index,
                                      std::vector<Candidate>& candidates) const {
  const asr_robot_model::Frustum& frustum = parameters_.frustum;
  const double side_angle = std::min(frustum.fovx(), frustum.fovy()) / 2.0;
  const std::size_t type_count = hypotheses.types().size();
  thread_local std::vector<double> utility;  // orientation x type
  thread_local std::vector<char> touched;
  thread_local std::vector<std::pair<std::size_t, double>> pending;
  utility.assign(orientations_.size() * type_count, 0.0);
  touched.assign(orientations_.size(), 0);
  for (const TiltLevel& level : orientations_.levels()) {
    const Eigen::Vector3d camera(position.x(), position.y(), level.camera_height);
    for (std::size_t index : nearby) {
      const Hypothesis& hypothesis = hypotheses.hypotheses()[index];
      const Eigen::Vector3d offset = hypothesis.box.pose.position - camera;
      const double distance = offset.norm();
      if (distance <= frustum.near() || distance * std::cos(side_angle) >= frustum.far())
        continue;
      const double elevation = std::asin(std::clamp(offset.z() / distance, -1.0, 1.0));
      if (std::abs(elevation - level.elevation) >= side_angle)
        continue;
      const double orientation = orientationUtility(hypothesis, camera, parameters_.rating_angle);
      if (orientation == 0.0)
        continue;
      const auto [first, count] =
          headingWindow(level, elevation, std::atan2(offset.y(), offset.x()), side_angle);
      pending.clear();
      const long headings = static_cast<long>(level.headings);
      for (long h = first; h < first + count; ++h) {
        const std::size_t o = level.first_orientation +
                              static_cast<std::size_t>(((h % headings) + headings) % headings);
        const double terms = sideProximity(orientations_.axis(o), offset, frustum);
        if (terms > 0.0)
          pending.emplace_back(o, orientation * terms);
      }
      if (pending.empty() || !map_.lineOfSight(camera, hypothesis.box))
        continue;
      for (const auto& [o, u] : pending) {
        utility[o * type_count + hypothesis.type] += u;
        touched[o] = 1;
      }
    }
  }
  for (std::size_t o = 0; o < orientations_.size(); ++o) {
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

NextBestViewPlanner::Step NextBestViewPlanner::rateStep(
    const HypothesisSet& hypotheses, const std::vector<Eigen::Vector2d>& positions,
    const RobotState& current) const {
  const asr_robot_model::Frustum& frustum = parameters_.frustum;
  const HypothesisGrid grid(hypotheses, frustum.far());
  std::vector<std::vector<Candidate>> per_position(positions.size());
  auto rate_position = [&](std::size_t p) {
    const std::vector<std::size_t> nearby = grid.near(hypotheses, positions[p], frustum.far());
    if (!nearby.empty())
      utilitiesAt(hypotheses, nearby, positions[p], p, per_position[p]);
  };
  if (pool_ != nullptr)
    pool_->parallelFor(positions.size(), rate_position);
  else
    for (std::size_t p = 0; p < positions.size(); ++p)
      rate_position(p);

  std::vector<Candidate> candidates;
  for (auto& list : per_position)
    for (Candidate& candidate : list)
      candidates.push_back(std::move(candidate));
  Step step;
  if (candidates.empty())
    return step;
  double utility_max = 0.0;
  bool worth_moving = false;
  for (const Candidate& candidate : candidates) {
    utility_max = std::max(utility_max, candidate.total);
    worth_moving = worth_moving || candidate.total > parameters_.min_utility_for_moving;
  }

  // Types and the rating's upper bound (all motion free) per candidate, then inverse kinematics
  // in falling order of the bound until no bound can beat the best rating found.
  const RatingWeights& weights = parameters_.weights;
  const std::size_t type_count = hypotheses.countingTypes();
  std::vector<TypeChoice> choices(candidates.size());
  std::vector<double> bounds(candidates.size(), -1.0);
  std::vector<double> dense(hypotheses.types().size());
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (worth_moving && candidates[c].total <= parameters_.min_utility_for_moving)
      continue;
    std::fill(dense.begin(), dense.end(), 0.0);
    for (const auto& [type, u] : candidates[c].per_type)
      dense[type] = u;
    choices[c] = bestTypeSubset(dense, utility_max, type_count, weights);
    InverseCosts free_motion;
    free_motion.recognition = 1.0 - static_cast<double>(choices[c].types.size()) / type_count;
    bounds[c] = rating(choices[c].utility, utility_max, free_motion, weights);
  }
  std::vector<std::size_t> order(candidates.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return bounds[a] > bounds[b]; });
  const asr_robot_model::BaseIsFree base_is_free = [this](double x, double y, double) {
    return map_.baseIsFree(x, y);
  };
  double best_rating = -1.0;
  for (std::size_t c : order) {
    if (bounds[c] < 0.0 || bounds[c] <= best_rating)
      break;
    const Candidate& candidate = candidates[c];
    const TiltLevel& level = orientations_.levels()[orientations_.levelOf(candidate.orientation)];
    const Eigen::Vector3d camera(positions[candidate.position].x(),
                                 positions[candidate.position].y(), level.camera_height);
    const Eigen::Quaterniond orientation(orientations_.rotation(candidate.orientation));
    const asr_robot_model::IkResult ik =
        kinematics_.solve(camera, orientation, current, base_is_free);
    if (!ik.reachable)
      continue;
    const asr_robot_model::Motion motion =
        asr_robot_model::motionBetween(current, ik.state, kinematics_.speeds());
    const InverseCosts costs = inverseCosts(motion, current, ik.state, robot_,
                                            choices[c].types.size(), type_count, parameters_);
    const double value = rating(choices[c].utility, utility_max, costs, weights);
    if (value > best_rating) {
      best_rating = value;
      PlannedView& view = step.view;
      view.found = step.found = true;
      view.camera = ik.camera;
      view.state = ik.state;
      view.types.clear();
      for (int type : choices[c].types)
        view.types.push_back(hypotheses.types()[type]);
      view.utility = choices[c].utility;
      view.utility_max = utility_max;
      view.rating = value;
      view.costs = costs;
      view.motion_seconds = motion.seconds;
    }
  }
  return step;
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
  for (int k = 0; k < parameters_.max_steps; ++k) {
    const double radius = std::pow(scale, 0.382) * parameters_.lattice_radius;
    const std::vector<Eigen::Vector2d> positions =
        hexagonalLattice(centre, radius, reach, low, high);
    rated += positions.size() * orientations_.size();
    Step step = rateStep(hypotheses, positions, current);
    if (!step.found)
      break;
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
  return result;
}

}  // namespace asr_nbv
