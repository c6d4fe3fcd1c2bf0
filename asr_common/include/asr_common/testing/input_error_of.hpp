// Test support for the suite's gtests (needs gtest): the message of an expected InputError.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "asr_common/input_error.hpp"

namespace asr_common::testing {

/// Runs `call` and returns the message of the InputError it throws; fails the test if it throws
/// none (and returns an empty string).
template <typename Call>
std::string inputErrorOf(Call call) {
  try {
    call();
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no InputError thrown";
  return {};
}

}  // namespace asr_common::testing
