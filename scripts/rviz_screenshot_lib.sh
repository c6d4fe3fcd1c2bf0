# Shared by the rviz screenshot scripts (source it from the repository root after sourcing
# devel/setup.bash): a private ROS master, and rviz grabbed on a virtual display.

# start_master PORT: a roscore of its own on PORT (so no other master is disturbed), stopped
# with everything in STOP_PIDS when the script exits.
start_master() {
  export ROS_MASTER_URI="http://localhost:$1"
  roscore -p "$1" > /dev/null 2>&1 &
  CORE=$!
  STOP_PIDS=""
  trap 'kill -INT $STOP_PIDS 2>/dev/null; sleep 2; kill $CORE 2>/dev/null' EXIT
  sleep 4
}

# grab_rviz CONFIG OUTPUT: rviz with CONFIG on a 1280x1024 virtual display, given time to load
# the robot model and the markers; its 3D view cropped into OUTPUT (a PNG).
grab_rviz() {
  local full
  full="$(mktemp --suffix=.png)"
  xvfb-run -a -s "-screen 0 1280x1024x24" bash -c "
    rviz -d '$1' > /dev/null 2>&1 &
    RVIZ=\$!
    sleep 25
    import -window root '$full'
    kill \$RVIZ"
  mkdir -p "$(dirname "$2")"
  convert "$full" -crop 880x910+363+62 +repage "$2"
  rm -f "$full"
  echo "wrote $2"
}
