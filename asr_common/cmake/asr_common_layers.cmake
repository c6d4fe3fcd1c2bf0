# asr_common's ROS layer and command-line library for its users (see asr_export_layer).
asr_export_layer(asr_common ROS asr_common_ros roscpp asr_msgs geometry_msgs std_msgs
  visualization_msgs)
asr_export_layer(asr_common CLI asr_common_cli)
