// The simulated detector against a brute-force reference (exact boxes, no voxels) over 1,000
// random views of a cluttered world, and its noise, misses and time.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

#include "asr_common/testing/input_error_of.hpp"
#include "asr_robot_model/detection_simulator.hpp"
#include "asr_robot_model/testing/cluttered_world.hpp"

using namespace asr_robot_model;
using asr_robot_model::testing::clutteredWorld;
using asr_robot_model::testing::randomView;

namespace {

constexpr double kResolution = 0.01;

// Parameters where the segment a + t (b - a), t in [0, 1], meets the box grown by `margin`
// (slab method in the box's frame); false if it does not.
bool segmentHitsBox(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Box& box,
                    double margin, double& t_in) {
  const Eigen::Vector3d p = box.pose.orientation.conjugate() * (a - box.pose.position);
  const Eigen::Vector3d d = box.pose.orientation.conjugate() * (b - a);
  const Eigen::Vector3d half = (box.size / 2.0).array() + margin;
  double low = 0.0, high = 1.0;
  for (int k = 0; k < 3; ++k) {
    if (half[k] <= 0.0)
      return false;
    if (std::abs(d[k]) < 1e-15) {
      if (std::abs(p[k]) > half[k])
        return false;
      continue;
    }
    double t1 = (-half[k] - p[k]) / d[k], t2 = (half[k] - p[k]) / d[k];
    if (t1 > t2)
      std::swap(t1, t2);
    low = std::max(low, t1);
    high = std::min(high, t2);
    if (low > high)
      return false;
  }
  t_in = low;
  return true;
}

enum class Reference { kFrustum, kNormals, kVisible, kOccluded, kAmbiguous };

Reference reference(const World& world, const asr_common::Pose& camera, std::size_t target,
                    const DetectionSettings& settings) {
  const WorldObject& object = world.objects[target];
  const Eigen::Isometry3d map_to_camera =
      (Eigen::Translation3d(camera.position) * camera.orientation).inverse();
  const double tx = std::tan(settings.frustum.fovx() / 2),
               ty = std::tan(settings.frustum.fovy() / 2);
  for (const Eigen::Vector3d& corner : object.box.corners()) {
    const Eigen::Vector3d p = map_to_camera * corner;
    if (p.z() < 0.4 || p.z() > 1.5 || std::abs(p.x()) > p.z() * tx || std::abs(p.y()) > p.z() * ty)
      return Reference::kFrustum;
  }
  bool facing = object.normals.empty();
  const Eigen::Vector3d to_camera = (camera.position - object.box.pose.position).normalized();
  for (const Eigen::Vector3d& normal : object.normals)
    facing = facing || std::acos(std::clamp((object.box.pose.orientation * normal).dot(to_camera),
                                            -1.0, 1.0)) < settings.max_normal_angle;
  if (!facing)
    return Reference::kNormals;
  // Voxels blur surfaces by up to a voxel diagonal: beyond it the verdict is certain.
  const double blur = kResolution * std::sqrt(3.0);
  const Eigen::Vector3d& eye = camera.position;
  const Eigen::Vector3d& centre = object.box.pose.position;
  double own_entry = 1.0, t = 0.0;
  segmentHitsBox(eye, centre, object.box, 2 * blur, own_entry);
  // The map holds box surfaces: from inside a box, or to a centre inside another box, a ray
  // crosses fewer surfaces than solid boxes would block; such views are not compared.
  bool near_miss = false;
  auto check = [&](const Box& other) {
    if (other.contains(eye, blur) || other.contains(centre, blur)) {
      near_miss = true;
      return false;
    }
    if (segmentHitsBox(eye, centre, other, -blur, t) && t < own_entry)
      return true;
    near_miss = near_miss || segmentHitsBox(eye, centre, other, blur, t);
    return false;
  };
  for (const Furniture& furniture : world.furniture)
    if (check(furniture.box))
      return Reference::kOccluded;
  for (std::size_t i = 0; i < world.objects.size(); ++i)
    if (i != target && check(world.objects[i].box))
      return Reference::kOccluded;
  return near_miss ? Reference::kAmbiguous : Reference::kVisible;
}

}  // namespace

