# asr_ism_tree's ROS layer and command-line library for its users (see asr_export_layer in
# asr_common's build rules).
asr_export_layer(asr_ism_tree ROS asr_ism_tree_ros asr_ism asr_common roscpp asr_msgs std_msgs
  std_srvs geometry_msgs visualization_msgs tf2_ros)
asr_export_layer(asr_ism_tree CLI asr_ism_tree_cli asr_common)
