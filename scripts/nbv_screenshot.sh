#!/bin/bash
# Renders next_best_view's markers in the shipped kitchen with rviz on a virtual display and saves
# the 3D view as docs/images/nbv_kitchen.png (docs/next_best_view.md): predicted poses, the
# candidate views rated in full and the chosen view's frustum. Needs `./asr build` first; runs
# its own ROS master on port 11398 so that it disturbs no other.
set -e
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
cd "$ROOT"
source devel/setup.bash
export ROS_MASTER_URI=http://localhost:11398
FULL="$(mktemp --suffix=.png)"
roscore -p 11398 > /dev/null 2>&1 &
CORE=$!
trap 'kill -INT $SIM $NBV 2>/dev/null; sleep 2; kill $CORE 2>/dev/null; rm -f "$FULL"' EXIT
sleep 4
# The simulation draws the furniture (world_markers) and the robot.
roslaunch asr_robot_model robot_sim.launch rviz:=false > /dev/null 2>&1 &
SIM=$!
roslaunch asr_nbv next_best_view.launch > /dev/null 2>&1 &
NBV=$!
sleep 6
/usr/bin/python3 scripts/nbv_screenshot_request.py
xvfb-run -a -s "-screen 0 1280x1024x24" bash -c "
  rviz -d asr_nbv/launch/next_best_view.rviz > /dev/null 2>&1 &
  RVIZ=\$!
  sleep 25
  import -window root '$FULL'
  kill \$RVIZ"
mkdir -p docs/images
convert "$FULL" -crop 880x910+363+62 +repage docs/images/nbv_kitchen.png
echo "wrote docs/images/nbv_kitchen.png"
