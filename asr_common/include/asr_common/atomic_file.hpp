#pragma once

#include <string>

namespace asr_common {

/// Writes `content` to `path` so that `path` holds either its old content or all of the new one,
/// never a part, even if the process or the machine stops half-way: the content goes to a new
/// temporary file in the same folder, which is flushed to disk and renamed over `path`, and the
/// folder is flushed so that the rename itself survives a crash. An existing file keeps its
/// permissions; a new one gets the umask's. Throws InputError naming `path` (and the system's
/// reason) if anything fails; the temporary file is then removed and `path` left as it was.
void writeFileAtomically(const std::string& path, const std::string& content);

}  // namespace asr_common
