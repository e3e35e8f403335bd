"""Small models that several test files use alike."""

# a crate on a lift: its inertial (a unit tensor) disagrees with its collision box,
# which sits 0.1 m up; `inertia --suggest` gives the box's tensor and centre of mass
CRATE = """<?xml version="1.0"?>
<robot name="crate">
  <link name="base_link"/>
  <joint name="lift" type="prismatic">
    <parent link="base_link"/>
    <child link="crate"/>
    <axis xyz="0 0 1"/>
    <limit lower="0" upper="0.5" effort="100" velocity="0.2"/>
  </joint>
  <link name="crate">
    <inertial>
      <mass value="2"/>
      <inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/>
    </inertial>
    <collision><origin xyz="0 0 0.1"/><geometry><box size="0.4 0.3 0.2"/></geometry></collision>
  </link>
</robot>
"""

# an arm with safe fixes (the deprecated forms xacro still reads: a macro named with its
# xacro: prefix, a bare `range`) and an unsafe one (a joint turned by 90, degrees where
# radians are meant)
FIXABLE_ARM = """<?xml version="1.0"?>
<robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="xacro:part" params="n">
    <link name="part_${n}"/>
  </xacro:macro>
  <xacro:property name="count" value="${len(list(range(2)))}"/>
  <link name="base_link"/>
  <link name="arm_link"/>
  <xacro:part n="${count}"/>
  <joint name="part_joint" type="fixed"><parent link="base_link"/><child link="part_2"/></joint>
  <joint name="arm_joint" type="revolute">
    <parent link="base_link"/>
    <child link="arm_link"/>
    <origin xyz="0 0 0.1" rpy="0 0 90"/>
    <limit lower="-1" upper="1" effort="10" velocity="1"/>
  </joint>
</robot>
"""
