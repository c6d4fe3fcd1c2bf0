#include "asr_ism/synthetic_demonstration.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "asr_ism/common_types.hpp"
#include "asr_ism/ism_learning.hpp"
#include "asr_ism/ism_recognizer.hpp"

namespace asr_ism {
namespace {

constexpr double kDegree = M_PI / 180.0;

bool samePoses(const Demonstration& a, const Demonstration& b) {
  if (a.objects() != b.objects() || a.stepCount() != b.stepCount())
    return false;
  for (std::size_t step = 0; step < a.stepCount(); ++step) {
    for (std::size_t object = 0; object < a.objectCount(); ++object) {
      const Pose& p = *a.pose(step, object);
      const Pose& q = *b.pose(step, object);
      if (p.position != q.position || p.orientation.coeffs() != q.orientation.coeffs())
        return false;
    }
  }
  return true;
}

void expectValidPoses(const Demonstration& demonstration) {
  for (std::size_t step = 0; step < demonstration.stepCount(); ++step) {
    for (std::size_t object = 0; object < demonstration.objectCount(); ++object) {
      const auto& pose = demonstration.pose(step, object);
      ASSERT_TRUE(pose.has_value()) << "step " << step << " object " << object;
      ASSERT_TRUE(pose->position.allFinite());
      ASSERT_TRUE(pose->orientation.coeffs().allFinite());
      EXPECT_NEAR(pose->orientation.norm(), 1.0, 1e-12);
      EXPECT_GE(pose->orientation.w(), 0.0);
    }
  }
}

// Largest distance of an object's positions from its first one.
double maximumTravel(const Demonstration& demonstration, std::size_t object) {
  double travel = 0.0;
  const Eigen::Vector3d first = demonstration.pose(0, object)->position;
  for (std::size_t step = 0; step < demonstration.stepCount(); ++step)
    travel = std::max(travel, (demonstration.pose(step, object)->position - first).norm());
  return travel;
}

// Learns the scene as a single ISM (a star around object 0, the simplest ISM tree) and returns its
// best confidence for one configuration: objective / number of members.
class StarModel {
 public:
  explicit StarModel(const Demonstration& demonstration) {
    std::vector<MemberTrajectory> members;
    for (std::size_t object = 0; object < demonstration.objectCount(); ++object)
      members.push_back({demonstration.objects()[object], -1, demonstration.trajectory(object)});
    ism_ = learnIsm(demonstration.scene(), demonstration.objects()[0], demonstration.trajectory(0),
                    members);
  }

  double confidence(const Configuration& configuration) const {
    std::vector<IsmInput> inputs;
    for (std::size_t i = 0; i < configuration.size(); ++i) {
      for (std::size_t m = 0; m < ism_.members.size(); ++m) {
        if (ism_.members[m].object == configuration[i].key)
          inputs.push_back(
              {static_cast<int>(m), configuration[i].pose, 1.0, {static_cast<int>(i)}});
      }
    }
    const auto results = recognizeIsm(ism_, inputs, IsmRecognitionParameters{});
    return results.empty() ? 0.0 : results.front().objective / ism_.members.size();
  }

