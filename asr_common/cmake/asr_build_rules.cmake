# Build rules every package of the suite shares, exported as a catkin CFG_EXTRAS of asr_common:
# a package gets them by find_package(catkin REQUIRED COMPONENTS asr_common ...).

# C++17, Release unless a build type is given, warnings on.
macro(asr_package_defaults)
  if(NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
    set(CMAKE_BUILD_TYPE Release)
  endif()
  set(CMAKE_CXX_STANDARD 17)
  set(CMAKE_CXX_STANDARD_REQUIRED ON)
  add_compile_options(-Wall -Wextra)
  # The real recordings (../shared/data/asr_recordings beside the repository), found from the
  # package's real source folder, so symlinked workspaces (catkin build) see the same folder.
  get_filename_component(_asr_package_real_dir "${PROJECT_SOURCE_DIR}" REALPATH)
  get_filename_component(ASR_RECORDINGS_DEFAULT
    "${_asr_package_real_dir}/../../shared/data/asr_recordings" ABSOLUTE)
endmacro()

# asr_library_path(<variable> <package> <library>): how users link <library> of catkin package
# <package>: its target when it is built in the same CMake project (catkin_make), else the file
# in the package's lib folder (catkin build, catkin_make_isolated, install space).
function(asr_library_path variable package library)
  if(TARGET ${library})
    set(${variable} ${library} PARENT_SCOPE)
  else()
    get_filename_component(_prefix "${${package}_DIR}/../../.." ABSOLUTE)
    set(${variable}
      "${_prefix}/lib/${CMAKE_SHARED_LIBRARY_PREFIX}${library}${CMAKE_SHARED_LIBRARY_SUFFIX}"
      PARENT_SCOPE)
  endif()
endfunction()

# asr_export_layer(<package> <LAYER> <library> [catkin packages the layer uses...]): for the users
# of a package's second library (its ROS layer, LAYER ROS, or its command-line library, LAYER
# CLI), sets <package>_<LAYER>_LIBRARIES and <package>_<LAYER>_INCLUDE_DIRS: the library and the
# libraries and include folders of the packages it uses (their core, and their layer of the same
# kind if they have one). The core, <package>_LIBRARIES, stays free of them, so a user of the
# core alone links no roscpp. Called from the package's own CFG_EXTRAS file.
macro(asr_export_layer package layer library)
  asr_library_path(_asr_layer_library ${package} ${library})
  set(${package}_${layer}_LIBRARIES ${_asr_layer_library} ${${package}_LIBRARIES})
  set(${package}_${layer}_INCLUDE_DIRS ${${package}_INCLUDE_DIRS})
  foreach(_asr_used ${ARGN})
    if(NOT ${_asr_used}_FOUND)
      find_package(${_asr_used} REQUIRED)
    endif()
    list(APPEND ${package}_${layer}_LIBRARIES ${${_asr_used}_${layer}_LIBRARIES}
      ${${_asr_used}_LIBRARIES})
    list(APPEND ${package}_${layer}_INCLUDE_DIRS ${${_asr_used}_${layer}_INCLUDE_DIRS}
      ${${_asr_used}_INCLUDE_DIRS})
  endforeach()
  if(${package}_${layer}_INCLUDE_DIRS)
    list(REMOVE_DUPLICATES ${package}_${layer}_INCLUDE_DIRS)
  endif()
endmacro()

# asr_add_node(<name> <source> <libraries...>): node executable <name> of the calling package
# (target <package>_<name>), installed with the package's executables.
function(asr_add_node name source)
  set(target ${PROJECT_NAME}_${name})
  add_executable(${target} ${source})
  set_target_properties(${target} PROPERTIES OUTPUT_NAME ${name})
  target_link_libraries(${target} ${ARGN})
  install(TARGETS ${target} RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
endfunction()

# asr_add_gtest(<name> <libraries...>): gtest <package>_<name> from test/<name>.cpp with gtest's
# main. Every test sees the recordings folder as ASR_RECORDINGS_DIR (tests skip without it).
function(asr_add_gtest name)
  set(target ${PROJECT_NAME}_${name})
  catkin_add_gtest(${target} test/${name}.cpp)
  if(TARGET ${target})
    target_link_libraries(${target} ${ARGN} gtest_main)
    target_compile_definitions(${target} PRIVATE ASR_RECORDINGS_DIR="${ASR_RECORDINGS_DEFAULT}")
  endif()
endfunction()

# asr_add_rostest(<name> LIBRARIES <libraries...> NODES <node targets...>): rostest
# test/<name>.test whose gtest node is test/<name>_rostest.cpp (with its own main, which calls
# ros::init). It sees the recordings as ASR_RECORDINGS_DIR and the package's node folder as
# ASR_NODE_DIR (for tests that start nodes themselves); the nodes are built before it.
function(asr_add_rostest name)
  cmake_parse_arguments(ARG "" "" "LIBRARIES;NODES" ${ARGN})
  find_package(rostest REQUIRED)
  set(target ${PROJECT_NAME}_${name}_rostest)
  add_rostest_gtest(${target} test/${name}.test test/${name}_rostest.cpp)
  target_link_libraries(${target} ${ARG_LIBRARIES})
  target_compile_definitions(${target} PRIVATE
    ASR_RECORDINGS_DIR="${ASR_RECORDINGS_DEFAULT}"
    ASR_NODE_DIR="${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION}")
  if(ARG_NODES)
    add_dependencies(${target} ${ARG_NODES})
  endif()
endfunction()

# asr_test_runs_tool(<test> <tool target> <definition>): test <package>_<test> runs the built tool
# as a user would: built first, its path in the compile definition <definition>, nlohmann_json
# to read its output.
function(asr_test_runs_tool test tool definition)
  if(TARGET ${PROJECT_NAME}_${test})
    find_package(nlohmann_json REQUIRED)
    target_link_libraries(${PROJECT_NAME}_${test} nlohmann_json::nlohmann_json)
    target_compile_definitions(${PROJECT_NAME}_${test} PRIVATE
      ${definition}="$<TARGET_FILE:${tool}>")
    add_dependencies(${PROJECT_NAME}_${test} ${tool})
  endif()
endfunction()
