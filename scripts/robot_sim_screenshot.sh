#!/bin/bash
# Renders the simulated robot in the shipped kitchen with rviz on a virtual display and saves the
# 3D view as docs/images/robot_kitchen.png (docs/robot.md). Needs `./asr build` first; runs its
# own ROS master on port 11399 so that it disturbs no other.
set -e
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
cd "$ROOT"
source devel/setup.bash
export ROS_MASTER_URI=http://localhost:11399
FULL="$(mktemp --suffix=.png)"
roscore -p 11399 > /dev/null 2>&1 &
CORE=$!
trap 'kill -INT $LAUNCH 2>/dev/null; sleep 2; kill $CORE 2>/dev/null; rm -f "$FULL"' EXIT
sleep 4
roslaunch asr_robot_model robot_sim.launch rviz:=false > /dev/null 2>&1 &
LAUNCH=$!
sleep 6
# rviz needs a while to load the robot model and the markers before the grab.
xvfb-run -a -s "-screen 0 1280x1024x24" bash -c "
  rviz -d asr_robot_model/launch/robot_sim.rviz > /dev/null 2>&1 &
  RVIZ=\$!
  sleep 25
  import -window root '$FULL'
  kill \$RVIZ"
mkdir -p docs/images
convert "$FULL" -crop 880x910+363+62 +repage docs/images/robot_kitchen.png
echo "wrote docs/images/robot_kitchen.png"
