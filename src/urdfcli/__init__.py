"""urdfcli: check, expand, draw and lint URDF and xacro robot descriptions."""

__version__ = "0.1.0"
