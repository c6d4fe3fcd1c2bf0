// `asr tags detect|render|print ...` (the executable tags): AprilTags from the command line.
#include "asr_common/cli/command_main.hpp"
#include "tag_commands.hpp"

namespace {

const char* const kUsage =
    "usage: asr tags <command> [options]   (poses: x y z qx qy qz qw, metres)\n"
    "  detect --image I.png --camera-info C.yaml [--tag-map M] [--decimate D] [--json]\n"
    "      -> {\"tags\": [{id, pose, reprojection_px}], \"objects\": [{type, id, pose,\n"
    "          covariance, tags, reprojection_px}], \"unknown_ids\", \"refused\"}\n"
    "         poses in the camera optical frame; colour images are converted to grey\n"
    "  render --world W --camera \"x y z qx qy qz qw\" --out I.png [--tag-map M]\n"
    "         [--camera-info C.yaml] [--save-camera-info C.yaml] [--seed S] [--noise N]\n"
    "         [--blur B] [--no-occlusion]\n"
    "      the simulated camera's image from camera_optical_frame at the pose (in map);\n"
    "      default camera 640 x 480, 60 deg horizontal field of view\n"
    "  print --ids 0-11 --out tags.pdf|tags.png [--family F] [--tag-map M] [--edge-mm E]\n"
    "        [--cell-px P]\n"
    "      tags to print (ids as 0-11 or 0,3,5-7). PDF: A4 pages, each tag at its true size, the\n"
    "      tag map's edge_length for the ids it has, else E mm (default 50); print at 100 %.\n"
    "      PNG: one sheet, each cell P pixels (default 24)\n"
    "  --tag-map defaults to the shipped config/tag_map.yaml (its family for print);\n"
    "  --json prints one line, else the same JSON indented.\n";

}  // namespace

int main(int argc, char** argv) {
  return asr_common::cli::runCommandMain("tags", kUsage,
                                         {{"detect", asr_robot_model::tools::runTagsDetect},
                                          {"render", asr_robot_model::tools::runTagsRender},
                                          {"print", asr_robot_model::tools::runTagsPrint}},
                                         argc, argv);
}
