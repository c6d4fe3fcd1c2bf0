// `asr_bench <benchmark> ...`: performance benchmarks of the ISM tree engine.
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "asr_ism/input_error.hpp"
#include "command_line.hpp"
#include "recognition_command.hpp"

namespace {

const char* const kUsage =
    "usage: asr_bench <benchmark> [options]\n"
    "benchmarks:\n"
    "  recognition [--json] [--recordings DIR] [--threads N] [--no-synthetic]\n"
    "              [--synthetic-json FILE]\n"
    "      learning and recognition times of ISM trees (star and complete topologies) for the\n"
    "      ten kitchen scenes of the recordings, and a scaling run on synthetic demonstrations.\n"
    "      --json prints the scene rows as one JSON array; --synthetic-json writes the synthetic\n"
    "      rows to FILE.\n";

}  // namespace

int main(int argc, char** argv) {
  using asr_ism_tree::tools::UsageError;
  const std::map<std::string, int (*)(const std::vector<std::string>&)> benchmarks = {
      {"recognition", asr_ism_tree::bench::runRecognitionCommand}};
  if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    std::cout << kUsage;
    return argc < 2 ? 2 : 0;
  }
  const auto benchmark = benchmarks.find(argv[1]);
  if (benchmark == benchmarks.end()) {
    std::cerr << "asr_bench: unknown benchmark '" << argv[1] << "'\n" << kUsage;
    return 2;
  }
  try {
    return benchmark->second(std::vector<std::string>(argv + 2, argv + argc));
  } catch (const UsageError& error) {
    std::cerr << "asr_bench " << argv[1] << ": " << error.message << "\n" << kUsage;
    return 2;
  } catch (const asr_ism::InputError& error) {
    std::cerr << "asr_bench " << argv[1] << ": error: " << error.what() << "\n";
    return 1;
  }
}
