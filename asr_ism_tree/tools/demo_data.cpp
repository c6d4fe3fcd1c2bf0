// `asr_demo_data --out DIR [--seed S] [--force]`: writes the suite's own demo data, generated
// here rather than copied from the recordings: a breakfast demonstration in the original ASR schema
// and two configurations to recognise, one consistent with it and one disturbed.
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "asr_common/cli/command_line.hpp"
#include "asr_common/input_error.hpp"
#include "asr_ism/configuration_file.hpp"
#include "asr_ism/sqlite/demonstration_writer.hpp"
#include "asr_ism/synthetic_demonstration.hpp"
#include "asr_ism_tree/star_center.hpp"
#include "asr_ism_tree/tree_generation.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"

namespace {

namespace fs = std::filesystem;
using asr_common::Configuration;
using asr_common::ObjectKey;
using asr_common::Pose;
using asr_ism::Demonstration;

const char* const kUsage =
    "usage: asr_demo_data --out DIR [--seed S] [--force]\n"
    "  writes DIR/breakfast.sqlite (a breakfast demonstration, original ASR schema),\n"
    "  DIR/breakfast_correct.yaml (a new configuration consistent with it) and\n"
    "  DIR/breakfast_disturbed.yaml (the same with the cup and the knife misplaced).\n"
    "  Existing files are only replaced with --force.\n";

constexpr double kDegree = M_PI / 180.0;
// The recorded step the new configurations start from: the middle of the demonstration.
constexpr std::size_t kBaseStep = 30;
// How the whole setting is moved on the table for the consistent configuration.
constexpr double kSettingTurn = 20.0 * kDegree;
const Eigen::Vector3d kSettingShift(-0.05, 0.20, 0.0);
// The disturbance: the cup goes 25 cm to the plate's other side, the knife turns crosswise.
constexpr double kCupMove = 0.25;
constexpr double kKnifeTurn = 90.0 * kDegree;

const ObjectKey kPlate{"PlateDeep", "0"};
const ObjectKey kCup{"Cup", "0"};
const ObjectKey kKnife{"Knife", "0"};

const Pose& poseOf(const Configuration& configuration, const ObjectKey& key) {
  for (const auto& estimate : configuration) {
    if (estimate.key == key)
      return estimate.pose;
  }
  throw asr_common::InputError("the breakfast configuration has no " + key.toString());
}

// The setting of the middle step, turned about the vertical through the plate and shifted on the
// table, then observed afresh (new sensor noise): no recorded step, but consistent with them.
Configuration consistentConfiguration(const Demonstration& demonstration, std::uint32_t seed) {
  const Configuration base = demonstration.configuration(kBaseStep);
  const Eigen::Vector3d pivot = poseOf(base, kPlate).position;
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(kSettingTurn, Eigen::Vector3d::UnitZ()));
  // Rotation about the pivot: p -> turn * (p - pivot) + pivot + shift.
  const Pose motion(pivot + kSettingShift - turn * pivot, turn);
  return asr_ism::addSensorNoise(asr_ism::transformConfiguration(base, motion), 0.003, kDegree,
                                 seed + 1);
}

// The consistent configuration with the cup on the wrong (left) side of the plate and the knife
// turned by 90 degrees. "Left" is the plate's -x axis: the setting's frame has x to the right.
Configuration disturbedConfiguration(const Configuration& consistent) {
  Eigen::Vector3d right = poseOf(consistent, kPlate).orientation * Eigen::Vector3d::UnitX();
  right.z() = 0.0;
  const Configuration cup_moved =
      asr_ism::disturbConfiguration(consistent, kCup, -kCupMove * right.normalized());
  return asr_ism::disturbConfiguration(
      cup_moved, kKnife, Eigen::Vector3d::Zero(),
      Eigen::Quaterniond(Eigen::AngleAxisd(kKnifeTurn, Eigen::Vector3d::UnitZ())));
}

