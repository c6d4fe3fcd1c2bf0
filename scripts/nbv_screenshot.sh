#!/bin/bash
# Renders next_best_view's markers in the shipped kitchen with rviz on a virtual display and saves
# the 3D view as docs/images/nbv_kitchen.png (docs/next_best_view.md): predicted poses, the
# candidate views rated in full and the chosen view's frustum. Needs `./asr build` first; runs
# its own ROS master on port 11398 so that it disturbs no other.
set -e
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
cd "$ROOT"
source devel/setup.bash
source scripts/rviz_screenshot_lib.sh
start_master 11398
# The simulation draws the furniture (world_markers) and the robot.
roslaunch asr_robot_model robot_sim.launch rviz:=false > /dev/null 2>&1 &
STOP_PIDS="$!"
roslaunch asr_nbv next_best_view.launch > /dev/null 2>&1 &
STOP_PIDS="$STOP_PIDS $!"
sleep 6
/usr/bin/python3 scripts/nbv_screenshot_request.py
grab_rviz asr_nbv/launch/next_best_view.rviz docs/images/nbv_kitchen.png
