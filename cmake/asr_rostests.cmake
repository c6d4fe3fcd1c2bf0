# Registers the rostests of the calling package by convention: every test/<name>.test with a
# test/<name>_rostest.cpp beside it becomes a rostest whose gtest node links the package's ROS
# layer (<package>_ros) and sees the recordings folder as ASR_RECORDINGS_DIR.
macro(asr_add_rostests)
  file(GLOB _asr_launch_files CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/test/*.test)
  if(_asr_launch_files)
    find_package(rostest REQUIRED)
  endif()
  foreach(_asr_launch_file ${_asr_launch_files})
    get_filename_component(_asr_test_name ${_asr_launch_file} NAME_WE)
    set(_asr_source ${CMAKE_CURRENT_SOURCE_DIR}/test/${_asr_test_name}_rostest.cpp)
    if(NOT EXISTS ${_asr_source})
      message(FATAL_ERROR "${_asr_launch_file} has no gtest node ${_asr_source}")
    endif()
    set(_asr_target ${PROJECT_NAME}_${_asr_test_name}_rostest)
    add_rostest_gtest(${_asr_target} ${_asr_launch_file} ${_asr_source})
    # The test's own main() calls ros::init, so no gtest_main.
    target_link_libraries(${_asr_target} ${PROJECT_NAME}_ros)
    # ASR_NODE_DIR: where the package's nodes are, for tests that start them themselves.
    target_compile_definitions(${_asr_target} PRIVATE
      ASR_RECORDINGS_DIR="${CMAKE_CURRENT_SOURCE_DIR}/../../shared/data/asr_recordings"
      ASR_NODE_DIR="${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION}")
    # The nodes under test are built before the test runs.
    if(${PROJECT_NAME}_NODE_TARGETS)
      add_dependencies(${_asr_target} ${${PROJECT_NAME}_NODE_TARGETS})
    endif()
  endforeach()
endmacro()
