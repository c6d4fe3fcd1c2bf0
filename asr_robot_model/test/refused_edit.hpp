// Test support: a valid file edited into a broken one must be refused with an InputError that
// names the file and the field.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "asr_common/testing/input_error_of.hpp"
#include "asr_common/testing/temp_dir.hpp"

namespace asr_robot_model::testing {

/// Writes `text` with its first `from` replaced by `to` as `name` in `dir`, runs `load(path)` and
/// expects an InputError whose message holds the path and `field`.
template <typename Load>
void expectEditRefused(const asr_common::testing::TempDir& dir, const std::string& name,
                       std::string text, const std::string& from, const std::string& to,
                       const std::string& field, Load load) {
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  const std::string path = dir.write(name, text);
  const std::string message = asr_common::testing::inputErrorOf([&] { load(path); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find(field), std::string::npos) << "'" << field << "' in: " << message;
}

}  // namespace asr_robot_model::testing
