#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "asr_state_machine/search_executive.hpp"

namespace asr_state_machine {

/// {"outcome", "reason", "sim_seconds", "compute_seconds", "decision_compute_ms_median",
///  "views", "found": [{"type", "id", "pose", "found_at_s", "view"}],
///  "scenes": [{"scene", "confidence", "objects": [{"type", "id"}]}], "start": robot state,
///  "visited": [{"camera": pose, "base": robot state, "at_s", "types"}],
///  "log": [{"t", "state", "event", "detail", "compute_ms"}]}; a robot state is
///  {"x", "y", "yaw", "pan", "tilt"}.
nlohmann::ordered_json searchResultJson(const SearchResult& result);

/// The search result that searchResultJson wrote (the parts a picture or a summary needs:
/// outcome, reason, times, start, visited views, found objects, scenes, log; the per-decision
/// compute times are not kept). Throws asr_common::InputError naming `source` and the field if
/// something is missing or malformed.
SearchResult searchResultFromJson(const nlohmann::json& json, const std::string& source);

/// searchResultFromJson of a file holding one result (what `asr search --json` prints).
SearchResult readSearchResult(const std::string& path);

/// One log entry as a JSON object (also one line of a search's JSON-lines log).
nlohmann::ordered_json logEntryJson(const LogEntry& entry);

}  // namespace asr_state_machine
