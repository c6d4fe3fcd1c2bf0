// Test support for the suite's gtests (needs gtest): run a built command-line tool as a user
// does and look at its exit code, stdout and stderr.
#pragma once

#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>

#include "asr_common/child_process.hpp"
#include "asr_common/testing/temp_dir.hpp"

namespace asr_common::testing {

struct ToolRun {
  int exit_code = -1;
  std::string out;
  std::vector<std::string> err;  // stderr, line by line
};

inline std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> result;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);)
    result.push_back(line);
  return result;
}

/// Runs `tool arguments...` with no standard input; stdout and stderr go through files in `dir`.
inline ToolRun runTool(const std::string& tool, const TempDir& dir,
                       const std::vector<std::string>& arguments) {
  const std::string out = dir.file("tool.stdout");
  const std::string err = dir.file("tool.stderr");
  ChildProcess process(tool, arguments, out, err);
  ToolRun run;
  run.exit_code = process.wait();
  EXPECT_NE(run.exit_code, -1) << tool << " did not exit normally";
  run.out = fileBytes(out);
  run.err = lines(fileBytes(err));
  return run;
}

/// Exit code, stdout and stderr, for failure messages.
inline std::string describe(const ToolRun& run) {
  std::string text =
      "exit code " + std::to_string(run.exit_code) + "\nstdout:\n" + run.out + "stderr:\n";
  for (const std::string& line : run.err)
    text += line + "\n";
  return text;
}

inline void expectSuccess(const ToolRun& run) {
  EXPECT_EQ(run.exit_code, 0) << describe(run);
  EXPECT_TRUE(run.err.empty()) << describe(run);
}

// Bad input to an `ism ...` tool: exit code 1, nothing on stdout, exactly one line on stderr that
// names every one of
// `named` (the offending file, scene, object...).
inline void expectInputError(const ToolRun& run, const std::vector<std::string>& named) {
  EXPECT_EQ(run.exit_code, 1) << describe(run);
  EXPECT_TRUE(run.out.empty()) << describe(run);
  ASSERT_EQ(run.err.size(), 1u) << describe(run);
  EXPECT_EQ(run.err[0].rfind("ism ", 0), 0u) << run.err[0];
  for (const std::string& name : named)
    EXPECT_NE(run.err[0].find(name), std::string::npos) << "'" << name << "' in: " << run.err[0];
}

}  // namespace asr_common::testing
