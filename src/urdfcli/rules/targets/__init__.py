"""The target rules: what each consumer refuses, changes or warns about.

Each consumer's rules are the ``rules`` module of its package in :mod:`urdfcli.targets`;
they run only for the targets asked for (``--target NAME``, ``targets`` in
``[tool.urdfcli]``). Here are what they share (:mod:`.common`, the documentation's
:mod:`.examples`) and the rules of a real load (:mod:`.load`, C001-C003).
"""

from ...targets.drake import rules as drake
from ...targets.gazebo import rules as gazebo
from ...targets.isaac import rules as isaac
from ...targets.kdl import rules as kdl
from ...targets.mujoco import rules as mujoco
from ...targets.pinocchio import rules as pinocchio
from ...targets.pybullet import rules as pybullet
from . import load

MODULES = (load, mujoco, drake, pinocchio, pybullet, gazebo, kdl, isaac)
