"""Drake's own load (``check --target drake --load``, the differential test): ``Parser(plant).AddModels``
and ``Finalize`` on ``AddMultibodyPlantSceneGraph``, as Drake's documentation loads a model,
given the packages urdfcli resolved; the bodies and joints of the plant."""

from __future__ import annotations

import re

from ...project.loading import Loader, Outcome, Packages, Said, finite, line_in, python_package


def built(path: str, variants: frozenset[str], packages: Packages) -> dict:
    from pydrake.multibody.parsing import Parser
    from pydrake.multibody.plant import AddMultibodyPlantSceneGraph
    from pydrake.multibody.tree import BodyIndex, JointIndex
    from pydrake.systems.framework import DiagramBuilder

    builder = DiagramBuilder()
    plant, _ = AddMultibodyPlantSceneGraph(builder, 1e-3)
    parser = Parser(plant)
    for name, folder in packages.items():
        if not parser.package_map().Contains(name):
            parser.package_map().Add(name, folder)
    parser.AddModels(path)
    plant.Finalize()
    bodies = []
    for i in range(1, plant.num_bodies()):
        body = plant.get_body(BodyIndex(i))
        inertia = body.default_spatial_inertia()  # about the body's origin: shifted to its centre of mass
        moments = inertia.Shift(inertia.get_com()).CalcRotationalInertia().CalcPrincipalMomentsOfInertia()
        bodies.append({"name": body.name(), "mass": float(body.default_mass()), "inertia": [float(m) for m in moments]})
    joints = []
    for i in range(plant.num_joints()):
        joint = plant.get_joint(JointIndex(i))
        lower, upper = joint.position_lower_limits(), joint.position_upper_limits()
        joints.append({"name": joint.name(), "type": joint.type_name(), "lower": [finite(v) for v in lower], "upper": [finite(v) for v in upper]})
    actuators = [plant.get_joint_actuator(index).joint().name() for index in plant.GetJointActuatorIndices()]
    return {"bodies": bodies, "joints": joints, "actuators": actuators, "nq": plant.num_positions(), "nv": plant.num_velocities()}


MESSAGE = re.compile(r"^(?:RuntimeError: |SystemExit: )?(?P<where>\S+?:\d+): (?P<severity>error|warning): (?P<text>.*)$")


def said(outcome: Outcome, path: str) -> list[Said]:
    """Drake names the file and line of each error and warning (``PATH:LINE: warning: ...``);
    a warning may go on over the next lines."""
    found: list[Said] = []
    text = outcome.printed + ("\n" + outcome.error if not outcome.accepted else "")
    for line in text.splitlines():
        match = MESSAGE.match(line.strip())
        if match is not None:
            severity = match["severity"]
            found.append(Said(severity, match["text"], line_in(match["where"], path), tuple(re.findall(r"'([^']+)'", match["text"]))))
        elif found and line.strip() and not line.startswith(("[", "RuntimeError", "SystemExit")):
            found[-1] = found[-1]._replace(text=f"{found[-1].text} {line.strip()}")
    if not outcome.accepted and not any(s.severity == "error" for s in found):
        found.append(Said("error", outcome.error.strip(), None, tuple(re.findall(r"'([^']+)'", outcome.error))))
    return found


LOADER = Loader("drake", python_package("pydrake", "drake"), said, built=built)
