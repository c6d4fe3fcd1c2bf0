// `asr_robot_bench` (`asr bench robot`): inverse kinematics per request and simulated detection
// per view, against the targets of issue 14.
#include <iomanip>
#include <iostream>
#include <random>
#include <sstream>

#include "asr_common/cli/command_line.hpp"
#include "asr_common/cli/command_main.hpp"
#include "asr_common/cli/targets.hpp"
#include "asr_common/cli/timing.hpp"
#include "asr_robot_model/detection_simulator.hpp"
#include "asr_robot_model/forward_kinematics.hpp"
#include "asr_robot_model/inverse_kinematics.hpp"
#include "asr_robot_model/testing/cluttered_world.hpp"

namespace {

using namespace asr_robot_model;

const char* const kUsage =
    "usage: asr bench robot [--requests N] [--views N] [--seed S]\n"
    "  inverse kinematics of N random reachable views of the shipped robot (default 20000),\n"
    "  without and with the OctoMap free-space check of a cluttered world; simulated detection\n"
    "  of 100 objects among 20 furniture boxes from N random views (default 2000). Prints\n"
    "  microseconds per request or view and whether the targets are met.\n";

constexpr double kIkTargetMicroseconds = 20.0;
constexpr double kDetectionTargetMicroseconds = 1000.0;

// Prints the measurement and adds it to the benchmark's targets.
void report(std::vector<asr_common::cli::Target>& targets, const std::string& what,
            double microseconds, double target) {
  std::ostringstream measured;
  measured << std::fixed << std::setprecision(2) << microseconds << " us";
  std::cout << "  " << std::left << std::setw(44) << what << std::right << std::setw(12)
            << measured.str() << "\n";
  std::ostringstream asked;
  asked << what << ": <= " << target << " us";
  targets.push_back({asked.str(), measured.str(), microseconds <= target});
}

// Microseconds per inverse kinematics request over random reachable views.
double ikMicroseconds(const InverseKinematics& ik, int requests, std::mt19937& random,
                      const BaseIsFree& base_is_free, int& reachable) {
  const RobotDescription& robot = ik.robot();
  std::uniform_real_distribution<double> x(0.5, 5.5), y(0.5, 4.5), yaw(-M_PI, M_PI);
  std::uniform_real_distribution<double> pan(robot.pan.lower, robot.pan.upper);
  std::uniform_real_distribution<double> tilt(robot.tilt.lower, robot.tilt.upper);
  std::vector<asr_common::Pose> views;
  std::vector<RobotState> starts;
  for (int i = 0; i < requests; ++i) {
    views.push_back(
        cameraPose(robot, {x(random), y(random), yaw(random), pan(random), tilt(random)}));
    starts.push_back({x(random), y(random), yaw(random), pan(random), tilt(random)});
  }
  reachable = 0;
  const double milliseconds = asr_common::cli::millisecondsOf([&] {
    for (int i = 0; i < requests; ++i)
      reachable +=
          ik.solve(views[i].position, views[i].orientation, starts[i], base_is_free).reachable;
  });
  return 1000.0 * milliseconds / requests;
}

int runRobotBenchmark(const std::vector<std::string>& arguments) {
  const asr_common::cli::CommandLine options(arguments, {"requests", "views", "seed"}, {});
  const int requests = static_cast<int>(options.integer("requests", 20000, 1, 10000000));
  const int view_count = static_cast<int>(options.integer("views", 2000, 1, 1000000));
  std::mt19937 random(static_cast<unsigned>(options.integer("seed", 14, 0, 4294967295LL)));
  const RobotDescription robot = loadRobotDescription(defaultRobotUrdf());
  const InverseKinematics ik(robot, speedsOf(robot));
  const World world = testing::clutteredWorld(random);
  const WorldMap map(world, 0.02, robot.base_radius);

  std::cout << "asr bench robot: shipped robot, world of " << world.furniture.size()
            << " furniture boxes and " << world.objects.size() << " objects, OctoMap 0.02 m\n";
  std::vector<asr_common::cli::Target> targets;
  int reachable = 0;
  report(targets, "inverse kinematics per request",
         ikMicroseconds(ik, requests, random, {}, reachable), kIkTargetMicroseconds);
  const BaseIsFree free = [&map](double x, double y, double) { return map.baseIsFree(x, y); };
  const double with_map = ikMicroseconds(ik, requests, random, free, reachable);
  report(targets, "inverse kinematics per request, free base", with_map, kIkTargetMicroseconds);
  std::cout << "    (" << reachable << " of " << requests
            << " random views reachable with a free base in the cluttered world)\n";

  DetectionSimulator simulator(world, map, DetectionSettings{}, 1);
  std::vector<asr_common::Pose> views;
  for (int i = 0; i < view_count; ++i)
    views.push_back(testing::randomView(world, random));
  std::size_t detected = 0;
  const double milliseconds = asr_common::cli::millisecondsOf([&] {
    for (const asr_common::Pose& view : views)
      detected += simulator.detect(view, {}).detected.size();
  });
  report(targets, "detection of 100 objects per view", 1000.0 * milliseconds / view_count,
         kDetectionTargetMicroseconds);
  std::cout << "    (" << detected << " detections over " << view_count << " views)\n";
  asr_common::cli::printTargets(std::cout, targets);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return asr_common::cli::runSingleCommandMain("asr_robot_bench", "robot", kUsage,
                                               runRobotBenchmark, argc, argv);
}
