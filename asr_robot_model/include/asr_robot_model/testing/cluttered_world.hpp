// Random cluttered worlds and views of them, shared by the detection test and the benchmark.
#pragma once

#include <random>
#include <string>

#include "asr_robot_model/world.hpp"

namespace asr_robot_model::testing {

inline Eigen::Quaterniond randomRotation(std::mt19937& random) {
  std::normal_distribution<double> g(0.0, 1.0);
  return Eigen::Quaterniond(g(random), g(random), g(random), g(random)).normalized();
}

// 20 furniture boxes and 100 objects at random in a 6 x 5 m room (object centres outside
// furniture).
inline World clutteredWorld(std::mt19937& random) {
  World world;
  world.room_min = {0, 0};
  world.room_max = {6, 5};
  std::uniform_real_distribution<double> x(0.5, 5.5), y(0.5, 4.5), z(0.2, 1.6);
  std::uniform_real_distribution<double> big(0.2, 0.9), small(0.03, 0.2);
  std::uniform_int_distribution<int> normal_count(0, 2);
  for (int i = 0; i < 20; ++i)
    world.furniture.push_back(
        {"box" + std::to_string(i),
         {asr_common::Pose({x(random), y(random), z(random)}, randomRotation(random)),
          {big(random), big(random), big(random)}}});
  while (world.objects.size() < 100) {
    WorldObject object;
    object.key = {"T" + std::to_string(world.objects.size() % 7),
                  std::to_string(world.objects.size())};
    object.box = {asr_common::Pose({x(random), y(random), z(random)}, randomRotation(random)),
                  {small(random), small(random), small(random)}};
    for (int n = normal_count(random); n > 0; --n)
      object.normals.push_back(randomRotation(random) * Eigen::Vector3d::UnitX());
    bool inside = false;
    for (const Furniture& furniture : world.furniture)
      inside = inside || furniture.box.contains(object.box.pose.position);
    if (!inside)
      world.objects.push_back(object);
  }
  return world;
}

inline bool insideAnything(const World& world, const Eigen::Vector3d& point) {
  for (const Furniture& furniture : world.furniture)
    if (furniture.box.contains(point, 0.05))
      return true;
  for (const WorldObject& object : world.objects)
    if (object.box.contains(point, 0.05))
      return true;
  return false;
}

// A camera 0.5..1.6 m from a random object, outside every box, looking roughly at it.
inline asr_common::Pose randomView(const World& world, std::mt19937& random) {
  std::uniform_int_distribution<std::size_t> pick(0, world.objects.size() - 1);
  std::uniform_real_distribution<double> distance(0.5, 1.6);
  std::normal_distribution<double> g(0.0, 1.0), aim(0.0, 0.1);
  Eigen::Vector3d target, from;
  do {
    target = world.objects[pick(random)].box.pose.position;
    from =
        target - distance(random) * Eigen::Vector3d(g(random), g(random), g(random)).normalized();
  } while (insideAnything(world, from));
  const Eigen::Vector3d forward =
      (target - from).normalized() + Eigen::Vector3d(aim(random), aim(random), aim(random));
  const Eigen::Quaterniond look =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), forward);
  return asr_common::Pose(from, look * Eigen::AngleAxisd(g(random), Eigen::Vector3d::UnitZ()));
}

}  // namespace asr_robot_model::testing
