// `asr_prediction_bench [prediction] [options]` (`asr bench prediction`): how fast and how
// accurately the objects of a scene are predicted.
#include "asr_common/cli/command_main.hpp"
#include "prediction_command.hpp"

namespace {

const char* const kUsage =
    "usage: asr bench prediction [--json] [--recordings DIR] [--plot FILE.png] [--no-synthetic]\n"
    "         [--no-accuracy] [--samples N] [--accuracy-samples N] [--timing-sets N]\n"
    "         [--accuracy-sets N] [--repetitions N] [--seed S]\n"
    "  runtime: predicting N poses (default 100) of every object of a scene, for the ten kitchen\n"
    "  scenes and synthetic scenes of 2-10 objects x 100-1000 steps, star and complete trees;\n"
    "  accuracy: every object of every recorded set left out, the rest recognised, N poses\n"
    "  (default 200) of it predicted. --plot draws the synthetic runtimes with gnuplot;\n"
    "  --json prints the rows and target checks as one JSON object.\n";

}  // namespace

int main(int argc, char** argv) {
  return asr_common::cli::runSingleCommandMain("asr_prediction_bench", "prediction", kUsage,
                                               asr_pose_prediction::bench::runPredictionBenchmark,
                                               argc, argv);
}
