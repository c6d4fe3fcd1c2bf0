# asr_pose_prediction's ROS layer for its users (see asr_export_layer in asr_common's build
# rules).
asr_export_layer(asr_pose_prediction ROS asr_pose_prediction_ros asr_ism_tree roscpp asr_msgs
  geometry_msgs visualization_msgs)
