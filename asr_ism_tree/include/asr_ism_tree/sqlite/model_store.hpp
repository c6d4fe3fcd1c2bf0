#pragma once

#include <string>
#include <vector>

#include "asr_ism_tree/ism_tree.hpp"

namespace asr_ism_tree::sqlite {

/// Version of the model tables this code writes and reads.
constexpr int kModelSchemaVersion = 1;

/// Stores a learned tree in `path` (created if missing; an existing demonstration file works
/// too). The suite's own tables (prefix `asr_ism_`, schema version in `asr_ism_schema`) are
/// created if missing; a previous model of the same scene is replaced; every other table and row
/// stays as it was. The whole write is one transaction: an error leaves the file unchanged.
/// `source` records where the model came from (e.g. the demonstration file). Throws InputError
/// naming the file if it is not SQLite or holds model tables of a newer schema version.
void saveIsmTree(const std::string& path, const IsmTree& tree, const std::string& source);

/// Loads the tree of `scene` from `path`. Throws InputError naming the file for a missing file,
/// a file without models, an unknown scene (listing the known ones) or an inconsistent model.
IsmTree loadIsmTree(const std::string& path, const std::string& scene);

/// Scenes with a stored tree in `path`, in the order they were first stored.
std::vector<std::string> listModelScenes(const std::string& path);

}  // namespace asr_ism_tree::sqlite
