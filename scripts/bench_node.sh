#!/usr/bin/env bash
# `./asr bench node`: starts a ROS master of its own on a free port, runs asr_node_bench against
# the scene_recognizer node, and stops the master again.
set -euo pipefail
devel="$1"
shift
# setup.bash reads variables that may be unset.
set +u
# shellcheck disable=SC1091
source "$devel/setup.bash"
set -u
port=$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("", 0)); print(s.getsockname()[1])')
export ROS_MASTER_URI="http://localhost:$port"
roscore -p "$port" >/dev/null 2>&1 &
master=$!
trap 'kill -INT $master 2>/dev/null; wait $master 2>/dev/null || true' EXIT
for _ in $(seq 100); do
  rosnode list >/dev/null 2>&1 && break
  sleep 0.1
done
"$devel/lib/asr_ism_tree/asr_node_bench" "$devel/lib/asr_ism_tree" "$@"
