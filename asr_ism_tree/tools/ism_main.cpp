// `asr ism <command> ...`: learn ISM trees, show them, recognise scenes from the command line.
#include <iostream>
#include <map>

#include "asr_ism/input_error.hpp"
#include "command_line.hpp"
#include "commands.hpp"

namespace {

const char* const kUsage =
    "usage: ism <command> [options]\n"
    "commands:\n"
    "  learn      --demo DB --scene NAME --topology star|complete|FILE [--star-center TYPE[:ID]]\n"
    "             --model OUT [--bin-size M] [--max-angle-deg D]\n"
    "  info       --model M [--scene NAME]\n"
    "  recognize  --model M --scene NAME (--objects FILE | --demo DB --set K) [--json]\n";

}  // namespace

int main(int argc, char** argv) {
  using namespace asr_ism_tree::tools;
  const std::map<std::string, int (*)(const std::vector<std::string>&)> commands = {
      {"learn", runLearn}, {"info", runInfo}, {"recognize", runRecognize}};
  if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    std::cout << kUsage;
    return argc < 2 ? 2 : 0;
  }
  const auto command = commands.find(argv[1]);
  if (command == commands.end()) {
    std::cerr << "ism: unknown command '" << argv[1] << "'\n" << kUsage;
    return 2;
  }
  try {
    return command->second(std::vector<std::string>(argv + 2, argv + argc));
  } catch (const UsageError& error) {
    std::cerr << "ism " << argv[1] << ": " << error.message << "\n" << kUsage;
    return 2;
  } catch (const asr_ism::InputError& error) {
    std::cerr << "ism " << argv[1] << ": error: " << error.what() << "\n";
    return 1;
  }
}
