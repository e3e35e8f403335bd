"""What ``check --target NAME --load`` reports from a real load into the consumer."""

from __future__ import annotations

from ..base import ERROR, INFO, WARNING, Kind, declare, explain

_EXAMPLE = '<link name="wrist"><inertial><mass value="0"/><inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial></link>'

LOAD_REJECTED = declare(
    "C001", "target-load-rejected", ERROR, "The consumer itself refused the model (--load).",
    explain(
        """With `--target NAME --load`: the model was loaded into the consumer itself (its
        Python package in a child process: mujoco, pydrake, pinocchio, pybullet,
        urdf_usd_converter; sdformat's `gz sdf`/`ign sdf` for Gazebo; kdl_parser for KDL),
        and it refused it. The message is the consumer's, whole, placed at the line it
        names, else at the link or joint it names.""",
        "The consumer cannot use the model as written.",
        '<robot name="r">\n  <link name="base"/>\n  ' + _EXAMPLE + "\n  <joint name=\"j\" type=\"continuous\"><parent link=\"base\"/><child link=\"wrist\"/></joint>\n</robot>",
        '<robot name="r">\n  <link name="base"/>\n</robot>',
    ),
    kind=Kind.LOADING,
)
LOAD_DISAGREES = declare(
    "C002", "target-load-disagrees", WARNING, "The consumer's verdict differs from urdfcli's prediction (--load).",
    explain(
        """With `--target NAME --load`: urdfcli predicted that the consumer would reject the model
        and it did not, or the other way round.""",
        "Either the model depends on something urdfcli does not read (a mesh file's content), or the consumer's version behaves otherwise: please report it.",
        '<robot name="r">\n  <link name="base"/>\n</robot>',
        '<robot name="r">\n  <link name="base"/>\n</robot>',
    ),
    kind=Kind.LOADING,
)
LOAD_SAYS = declare(
    "C003", "target-load-warning", INFO, "A warning the consumer printed while loading (--load).",
    explain(
        "With `--target NAME --load`: a warning the consumer printed while loading the model, placed at the link or joint it names.",
        "The consumer changed or ignored something it warns about.",
        '<robot name="r">\n  <link name="base"/>\n</robot>',
        '<robot name="r">\n  <link name="base"/>\n</robot>',
    ),
    kind=Kind.LOADING,
)
LOAD_UNAVAILABLE = declare(
    "C004", "target-load-unavailable", INFO, "The consumer cannot be run here (--load).",
    explain(
        """With `--target NAME --load`: the consumer is not installed on this machine (its
        Python package, sdformat's tool, or kdl_parser's headers and a C++ compiler), so only
        urdfcli's prediction is reported; the message says what to install.""",
        "Nothing is wrong with the model: the real load could not be made.",
        '<robot name="r">\n  <link name="base"/>\n</robot>',
        '<robot name="r">\n  <link name="base"/>\n</robot>',
    ),
    kind=Kind.LOADING,
)
