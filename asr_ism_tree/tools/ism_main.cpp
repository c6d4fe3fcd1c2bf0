// `asr ism <command> ...`: learn ISM trees, show them, recognise scenes from the command line.
#include "asr_common/cli/command_main.hpp"
#include "commands.hpp"

namespace {

const char* const kUsage =
    "usage: ism <command> [options]\n"
    "commands:\n"
    "  learn      --demo DB --scene NAME --topology star|complete|FILE [--star-center TYPE[:ID]]\n"
    "             --model OUT [--bin-size M] [--max-angle-deg D]\n"
    "  info       --model M [--scene NAME]\n"
    "  recognize  --model M --scene NAME (--objects FILE | --demo DB --set K) [--json]\n"
    "             [--max-estimates N]\n"
    "  select-topology --demo DB --scene NAME --topology-out FILE --model OUT [--tests N]\n"
    "             [--seed S] [--alpha A] [--beta B] [--max-duration-ms D] [--max-height H]\n"
    "             [--max-evaluations E] [--method hill-climbing|annealing] [--start FILE]\n"
    "             [--threads T] [--tests-in DB | --tests-out DB]\n"
    "             [--bin-size M] [--max-angle-deg D]\n";

}  // namespace

int main(int argc, char** argv) {
  using namespace asr_ism_tree::tools;
  return asr_common::cli::runCommandMain("ism", kUsage,
                                         {{"learn", runLearn},
                                          {"info", runInfo},
                                          {"recognize", runRecognize},
                                          {"select-topology", runSelectTopology}},
                                         argc, argv);
}
