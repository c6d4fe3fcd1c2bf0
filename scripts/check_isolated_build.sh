#!/usr/bin/env bash
# Checks that every package of the repository builds alone, the ROS way: in temporary
# workspaces whose src/ holds a copy of the repository's packages (as they are when it starts),
#  1. `catkin build` (catkin-tools: one CMake project per package, in dependency order);
#  2. `catkin_make_isolated --install`, then that the install space holds the libraries, headers,
#     nodes, tools, launch files and parameters, and that a user of a package's ROS-free core
#     links no roscpp while its ROS layer brings it.
# Prints the time of each build. Usage: scripts/check_isolated_build.sh [jobs] (default: nproc).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
JOBS="${1:-${ASR_JOBS:-$(nproc)}}"
# Debian's catkin lives in /usr/bin; a pyenv python3 earlier on PATH lacks catkin_pkg.
export PATH="/usr/bin:$PATH"
CMAKE_ARGS=(-DCMAKE_BUILD_TYPE=Release -DPYTHON_EXECUTABLE=/usr/bin/python3)

WORK="$(mktemp -d "${TMPDIR:-/tmp}/asr_isolated.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT

# A workspace whose src/ holds every package (a folder with a package.xml) of the repository.
new_workspace() {
  local workspace="$WORK/$1"
  mkdir -p "$workspace/src"
  cp -r "$WORK/packages/." "$workspace/src/"
  echo "$workspace"
}

