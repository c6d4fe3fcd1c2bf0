#!/usr/bin/env bash
# `./asr demo`: an active search of the simulated kitchen, end to end. Learns the kitchen's scene
# models from the recordings (or reuses out/kitchen/kitchen_models.sqlite), starts the whole
# graph with search.launch headless on simulated time (its own ROS master), records a rosbag of
# the run, and prints a summary; writes the result, the log, the bag and a top-down picture into
# the output folder. Without search.launch (an older build) the same search runs in-process.
# Usage: scripts/demo.sh <devel folder> [output folder]
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
DEVEL="$1"
OUT="${2:-$ROOT/out/demo}"
WORLD="$ROOT/asr_state_machine/config/worlds/kitchen.yaml"
MODELS="${ASR_DEMO_MODELS:-$ROOT/out/kitchen/kitchen_models.sqlite}"
SEED="${ASR_DEMO_SEED:-1}"
SEARCH="$DEVEL/lib/asr_state_machine/search"
mkdir -p "$OUT"
started=$(date +%s)

step() { printf '\n=== %s\n' "$*"; }

step "1. The kitchen's scene models (gedeck, Brot_Regal, Muesli_Regal), learned from the recordings"
if [ -s "$MODELS" ]; then
  echo "reusing $MODELS (delete it to learn again)"
else
  mkdir -p "$(dirname "$MODELS")"
  "$DEVEL/lib/asr_state_machine/learn_kitchen_models" --model "$MODELS"
fi

rm -f "$OUT/result.json" "$OUT/search_log.jsonl" "$OUT/search.bag" "$OUT/search.png"
if [ -f "$ROOT/asr_state_machine/launch/search.launch" ]; then
  step "2. Search the kitchen: search.launch headless on simulated time, recorded into search.bag"
  # setup.bash reads variables that may be unset.
  set +u
  # shellcheck disable=SC1091
  source "$DEVEL/setup.bash"
  set -u
  export ROS_LOG_DIR="$OUT/ros_log"
  port=$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("", 0)); print(s.getsockname()[1])')
  export ROS_MASTER_URI="http://localhost:$port"
  roscore -p "$port" >"$OUT/roscore.log" 2>&1 &
  master=$!
  recorder=""
  stop_all() {
    if [ -n "$recorder" ]; then kill -INT "$recorder" 2>/dev/null || true; wait "$recorder" || true; fi
    kill -INT "$master" 2>/dev/null || true
    wait "$master" 2>/dev/null || true
  }
  trap stop_all EXIT
  for _ in $(seq 150); do
    rosnode list >/dev/null 2>&1 && break
    sleep 0.2
  done
  # On the search's simulated time (the driver's /clock, which search.launch turns on), so that
  # the bag replays at the pace the robot moved, not the few seconds the search took.
  rosparam set /use_sim_time true
  # The search's own topics and the robot's; subscribed before the graph starts, so nothing of
  # the search is missed.
  rosbag record --quiet -O "$OUT/search.bag" /clock /tf /tf_static /joint_states /robot_state \
    /objects /search_log /search_executive/state /search_executive/result /search_markers \
    /world_markers /scene_markers /prediction_markers /nbv_markers >"$OUT/rosbag.log" 2>&1 &
  recorder=$!
  roslaunch asr_state_machine search.launch world:="$WORLD" model_files:="[$MODELS]" \
    seed:="$SEED" rviz:=false exit_when_done:=true result_file:="$OUT/result.json" \
    log_file:="$OUT/search_log.jsonl" >"$OUT/roslaunch.log" 2>&1 || true
  stop_all
  trap - EXIT
  if [ ! -s "$OUT/result.json" ]; then
    echo "demo: the search wrote no result; see $OUT/roslaunch.log" >&2
    tail -n 20 "$OUT/roslaunch.log" >&2
    exit 1
  fi
else
  step "2. Search the kitchen in-process on simulated time (./asr search)"
  "$SEARCH" --world "$WORLD" --models "$MODELS" --seed "$SEED" --json >"$OUT/result.json"
fi

step "3. What happened"
"$SEARCH" --world "$WORLD" --result "$OUT/result.json" --png "$OUT/search.png"

step "Done in $(($(date +%s) - started)) s. Files in $OUT:"
for file in result.json search_log.jsonl search.bag search.png; do
  if [ -f "$OUT/$file" ]; then echo "  $file"; fi
done
if [ -f "$OUT/search.bag" ]; then
  echo "Replay (on the search's simulated time, from its /clock): rosparam set use_sim_time true; rosbag play $OUT/search.bag; rviz -d asr_state_machine/launch/search.rviz"
fi
