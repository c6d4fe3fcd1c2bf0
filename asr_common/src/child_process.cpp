#include "asr_common/child_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <stdexcept>
#include <thread>

extern char** environ;

namespace asr_common {
namespace {

// The file actions of a child: stdin from /dev/null, stdout and stderr to files where given.
class FileActions {
 public:
  FileActions(const std::string& stdout_path, const std::string& stderr_path) {
    ::posix_spawn_file_actions_init(&actions_);
    ::posix_spawn_file_actions_addopen(&actions_, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    if (!stdout_path.empty()) {
      ::posix_spawn_file_actions_addopen(&actions_, STDOUT_FILENO, stdout_path.c_str(),
                                         O_WRONLY | O_CREAT | O_TRUNC, 0644);
    }
    if (!stderr_path.empty()) {
      ::posix_spawn_file_actions_addopen(&actions_, STDERR_FILENO, stderr_path.c_str(),
                                         O_WRONLY | O_CREAT | O_TRUNC, 0644);
    }
  }
  FileActions(const FileActions&) = delete;
  FileActions& operator=(const FileActions&) = delete;
  ~FileActions() { ::posix_spawn_file_actions_destroy(&actions_); }
  const posix_spawn_file_actions_t* get() const { return &actions_; }

 private:
  posix_spawn_file_actions_t actions_;
};

}  // namespace

ChildProcess::ChildProcess(const std::string& executable, const std::vector<std::string>& arguments,
                           const std::string& stdout_path, const std::string& stderr_path) {
  std::vector<std::string> all = {executable};
  all.insert(all.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& argument : all)
    argv.push_back(argument.data());
  argv.push_back(nullptr);
  const FileActions actions(stdout_path, stderr_path);
  if (::posix_spawn(&pid_, executable.c_str(), actions.get(), nullptr, argv.data(), environ) != 0) {
    pid_ = -1;
    throw std::runtime_error("cannot start " + executable);
  }
}

void ChildProcess::collect(int status) {
  exit_status_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  pid_ = -1;
}

bool ChildProcess::running() {
  if (pid_ <= 0)
    return false;
  int status = 0;
  if (::waitpid(pid_, &status, WNOHANG) == pid_) {
    collect(status);
    return false;
  }
  return true;
}

int ChildProcess::waitForExit(std::chrono::duration<double> timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (running() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  return running() ? -1 : exit_status_;
}

int ChildProcess::wait() {
  if (pid_ > 0) {
    int status = 0;
    if (::waitpid(pid_, &status, 0) == pid_)
      collect(status);
  }
  return exit_status_;
}

void ChildProcess::stop(std::chrono::duration<double> grace) {
  if (pid_ <= 0)
    return;
  ::kill(pid_, SIGINT);
  if (waitForExit(grace) == -1 && pid_ > 0) {
    ::kill(pid_, SIGKILL);
    wait();
  }
}

}  // namespace asr_common
