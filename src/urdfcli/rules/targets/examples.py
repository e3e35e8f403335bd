"""The XML examples several target rules document themselves with: each pair is one
defect and its fix, written once and given to each rule's ``Example`` and ``Use instead``
(:func:`urdfcli.rules.base.explain`)."""

from __future__ import annotations

_ELBOW = """
<joint name="elbow" type="revolute">
  <parent link="upper_arm"/><child link="forearm"/>{axis}{limit}
</joint>"""
_LIMIT = '\n  <limit lower="{lower}" upper="{upper}" effort="10" velocity="1"/>'
_AXIS = '<axis xyz="0 0 1"/>'

# lower above upper (MuJoCo and PyBullet free the joint, Drake aborts, Gazebo swaps them)
INVERTED_LIMITS = _ELBOW.format(axis="", limit=_LIMIT.format(lower="1.5", upper="-1.5"))
ORDERED_LIMITS = _ELBOW.format(axis="", limit=_LIMIT.format(lower="-1.5", upper="1.5"))

# a revolute joint without <limit> (urdfdom and PyBullet refuse it, Isaac Sim locks it)
NO_LIMIT = _ELBOW.format(axis=_AXIS, limit="")
WITH_LIMIT = _ELBOW.format(axis=_AXIS, limit=_LIMIT.format(lower="-1.5", upper="1.5"))

# a tensor breaking A + B >= C (MuJoCo and Gazebo refuse it, Drake and PyBullet replace it)
_WRIST = """
<link name="wrist">
  <inertial><mass value="1"/><inertia ixx="{moment}" ixy="0" ixz="0" iyy="{moment}" iyz="0" izz="0.01"/></inertial>
</link>"""
TRIANGLE_BROKEN = _WRIST.format(moment="0.001")
TRIANGLE_KEPT = _WRIST.format(moment="0.006")

# a free body inside a model (PyBullet welds it, Gazebo cannot load it)
FLOATING_JOINT = '<joint name="object" type="floating"><parent link="world"/><child link="box"/></joint>'
FIXED_JOINT = FLOATING_JOINT.replace('type="floating"', 'type="fixed"')

# a gripper whose second finger mimics the first (Pinocchio and Gazebo let it move on its own)
_FINGER = ('<joint name="{name}" type="prismatic"><parent link="palm"/><child link="{child}"/>'
           '<limit lower="0" upper="0.04" effort="10" velocity="0.1"/>')
MIMIC_GRIPPER = f"""
<robot name="gripper">
  <link name="palm"/><link name="left"/><link name="right"/>
  {_FINGER.format(name="left_joint", child="left")}</joint>
  {_FINGER.format(name="right_joint", child="right")}
    <mimic joint="left_joint"/></joint>
</robot>"""
ONE_FINGER = f"""
<robot name="gripper">
  <link name="palm"/><link name="left"/>
  {_FINGER.format(name="left_joint", child="left")}</joint>
</robot>"""

# a rover: its 5 kg chassis and a part joined to it (Gazebo drops a massless one and lumps a fixed one)
CHASSIS = '<link name="chassis"><inertial><mass value="5"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>'
_SMALL = '<inertial><mass value="0.1"/><inertia ixx="1e-4" ixy="0" ixz="0" iyy="1e-4" iyz="0" izz="1e-4"/></inertial>'
_ROVER = """
<robot name="rover">
  {chassis}
  {link}
  <joint name="{part}_joint" type="{kind}"><parent link="chassis"/><child link="{part}"/></joint>{more}
</robot>"""


def rover(part: str, kind: str, inertial: bool = True, more: str = "") -> str:
    """The rover with one part on a joint of ``kind``; ``more`` goes after the joint."""
    link = f'<link name="{part}">{_SMALL}</link>' if inertial else f'<link name="{part}"/>'
    return _ROVER.format(chassis=CHASSIS, part=part, kind=kind, link=link, more=more and "\n  " + more)


# a link with a collision mesh (MuJoCo and Drake read only some formats, MuJoCo no package://)
_MESHED = """
<link name="base">
  <collision><geometry><mesh filename="{}"/></geometry></collision>
</link>"""


def meshed(filename: str) -> str:
    return _MESHED.format(filename)


# an arm whose wrist turns on a continuous joint (MuJoCo refuses a massless wrist, weighs one by its shapes)
_ARM = """
<robot name="arm">
  <link name="base"/>
  {wrist}
  <joint name="roll" type="continuous"><parent link="base"/><child link="wrist"/></joint>
</robot>"""
WRIST_BOX = '<collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision>'


def arm(*wrist: str) -> str:
    """The arm, its wrist link holding ``wrist`` (one element a line)."""
    inside = "".join(f"\n    {part}" for part in wrist)
    return _ARM.format(wrist=f'<link name="wrist">{inside}\n  </link>' if wrist else '<link name="wrist"/>')


def wrist_inertial(mass: str, moment: str) -> str:
    return f'<inertial><mass value="{mass}"/><inertia ixx="{moment}" ixy="0" ixz="0" iyy="{moment}" iyz="0" izz="{moment}"/></inertial>'
