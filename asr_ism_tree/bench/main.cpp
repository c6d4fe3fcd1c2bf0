// `asr_bench <benchmark> ...`: performance benchmarks of the ISM tree engine.
#include "asr_common/cli/command_main.hpp"
#include "exact_search_benchmark.hpp"
#include "recognition_command.hpp"
#include "topology_command.hpp"

namespace {

const char* const kUsage =
    "usage: asr_bench <benchmark> [options]\n"
    "benchmarks:\n"
    "  recognition [--json] [--recordings DIR] [--threads N] [--no-synthetic]\n"
    "              [--synthetic-json FILE] [--no-clutter | --clutter-only] [--max-votes V]\n"
    "      learning and recognition times of ISM trees (star and complete topologies) for the\n"
    "      ten kitchen scenes of the recordings, and a scaling run on synthetic demonstrations.\n"
    "      --json prints the scene rows as one JSON array; --synthetic-json writes the synthetic\n"
    "      rows to FILE. The clutter series recognises gedeck set 5 repeated with jitter up to\n"
    "      10,000 estimates (star and complete trees), its best compared with the exhaustive\n"
    "      search's (every repeat entering, as before they were merged) up to 500 (star) and\n"
    "      2,000 (complete) estimates; then the series without its recorded set (every copy\n"
    "      jittered), with the same time targets; --max-votes sets its exact search's votes cap\n"
    "      per ISM (default: the library's).\n"
    "  topology [--json] [--out DIR] [--scenes A,B] [--recordings DIR] [--tests N] [--alpha A]\n"
    "           [--beta B] [--max-duration-ms D] [--max-evaluations E] [--seed S]\n"
    "           [--synthetic-max-objects N] [--threads T] [--no-synthetic]\n"
    "      the paper's kitchen table: star, RTS-optimised and complete trees of the ten kitchen\n"
    "      scenes (relations, false positives, recognition time), and the runtime plot of\n"
    "      optimised trees of synthetic scenes; tables and plot in DIR (default out/topology).\n"
    "  exact [--recordings DIR] [--scene NAME] [--tests N] [--demo FILE --scene NAME]\n"
    "        [--max-votes V] [--max-comparisons C] [--max-pose-steps P] [--diverse K]\n"
    "        [--subsets S]\n"
    "      what the exact tree search costs where its bound is loosest: topology selection's N\n"
    "      (200) test configurations of each kitchen scene (or of a scene of FILE), recognised\n"
    "      by the complete tree with and without it (times, the work it spent, where it gave up\n"
    "      or raised the best), under its limits (default 60,000 votes, 5,000,000 comparisons;\n"
    "      where it gives up, K (32) pose-diverse results per sub-ISM are tried, 0: none, and\n"
    "      subsets of the seen objects are recognised within S (20,000,000) units of work, 0: "
    "none).\n";

}  // namespace

int main(int argc, char** argv) {
  return asr_common::cli::runCommandMain(
      "asr_bench", kUsage,
      {{"recognition", asr_ism_tree::bench::runRecognitionCommand},
       {"topology", asr_ism_tree::bench::runTopologyCommand},
       {"exact", asr_ism_tree::bench::runExactSearchCommand}},
      argc, argv);
}
