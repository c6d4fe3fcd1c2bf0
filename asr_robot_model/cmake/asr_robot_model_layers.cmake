# asr_robot_model's ROS layer for its users (see asr_export_layer in asr_common's build rules).
asr_export_layer(asr_robot_model ROS asr_robot_model_ros asr_common roscpp actionlib asr_msgs tf2_ros
  sensor_msgs rosgraph_msgs visualization_msgs std_msgs image_transport cv_bridge)
