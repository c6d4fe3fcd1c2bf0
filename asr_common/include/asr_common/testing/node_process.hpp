// Test support for rostests: start one of the suite's nodes as a child process with private
// parameters given on its command line (`_name:=value`), after the test has prepared its input
// files, and stop it when the test ends.
#pragma once

#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace asr_common::testing {

class NodeProcess {
 public:
  /// Starts `executable` with `arguments` (e.g. "__name:=recognizer", "_rate:=5").
  NodeProcess(const std::string& executable, const std::vector<std::string>& arguments) {
    std::vector<std::string> all = {executable};
    all.insert(all.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (std::string& argument : all)
      argv.push_back(argument.data());
    argv.push_back(nullptr);
    if (::posix_spawn(&pid_, executable.c_str(), nullptr, nullptr, argv.data(), environ) != 0) {
      pid_ = -1;
      ADD_FAILURE() << "cannot start " << executable;
    }
  }
  NodeProcess(const NodeProcess&) = delete;
  NodeProcess& operator=(const NodeProcess&) = delete;

  ~NodeProcess() { stop(); }

  /// True while the process runs.
  bool running() {
    if (pid_ <= 0)
      return false;
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) == pid_) {
      exit_status_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      pid_ = -1;
      return false;
    }
    return true;
  }

  /// Waits up to `timeout` for the process to end by itself; its exit code, or -1 (still runs or
  /// killed by a signal).
  int waitForExit(std::chrono::duration<double> timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (running() && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    return running() ? -1 : exit_status_;
  }

  /// SIGINT (a node shuts down cleanly), then SIGKILL after two seconds.
  void stop() {
    if (pid_ <= 0)
      return;
    ::kill(pid_, SIGINT);
    if (waitForExit(std::chrono::seconds(2)) == -1 && pid_ > 0) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
      pid_ = -1;
    }
  }

 private:
  pid_t pid_ = -1;
  int exit_status_ = -1;
};

}  // namespace asr_common::testing