// Best confidences of the configurations with a star and a complete tree of the demonstration, so
// the user sees at once that the data behaves as intended.
std::string recognitionCheck(const Demonstration& demonstration, const Configuration& consistent,
                             const Configuration& disturbed) {
  using namespace asr_ism_tree;
  std::ostringstream text;
  text << std::fixed << std::setprecision(3);
  const std::pair<const char*, RelationTopology> topologies[] = {
      {"star", RelationTopology::star(demonstration.objects(), chooseStarCenter(demonstration))},
      {"complete", RelationTopology::complete(demonstration.objects())}};
  for (const auto& [name, topology] : topologies) {
    const IsmTree tree =
        generateIsmTree(demonstration, topology, asr_ism::IsmRecognitionParameters{});
    const TreeRecognizer recognizer(tree);
    const auto best = [&](const Configuration& configuration) {
      const auto instances = recognizer.recognize(configuration);
      return instances.empty() ? 0.0 : instances.front().confidence;
    };
    text << "  " << std::left << std::setw(9) << name << "tree: correct " << best(consistent)
         << ", disturbed " << best(disturbed) << "\n";
  }
  return text.str();
}

int run(const std::vector<std::string>& arguments) {
  using asr_common::cli::UsageError;
  const asr_common::cli::CommandLine options(arguments, {"out", "seed"}, {"force"});
  const fs::path out = options.required("out");
  const long long seed = options.integer("seed", 1, 0, 0xffffffffLL);
  const bool force = options.flag("force");

  const fs::path demonstration_path = out / "breakfast.sqlite";
  const fs::path correct_path = out / "breakfast_correct.yaml";
  const fs::path disturbed_path = out / "breakfast_disturbed.yaml";
  if (!force) {
    for (const fs::path& path : {demonstration_path, correct_path, disturbed_path}) {
      if (fs::exists(path)) {
        throw asr_common::InputError(path.string() +
                                     " exists already; nothing written (give --force to replace)");
      }
    }
  }
  std::error_code error;
  fs::create_directories(out, error);
  if (error)
    throw asr_common::InputError(out.string() + ": cannot create the folder: " + error.message());

  const Demonstration demonstration =
      asr_ism::makeBreakfastDemonstration(static_cast<std::uint32_t>(seed));
  const Configuration consistent =
      consistentConfiguration(demonstration, static_cast<std::uint32_t>(seed));
  const Configuration disturbed = disturbedConfiguration(consistent);

  // The writer appends, so a replaced demonstration file must go first.
  if (force)
    fs::remove(demonstration_path);
  asr_ism::sqlite::appendDemonstration(demonstration_path.string(), demonstration);
  asr_ism::writeConfigurationFile(correct_path.string(), consistent, force);
  asr_ism::writeConfigurationFile(disturbed_path.string(), disturbed, force);

  std::string objects;
  for (const ObjectKey& key : demonstration.objects())
    objects += (objects.empty() ? "" : ", ") + key.toString();
  std::cout << "wrote " << demonstration_path.string() << ": scene '" << demonstration.scene()
            << "', " << demonstration.stepCount() << " recorded sets of "
            << demonstration.objectCount() << " objects (" << objects << "), seed " << seed << "\n"
            << "wrote " << correct_path.string() << ": the setting of set " << kBaseStep
            << " turned " << std::lround(kSettingTurn / kDegree)
            << " deg about the plate and moved " << std::lround(kSettingShift.norm() * 100.0)
            << " cm, with fresh sensor noise\n"
            << "wrote " << disturbed_path.string() << ": the same with the cup moved "
            << std::lround(kCupMove * 100.0) << " cm to the wrong side and the knife turned "
            << std::lround(kKnifeTurn / kDegree) << " deg\n"
            << "best confidences (trees learned from the demonstration, default parameters):\n"
            << recognitionCheck(demonstration, consistent, disturbed);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> arguments(argv + 1, argv + argc);
  if (arguments.size() == 1 && (arguments[0] == "--help" || arguments[0] == "-h")) {
    std::cout << kUsage;
    return 0;
  }
  try {
    return run(arguments);
  } catch (const asr_common::cli::UsageError& error) {
    std::cerr << "asr_demo_data: " << error.message << "\n" << kUsage;
    return 2;
  } catch (const asr_common::InputError& error) {
    std::cerr << "asr_demo_data: error: " << error.what() << "\n";
    return 1;
  } catch (const fs::filesystem_error& error) {
    std::cerr << "asr_demo_data: error: " << error.what() << "\n";
    return 1;
  }
}
