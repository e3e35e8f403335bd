"""The robot model: links and joints read tolerantly, kinematics, mass properties, meshes, poses."""
