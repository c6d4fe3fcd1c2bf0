#include "asr_ism_tree/topology_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "asr_common/input_error.hpp"

namespace asr_ism_tree {

using asr_common::InputError;

namespace {

// The form an object is written in: `type:id`, or `type` for an empty id (ObjectKey::toString).
std::string writtenName(const ObjectKey& key) {
  return key.toString();
}

// Finds the object a token of a topology file names: an exact `type:id` (or `type` for an empty
// id) first, else a type that only one object has.
std::size_t resolveObject(const std::string& token, const std::vector<ObjectKey>& objects,
                          const std::string& where) {
  std::vector<std::size_t> exact, by_type;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (writtenName(objects[i]) == token)
      exact.push_back(i);
    if (objects[i].type == token)
      by_type.push_back(i);
  }
  const auto list = [&](const std::vector<std::size_t>& indices) {
    std::string names;
    for (std::size_t i : indices)
      names += (names.empty() ? "" : ", ") + writtenName(objects[i]);
    return names;
  };
  if (exact.size() == 1)
    return exact.front();
  if (exact.size() > 1)
    throw InputError(where + ": object '" + token + "' is ambiguous (" + list(exact) + ")");
  if (by_type.size() == 1)
    return by_type.front();
  if (by_type.size() > 1) {
    throw InputError(where + ": object type '" + token + "' is ambiguous; write one of " +
                     list(by_type));
  }
  std::vector<std::size_t> all(objects.size());
  for (std::size_t i = 0; i < objects.size(); ++i)
    all[i] = i;
  throw InputError(where + ": unknown object '" + token + "' (the scene has: " + list(all) + ")");
}

std::string systemError(const std::string& path, const std::string& action) {
  return path + ": cannot " + action + ": " + std::strerror(errno);
}

void writeAll(int descriptor, const std::string& text, const std::string& path) {
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t result = ::write(descriptor, text.data() + written, text.size() - written);
    if (result < 0) {
      if (errno == EINTR)
        continue;
      throw InputError(systemError(path, "write"));
    }
    written += static_cast<std::size_t>(result);
  }
}

// Creates a new file beside `path` (same folder, so rename is atomic) with a unique name; the mode
// follows the umask like any new file.
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

std::string topologyText(const std::string& path, const RelationTopology& topology) {
  const auto& objects = topology.objects();
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const std::string name = writtenName(objects[i]);
    if (name.empty() || name.find_first_of(" \t\r\n#") != std::string::npos) {
      throw InputError(path + ": object '" + name +
                       "' cannot be written to a topology file (empty, whitespace or '#')");
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (writtenName(objects[j]) == name)
        throw InputError(path + ": two objects would both be written as '" + name + "'");
    }
  }
  std::ostringstream text;
  text << "# Relation topology: " << objects.size() << " objects, " << topology.relationCount()
       << " relations.\n"
       << "# One relation per line: OBJECT OBJECT, an object written TYPE:ID (TYPE if the id is\n"
       << "# empty); '#' starts a comment.\n"
       << "# Objects:";
  for (const auto& object : objects)
    text << ' ' << writtenName(object);
  text << '\n';
  for (const auto& [a, b] : topology.relations())
    text << writtenName(objects[a]) << ' ' << writtenName(objects[b]) << '\n';
  return text.str();
}

}  // namespace

RelationTopology readTopologyFile(const std::string& path, const std::vector<ObjectKey>& objects) {
  struct stat info;
  if (::stat(path.c_str(), &info) != 0)
    throw InputError(path + ": no such topology file");
  if (!S_ISREG(info.st_mode))
    throw InputError(path + ": not a regular file");
  std::ifstream file(path);
  if (!file)
    throw InputError(path + ": cannot open the topology file");

  RelationTopology topology(objects);
  std::string line;
  for (int number = 1; std::getline(file, line); ++number) {
    const std::string where = path + ":" + std::to_string(number);
    const std::size_t comment = line.find('#');
    if (comment != std::string::npos)
      line.erase(comment);
    std::istringstream fields(line);
    std::vector<std::string> tokens;
    for (std::string token; fields >> token;)
      tokens.push_back(token);
    if (tokens.empty())
      continue;
    if (tokens.size() != 2) {
      throw InputError(where + ": expected a relation of two objects, 'A B', got '" + line + "'");
    }
    const std::size_t a = resolveObject(tokens[0], objects, where);
    const std::size_t b = resolveObject(tokens[1], objects, where);
    if (a == b) {
      throw InputError(where + ": object " + writtenName(objects[a]) + " is related to itself");
    }
    topology.addRelation(a, b);
  }
  if (file.bad())
    throw InputError(path + ": error while reading the topology file");
  topology.requireConnected(path);
  return topology;
}

void writeTopologyFile(const std::string& path, const RelationTopology& topology) {
  // Refused before anything touches the disk: a file that cannot be read back is no use.
  topology.requireConnected(path);
  const std::string text = topologyText(path, topology);

  std::string temporary_path;
  const int descriptor = createTemporaryBeside(path, temporary_path);
  try {
    writeAll(descriptor, text, temporary_path);
    // An existing file keeps its permissions.
    struct stat info;
    if (::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode))
      ::fchmod(descriptor, info.st_mode & 07777);
    // On disk before the rename, so a crash cannot leave an empty file under the real name.
    if (::fsync(descriptor) != 0)
      throw InputError(systemError(temporary_path, "flush"));
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
}

}  // namespace asr_ism_tree
