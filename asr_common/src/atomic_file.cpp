#include "asr_common/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>

#include "asr_common/input_error.hpp"

namespace asr_common {
namespace {

std::string systemError(const std::string& path, const std::string& action) {
  return path + ": cannot " + action + ": " + std::strerror(errno);
}

void writeAll(int descriptor, const std::string& content, const std::string& path) {
  std::size_t written = 0;
  while (written < content.size()) {
    const ssize_t result = ::write(descriptor, content.data() + written, content.size() - written);
    if (result < 0) {
      if (errno == EINTR)
        continue;
      throw InputError(systemError(path, "write"));
    }
    written += static_cast<std::size_t>(result);
  }
}

// Creates a new file beside `path` (same folder, so the rename is atomic) with a unique name.
int createTemporaryBeside(const std::string& path, std::string& temporary_path) {
  static std::atomic<unsigned> counter{0};
  for (int attempt = 0; attempt < 100; ++attempt) {
    temporary_path = path + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    const int descriptor = ::open(temporary_path.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0666);
    if (descriptor >= 0)
      return descriptor;
    if (errno != EEXIST)
      throw InputError(systemError(path, "create a temporary file beside it"));
  }
  throw InputError(path + ": cannot create a temporary file beside it (all names taken)");
}

// Content, permissions of the file it replaces, and a flush to disk before the rename, so a
// crash cannot leave an empty file under the real name.
void fillTemporary(int descriptor, const std::string& path, const std::string& temporary_path,
                   const std::string& content) {
  writeAll(descriptor, content, temporary_path);
  struct stat info;
  if (::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode))
    ::fchmod(descriptor, info.st_mode & 07777);
  if (::fsync(descriptor) != 0)
    throw InputError(systemError(temporary_path, "flush"));
}

// The folder's entry for the renamed file reaches the disk too. A folder that cannot be opened
// for this (some file systems) leaves the rename done but not yet flushed, which is no error.
void flushFolderOf(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  const std::string folder = slash == std::string::npos ? "."
                             : slash == 0               ? "/"
                                                        : path.substr(0, slash);
  const int descriptor = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY);
  if (descriptor < 0)
    return;
  ::fsync(descriptor);
  ::close(descriptor);
}

}  // namespace

void writeFileAtomically(const std::string& path, const std::string& content) {
  std::string temporary_path;
  const int descriptor = createTemporaryBeside(path, temporary_path);
  try {
    fillTemporary(descriptor, path, temporary_path, content);
  } catch (...) {
    ::close(descriptor);
    ::unlink(temporary_path.c_str());
    throw;
  }
  if (::close(descriptor) != 0) {
    const std::string message = systemError(temporary_path, "close");
    ::unlink(temporary_path.c_str());
    throw InputError(message);
  }
  if (::rename(temporary_path.c_str(), path.c_str()) != 0) {
    const std::string message = systemError(path, "replace it with " + temporary_path);
    ::unlink(temporary_path.c_str());
    throw InputError(message);
  }
  flushFolderOf(path);
}

}  // namespace asr_common
