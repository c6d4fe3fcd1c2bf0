#include "asr_ism/synthetic_demonstration.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "asr_ism/common_types.hpp"
#include "asr_ism/portable_random.hpp"

namespace asr_ism {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;
constexpr double kTableHeight = 0.75;
// Centre of the table top in the map frame; the robot would stand near the origin.
const Eigen::Vector2d kTableCentre(1.0, 0.0);
constexpr double kPositionNoise = 0.003;       // metres per axis
constexpr double kAngleNoise = 1.0 * kDegree;  // RMS angle

Eigen::Quaterniond yawRotation(double yaw) {
  return Eigen::Quaterniond(std::cos(0.5 * yaw), 0.0, 0.0, std::sin(0.5 * yaw));
}

// A small random rotation whose angle has an RMS of `angle_sigma`. Built as the normalised
// quaternion (1, r / 2) of a rotation vector r, which for noise-sized angles is the exact rotation
// by |r| up to |r|^3 / 12, and needs no trigonometry.
Eigen::Quaterniond noiseRotation(PortableRandom& random, double angle_sigma) {
  const double per_axis = angle_sigma / std::sqrt(3.0);
  const Eigen::Vector3d half_vector = 0.5 * per_axis * random.gaussianVector();
  return Eigen::Quaterniond(1.0, half_vector.x(), half_vector.y(), half_vector.z()).normalized();
}

Pose noisy(const Pose& pose, PortableRandom& random, double position_sigma, double angle_sigma) {
  const Eigen::Vector3d position_noise = position_sigma * random.gaussianVector();
  return Pose(pose.position + position_noise,
              noiseRotation(random, angle_sigma) * pose.orientation);
}

// 0 before the step centred at `centre`, 1 after it, a smooth cosine ramp of `width` between.
double smoothStep(double t, double centre, double width) {
  const double u = std::clamp((t - centre) / width + 0.5, 0.0, 1.0);
  return 0.5 - 0.5 * std::cos(kPi * u);
}

// Normalised time of a step, in [0, 1].
double normalisedTime(std::size_t step, std::size_t steps) {
  return steps > 1 ? static_cast<double>(step) / static_cast<double>(steps - 1) : 0.0;
}

// How one object of a synthetic scene moves: its rest pose on the table and a smooth slide and
// turn about it, as sinusoids of the normalised time.
struct SyntheticMotion {
  Eigen::Vector3d rest_position;
  double rest_yaw = 0.0;
  Eigen::Vector2d slide_direction;
  double slide_amplitude = 0.0;  // half the travel along slide_direction
  double slide_frequency = 0.0;  // cycles over the demonstration
  double slide_phase = 0.0;
  double sway_amplitude = 0.0;  // across slide_direction
  double sway_phase = 0.0;
  double turn_amplitude = 0.0;  // half the range of yaw
  double turn_frequency = 0.0;
  double turn_phase = 0.0;

