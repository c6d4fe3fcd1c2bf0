#include "asr_robot_model/ros/simulation_setup.hpp"

#include "asr_common/ros/node_parameters.hpp"

namespace asr_robot_model::ros_interface {

using namespace asr_common::ros_interface;

SimulationSetup loadSimulationSetup(const ros::NodeHandle& private_node) {
  SimulationSetup setup;
  setup.robot = loadRobotDescription(
      optionalParameter<std::string>(private_node, "urdf", defaultRobotUrdf()));
  setup.catalogue = loadObjectCatalogue(
      optionalParameter<std::string>(private_node, "catalogue", defaultObjectCatalogue()));
  setup.world = loadWorld(requiredParameter<std::string>(private_node, "world"), setup.catalogue);
  const double resolution = numberParameter(private_node, "map_resolution", 0.02, 0.005, 1.0);
  setup.map = std::make_unique<WorldMap>(setup.world, resolution, setup.robot.base_radius);
  return setup;
}

}  // namespace asr_robot_model::ros_interface
