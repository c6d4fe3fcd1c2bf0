#pragma once

#include <memory>
#include <string>
#include <vector>

#include "asr_state_machine/search_executive.hpp"

namespace asr_state_machine {

/// What one in-process search is asked to do (`asr search`).
struct SearchRequest {
  std::string world;                     // world file (asr_robot_model's format)
  std::vector<std::string> model_files;  // ISM-tree model databases
  std::vector<std::string> scenes;       // searched scenes; empty: every scene of the models
  std::string demonstrated;              // objects file of demonstrated poses (may be empty)
  std::string catalogue;                 // object catalogue; empty: the shipped one
  SearchConfig config;
  /// Start pose disturbance (bench): metres and radians of seeded uniform noise on x, y and yaw.
  double start_jitter = 0.0;
};

/// One search with the in-process parts, on simulated time. Construction loads and checks every
/// input, so bad input (a world, model or scene that does not exist, a required scene no model
/// holds) fails with asr_common::InputError naming it before anything moves.
class InProcessSearch {
 public:
  explicit InProcessSearch(const SearchRequest& request);
  ~InProcessSearch();
  InProcessSearch(const InProcessSearch&) = delete;
  InProcessSearch& operator=(const InProcessSearch&) = delete;

  SearchResult run();

 private:
  struct Setup;
  std::unique_ptr<Setup> setup_;
};

}  // namespace asr_state_machine
