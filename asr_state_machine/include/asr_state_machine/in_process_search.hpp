#pragma once

#include <memory>
#include "asr_state_machine/search_inputs.hpp"

namespace asr_state_machine {

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