# One copy of the packages for both workspaces, so that edits during the check do not matter.
copy_packages() {
  mkdir -p "$WORK/packages"
  for manifest in "$ROOT"/*/package.xml; do
    cp -r "$(dirname "$manifest")" "$WORK/packages/"
  done
}

# Runs a build command quietly; on failure shows the end of its output.
run_logged() {
  local log="$1"
  shift
  if ! "$@" >"$log" 2>&1; then
    tail -n 60 "$log" >&2
    echo "check_isolated_build: FAILED: $*" >&2
    exit 1
  fi
}

check_catkin_build() {
  local workspace start
  workspace="$(new_workspace catkin_build)"
  start=$SECONDS
  (cd "$workspace" && catkin init >/dev/null &&
    run_logged "$WORK/catkin_build.log" catkin build --no-status --no-notify -j "$JOBS" \
      --cmake-args "${CMAKE_ARGS[@]}")
  echo "catkin build: $(ls "$workspace/src" | wc -l) packages built in $((SECONDS - start)) s"
}

check_catkin_make_isolated() {
  local workspace start
  workspace="$(new_workspace isolated)"
  start=$SECONDS
  (cd "$workspace" &&
    run_logged "$WORK/isolated.log" catkin_make_isolated --install -j"$JOBS" "${CMAKE_ARGS[@]}")
  echo "catkin_make_isolated --install: built and installed in $((SECONDS - start)) s"
  check_install_space "$workspace/install_isolated"
  check_core_without_ros "$workspace/install_isolated"
  check_shipped_files_installed "$workspace"
}

# The installed robot tool finds the shipped URDF in the install space once the sources are gone.
check_shipped_files_installed() {
  local workspace="$1"
  mv "$workspace/src" "$workspace/src.moved"
  if ! LD_LIBRARY_PATH="$workspace/install_isolated/lib" \
      "$workspace/install_isolated/lib/asr_robot_model/robot" fk --state "0 0 0 0 0" --json \
      >"$WORK/shipped_files.log" 2>&1; then
    cat "$WORK/shipped_files.log" >&2
    echo "check_isolated_build: the installed robot tool does not find its shipped URDF" >&2
    exit 1
  fi
  mv "$workspace/src.moved" "$workspace/src"
  echo "install space: the shipped URDF is found there without the sources"
}

# What a user of the installed suite needs is there.
check_install_space() {
  local install="$1" missing=0
  for file in \
    lib/libasr_common.so lib/libasr_common_ros.so lib/libasr_common_cli.so \
    lib/libasr_ism.so lib/libasr_ism_ros.so lib/libasr_ism_tree.so lib/libasr_ism_tree_ros.so \
    lib/libasr_ism_tree_cli.so lib/libasr_pose_prediction.so lib/libasr_pose_prediction_ros.so \
    include/asr_common/pose.hpp include/asr_common/testing/temp_dir.hpp \
    include/asr_ism/ism.hpp include/asr_ism_tree/ism_tree.hpp \
    include/asr_pose_prediction/pose_predictor.hpp \
    lib/asr_ism/recorder lib/asr_ism/replay_demonstration lib/asr_ism/bag_to_demonstration \
    lib/asr_ism_tree/scene_recognizer lib/asr_ism_tree/trainer lib/asr_ism_tree/ism \
    lib/asr_ism_tree/asr_bench lib/asr_ism_tree/asr_demo_data \
    lib/asr_pose_prediction/pose_predictor lib/asr_pose_prediction/ism_predict \
    lib/asr_pose_prediction/asr_prediction_bench \
    share/asr_bringup/launch/recognize.launch share/asr_bringup/launch/learn.launch \
    share/asr_bringup/launch/replay.launch share/asr_bringup/config/scene_recognizer.yaml \
    share/asr_common/cmake/asr_build_rules.cmake \
    lib/libasr_robot_model.so lib/libasr_robot_model_ros.so \
    include/asr_robot_model/robot_description.hpp lib/asr_robot_model/robot \
    lib/asr_robot_model/robot_driver lib/asr_robot_model/object_detector_sim \
    lib/asr_robot_model/tags lib/asr_robot_model/apriltag_detector lib/asr_robot_model/camera_sim \
    share/asr_robot_model/config/tag_map.yaml \
    share/asr_robot_model/launch/robot_sim.launch share/asr_robot_model/launch/robot_sim.rviz \
    share/asr_robot_model/urdf/asr_robot.urdf share/asr_robot_model/config/object_types.yaml \
    share/asr_robot_model/config/worlds/kitchen.yaml \
    lib/libasr_state_machine.so include/asr_state_machine/search_executive.hpp \
    lib/asr_state_machine/search lib/asr_state_machine/learn_kitchen_models \
    share/asr_state_machine/config/worlds/kitchen.yaml; do
    if [ ! -e "$install/$file" ]; then
      echo "check_isolated_build: not installed: $file" >&2
      missing=1
    fi
  done
  [ "$missing" -eq 0 ] || exit 1
  echo "install space: libraries, headers, nodes, tools, launch files and parameters present"
}

# A CMake project that uses the installed asr_ism_tree: its core variables must not bring
# roscpp, its ROS layer variables must.
check_core_without_ros() {
  local install="$1" user="$WORK/core_user"
  mkdir -p "$user"
  cat >"$user/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.10)
project(core_user)
find_package(catkin REQUIRED COMPONENTS asr_ism_tree)
foreach(library ${catkin_LIBRARIES})
  if(library MATCHES "roscpp")
    message(FATAL_ERROR "the core of asr_ism_tree brings ROS: ${library}")
  endif()
endforeach()
if(NOT asr_ism_tree_ROS_LIBRARIES MATCHES "roscpp")
  message(FATAL_ERROR "asr_ism_tree_ROS_LIBRARIES lacks roscpp: ${asr_ism_tree_ROS_LIBRARIES}")
endif()
if(NOT asr_ism_tree_CLI_LIBRARIES MATCHES "asr_common_cli")
  message(FATAL_ERROR "asr_ism_tree_CLI_LIBRARIES lacks asr_common_cli")
endif()
CMAKE
  run_logged "$WORK/core_user.log" env CMAKE_PREFIX_PATH="$install" \
    cmake -S "$user" -B "$user/build" "${CMAKE_ARGS[@]}"
  echo "exported libraries: the core links no roscpp; the ROS and CLI layers are separate"
}

copy_packages
check_catkin_build
check_catkin_make_isolated
echo "check_isolated_build: passed"
