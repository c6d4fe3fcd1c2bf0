# asr_nbv's ROS layer for its users (see asr_export_layer in asr_common's build rules).
asr_export_layer(asr_nbv ROS asr_nbv_ros asr_robot_model roscpp asr_msgs visualization_msgs)
