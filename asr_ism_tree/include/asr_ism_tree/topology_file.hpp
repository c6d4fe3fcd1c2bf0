#pragma once

#include <string>
#include <vector>

#include "asr_ism_tree/relation_topology.hpp"

namespace asr_ism_tree {

/// Reads a relation topology over `objects` from a plain-text file: one relation per line,
/// `A B`, where an object is written `type:id`, or just `type` when its id is empty or its type is
/// unique among `objects`. `#` starts a comment; blank lines are ignored. A relation listed twice
/// counts once. Throws InputError naming the file (and the line, where there is one) if the file
/// is missing or unreadable, a line is not two objects, an object is unknown or its plain type is
/// ambiguous, an object is related to itself, or the topology is not connected.
RelationTopology readTopologyFile(const std::string& path, const std::vector<ObjectKey>& objects);

/// Writes `topology` in the format readTopologyFile reads, with a header comment, objects as
/// `type:id` (plain `type` where the id is empty). The file is written to a temporary file in the
/// same folder and then renamed over `path`, so `path` holds either its old content or the
/// complete new one, never a part. Throws InputError naming the file if the topology is not
/// connected, an object cannot be written unambiguously (whitespace or `#` in its name, or two
/// objects written alike), or the file cannot be written.
void writeTopologyFile(const std::string& path, const RelationTopology& topology);

}  // namespace asr_ism_tree
