# asr_ism's ROS layer for its users (see asr_export_layer in asr_common's build rules).
asr_export_layer(asr_ism ROS asr_ism_ros asr_common roscpp asr_msgs geometry_msgs std_msgs
  tf2_ros tf2_geometry_msgs tf2_msgs visualization_msgs rosbag)
