#pragma once

#include <map>
#include <string>
#include <vector>

namespace asr_common::cli {

/// A subcommand: parses its arguments, runs, prints; returns the exit code.
using Command = int (*)(const std::vector<std::string>& arguments);

/// The main() of a tool with subcommands: `program <command> [options]`. Unknown or missing
/// commands and UsageError print one line and the usage to stderr and give 2; InputError (bad
/// input) and any other exception print one line, `program command: error: ...`, and give 1.
/// Messages are kept on one line (line breaks in a path or scene name are escaped), so a caller
/// can always read the error from the last line of stderr.
int runCommandMain(const std::string& program, const std::string& usage,
                   const std::map<std::string, Command>& commands, int argc, char** argv);

/// The main() of a tool without subcommands: `program [options]`, with the exit codes and
/// one-line messages of runCommandMain (`program: error: ...`); --help or -h prints the usage.
int runToolMain(const std::string& program, const std::string& usage, Command run, int argc,
                char** argv);

/// The main() of a tool that is one subcommand of a larger front end (`ism predict`): runs `run`
/// as the only command of `program`, so errors read "program command: ..." with runCommandMain's
/// exit codes. The command's name may be given as the first argument or left out (the asr script
/// leaves it out); --help or -h anywhere prints the usage.
int runSingleCommandMain(const std::string& program, const std::string& command,
                         const std::string& usage, Command run, int argc, char** argv);

/// `message` with line breaks and other control characters escaped.
std::string oneLine(const std::string& message);

}  // namespace asr_common::cli
