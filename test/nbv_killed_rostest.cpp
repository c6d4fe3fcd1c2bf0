// System test: search.launch on the kitchen, and the next-best-view planner killed (SIGKILL, as
// a crash) once the search is under way. The search ends `aborted` with a reason naming the
// planner, the executive keeps running and says so; it never hangs. Wall-clock waits are hang
// guards only.
#include <gtest/gtest.h>
#include <signal.h>

#include "asr_common/testing/rostest_support.hpp"
#include "search_launch.hpp"

namespace asr_integration_tests {
namespace {

TEST(NbvKilled, TheSearchEndsAbortedNamingThePlanner) {
  SearchLaunch launch("nbv_killed",
                      {"world:=" + kitchenWorld(), "model_files:=[" + kitchenModels() + "]",
                       "seed:=1", "part_timeout:=30"});
  // Under way: the direct search has begun. Its first find leads to the indirect search, which
  // asks the planner, and one view finds at most a few of the 14 objects: the search needs the
  // planner many times more after this point, so a request meets it dead.
  ASSERT_TRUE(launch.waitForState("DIRECT_SEARCH"))
      << "the search never began; last state " << launch.lastState() << "\n"
      << launch.logTail();
  const std::optional<int> pid = nodePid("/next_best_view");
  ASSERT_TRUE(pid) << "the master does not know /next_best_view";
  ASSERT_EQ(::kill(*pid, SIGKILL), 0);

  const auto result = launch.waitForResult();
  ASSERT_TRUE(result) << "no result after the planner was killed (a hang); last state "
                      << launch.lastState() << "\n"
                      << launch.logTail();
  EXPECT_EQ((*result)["outcome"], "aborted") << result->dump(1);
  EXPECT_NE((*result)["reason"].get<std::string>().find("next_best_view"), std::string::npos)
      << (*result)["reason"];
  EXPECT_TRUE(launch.waitForState("aborted", 30.0)) << launch.lastState();
  // The executive still runs (it keeps its latched state and result for whoever asks).
  EXPECT_TRUE(nodePid("/search_executive").has_value());
}

}  // namespace
}  // namespace asr_integration_tests

int main(int argc, char** argv) {
  return asr_common::testing::runRostests(argc, argv, "nbv_killed_rostest");
}
