// `asr ism predict ...` (the executable ism_predict): recognise a scene, predict its missing
// objects.
#include "asr_common/cli/command_main.hpp"
#include "predict_command.hpp"

namespace {

const char* const kUsage =
    "usage: asr ism predict --model M --scene NAME (--objects FILE | --demo DB --set K)\n"
    "         [--hide TYPE[,TYPE]] [--samples N] [--seed S] [--instances K] [--object TYPE[:ID]]\n"
    "         [--json] [--summary]\n"
    "  recognises the scene in the objects and predicts poses of every object the best\n"
    "  instance lacks (N poses per object, default 100; seed S, default 0). --hide leaves the\n"
    "  objects of those types out of the input, as if not seen yet. --instances K\n"
    "  predicts from the best K instances, poses split by confidence; --object predicts that\n"
    "  object only; --summary prints each object's mean position and spread instead of the\n"
    "  poses (with --json: adds a summary per object).\n";

}  // namespace

int main(int argc, char** argv) {
  // Errors read "ism predict: ...", as the user typed `asr ism predict`.
  return asr_common::cli::runSingleCommandMain("ism", "predict", kUsage,
                                               asr_pose_prediction::tools::runPredict, argc, argv);
}
