#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "asr_ism/demonstration.hpp"

namespace asr_ism::sqlite {

class Database;

/// Appends recorded configurations to a demonstration file in the original ASR schema
/// (recorded_patterns, recorded_sets, recorded_objects, recorded_poses), so the original tools and
/// this suite's reader both read it. The file and its tables are created if missing; existing
/// rows are never changed or removed. Each configuration is written in one transaction, so a
/// crash loses at most the configuration being written.
class DemonstrationWriter {
 public:
  /// Throws InputError naming the file if it is not SQLite or its recorded_* tables do not have
  /// the original columns.
  explicit DemonstrationWriter(const std::string& path);
  ~DemonstrationWriter();
  DemonstrationWriter(const DemonstrationWriter&) = delete;
  DemonstrationWriter& operator=(const DemonstrationWriter&) = delete;

  /// Appends `configuration` as a new recorded set of `scene` (created if new); objects are
  /// matched by (type, observedId) and created if new. Returns the new set's id. Throws
  /// InputError for an empty scene name, an empty configuration, a non-finite pose or a zero
  /// quaternion (also for an object with an empty type, an object listed twice, or a quaternion
  /// that the reader would refuse as not normalised); nothing is written then. Quaternions are
  /// stored canonicalised (unit length, w >= 0) in the columns qw, qx, qy, qz.
  std::int64_t appendConfiguration(const std::string& scene, const Configuration& configuration);

 private:
  std::unique_ptr<Database> db_;
};

/// Appends every time step of `demonstration` to `path` as recorded sets of its scene, in one
/// transaction. Steps without any observed object are skipped. Every step is validated as in
/// appendConfiguration before anything is written; a demonstration without any observed object
/// is an InputError too. Reading it back gives the objects in order of first observation.
void appendDemonstration(const std::string& path, const Demonstration& demonstration);

}  // namespace asr_ism::sqlite
