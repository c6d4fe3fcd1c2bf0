// Test support for the suite's gtests (needs gtest): a fresh folder per test and its files.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>
#include <vector>

namespace asr_common::testing {

/// The whole content of a file, byte for byte (empty if it cannot be read).
inline std::string fileBytes(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

/// A fresh, empty folder `<temp>/<prefix>_<test name>_<pid>` for the current test, removed with
/// everything in it when the TempDir goes (also after a test took permissions away). Files the
/// tests break or write live here, never in the recordings folder.
class TempDir {
 public:
  explicit TempDir(const std::string& prefix) {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = test != nullptr ? test->name() : "no_test";
    // Parameterised tests are named "Test/0": keep the folder one level deep.
    std::replace_if(
        name.begin(), name.end(),
        [](unsigned char c) { return !std::isalnum(c) && c != '_' && c != '-'; }, '_');
    path_ = std::filesystem::temp_directory_path() /
            (prefix + "_" + name + "_" + std::to_string(::getpid()));
    removeAll();
    std::filesystem::create_directories(path_);
  }
  ~TempDir() { removeAll(); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::string path() const { return path_.string(); }
  /// The path of `name` in the folder (the file need not exist).
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  /// Writes `text` to `name` in the folder and returns its path.
  std::string write(const std::string& name, const std::string& text) const {
    const std::string target = file(name);
    std::ofstream(target, std::ios::binary) << text;
    return target;
  }
  /// A writable copy of `source` (e.g. a read-only recording) under its own file name.
  std::string copyOf(const std::string& source) const {
    const std::string target = file(std::filesystem::path(source).filename().string());
    std::filesystem::copy_file(source, target);
    std::filesystem::permissions(
        target, std::filesystem::perms::owner_read | std::filesystem::perms::owner_write);
    return target;
  }
  /// The names of the folder's entries, sorted.
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(path_))
      names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

 private:
  // Gives the owner back full access to every folder below (a test may have made one read-only)
  // so that everything can be removed; never throws.
  static void restoreOwnerAccess(const std::filesystem::path& folder) {
    std::error_code error;
    std::filesystem::permissions(folder, std::filesystem::perms::owner_all,
                                 std::filesystem::perm_options::add, error);
    for (std::filesystem::directory_iterator entry(folder, error), end; !error && entry != end;
         entry.increment(error)) {
      if (entry->is_directory(error) && !entry->is_symlink(error))
        restoreOwnerAccess(entry->path());
    }
  }
  void removeAll() const {
    std::error_code error;
    if (!std::filesystem::exists(path_, error))
      return;
    restoreOwnerAccess(path_);
    std::filesystem::remove_all(path_, error);
  }

  std::filesystem::path path_;
};

}  // namespace asr_common::testing
