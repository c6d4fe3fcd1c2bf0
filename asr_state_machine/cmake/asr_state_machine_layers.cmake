# asr_state_machine's ROS layer for its users (see asr_export_layer in asr_common's build rules).
asr_export_layer(asr_state_machine ROS asr_state_machine_ros asr_robot_model asr_ism_tree
  asr_common roscpp actionlib asr_msgs std_msgs visualization_msgs)
