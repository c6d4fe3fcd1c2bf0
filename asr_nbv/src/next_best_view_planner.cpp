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
  const double spread = arcCosineUpperBound(q) / level.heading_step;
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
      orientations_(robot, parameters_.orientation_step, seed),
      orientation_bound_(parameters_.rating_angle),
      side_bound_(std::min(parameters_.frustum.fovx(), parameters_.frustum.fovy()) / 2.0),
      proximity_bound_((parameters_.frustum.far() - parameters_.frustum.near()) / 2.0) {
  checkNbvParameters(parameters_);
  const double side_angle = std::min(parameters_.frustum.fovx(), parameters_.frustum.fovy()) / 2.0;
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

double NextBestViewPlanner::orientationBound(const Hypothesis& hypothesis,
                                             const Eigen::Vector3d& offset, double distance) const {
  if (hypothesis.normals.empty())
    return hypothesis.active[0] ? 1.0 : 0.0;
  // The camera is at -offset from the hypothesis.
  double best = 0.0;
  for (std::size_t n = 0; n < hypothesis.normals.size(); ++n) {
    if (hypothesis.active[n])
      best = std::max(best,
                      orientation_bound_.ofCosine(-hypothesis.normals[n].dot(offset) / distance));
  }
  return best;
}

void NextBestViewPlanner::utilitiesAt(const HypothesisSet& hypotheses,
                                      const std::vector<Eigen::Vector3d>& points,
                                      const std::vector<std::size_t>& nearby,
                                      const Eigen::Vector2d& position, std::size_t position_index,
                                      std::vector<Candidate>& candidates) const {
  const asr_robot_model::Frustum& frustum = parameters_.frustum;
  const double side_angle = std::min(frustum.fovx(), frustum.fovy()) / 2.0;
  const double side_cosine = std::cos(side_angle);
  const double reach = frustum.far() / side_cosine;
  const double middle = (frustum.near() + frustum.far()) / 2.0;
  const std::size_t type_count = hypotheses.types().size();
  const std::vector<TiltLevel>& levels = orientations_.levels();
  thread_local std::vector<double> utility;  // orientation x type
  thread_local std::vector<char> touched;
  utility.assign(orientations_.size() * type_count, 0.0);
  touched.assign(orientations_.size(), 0);
  for (std::size_t index : nearby) {
    const Eigen::Vector3d& point = points[index];
    const Eigen::Vector2d across = point.head<2>() - position;
    const double horizontal = across.norm();
    double azimuth = std::numeric_limits<double>::quiet_NaN();  // when a level needs it
    for (std::size_t l = 0; l < levels.size(); ++l) {
      const TiltLevel& level = levels[l];
      // Only levels whose axis elevation lies within the side angle of the hypothesis' can see
      // it: a slope test, no arc function.
      const double rise = point.z() - level.camera_height;
      if (rise <= horizontal * band_low_[l] || rise >= horizontal * band_high_[l])
        continue;
      const Eigen::Vector3d camera(position.x(), position.y(), level.camera_height);
      const Eigen::Vector3d offset = point - camera;
      const double distance = offset.norm();
      if (distance <= frustum.near() || distance >= reach)
        continue;
      const Hypothesis& hypothesis = hypotheses.hypotheses()[index];
      const double orientation = orientationBound(hypothesis, offset, distance);
      if (orientation == 0.0)
        continue;
      if (std::isnan(azimuth))
        azimuth = std::atan2(across.y(), across.x());
      const double inverse_distance = 1.0 / distance;
      const auto [first, count] =
          headingWindow(level, level_sine_[l], level_cosine_[l], rise * inverse_distance,
                        horizontal * inverse_distance, azimuth, side_cosine);
      const long headings = static_cast<long>(level.headings);
      long h = ((first % headings) + headings) % headings;
      double* const row = utility.data() + hypothesis.type;
      for (long k = 0; k < count; ++k, h = (h + 1 == headings) ? 0 : h + 1) {
        const std::size_t o = level.first_orientation + static_cast<std::size_t>(h);
        // Bounds of sideProximity's terms, as the orientation's above.
        const double depth = orientations_.axis(o).dot(offset);
        if (depth <= side_cosine * distance)
          continue;
        const double terms = proximity_bound_.ofDistance(std::abs(depth - middle)) *
                             side_bound_.ofCosine(depth * inverse_distance);
        if (terms > 0.0) {
          row[o * type_count] += orientation * terms;
          touched[o] = 1;
        }
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

asr_common::Pose NextBestViewPlanner::cameraOf(
    const Candidate& candidate, const std::vector<Eigen::Vector2d>& positions) const {
  const TiltLevel& level = orientations_.levels()[orientations_.levelOf(candidate.orientation)];
  const Eigen::Vector2d& xy = positions[candidate.position];
  asr_common::Pose camera;
  camera.position = Eigen::Vector3d(xy.x(), xy.y(), level.camera_height);
  camera.orientation = Eigen::Quaterniond(orientations_.rotation(candidate.orientation));
  return camera;
}

std::vector<double> NextBestViewPlanner::occludedUtility(const HypothesisSet& hypotheses,
                                                         const std::vector<std::size_t>& nearby,
                                                         const asr_common::Pose& camera,
                                                         std::vector<signed char>& sight) const {
  std::vector<double> per_type(hypotheses.types().size(), 0.0);
  if (sight.empty())
    sight.assign(nearby.size(), -1);
  for (std::size_t k = 0; k < nearby.size(); ++k) {
    const Hypothesis& hypothesis = hypotheses.hypotheses()[nearby[k]];
    const double u = hypothesisUtility(camera, hypothesis, parameters_);
    if (u <= 0.0)
      continue;
    if (sight[k] < 0)
      sight[k] = map_.lineOfSight(camera.position, hypothesis.box) ? 1 : 0;
    if (sight[k] == 1)
      per_type[hypothesis.type] += u;
  }
  return per_type;
}

NextBestViewPlanner::Step NextBestViewPlanner::rateStep(
    const HypothesisSet& hypotheses, const std::vector<Eigen::Vector2d>& positions,
    const RobotState& current) const {
  const asr_robot_model::Frustum& frustum = parameters_.frustum;
  const double reach = frustum.far() / std::cos(std::min(frustum.fovx(), frustum.fovy()) / 2.0);
  const HypothesisGrid grid(hypotheses, reach);
  // The positions packed, for the first pass's sweep over them.
  std::vector<Eigen::Vector3d> points;
  points.reserve(hypotheses.hypotheses().size());
  for (const Hypothesis& hypothesis : hypotheses.hypotheses())
    points.push_back(hypothesis.box.pose.position);
  std::vector<std::vector<std::size_t>> nearby(positions.size());
  std::vector<std::vector<Candidate>> per_position(positions.size());
  auto rate_position = [&](std::size_t p) {
    nearby[p] = grid.near(hypotheses, positions[p], reach);
    if (!nearby[p].empty())
      utilitiesAt(hypotheses, points, nearby[p], positions[p], p, per_position[p]);
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

  // Occlusion only lowers utilities, so the utilities without it bound the exact ones: line of
  // sight is checked only for the candidates whose bound can still win, best bound first.
  std::vector<std::vector<double>> exact(candidates.size());
  std::vector<double> exact_total(candidates.size(), -1.0);
  // Lines of sight from a camera position (lattice point and tilt level's height) to its nearby
  // hypotheses, cast once for all the orientations rated there.
  const std::size_t level_count = orientations_.levels().size();
  std::vector<std::vector<signed char>> sight(positions.size() * level_count);
  auto exactUtility = [&](std::size_t c) {
    if (exact_total[c] < 0.0) {
      const Candidate& candidate = candidates[c];
      exact[c] = occludedUtility(
          hypotheses, nearby[candidate.position], cameraOf(candidate, positions),
          sight[candidate.position * level_count + orientations_.levelOf(candidate.orientation)]);
      exact_total[c] = std::accumulate(exact[c].begin(), exact[c].end(), 0.0);
    }
    return exact_total[c];
  };
  std::vector<std::size_t> by_utility(candidates.size());
  std::iota(by_utility.begin(), by_utility.end(), 0);
  std::stable_sort(by_utility.begin(), by_utility.end(), [&](std::size_t a, std::size_t b) {
    return candidates[a].total > candidates[b].total;
  });
  double utility_max = 0.0;
  for (std::size_t c : by_utility) {
    if (candidates[c].total <= utility_max)
      break;
    utility_max = std::max(utility_max, exactUtility(c));
  }
  if (utility_max <= 0.0)
    return step;
  const bool worth_moving = utility_max > parameters_.min_utility_for_moving;

  // Types and the rating's upper bound (motion free, no occlusion) per candidate, then exact
  // utility and inverse kinematics in falling order of the bound until none can beat the best.
  const RatingWeights& weights = parameters_.weights;
  const std::size_t type_count = hypotheses.countingTypes();
  std::vector<double> bounds(candidates.size(), -1.0);
  std::vector<double> dense(hypotheses.types().size());
  // The base must carry the camera at least this far: the rating's base term is bounded.
  const Eigen::Vector2d base(current.x, current.y);
  const double sigma = parameters_.base_distance_sigma;
  auto boundOf = [&](const TypeChoice& choice, const Eigen::Vector2d& camera) {
    InverseCosts best_motion;
    const double drive = std::max(0.0, (camera - base).norm() - camera_reach_);
    best_motion.base = std::exp(-drive * drive / (2.0 * sigma * sigma));
    best_motion.recognition = 1.0 - static_cast<double>(choice.types.size()) / type_count;
    return rating(choice.utility, utility_max, best_motion, weights);
  };
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (worth_moving && candidates[c].total <= parameters_.min_utility_for_moving)
      continue;
    std::fill(dense.begin(), dense.end(), 0.0);
    for (const auto& [type, u] : candidates[c].per_type)
      dense[type] = u;
    bounds[c] = boundOf(bestTypeSubset(dense, utility_max, type_count, weights),
                        positions[candidates[c].position]);
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
    const double total = exactUtility(c);
    if (total <= 0.0 || (worth_moving && total <= parameters_.min_utility_for_moving))
      continue;
    const TypeChoice choice = bestTypeSubset(exact[c], utility_max, type_count, weights);
    if (boundOf(choice, positions[candidates[c].position]) <= best_rating)
      continue;
    const asr_common::Pose camera = cameraOf(candidates[c], positions);
    const asr_robot_model::IkResult ik =
        kinematics_.solve(camera.position, camera.orientation, current, base_is_free);
    if (!ik.reachable)
      continue;
    const asr_robot_model::Motion motion =
        asr_robot_model::motionBetween(current, ik.state, kinematics_.speeds());
    const InverseCosts costs = inverseCosts(motion, current, ik.state, robot_, choice.types.size(),
                                            type_count, parameters_);
    const double value = rating(choice.utility, utility_max, costs, weights);
    step.view.rated.push_back({ik.camera, value});
    if (value > best_rating) {
      best_rating = value;
      PlannedView& view = step.view;
      view.found = step.found = true;
      view.camera = ik.camera;
      view.state = ik.state;
      view.types.clear();
      for (int type : choice.types)
        view.types.push_back(hypotheses.types()[type]);
      view.utility = choice.utility;
      view.utility_max = utility_max;
      view.rating = value;
      view.costs = costs;
      view.motion_seconds = motion.seconds;
    }
  }
  return step;
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
  for (int k = 0; k < parameters_.max_steps; ++k) {
    const double radius = std::pow(scale, 0.382) * parameters_.lattice_radius;
    std::vector<Eigen::Vector2d> positions = hexagonalLattice(centre, radius, reach, low, high);
    // Like the original's costmap: drop positions the base cannot carry the camera to (the
    // lattice's centre, where the camera is or was chosen, stays).
    positions.erase(std::remove_if(positions.begin() + 1, positions.end(),
                                   [this](const Eigen::Vector2d& xy) { return !reachable(xy); }),
                    positions.end());
    rated += positions.size() * orientations_.size();
    Step step = rateStep(hypotheses, positions, current);
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
