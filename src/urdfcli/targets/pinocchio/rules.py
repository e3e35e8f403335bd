"""Pinocchio 4.1's URDF parser (``pinocchio.buildModelFromUrdf``): src/parsers/urdf/model.cpp and
include/pinocchio/parsers/urdf/model.hxx (the tree walk), include/pinocchio/multibody/joint/joint-mimic.hxx."""

from __future__ import annotations

from ...rules.base import ERROR, WARNING, Kind, check, explain
from ...model.kinematics import walks
from ...rules.targets.common import MIMICKED, mimic_at, mimic_joints, mimics_said_once
from ...rules.targets.examples import MIMIC_GRIPPER, ONE_FINGER



@check(
    "C301", "pinocchio-ignores-mimic", WARNING, "Pinocchio ignores <mimic> unless built with mimic=True.", kind=Kind.TARGET, target="pinocchio",
    doc=explain(
        """With `--target pinocchio` (not `pinocchio:mimic`): says, once per model, which joints have a `<mimic>`.""",
        """`buildModelFromUrdf(path)` reads `<mimic>` only when called with `mimic=True`
        (src/parsers/urdf/model.cpp): by default the mimic joint is one more free degree
        of freedom, so a gripper's second finger moves on its own and `model.nq` counts it.""",
        MIMIC_GRIPPER,
        ONE_FINGER,
    ),
)
def ignores_mimic(loaded, given):
    if "mimic" in given.profile.variants:
        return
    yield from mimics_said_once(
        loaded, "C301", "Pinocchio makes {joints} free degrees of freedom: it ignores <mimic> by default",
        "build the model with pinocchio.buildModelFromUrdf(path, mimic=True) (and check it with --target pinocchio:mimic)",
    )


@check("C302", "pinocchio-mimic-unsupported", ERROR, "Pinocchio's mimic=True rejects mimic chains and mixed joint kinds.", kind=Kind.TARGET, target="pinocchio:mimic")
def mimic_unsupported(loaded, given):
    """## What it does
    With `--target pinocchio:mimic`: finds a mimic joint whose mimicked joint itself
    mimics another (a chain), or is of another kind (a prismatic joint mimicking a
    revolute one; revolute and continuous count as one kind).

    ## Why is this bad?
    With `mimic=True`, Pinocchio builds each mimic joint on the joint it follows, and
    asserts both are of one kind and the followed one is not a mimic itself
    (joint-mimic.hxx): the model does not build.

    ## Example
    ```xml
    <robot name="hand">
      <link name="palm"/><link name="a"/><link name="b"/>
      <joint name="slide" type="prismatic"><parent link="palm"/><child link="a"/><limit lower="0" upper="0.04" effort="10" velocity="0.1"/></joint>
      <joint name="turn" type="revolute"><parent link="palm"/><child link="b"/><limit lower="0" upper="1" effort="10" velocity="1"/>
        <mimic joint="slide"/></joint>
    </robot>
    ```

    ## Use instead
    ```xml
    <robot name="hand">
      <link name="palm"/><link name="a"/><link name="b"/>
      <joint name="slide" type="prismatic"><parent link="palm"/><child link="a"/><limit lower="0" upper="0.04" effort="10" velocity="0.1"/></joint>
      <joint name="slide2" type="prismatic"><parent link="palm"/><child link="b"/><limit lower="0" upper="0.04" effort="10" velocity="0.1"/>
        <mimic joint="slide"/></joint>
    </robot>
    ```
    """
    if "mimic" not in given.profile.variants:
        return
    joints = loaded.robot.joints
    kind = {"revolute": "revolute", "continuous": "revolute", "prismatic": "prismatic"}
    for joint in joints.values():
        followed = joints.get(joint.mimic.joint) if joint.mimic is not None else None
        if followed is None or joint.type not in MIMICKED:
            continue
        if followed.mimic is not None:
            why = f"'{followed.name}' is itself a mimic joint"
        elif kind.get(followed.type or "") != kind[joint.type]:
            why = f"it is {joint.type} and '{followed.name}' is {followed.type}"
        else:
            continue
        yield loaded.diagnostic(
            "C302",
            f"Pinocchio (mimic=True) rejects joint '{joint.name}': {why}",
            joint.part("mimic") or joint.at,
            "make the joint mimic the first joint of the chain, of its own kind",
            subjects=(joint.name, followed.name),
        )


@check("C303", "pinocchio-mimic-order", ERROR, "Pinocchio's mimic=True rejects a mimic joint it reaches before the joint it follows.", kind=Kind.TARGET, target="pinocchio:mimic")
def mimic_order(loaded, given):
    """## What it does
    With `--target pinocchio:mimic`: finds a mimic joint that Pinocchio's tree walk
    reaches before the joint it follows (depth first from the root, the children of a
    link in the order of their joints' names), or whose followed joint does not exist
    or is itself.

    ## Why is this bad?
    With `mimic=True`, Pinocchio builds the joints in that walk and a mimic joint needs
    the joint it follows already built: "The parent joint of the mimic joint is not in
    the kinematic tree" (src/parsers/urdf/model.cpp). A gripper whose mimicking finger
    is named (or hangs from a branch named) before the driving one does not build;
    romeo and talos_full_v2 in example-robot-data are such models.

    ## Example
    ```xml
    <robot name="gripper">
      <link name="palm"/><link name="left"/><link name="right"/>
      <joint name="b_finger" type="prismatic"><parent link="palm"/><child link="left"/>
        <limit lower="0" upper="0.04" effort="10" velocity="0.1"/></joint>
      <joint name="a_finger" type="prismatic"><parent link="palm"/><child link="right"/>
        <limit lower="0" upper="0.04" effort="10" velocity="0.1"/><mimic joint="b_finger"/></joint>
    </robot>
    ```

    ## Use instead
    ```xml
    <robot name="gripper">
      <link name="palm"/><link name="left"/><link name="right"/>
      <joint name="a_finger" type="prismatic"><parent link="palm"/><child link="left"/>
        <limit lower="0" upper="0.04" effort="10" velocity="0.1"/></joint>
      <joint name="b_finger" type="prismatic"><parent link="palm"/><child link="right"/>
        <limit lower="0" upper="0.04" effort="10" velocity="0.1"/><mimic joint="a_finger"/></joint>
    </robot>
    ```
    """
    if "mimic" not in given.profile.variants:
        return
    joints = loaded.robot.joints
    order = {link: index for walk in walks(loaded.robot).values() for index, link in enumerate(walk)}
    for joint in mimic_joints(loaded):
        followed = joints.get(joint.mimic.joint)
        if followed is None:
            why = f"it follows '{joint.mimic.joint}', which is no joint"
        elif followed is joint:
            why = "it follows itself"
        elif order.get(joint.child, -1) < order.get(followed.child, -1):
            why = f"the tree walk reaches it before '{followed.name}', the joint it follows"
        else:
            continue
        yield loaded.diagnostic(
            "C303",
            f"Pinocchio (mimic=True) rejects joint '{joint.name}': {why} ('The parent joint of the mimic joint is not in the kinematic tree')",
            mimic_at(joint),
            "rename the joints so that the followed joint comes first (the walk takes a link's children in the order of their joints' names)",
            subjects=(joint.name, *((followed.name,) if followed is not None else ())),
        )
