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
from ..base import Kind, Rule
from . import load

MODULES = (load, mujoco, drake, pinocchio, pybullet, gazebo, kdl, isaac)
NOT_ABOUT_THE_MODEL = (Kind.TARGET, Kind.LOADING, Kind.SOURCES, Kind.SEMANTIC)  # a consumer's own rules, its real load, the xacro files as written, an SRDF (no consumer here reads one)


def about_the_model(rule: Rule) -> bool:
    """Whether a rule judges the model a consumer reads: neither a consumer's own rule nor
    one about the xacro sources (a consumer reads their expansion) or an SRDF. Its errors are the plain
    errors each consumer refuses, unless it loads the model anyway (``Consumer.loads_anyway``)."""
    return rule.kind not in NOT_ABOUT_THE_MODEL
