"""What each consumer rejects, changes or warns about: one module per consumer.

These rules run only for the targets asked for (``--target NAME``, ``targets`` in
``[tool.urdfcli]``); each reads what :mod:`urdfcli.model.targets` works out that
the consumer builds, and its documentation names the consumer's source it encodes.
Codes: C0 a real load (--load), C1 MuJoCo, C2 Drake, C3 Pinocchio, C4 PyBullet, C5 Gazebo, C6 KDL, C7 Isaac Sim.
"""

from . import drake, gazebo, isaac, kdl, load, mujoco, pinocchio, pybullet

MODULES = (load, mujoco, drake, pinocchio, pybullet, gazebo, kdl, isaac)
