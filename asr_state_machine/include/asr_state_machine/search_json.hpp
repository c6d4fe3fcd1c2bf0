#pragma once

#include <nlohmann/json.hpp>

#include "asr_state_machine/search_executive.hpp"

namespace asr_state_machine {

/// {"outcome", "reason", "sim_seconds", "compute_seconds", "decision_compute_ms_median",
///  "views", "found": [{"type", "id", "pose", "found_at_s", "view"}],
///  "scenes": [{"scene", "confidence"}], "log": [{"t", "state", "event", "detail",
///  "compute_ms"}]}
nlohmann::ordered_json searchResultJson(const SearchResult& result);

/// One log entry as a JSON object (also one line of a search's JSON-lines log).
nlohmann::ordered_json logEntryJson(const LogEntry& entry);

}  // namespace asr_state_machine
