#pragma once

#include <sys/types.h>

#include <chrono>
#include <string>
#include <vector>

namespace asr_common {

/// A program run as a child process, the one way the suite starts nodes and tools from tests
/// and benchmarks: no shell (arguments pass as they are), standard input from /dev/null, and
/// stopped (SIGINT, so a node shuts down cleanly) when the object goes.
class ChildProcess {
 public:
  /// Starts `executable` with `arguments` (e.g. "__name:=recognizer", "_rate:=5"). Its stdout
  /// and stderr go to the files `stdout_path` and `stderr_path` (created or truncated), or to
  /// this process's where a path is empty. Throws std::runtime_error naming the executable if
  /// it cannot be started.
  ChildProcess(const std::string& executable, const std::vector<std::string>& arguments,
               const std::string& stdout_path = "", const std::string& stderr_path = "");
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;
  ~ChildProcess() { stop(); }

  /// True while the process runs.
  bool running();

  /// Waits up to `timeout` for the process to end by itself; its exit code, or -1 (it still runs
  /// or was ended by a signal).
  int waitForExit(std::chrono::duration<double> timeout);

  /// Waits for the process to end by itself; its exit code, or -1 if a signal ended it.
  int wait();

  /// SIGINT, then SIGKILL if it still runs `grace` later (roslaunch needs longer than a node:
  /// it stops its nodes first).
  void stop(std::chrono::duration<double> grace = std::chrono::seconds(2));

 private:
  void collect(int status);

  pid_t pid_ = -1;
  int exit_status_ = -1;
};

}  // namespace asr_common
