"""A stand-in for ROS's ament_index_python, so the real `xacro` CLI can resolve
$(find pkg) in differential tests: packages come from the JSON object in the
environment variable URDFCLI_TEST_PACKAGES ({"name": "/abs/dir"})."""
