#include "asr_common/pose.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "asr_common/input_error.hpp"

namespace asr_common {
namespace {

Pose makePose(double x, double y, double z, double angle, Eigen::Vector3d axis) {
  return Pose(Eigen::Vector3d(x, y, z),
              Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis.normalized())));
}

TEST(Pose, RelativePoseRoundTrip) {
  const Pose a = makePose(1.0, -2.0, 0.5, 0.7, {1, 2, 3});
  const Pose b = makePose(-0.3, 0.4, 2.0, -2.1, {0, 1, -1});
  const Pose b_in_a = relativePose(a, b);
  EXPECT_TRUE(approximatelyEqual(compose(a, b_in_a), b, 1e-12, 1e-12));
  EXPECT_TRUE(approximatelyEqual(compose(inverse(a), a), Pose::identity(), 1e-12, 1e-12));
  EXPECT_TRUE(approximatelyEqual(relativePose(b, a), inverse(b_in_a), 1e-12, 1e-12));
}

TEST(Pose, QuaternionsAreCanonical) {
  const Pose pose(Eigen::Vector3d::Zero(), Eigen::Quaterniond(-0.5, 0.5, 0.5, 0.5));
  EXPECT_GE(pose.orientation.w(), 0.0);
  EXPECT_NEAR(pose.orientation.norm(), 1.0, 1e-15);
  EXPECT_NEAR(angleBetween(pose.orientation, Eigen::Quaterniond(0.5, -0.5, -0.5, -0.5)), 0.0,
              1e-12);
}

TEST(Pose, CanonicalisingIsIdempotentAndKeepsUnitQuaternionsBitForBit) {
  std::mt19937 random(11);
  std::normal_distribution<double> gaussian;
  int rescaled_by_normalising = 0;
  for (int i = 0; i < 1000; ++i) {
    const Eigen::Quaterniond raw(gaussian(random), gaussian(random), gaussian(random),
                                 gaussian(random));
    const Eigen::Quaterniond once = canonicalQuaternion(raw);
    EXPECT_EQ(canonicalQuaternion(once).coeffs(), once.coeffs());
    EXPECT_EQ(canonicalQuaternion(Eigen::Quaterniond(-once.coeffs())).coeffs(), once.coeffs());
    rescaled_by_normalising += once.normalized().coeffs() != once.coeffs();
  }
  // Plain normalising would have changed some of these unit quaternions in their last bits.
  EXPECT_GT(rescaled_by_normalising, 0);
}

TEST(Pose, AngleBetweenIsPreciseForTinyAndLargeAngles) {
  const Eigen::Quaterniond a(Eigen::AngleAxisd(1e-10, Eigen::Vector3d::UnitZ()));
  EXPECT_NEAR(angleBetween(Eigen::Quaterniond::Identity(), a), 1e-10, 1e-18);
  const Eigen::Quaterniond b(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));
  EXPECT_NEAR(angleBetween(Eigen::Quaterniond::Identity(), b), M_PI / 2, 1e-12);
}

TEST(Pose, ValidationRejectsBadPoses) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(validatedPose({nan, 0, 0}, Eigen::Quaterniond::Identity(), "cup"), InputError);
  EXPECT_THROW(validatedPose({0, 0, 0}, Eigen::Quaterniond(nan, 0, 0, 0), "cup"), InputError);
  EXPECT_THROW(validatedPose({0, 0, 0}, Eigen::Quaterniond(0, 0, 0, 0), "cup"), InputError);
  EXPECT_THROW(validatedPose({0, 0, 0}, Eigen::Quaterniond(2, 0, 0, 0), "cup"), InputError);
  try {
    validatedPose({0, 0, 0}, Eigen::Quaterniond(0, 0, 0, 0), "objects.yaml, object 3 (Cup)");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("objects.yaml, object 3 (Cup)"), std::string::npos);
    EXPECT_NE(std::string(error.what()).find("zero quaternion"), std::string::npos);
  }
  // Rounding noise in a recorded quaternion is normalised away.
  const Pose pose = validatedPose({0, 0, 0}, Eigen::Quaterniond(1.0000004, 0, 0, 0), "cup");
  EXPECT_NEAR(pose.orientation.norm(), 1.0, 1e-15);
}

}  // namespace
}  // namespace asr_common