  Pose at(double t) const {
    const double slide = slide_amplitude * std::sin(2.0 * kPi * slide_frequency * t + slide_phase);
    const double sway = sway_amplitude * std::sin(2.0 * kPi * slide_frequency * t + sway_phase);
    const Eigen::Vector2d across(-slide_direction.y(), slide_direction.x());
    const Eigen::Vector2d offset = slide * slide_direction + sway * across;
    const double yaw =
        rest_yaw + turn_amplitude * std::sin(2.0 * kPi * turn_frequency * t + turn_phase);
    return Pose(rest_position + Eigen::Vector3d(offset.x(), offset.y(), 0.0), yawRotation(yaw));
  }
};

std::vector<SyntheticMotion> drawSyntheticMotions(std::size_t objects, PortableRandom& random) {
  constexpr double kHalfTable = 0.45;      // rest positions within a 0.9 m square
  constexpr double kMinimumSpacing = 0.1;  // between rest positions, where the table allows
  std::vector<SyntheticMotion> motions;
  for (std::size_t i = 0; i < objects; ++i) {
    SyntheticMotion motion;
    // Rejection sampling keeps objects apart; after many failures (crowded table) accept anyway.
    Eigen::Vector2d spot;
    for (int attempt = 0; attempt < 1000; ++attempt) {
      spot = random.uniformSquare(-kHalfTable, kHalfTable);
      const bool clear =
          std::all_of(motions.begin(), motions.end(), [&](const SyntheticMotion& other) {
            return (other.rest_position.head<2>() - (kTableCentre + spot)).norm() >=
                   kMinimumSpacing;
          });
      if (clear)
        break;
    }
    motion.rest_position = Eigen::Vector3d(kTableCentre.x() + spot.x(), kTableCentre.y() + spot.y(),
                                           kTableHeight + random.uniform(0.02, 0.12));
    motion.rest_yaw = random.uniform(0.0, 2.0 * kPi);
    const double direction = random.uniform(0.0, 2.0 * kPi);
    motion.slide_direction = Eigen::Vector2d(std::cos(direction), std::sin(direction));
    // Travel (twice the amplitude) from 3 cm to 30 cm; turns from 3 to 30 degrees.
    motion.slide_amplitude = random.uniform(0.015, 0.15);
    motion.slide_frequency = random.uniform(0.5, 1.5);
    motion.slide_phase = random.uniform(0.0, 2.0 * kPi);
    motion.sway_amplitude = 0.3 * motion.slide_amplitude;
    motion.sway_phase = random.uniform(0.0, 2.0 * kPi);
    motion.turn_amplitude = random.uniform(1.5, 15.0) * kDegree;
    motion.turn_frequency = random.uniform(0.5, 1.5);
    motion.turn_phase = random.uniform(0.0, 2.0 * kPi);
    motions.push_back(motion);
  }
  return motions;
}

// A nudge of one object of the breakfast setting: a shift and a turn (in the setting frame)
// applied smoothly around a moment of the demonstration.
struct Nudge {
  Eigen::Vector2d shift = Eigen::Vector2d::Zero();
  double turn = 0.0;
  double moment = 0.5;  // normalised time
  double duration = 0.1;
};

Nudge drawNudge(PortableRandom& random, double min_shift, double max_shift, double min_turn,
                double max_turn) {
  Nudge nudge;
  const double direction = random.uniform(0.0, 2.0 * kPi);
  const double distance = random.uniform(min_shift, max_shift);
  nudge.shift = distance * Eigen::Vector2d(std::cos(direction), std::sin(direction));
  nudge.turn = random.signedUniform(min_turn, max_turn);
  nudge.moment = random.uniform(0.2, 0.8);
  nudge.duration = random.uniform(0.05, 0.2);
  return nudge;
}

}  // namespace

Demonstration makeSyntheticDemonstration(std::size_t objects, std::size_t steps, std::uint32_t seed,
                                         const std::string& scene) {
  if (objects == 0 || steps == 0) {
    throw InputError("synthetic demonstration: needs at least one object and one time step");
  }
  std::vector<ObjectKey> keys;
  for (std::size_t i = 0; i < objects; ++i)
    keys.push_back({"object_" + std::to_string(i), "0"});
  Demonstration demonstration(scene, keys);

  // The motions are drawn first, so they do not depend on how many steps sample them.
  PortableRandom random(seed);
  const std::vector<SyntheticMotion> motions = drawSyntheticMotions(objects, random);
  for (std::size_t step = 0; step < steps; ++step) {
    demonstration.addStep();
    const double t = normalisedTime(step, steps);
    for (std::size_t i = 0; i < objects; ++i) {
      demonstration.setPose(step, i, noisy(motions[i].at(t), random, kPositionNoise, kAngleNoise));
    }
  }
  return demonstration;
}

