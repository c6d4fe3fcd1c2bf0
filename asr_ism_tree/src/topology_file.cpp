#include "asr_ism_tree/topology_file.hpp"

#include <sys/stat.h>

#include <fstream>
#include <sstream>

#include "asr_common/atomic_file.hpp"
#include "asr_common/input_error.hpp"
#include "asr_common/object_name.hpp"

namespace asr_ism_tree {

using asr_common::InputError;

namespace {

// The form an object is written in: `type:id`, or `type` for an empty id (ObjectKey::toString).
std::string writtenName(const ObjectKey& key) {
  return key.toString();
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
    const std::size_t a = asr_common::resolveObjectName(tokens[0], objects, where);
    const std::size_t b = asr_common::resolveObjectName(tokens[1], objects, where);
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

  asr_common::writeFileAtomically(path, text);
}

}  // namespace asr_ism_tree
