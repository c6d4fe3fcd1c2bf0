# Registers the gtests and rostests of the calling package by convention:
# - test/*_test.cpp -> gtest <package>_<name>, linking the ROS-free core <package>, or the ROS
#   layer <package>_ros for test/ros_*_test.cpp (no master needed);
# - test/<name>.test + test/<name>_rostest.cpp -> rostest (see asr_rostests.cmake).
# Every test sees the recordings folder as ASR_RECORDINGS_DIR (they skip when it is absent).
include(${CMAKE_CURRENT_LIST_DIR}/asr_rostests.cmake)

macro(asr_add_tests)
  file(GLOB _asr_test_sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/test/*_test.cpp)
  foreach(_asr_test_source ${_asr_test_sources})
    get_filename_component(_asr_test_name ${_asr_test_source} NAME_WE)
    set(_asr_test_target ${PROJECT_NAME}_${_asr_test_name})
    catkin_add_gtest(${_asr_test_target} ${_asr_test_source})
    if(_asr_test_name MATCHES "^ros_")
      target_link_libraries(${_asr_test_target} ${PROJECT_NAME}_ros gtest_main)
    else()
      target_link_libraries(${_asr_test_target} ${PROJECT_NAME} gtest_main)
    endif()
    target_compile_definitions(${_asr_test_target} PRIVATE
      ASR_RECORDINGS_DIR="${CMAKE_CURRENT_SOURCE_DIR}/../../shared/data/asr_recordings")
  endforeach()
  asr_add_rostests()
endmacro()

# Lets test <package>_<test> run the tool target <tool> as a user would: built first, its path
# in the compile definition <definition>, nlohmann_json to read its output.
macro(asr_test_runs_tool test tool definition)
  if(TARGET ${PROJECT_NAME}_${test} AND TARGET ${tool})
    find_package(nlohmann_json REQUIRED)
    target_link_libraries(${PROJECT_NAME}_${test} nlohmann_json::nlohmann_json)
    target_compile_definitions(${PROJECT_NAME}_${test} PRIVATE
      ${definition}="$<TARGET_FILE:${tool}>")
    add_dependencies(${PROJECT_NAME}_${test} ${tool})
  endif()
endmacro()
