#include "asr_common/cli/command_main.hpp"

#include <cstdio>
#include <exception>
#include <iostream>

#include "asr_common/cli/command_line.hpp"
#include "asr_common/input_error.hpp"

namespace asr_common::cli {

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

namespace {

// Runs `command`, turning its exceptions into one line after `name` and an exit code: 2 and the
// usage for a UsageError, 1 for bad input or anything else.
int runGuarded(const std::string& name, const std::string& usage, Command command,
               const std::vector<std::string>& arguments) {
  try {
    return command(arguments);
  } catch (const UsageError& error) {
    std::cerr << name << oneLine(error.message) << "\n" << usage;
    return 2;
  } catch (const InputError& error) {
    std::cerr << name << "error: " << oneLine(error.what()) << "\n";
    return 1;
  } catch (const std::exception& error) {
    // Not expected (the core reports bad input as InputError), but still one line, not an abort.
    std::cerr << name << "internal error: " << oneLine(error.what()) << "\n";
    return 1;
  }
}

bool asksForHelp(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h")
      return true;
  }
  return false;
}

}  // namespace

int runCommandMain(const std::string& program, const std::string& usage,
                   const std::map<std::string, Command>& commands, int argc, char** argv) {
  if (argc < 2) {
    std::cerr << program << ": no command given\n" << usage;
    return 2;
  }
  if (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    std::cout << usage;
    return 0;
  }
  const auto command = commands.find(argv[1]);
  if (command == commands.end()) {
    std::cerr << program << ": unknown command '" << oneLine(argv[1]) << "'\n" << usage;
    return 2;
  }
  // `program command --help` is a question, not a misspelt option: the usage, exit code 0.
  if (asksForHelp(argc, argv)) {
    std::cout << usage;
    return 0;
  }
  return runGuarded(program + " " + argv[1] + ": ", usage, command->second,
                    std::vector<std::string>(argv + 2, argv + argc));
}

int runToolMain(const std::string& program, const std::string& usage, Command run, int argc,
                char** argv) {
  if (asksForHelp(argc, argv)) {
    std::cout << usage;
    return 0;
  }
  return runGuarded(program + ": ", usage, run, std::vector<std::string>(argv + 1, argv + argc));
}

int runSingleCommandMain(const std::string& program, const std::string& command,
                         const std::string& usage, Command run, int argc, char** argv) {
  if (asksForHelp(argc, argv)) {
    std::cout << usage;
    return 0;
  }
  const std::vector<std::string> arguments(argv + (argc > 1 && command == argv[1] ? 2 : 1),
                                           argv + argc);
  return runGuarded(program + " " + command + ": ", usage, run, arguments);
}

}  // namespace asr_common::cli