 private:
  Ism ism_;
};

TEST(SyntheticDemonstration, HasTheRequestedSize) {
  const Demonstration demonstration = makeSyntheticDemonstration(7, 123, 5, "scaling");
  EXPECT_EQ(demonstration.scene(), "scaling");
  ASSERT_EQ(demonstration.objectCount(), 7u);
  EXPECT_EQ(demonstration.stepCount(), 123u);
  EXPECT_EQ(demonstration.objects()[0], (ObjectKey{"object_0", "0"}));
  EXPECT_EQ(demonstration.objects()[6], (ObjectKey{"object_6", "0"}));
  EXPECT_NO_THROW(demonstration.validate("test"));
  expectValidPoses(demonstration);
}

TEST(SyntheticDemonstration, IsDeterministicForASeed) {
  EXPECT_TRUE(
      samePoses(makeSyntheticDemonstration(5, 50, 42), makeSyntheticDemonstration(5, 50, 42)));
  EXPECT_FALSE(
      samePoses(makeSyntheticDemonstration(5, 50, 42), makeSyntheticDemonstration(5, 50, 43)));
}

// The distributions are implemented on the raw mt19937 output, so these values must be the same on
// every platform, compiler and standard library (checked with GCC and Clang; the tolerance allows
// for the last bit of sin and cos).
TEST(SyntheticDemonstration, GivesTheSameValuesEverywhere) {
  const Pose pose = *makeSyntheticDemonstration(3, 10, 1).pose(9, 2);
  EXPECT_NEAR(pose.position.x(), 1.3624186693823594, 1e-12);
  EXPECT_NEAR(pose.position.y(), 0.35874136975138821, 1e-12);
  EXPECT_NEAR(pose.position.z(), 0.77617642213415061, 1e-12);
  EXPECT_NEAR(pose.orientation.w(), 0.99344069082538822, 1e-12);
  EXPECT_NEAR(pose.orientation.z(), 0.1141023688189539, 1e-12);
  const Pose cup = *makeBreakfastDemonstration(1).pose(59, 1);
  EXPECT_NEAR(cup.position.x(), 1.4140354662705539, 1e-12);
  EXPECT_NEAR(cup.position.y(), 0.02530205701093742, 1e-12);
  EXPECT_NEAR(cup.position.z(), 0.80254316185234931, 1e-12);
  EXPECT_NEAR(cup.orientation.w(), 0.90474954371355154, 1e-12);
  EXPECT_NEAR(cup.orientation.z(), -0.42580986095563628, 1e-12);
}

TEST(SyntheticDemonstration, ObjectsStayOnTheTableAndMoveLikeAPersonMovesThem) {
  const Demonstration demonstration = makeSyntheticDemonstration(10, 200, 7);
  for (std::size_t object = 0; object < demonstration.objectCount(); ++object) {
    for (std::size_t step = 0; step < demonstration.stepCount(); ++step) {
      const Pose& pose = *demonstration.pose(step, object);
      EXPECT_NEAR(pose.position.x(), 1.0, 0.7);
      EXPECT_NEAR(pose.position.y(), 0.0, 0.7);
      EXPECT_GT(pose.position.z(), 0.75);
      EXPECT_LT(pose.position.z(), 0.9);
      // Upright: the object's z axis stays within a few degrees of the vertical.
      const Eigen::Vector3d up = pose.orientation * Eigen::Vector3d::UnitZ();
      EXPECT_GT(up.z(), std::cos(5.0 * kDegree));
    }
    const double travel = maximumTravel(demonstration, object);
    EXPECT_GT(travel, 0.01) << "object " << object;
    EXPECT_LT(travel, 0.35) << "object " << object;
  }
}

TEST(SyntheticDemonstration, NoiseIsAboutThreeMillimetresAndOneDegree) {
  // Consecutive steps of a dense demonstration differ almost only by noise.
  const Demonstration demonstration = makeSyntheticDemonstration(4, 5000, 11);
  double squared_distance = 0.0;
  double squared_angle = 0.0;
  std::size_t count = 0;
  for (std::size_t object = 0; object < demonstration.objectCount(); ++object) {
    for (std::size_t step = 1; step < demonstration.stepCount(); ++step) {
      const Pose& a = *demonstration.pose(step - 1, object);
      const Pose& b = *demonstration.pose(step, object);
      squared_distance += (a.position - b.position).squaredNorm();
      squared_angle += std::pow(angleBetween(a.orientation, b.orientation), 2);
      ++count;
    }
  }
  // Differences of two independent noisy poses: variance doubles.
  const double position_sigma = std::sqrt(squared_distance / count / 6.0);
  const double angle_rms = std::sqrt(squared_angle / count / 2.0);
  EXPECT_NEAR(position_sigma, 0.003, 0.0005);
  EXPECT_NEAR(angle_rms, 1.0 * kDegree, 0.15 * kDegree);
}

TEST(SyntheticDemonstration, MoreStepsSampleTheSameMotion) {
  const Demonstration coarse = makeSyntheticDemonstration(4, 11, 3);
  const Demonstration fine = makeSyntheticDemonstration(4, 101, 3);
  for (std::size_t object = 0; object < 4; ++object) {
    // Step k of 11 and step 10 k of 101 are the same moment; they differ only by noise.
    for (std::size_t k = 0; k < 11; ++k) {
      EXPECT_LT((coarse.pose(k, object)->position - fine.pose(10 * k, object)->position).norm(),
                0.04);
    }
  }
}

TEST(SyntheticDemonstration, RefusesAnEmptyScene) {
  EXPECT_THROW(makeSyntheticDemonstration(0, 10, 1), InputError);
  EXPECT_THROW(makeSyntheticDemonstration(3, 0, 1), InputError);
}

TEST(SyntheticDemonstration, ASingleIsmRecognisesItsOwnSteps) {
  const Demonstration demonstration = makeSyntheticDemonstration(5, 40, 9);
  const StarModel model(demonstration);
  for (std::size_t step = 0; step < demonstration.stepCount(); step += 7)
    EXPECT_GE(model.confidence(demonstration.configuration(step)), 0.99) << "step " << step;
}

TEST(BreakfastDemonstration, IsAPlaceSettingOverSixtySteps) {
  const Demonstration demonstration = makeBreakfastDemonstration(1);
  EXPECT_EQ(demonstration.scene(), "breakfast");
  EXPECT_EQ(demonstration.stepCount(), 60u);
  std::vector<std::string> types;
  for (const ObjectKey& key : demonstration.objects())
    types.push_back(key.type);
  EXPECT_EQ(types,
            (std::vector<std::string>{"PlateDeep", "Cup", "Fork", "Knife", "Spoon", "CerealBox"}));
  expectValidPoses(demonstration);
  EXPECT_TRUE(samePoses(demonstration, makeBreakfastDemonstration(1)));
  EXPECT_FALSE(samePoses(demonstration, makeBreakfastDemonstration(2)));
}

TEST(BreakfastDemonstration, TheSettingSlidesAlongTheTableAsAWhole) {
  const Demonstration demonstration = makeBreakfastDemonstration(4);
  const std::size_t last = demonstration.stepCount() - 1;
  // Every object travels with the setting, 35-45 cm give or take its nudge and noise.
  for (std::size_t object = 0; object < demonstration.objectCount(); ++object) {
    const Eigen::Vector3d travel =
        demonstration.pose(last, object)->position - demonstration.pose(0, object)->position;
    EXPECT_GT(travel.x(), 0.25) << demonstration.objects()[object].toString();
    EXPECT_LT(travel.norm(), 0.55) << demonstration.objects()[object].toString();
  }
  // The arrangement stays a setting: plate and cereal box keep their distance within noise.
  for (std::size_t step = 0; step <= last; ++step) {
    const double distance =
        (demonstration.pose(step, 0)->position - demonstration.pose(step, 5)->position).norm();
    EXPECT_NEAR(distance, std::sqrt(0.12 * 0.12 + 0.30 * 0.30 + 0.13 * 0.13), 0.02);
  }
}

TEST(BreakfastDemonstration, ASingleIsmRecognisesEveryStep) {
  const Demonstration demonstration = makeBreakfastDemonstration(1);
  const StarModel model(demonstration);
  for (std::size_t step = 0; step < demonstration.stepCount(); ++step)
    EXPECT_GE(model.confidence(demonstration.configuration(step)), 0.99) << "step " << step;
}

TEST(ConfigurationChanges, TransformKeepsRelativePoses) {
  const Configuration original = makeBreakfastDemonstration(1).configuration(10);
  const Pose motion(Eigen::Vector3d(0.3, -0.2, 0.0),
                    Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ())));
  const Configuration moved = transformConfiguration(original, motion);
  ASSERT_EQ(moved.size(), original.size());
  for (std::size_t i = 1; i < moved.size(); ++i) {
    EXPECT_EQ(moved[i].key, original[i].key);
    EXPECT_TRUE(approximatelyEqual(relativePose(moved[0].pose, moved[i].pose),
                                   relativePose(original[0].pose, original[i].pose), 1e-12, 1e-9));
  }
}

