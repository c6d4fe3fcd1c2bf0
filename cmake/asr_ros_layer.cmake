# The ROS side of a suite package, by convention: the ROS layer library <package>_ros from
# src/ros/*.cpp (linking the ROS-free core target <package> and catkin's libraries), and one
# node executable per file in src/nodes/*.cpp (named after the file). The core never links ROS.
macro(asr_add_ros_layer_and_nodes)
  file(GLOB _asr_ros_sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/src/ros/*.cpp)
  if(_asr_ros_sources)
    add_library(${PROJECT_NAME}_ros ${_asr_ros_sources})
    target_include_directories(${PROJECT_NAME}_ros PUBLIC include ${catkin_INCLUDE_DIRS})
    target_link_libraries(${PROJECT_NAME}_ros PUBLIC ${PROJECT_NAME} ${catkin_LIBRARIES})
    add_dependencies(${PROJECT_NAME}_ros ${catkin_EXPORTED_TARGETS})
    target_compile_options(${PROJECT_NAME}_ros PRIVATE -Wall -Wextra)
    install(TARGETS ${PROJECT_NAME}_ros
      ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
      LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
  endif()
  set(${PROJECT_NAME}_NODE_TARGETS "")
  file(GLOB _asr_node_sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/src/nodes/*.cpp)
  foreach(_asr_node_source ${_asr_node_sources})
    get_filename_component(_asr_node_name ${_asr_node_source} NAME_WE)
    set(_asr_node_target ${PROJECT_NAME}_${_asr_node_name})
    add_executable(${_asr_node_target} ${_asr_node_source})
    set_target_properties(${_asr_node_target} PROPERTIES OUTPUT_NAME ${_asr_node_name})
    target_link_libraries(${_asr_node_target} ${PROJECT_NAME}_ros)
    target_compile_options(${_asr_node_target} PRIVATE -Wall -Wextra)
    list(APPEND ${PROJECT_NAME}_NODE_TARGETS ${_asr_node_target})
    install(TARGETS ${_asr_node_target} RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
  endforeach()
endmacro()
