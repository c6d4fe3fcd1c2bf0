// `asr ism <command> ...`: learn ISM trees, show them, recognise scenes from the command line.
#include <cstdio>
#include <exception>
#include <iostream>
#include <map>
#include <string>

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

// The message on one line: a scene name or path with a line break in it (they come from the
// command line and from files) must not split the one error line a caller reads.
std::string oneLine(const std::string& message) {
  std::string line;
  for (char c : message) {
    const auto code = static_cast<unsigned char>(c);
    if (c == '\n') {
      line += "\\n";
    } else if (c == '\r') {
      line += "\\r";
    } else if (code < 0x20 || code == 0x7f) {
      char escape[5];
      std::snprintf(escape, sizeof escape, "\\x%02x", code);
      line += escape;
    } else {
      line += c;
    }
  }
  return line;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace asr_ism_tree::tools;
  const std::map<std::string, int (*)(const std::vector<std::string>&)> commands = {
      {"learn", runLearn}, {"info", runInfo}, {"recognize", runRecognize}};
  if (argc < 2) {
    std::cerr << "ism: no command given\n" << kUsage;
    return 2;
  }
  if (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    std::cout << kUsage;
    return 0;
  }
  const auto command = commands.find(argv[1]);
  if (command == commands.end()) {
    std::cerr << "ism: unknown command '" << oneLine(argv[1]) << "'\n" << kUsage;
    return 2;
  }
  const std::string name = "ism " + std::string(argv[1]) + ": ";
  try {
    return command->second(std::vector<std::string>(argv + 2, argv + argc));
  } catch (const UsageError& error) {
    std::cerr << name << oneLine(error.message) << "\n" << kUsage;
    return 2;
  } catch (const asr_ism::InputError& error) {
    std::cerr << name << "error: " << oneLine(error.what()) << "\n";
    return 1;
  } catch (const std::exception& error) {
    // Not expected (the core reports bad input as InputError), but still one line, not an abort.
    std::cerr << name << "internal error: " << oneLine(error.what()) << "\n";
    return 1;
  }
}