TEST(DetectionSimulator, AgreesWithABruteForceReferenceOnAThousandRandomViews) {
  std::mt19937 random(6);
  const World world = clutteredWorld(random);
  const WorldMap map(world, kResolution, 0.3);
  const DetectionSettings settings;
  DetectionSimulator simulator(world, map, settings, 1);
  int counts[5] = {0, 0, 0, 0, 0};
  for (int view = 0; view < 1000; ++view) {
    const asr_common::Pose camera = randomView(world, random);
    for (std::size_t i = 0; i < world.objects.size(); ++i) {
      const Reference expected = reference(world, camera, i, settings);
      ++counts[static_cast<int>(expected)];
      const std::optional<Rejection> got = simulator.visibility(camera, world.objects[i]);
      switch (expected) {
        case Reference::kFrustum:
          ASSERT_EQ(got, Rejection::kFrustum) << view << " " << i;
          break;
        case Reference::kNormals:
          ASSERT_EQ(got, Rejection::kNormals) << view << " " << i;
          break;
        case Reference::kVisible:
          ASSERT_EQ(got, std::nullopt) << view << " " << i;
          break;
        case Reference::kOccluded:
          ASSERT_EQ(got, Rejection::kOccluded) << view << " " << i;
          break;
        case Reference::kAmbiguous:
          break;
      }
    }
  }
  // The views exercise every verdict, and the voxel blur leaves few cases undecided.
  const int visible = counts[static_cast<int>(Reference::kVisible)];
  const int occluded = counts[static_cast<int>(Reference::kOccluded)];
  EXPECT_GT(visible, 150);
  EXPECT_GT(occluded, 25);
  EXPECT_GT(counts[static_cast<int>(Reference::kNormals)], 150);
  EXPECT_LT(counts[static_cast<int>(Reference::kAmbiguous)], (visible + occluded) / 2);
  std::cout << "visible " << counts[2] << ", occluded " << counts[3] << ", normals " << counts[1]
            << ", ambiguous " << counts[4] << "\n";
}

TEST(DetectionSimulator, DetectsRequestedTypesChargesTimeAddsSeededNoiseAndMisses) {
  World world;
  world.room_min = {-1, -1};
  world.room_max = {5, 5};
  const Box cup{asr_common::Pose({1.0, 0.0, 1.0}, Eigen::Quaterniond::Identity()),
                {0.08, 0.08, 0.1}};
  world.objects.push_back({{"Cup", "0"}, cup, {}});
  world.objects.push_back(
      {{"Plate", "0"},
       {asr_common::Pose({1.0, 0.1, 1.0}, Eigen::Quaterniond::Identity()), {0.05, 0.05, 0.01}},
       {Eigen::Vector3d::UnitX()}});
  const WorldMap map(world, kResolution, 0.3);
  // The camera at the origin looking along +x (optical z), x right (-y), y down (-z).
  Eigen::Matrix3d axes;
  axes.col(0) = -Eigen::Vector3d::UnitY();
  axes.col(1) = -Eigen::Vector3d::UnitZ();
  axes.col(2) = Eigen::Vector3d::UnitX();
  const asr_common::Pose camera(Eigen::Vector3d(0, 0, 1), Eigen::Quaterniond(axes));
  DetectionSimulator exact(world, map, DetectionSettings{}, 1);
  const Detections cups = exact.detect(camera, {"Cup"});
  ASSERT_EQ(cups.detected.size(), 1u);
  EXPECT_TRUE(asr_common::approximatelyEqual(cups.detected[0].pose, cup.pose));
  EXPECT_DOUBLE_EQ(cups.seconds, 3.0);
  // The plate faces away from the camera (its normal is +x, the camera is at -x).
  const Detections both = exact.detect(camera, {});
  EXPECT_DOUBLE_EQ(both.seconds, 6.0);
  ASSERT_EQ(both.rejected.size(), 1u);
  EXPECT_EQ(both.rejected[0].why, Rejection::kNormals);
  DetectionSettings noisy;
  noisy.position_sigma = 0.01;
  noisy.angle_sigma = 0.05;
  DetectionSimulator a(world, map, noisy, 7), b(world, map, noisy, 7);
  double spread = 0.0;
  for (int i = 0; i < 200; ++i) {
    const auto pa = a.detect(camera, {"Cup"}).detected.at(0).pose;
    EXPECT_TRUE(asr_common::approximatelyEqual(pa, b.detect(camera, {"Cup"}).detected.at(0).pose));
    spread += (pa.position - cup.pose.position).squaredNorm();
  }
  EXPECT_NEAR(std::sqrt(spread / 600), 0.01, 0.002);  // per-axis sigma
  DetectionSettings missing;
  missing.miss_probability = 1.0;
  DetectionSimulator never(world, map, missing, 1);
  EXPECT_EQ(never.detect(camera, {"Cup"}).rejected.at(0).why, Rejection::kMissed);
  EXPECT_STREQ(rejectionName(Rejection::kOccluded), "occluded");
}

TEST(DetectionSimulator, BadSettingsAreNamed) {
  World world;
  world.room_max = {1, 1};
  const WorldMap map(world, kResolution, 0.3);
  DetectionSettings bad;
  bad.miss_probability = 1.5;
  EXPECT_NE(asr_common::testing::inputErrorOf([&] {
              DetectionSimulator(world, map, bad, 1);
            }).find("miss_probability"),
            std::string::npos);
}