TEST(ConfigurationChanges, DisturbMovesAndTurnsOneObjectOnly) {
  const Configuration original = makeBreakfastDemonstration(1).configuration(0);
  const Eigen::Quaterniond quarter_turn(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  const Configuration disturbed = disturbConfiguration(
      original, {"Knife", "0"}, Eigen::Vector3d(-0.25, 0.0, 0.0), quarter_turn);
  for (std::size_t i = 0; i < original.size(); ++i) {
    if (original[i].key.type != "Knife") {
      EXPECT_TRUE(approximatelyEqual(original[i].pose, disturbed[i].pose, 0.0, 0.0));
      continue;
    }
    EXPECT_NEAR((disturbed[i].pose.position - original[i].pose.position).norm(), 0.25, 1e-12);
    EXPECT_NEAR(angleBetween(disturbed[i].pose.orientation, original[i].pose.orientation), M_PI / 2,
                1e-9);
  }
  EXPECT_THROW(disturbConfiguration(original, {"Teapot", "0"}, Eigen::Vector3d::Zero()),
               InputError);
}

TEST(ConfigurationChanges, SensorNoiseIsDeterministicAndSmall) {
  const Configuration original = makeBreakfastDemonstration(1).configuration(0);
  const Configuration a = addSensorNoise(original, 0.003, kDegree, 17);
  const Configuration b = addSensorNoise(original, 0.003, kDegree, 17);
  for (std::size_t i = 0; i < original.size(); ++i) {
    EXPECT_EQ(a[i].pose.position, b[i].pose.position);
    EXPECT_LT((a[i].pose.position - original[i].pose.position).norm(), 0.03);
    EXPECT_LT(angleBetween(a[i].pose.orientation, original[i].pose.orientation), 10 * kDegree);
    EXPECT_NEAR(a[i].pose.orientation.norm(), 1.0, 1e-12);
  }
}

}  // namespace
}  // namespace asr_ism