namespace {

// The place setting in its own frame (x right, y away from the person, z up): position of each
// object's centre and its yaw. Cutlery lies with its long (x) axis pointing away.
struct BreakfastItem {
  const char* type;
  Eigen::Vector3d position;
  double yaw;
  bool nudged;
};

const std::vector<BreakfastItem>& breakfastItems() {
  static const std::vector<BreakfastItem> items = {
      {"PlateDeep", {0.0, 0.0, 0.02}, 0.0, false},
      {"Cup", {0.17, 0.17, 0.05}, -30.0 * kDegree, true},
      {"Fork", {-0.17, 0.0, 0.01}, 90.0 * kDegree, true},
      {"Knife", {0.16, 0.0, 0.01}, 90.0 * kDegree, true},
      {"Spoon", {0.21, 0.0, 0.01}, 90.0 * kDegree, true},
      {"CerealBox", {-0.12, 0.30, 0.15}, 10.0 * kDegree, false},
  };
  return items;
}

// Cup and cutlery are nudged once each: the cup by a few cm and up to 20 degrees, the cutlery
// by 1-2 cm and a few degrees.
std::vector<Nudge> breakfastNudges(PortableRandom& random) {
  std::vector<Nudge> nudges;
  for (const BreakfastItem& item : breakfastItems()) {
    if (!item.nudged)
      nudges.emplace_back();
    else if (std::string(item.type) == "Cup")
      nudges.push_back(drawNudge(random, 0.02, 0.05, 5.0 * kDegree, 20.0 * kDegree));
    else
      nudges.push_back(drawNudge(random, 0.01, 0.02, 2.0 * kDegree, 6.0 * kDegree));
  }
  return nudges;
}

// Where an item is in the setting at time t in [0, 1], with its nudge done as far as it is.
Pose itemInSetting(const BreakfastItem& item, const Nudge& nudge, double t) {
  const double done = smoothStep(t, nudge.moment, nudge.duration);
  const Eigen::Vector3d position =
      item.position + done * Eigen::Vector3d(nudge.shift.x(), nudge.shift.y(), 0.0);
  return Pose(position, yawRotation(item.yaw + done * nudge.turn));
}

}  // namespace

Demonstration makeBreakfastDemonstration(std::uint32_t seed) {
  constexpr std::size_t kSteps = 60;
  const std::vector<BreakfastItem>& items = breakfastItems();
  std::vector<ObjectKey> keys;
  for (const BreakfastItem& item : items)
    keys.push_back({item.type, "0"});
  Demonstration demonstration("breakfast", keys);

  PortableRandom random(seed);
  // The whole setting slides about 40 cm along the table and turns a little.
  const Eigen::Vector2d start = kTableCentre + Eigen::Vector2d(-0.2, -0.15);
  const double travel_along = random.uniform(0.35, 0.45);
  const double travel_across = random.uniform(-0.05, 0.05);
  const Eigen::Vector2d travel(travel_along, travel_across);
  const double start_yaw = random.uniform(-5.0, 5.0) * kDegree;
  const double turn = random.signedUniform(3.0, 8.0) * kDegree;
  const std::vector<Nudge> nudges = breakfastNudges(random);

  for (std::size_t step = 0; step < kSteps; ++step) {
    demonstration.addStep();
    const double t = normalisedTime(step, kSteps);
    const double progress = smoothStep(t, 0.5, 1.0);  // eases in and out over the whole recording
    const Eigen::Vector2d origin = start + progress * travel;
    const Pose setting(Eigen::Vector3d(origin.x(), origin.y(), kTableHeight),
                       yawRotation(start_yaw + progress * turn));
    for (std::size_t i = 0; i < keys.size(); ++i) {
      demonstration.setPose(step, i,
                            noisy(compose(setting, itemInSetting(items[i], nudges[i], t)), random,
                                  kPositionNoise, kAngleNoise));
    }
  }
  return demonstration;
}

Configuration transformConfiguration(const Configuration& configuration, const Pose& motion) {
  Configuration moved = configuration;
  for (ObjectEstimate& estimate : moved)
    estimate.pose = compose(motion, estimate.pose);
  return moved;
}

Configuration disturbConfiguration(const Configuration& configuration, const ObjectKey& key,
                                   const Eigen::Vector3d& offset,
                                   const Eigen::Quaterniond& rotation) {
  Configuration disturbed = configuration;
  const auto found =
      std::find_if(disturbed.begin(), disturbed.end(),
                   [&](const ObjectEstimate& estimate) { return estimate.key == key; });
  if (found == disturbed.end()) {
    throw InputError("disturbConfiguration: the configuration does not contain " + key.toString());
  }
  found->pose = Pose(found->pose.position + offset, rotation * found->pose.orientation);
  return disturbed;
}

Configuration addSensorNoise(const Configuration& configuration, double position_sigma,
                             double angle_sigma, std::uint32_t seed) {
  PortableRandom random(seed);
  Configuration noisy_configuration = configuration;
  for (ObjectEstimate& estimate : noisy_configuration)
    estimate.pose = noisy(estimate.pose, random, position_sigma, angle_sigma);
  return noisy_configuration;
}

}  // namespace asr_ism
