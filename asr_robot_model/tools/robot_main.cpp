// `asr robot fk|ik|detect ...` (the executable robot): the robot model from the command line.
#include "asr_common/cli/command_main.hpp"
#include "robot_commands.hpp"

namespace {

const char* const kUsage =
    "usage: asr robot <command> [options]   (poses: camera_optical_frame in map, radians)\n"
    "  fk [--urdf U] --state \"x y yaw pan tilt\" [--json]\n"
    "      -> {\"camera\": pose}\n"
    "  ik [--urdf U] [--world W] --camera \"x y z qx qy qz qw\" [--from \"x y yaw pan tilt\"]\n"
    "     [--resolution R] [--json]\n"
    "      -> {\"reachable\", \"reason\", \"explanation\", \"state\", \"camera\", \"seconds\",\n"
    "          \"roll_difference\"}; reason: tilt_limit, height, base_collision, invalid_pose\n"
    "  detect --world W --camera \"x y z qx qy qz qw\" [--types A,B] [--seed S] [--json]\n"
    "      -> {\"detected\": [{type, id, pose}], \"rejected\": [{type, id, why}], \"seconds\"}\n"
    "         why: frustum, normals, occluded, missed\n"
    "  --urdf defaults to the shipped robot, --catalogue to config/object_types.yaml; a world\n"
    "  is YAML or JSON (docs/robot.md); --resolution is the OctoMap's voxel (default 0.02 m);\n"
    "  --json prints one line, else the same JSON indented.\n";

}  // namespace

int main(int argc, char** argv) {
  return asr_common::cli::runCommandMain("robot", kUsage,
                                         {{"fk", asr_robot_model::tools::runFk},
                                          {"ik", asr_robot_model::tools::runIk},
                                          {"detect", asr_robot_model::tools::runDetect}},
                                         argc, argv);
}
