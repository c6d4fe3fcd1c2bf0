// The camera frustum: its boundary, the defaults, intrinsics and bad parameters.
#include <gtest/gtest.h>

#include <cmath>

#include "asr_common/testing/input_error_of.hpp"
#include "asr_robot_model/frustum.hpp"

using asr_common::testing::inputErrorOf;
using asr_robot_model::Frustum;

TEST(Frustum, DefaultsAreTheOriginalCamera) {
  const Frustum frustum = Frustum::defaults();
  EXPECT_NEAR(frustum.fovx(), 30 * M_PI / 180, 1e-15);
  EXPECT_NEAR(frustum.fovy(), 20 * M_PI / 180, 1e-15);
  EXPECT_DOUBLE_EQ(frustum.near(), 0.4);
  EXPECT_DOUBLE_EQ(frustum.far(), 1.5);
}

TEST(Frustum, BoundaryIsInsideAndJustBeyondIsOutside) {
  const Frustum frustum = Frustum::defaults();
  const double half_width = std::tan(15 * M_PI / 180);
  const double half_height = std::tan(10 * M_PI / 180);
  for (double z : {0.4, 1.0, 1.5}) {
    EXPECT_TRUE(frustum.contains({z * half_width * 0.999999, z * half_height * 0.999999, z}));
    EXPECT_TRUE(frustum.contains({-z * half_width * 0.999999, -z * half_height * 0.999999, z}));
    EXPECT_FALSE(frustum.contains({z * half_width * 1.000001, 0, z}));
    EXPECT_FALSE(frustum.contains({0, -z * half_height * 1.000001, z}));
  }
  EXPECT_FALSE(frustum.contains({0, 0, 0.399999}));
  EXPECT_FALSE(frustum.contains({0, 0, 1.500001}));
  EXPECT_FALSE(frustum.contains({0, 0, -1.0}));  // behind the camera
}

TEST(Frustum, FromIntrinsicsOpensAsThePinholeModelSays) {
  const Frustum frustum = Frustum::fromIntrinsics(640, 480, 525.0, 525.0, 0.4, 3.0);
  EXPECT_NEAR(frustum.fovx(), 2 * std::atan(320.0 / 525.0), 1e-15);
  EXPECT_NEAR(frustum.fovy(), 2 * std::atan(240.0 / 525.0), 1e-15);
  // A point projecting onto the image's right edge is on the boundary.
  EXPECT_TRUE(frustum.contains({320.0 / 525.0 * 0.999999, 0, 1.0}));
  EXPECT_FALSE(frustum.contains({320.0 / 525.0 * 1.000001, 0, 1.0}));
}

TEST(Frustum, BadParametersAreNamed) {
  EXPECT_NE(inputErrorOf([] { Frustum(0.0, 0.3, 0.4, 1.5); }).find("fovx"), std::string::npos);
  EXPECT_NE(inputErrorOf([] { Frustum(0.5, M_PI, 0.4, 1.5); }).find("fovy"), std::string::npos);
  EXPECT_NE(inputErrorOf([] { Frustum(0.5, 0.3, NAN, 1.5); }).find("near"), std::string::npos);
  EXPECT_NE(inputErrorOf([] { Frustum(0.5, 0.3, 1.5, 1.5); }).find("far"), std::string::npos);
  EXPECT_NE(inputErrorOf([] { Frustum::fromIntrinsics(640, 480, 0.0, 525, 0.4, 1.5); }).find("fx"),
            std::string::npos);
}
