#pragma once

#include <string>
#include <vector>

namespace asr_ism_tree::tools {

// Each subcommand of `asr ism`: parses its options, runs the core, prints; returns the exit code.
int runLearn(const std::vector<std::string>& arguments);
int runInfo(const std::vector<std::string>& arguments);
int runRecognize(const std::vector<std::string>& arguments);
int runSelectTopology(const std::vector<std::string>& arguments);

}  // namespace asr_ism_tree::tools
