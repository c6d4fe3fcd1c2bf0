// The one checked integer parsing of the suite's tools: out of range is refused, never truncated.

#include "asr_common/cli/command_line.hpp"

#include <gtest/gtest.h>

#include <climits>
#include <random>

namespace asr_common::cli {
namespace {

CommandLine withValue(const std::string& text) {
  return CommandLine({"--n", text}, {"n"}, {});
}

std::string usageErrorOf(const CommandLine& options, long long min, long long max) {
  try {
    options.integer("n", 0, min, max);
  } catch (const UsageError& error) {
    return error.message;
  }
  return "";
}

TEST(CommandLineInteger, EveryValueIsAcceptedExactlyWhenInRange) {
  // Property over random values and ranges, near the edges of 32 and 64 bits included.
  std::mt19937_64 random(5);
  const long long edges[] = {0,       1,         -1,       4294967295LL, 4294967296LL, 4294967303LL,
                             INT_MAX, LLONG_MAX, LLONG_MIN};
  for (int trial = 0; trial < 2000; ++trial) {
    const long long a = trial % 3 == 0 ? edges[random() % 9] : static_cast<long long>(random());
    const long long b =
        trial % 5 == 0 ? edges[random() % 9] : static_cast<long long>(random() >> (random() % 64));
    const long long min = std::min(a, b), max = std::max(a, b);
    const long long value =
        trial % 2 == 0 ? edges[random() % 9] : static_cast<long long>(random() >> (random() % 64));
    const CommandLine options = withValue(std::to_string(value));
    if (value >= min && value <= max) {
      EXPECT_EQ(options.integer("n", 0, min, max), value);
    } else {
      const std::string message = usageErrorOf(options, min, max);
      EXPECT_NE(message.find("--n is out of range: " + std::to_string(value)), std::string::npos)
          << message;
      EXPECT_NE(message.find("[" + std::to_string(min) + ", " + std::to_string(max) + "]"),
                std::string::npos)
          << message;
    }
  }
}

TEST(CommandLineInteger, TheIssuesExamplesAreRefused) {
  // --seed 4294967303 was seed 7; --max-height 4294967296 was "unlimited".
  EXPECT_NE(usageErrorOf(withValue("4294967303"), 0, 4294967295LL).find("out of range"),
            std::string::npos);
  EXPECT_NE(usageErrorOf(withValue("4294967296"), 0, 1000).find("out of range"), std::string::npos);
  EXPECT_NE(usageErrorOf(withValue("-1"), 0, 4294967295LL).find("out of range"), std::string::npos);
  EXPECT_NE(usageErrorOf(withValue("99999999999999999999"), 0, LLONG_MAX).find("out of range"),
            std::string::npos);
  for (const char* text : {"", "7x", " 7", "+7", "1e3", "0x10", "7.0", "-", "seven"}) {
    EXPECT_NE(usageErrorOf(withValue(text), 0, 100).find("needs an integer in [0, 100]"),
              std::string::npos)
        << "'" << text << "'";
  }
  EXPECT_EQ(withValue("-5").integer("n", 0, -10, 10), -5);
  EXPECT_EQ(CommandLine({}, {"n"}, {}).integer("n", 42, 0, 10), 42);  // the fallback as given
}

TEST(CommandLineNumbers, ExactlyTheCountOfFiniteNumbers) {
  EXPECT_EQ(withValue(" 1 -2.5  3e1 ").numbers("n", 3, "a b c"),
            (std::vector<double>{1.0, -2.5, 30.0}));
  for (const char* bad : {"1 2", "1 2 3 4", "1 nan 3", "1 inf 3", "1 2x 3", ""}) {
    try {
      withValue(bad).numbers("n", 3, "a b c");
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const UsageError& error) {
      EXPECT_NE(error.message.find("--n"), std::string::npos) << error.message;
    }
  }
  EXPECT_THROW(CommandLine({}, {"n"}, {}).numbers("n", 1, "a"), UsageError);  // required
}

}  // namespace
}  // namespace asr_common::cli
