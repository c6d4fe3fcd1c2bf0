#include "asr_common/cli/targets.hpp"

#include <ostream>

namespace asr_common::cli {

void printTargets(std::ostream& out, const std::vector<Target>& targets) {
  if (targets.empty()) {
    out << "Targets: none checked (nothing was measured)\n";
    return;
  }
  out << "Targets\n";
  std::size_t met = 0;
  for (const Target& target : targets) {
    out << (target.met ? "  met     " : "  MISSED  ") << target.target << ": " << target.measured
        << "\n";
    met += target.met ? 1 : 0;
  }
  out << "  " << met << " of " << targets.size() << " targets met\n";
}

}  // namespace asr_common::cli
