"""Reading: XML (one reader), xacro in a bounded worker, ROS packages, source positions."""
