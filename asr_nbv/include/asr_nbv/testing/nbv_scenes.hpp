// Small worlds and hypotheses for the planner's tests and benchmark.
#pragma once

#include <random>
#include <string>
#include <vector>

#include "asr_nbv/hypotheses.hpp"
#include "asr_robot_model/world.hpp"

namespace asr_nbv::testing {

// An empty room of width x depth metres.
inline asr_robot_model::World emptyRoom(double width, double depth) {
  asr_robot_model::World world;
  world.room_min = {0.0, 0.0};
  world.room_max = {width, depth};
  return world;
}

inline asr_robot_model::Furniture furniture(const std::string& name, const Eigen::Vector3d& centre,
                                            const Eigen::Vector3d& size) {
  return {name, {asr_common::Pose(centre, Eigen::Quaterniond::Identity()), size}};
}

// A 6 x 5 m kitchen: two tables, a cupboard, a shelf and a counter along the walls.
inline asr_robot_model::World furnishedRoom() {
  asr_robot_model::World world = emptyRoom(6.0, 5.0);
  world.furniture = {furniture("table_1", {1.5, 1.5, 0.37}, {1.2, 0.8, 0.74}),
                     furniture("table_2", {4.2, 3.4, 0.37}, {1.0, 1.0, 0.74}),
                     furniture("cupboard", {5.7, 0.9, 0.9}, {0.5, 1.2, 1.8}),
                     furniture("shelf", {0.25, 4.0, 0.8}, {0.4, 1.4, 1.6}),
                     furniture("counter", {3.0, 0.3, 0.45}, {1.6, 0.5, 0.9})};
  return world;
}

// One cloud per object: `poses` poses scattered (sigma 0.1 m, yaw only) around a centre on a
// piece of furniture's top, types T0..T(types-1), one object per type.
inline std::vector<PredictedCloud> cloudsOnFurniture(const asr_robot_model::World& world,
                                                     std::size_t types, std::size_t poses,
                                                     unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> scatter(0.0, 0.1), yaw(0.0, 0.6);
  std::vector<PredictedCloud> clouds;
  for (std::size_t t = 0; t < types; ++t) {
    const asr_robot_model::Box& top = world.furniture[t % world.furniture.size()].box;
    const Eigen::Vector3d centre =
        top.pose.position + Eigen::Vector3d(0.0, 0.0, top.size.z() / 2.0 + 0.08);
    PredictedCloud cloud;
    cloud.key = {"T" + std::to_string(t), "0"};
    for (std::size_t p = 0; p < poses; ++p) {
      const Eigen::Vector3d position =
          centre + Eigen::Vector3d(scatter(random), scatter(random), 0);
      cloud.poses.emplace_back(position, Eigen::Quaterniond(Eigen::AngleAxisd(
                                             yaw(random) + t, Eigen::Vector3d::UnitZ())));
    }
    clouds.push_back(cloud);
  }
  return clouds;
}

// A catalogue giving types T0..T(types-1) boxes of 0.1 m and normals +-x (odd types: none).
inline asr_robot_model::ObjectCatalogue twoSidedCatalogue(std::size_t types) {
  asr_robot_model::ObjectCatalogue catalogue;
  for (std::size_t t = 0; t < types; ++t) {
    asr_robot_model::ObjectType type;
    type.size = Eigen::Vector3d::Constant(0.1);
    if (t % 2 == 0)
      type.normals = {Eigen::Vector3d::UnitX(), -Eigen::Vector3d::UnitX()};
    catalogue["T" + std::to_string(t)] = type;
  }
  return catalogue;
}

}  // namespace asr_nbv::testing
