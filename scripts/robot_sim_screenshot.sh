#!/bin/bash
# Renders the simulated robot in the shipped kitchen with rviz on a virtual display and saves the
# 3D view as docs/images/robot_kitchen.png (docs/robot.md). Needs `./asr build` first; runs its
# own ROS master on port 11399 so that it disturbs no other.
set -e
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
cd "$ROOT"
source devel/setup.bash
source scripts/rviz_screenshot_lib.sh
start_master 11399
roslaunch asr_robot_model robot_sim.launch rviz:=false > /dev/null 2>&1 &
STOP_PIDS="$!"
sleep 6
grab_rviz asr_robot_model/launch/robot_sim.rviz docs/images/robot_kitchen.png
