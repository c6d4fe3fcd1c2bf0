#pragma once

#include <ros/node_handle.h>

#include <memory>

#include "asr_robot_model/robot_description.hpp"
#include "asr_robot_model/world.hpp"
#include "asr_robot_model/world_map.hpp"

// What the simulation nodes read from their private parameters: the robot (~urdf, default the
// shipped one), the world (~world, required) with its object catalogue (~catalogue, default the
// shipped one) and its OctoMap (~map_resolution, metres, default 0.02).
namespace asr_robot_model::ros_interface {

struct SimulationSetup {
  RobotDescription robot;
  ObjectCatalogue catalogue;
  World world;
  std::unique_ptr<WorldMap> map;
};

/// Throws asr_common::InputError naming the parameter or the file for anything missing or bad.
SimulationSetup loadSimulationSetup(const ros::NodeHandle& private_node);

}  // namespace asr_robot_model::ros_interface
