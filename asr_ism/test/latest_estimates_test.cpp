#include "asr_ism/latest_estimates.hpp"

#include <gtest/gtest.h>

namespace asr_ism {
namespace {

ObjectEstimate estimate(const std::string& type, const std::string& id, double x) {
  return {{type, id}, Pose(Eigen::Vector3d(x, 0.0, 0.0), Eigen::Quaterniond::Identity())};
}

TEST(LatestEstimates, KeepsTheNewestEstimatePerObject) {
  LatestEstimates latest;
  latest.update(estimate("Cup", "1", 1.0), 10.0);
  latest.update(estimate("Cup", "1", 2.0), 12.0);
  latest.update(estimate("Cup", "1", 3.0), 11.0);  // older than what is kept: ignored
  latest.update(estimate("Cup", "2", 4.0), 11.0);  // another instance of the type
  const Configuration now = latest.current(12.0, 5.0);
  ASSERT_EQ(now.size(), 2u);
  EXPECT_EQ(now[0].key, (ObjectKey{"Cup", "1"}));
  EXPECT_EQ(now[0].pose.position.x(), 2.0);
  EXPECT_EQ(now[1].key, (ObjectKey{"Cup", "2"}));
}

TEST(LatestEstimates, LeavesOutObjectsNotSeenWithinTheTimeout) {
  LatestEstimates latest;
  latest.update(estimate("Plate", "", 0.0), 0.0);
  latest.update(estimate("Cup", "", 0.0), 9.0);
  EXPECT_EQ(latest.current(10.0, 2.0).size(), 1u);
  EXPECT_EQ(latest.current(10.0, 10.0).size(), 2u);  // exactly at the time-out: still current
  EXPECT_EQ(latest.current(10.0, 0.0).size(), 2u);   // no time-out
  EXPECT_EQ(latest.size(), 2u);
  latest.clear();
  EXPECT_TRUE(latest.current(10.0, 0.0).empty());
}

}  // namespace
}  // namespace asr_ism
