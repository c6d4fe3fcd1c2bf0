// The suite's input limits (input_limits.hpp): where they are checked, what the messages say, and
// that they keep every vote of accepted input inside the voting space.

#include "asr_ism/input_limits.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "asr_common/testing/input_error_of.hpp"
#include "asr_ism/ism_learning.hpp"
#include "asr_ism/voting_space.hpp"

namespace asr_ism {
namespace {

using asr_common::testing::inputErrorOf;

Pose at(double x, double y, double z) {
  return Pose(Eigen::Vector3d(x, y, z), Eigen::Quaterniond::Identity());
}

TEST(InputLimits, PositionsBeyondTheLimitAreRefusedWithTheLimitNamed) {
  for (double far : {1e5, -1e7, std::nextafter(kMaxCoordinate, 2e3)}) {
    for (int axis = 0; axis < 3; ++axis) {
      Eigen::Vector3d position(0.5, 0.5, 0.5);
      position[axis] = far;
      const std::string message = inputErrorOf(
          [&] { validatedPose(position, Eigen::Quaterniond::Identity(), "object estimate Cup"); });
      EXPECT_NE(message.find("object estimate Cup"), std::string::npos) << message;
      EXPECT_NE(message.find("1000 m"), std::string::npos) << message;
    }
  }
  const Eigen::Vector3d corner(kMaxCoordinate, -kMaxCoordinate, kMaxCoordinate);
  EXPECT_EQ(validatedPose(corner, Eigen::Quaterniond::Identity(), "corner").position, corner);
}

TEST(InputLimits, RecognitionParametersOutsideTheirRangesAreRefused) {
  const double infinity = std::numeric_limits<double>::infinity();
  for (double bin : {0.0, -0.1, infinity, 1e300, std::nan(""), 0.009, 10.5}) {
    IsmRecognitionParameters parameters;
    parameters.bin_size = bin;
    const std::string message =
        inputErrorOf([&] { checkRecognitionParameters(parameters, "model.sqlite"); });
    EXPECT_NE(message.find("model.sqlite"), std::string::npos) << message;
    EXPECT_NE(message.find("bin_size"), std::string::npos) << message;
  }
  for (double angle : {0.0, -1.0, 3.2, infinity, std::nan("")}) {
    IsmRecognitionParameters parameters;
    parameters.max_angle_deviation = angle;
    EXPECT_NE(inputErrorOf([&] {
                checkRecognitionParameters(parameters, "m");
              }).find("max_angle_deviation"),
              std::string::npos);
  }
  for (double bin : {kMinBinSize, 0.1, kMaxBinSize}) {
    IsmRecognitionParameters parameters;
    parameters.bin_size = bin;
    parameters.max_angle_deviation = M_PI;
    EXPECT_NO_THROW(checkRecognitionParameters(parameters, "m"));
  }
}

TEST(InputLimits, LearningRefusesAnOutlierPoseAndNamesTheStep) {
  // One pose of the cup 1e7 m away was a glitch: a model learned from it would vote 1e7 m away
  // from every later estimate. Within the coordinate limit but 150 m apart is refused too.
  const Trajectory reference = {at(1.0, 2.0, 0.7), at(1.0, 2.0, 0.7), at(1.0, 2.0, 0.7)};
  for (double far : {1e7, 151.0}) {
    const Trajectory cup = {at(1.2, 2.0, 0.7), at(far, 2.0, 0.7), at(1.3, 2.0, 0.7)};
    const std::string message = inputErrorOf([&] {
      learnIsm("setting", {"Plate", ""}, reference, {{{"Cup", ""}, -1, cup}});
    });
    EXPECT_NE(message.find("time step 1"), std::string::npos) << message;
    EXPECT_NE(message.find("Cup"), std::string::npos) << message;
    EXPECT_NE(message.find("outlier"), std::string::npos) << message;
  }
  const Trajectory cup = {at(1.2, 2.0, 0.7), at(90.0, 2.0, 0.7), at(1.3, 2.0, 0.7)};
  EXPECT_NO_THROW(learnIsm("setting", {"Plate", ""}, reference, {{{"Cup", ""}, -1, cup}}));
}

TEST(InputLimits, TheVotingExtentOfAcceptedInputFitsEveryAcceptedBinSize) {
  // Property: for every bin size accepted and trees up to 80 levels whose relations are within
  // the limit, the check passes, and every vote such a tree can cast fits the voting space.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> exponent(std::log(kMinBinSize), std::log(kMaxBinSize));
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const double bin = std::exp(exponent(random));
    const int height = 1 + trial % 80;
    ASSERT_NO_THROW(checkVotingExtent(bin, height, kMaxRelationLength, "tree")) << bin;
    // The votes farthest apart: estimates at opposite corners of the accepted cube, each moved
    // by one relation per level straight outwards, all in one space.
    const double corner = kMaxCoordinate + height * kMaxRelationLength;
    const double x[2] = {corner, -corner}, y[2] = {corner * unit(random), -corner},
                 z[2] = {-corner, corner};
    EXPECT_NO_THROW(VotingSpace(bin, x, y, z, 2)) << "bin " << bin << ", height " << height;
  }
  // Beyond it, the check names the tree rather than letting the recogniser fail later.
  const std::string message = inputErrorOf([&] { checkVotingExtent(0.01, 200, 100.0, "tall"); });
  EXPECT_NE(message.find("tall"), std::string::npos) << message;
}

}  // namespace
}  // namespace asr_ism
