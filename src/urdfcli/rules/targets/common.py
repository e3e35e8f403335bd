"""What the target rules share: where a link or joint was written, the joints several
consumers treat alike, and how to say a number."""

from __future__ import annotations

from ...model.load import Loaded
from ...model.massprops import number
from ...read.memo import once as memo
from ..base import names


def link_at(loaded: Loaded, name: str) -> int | None:
    link = loaded.robot.links.get(name)
    return link.at if link is not None else None


def inertial_at(loaded: Loaded, name: str) -> int | None:
    """Where a link's ``<inertial>`` is, else the link itself."""
    link = loaded.robot.links[name]
    return link.inertial.at if link.inertial is not None else link.at


def mimic_at(joint) -> int:
    found = joint.part("mimic")
    return found if found is not None else joint.at


def about_joint(loaded: Loaded, code: str, joint, message: str, hint: str, at: int | None = None):
    """A diagnostic about one joint, at ``at`` (else where the joint was written)."""
    return loaded.diagnostic(code, message, at if at is not None else joint.at, hint, subjects=(joint.name,))


def limit_at(joint) -> int:
    found = joint.part("limit")
    return found if found is not None else joint.at


BOUNDED = ("revolute", "prismatic")  # the joints URDF gives a <limit> with a lower and an upper
MIMICKED = ("revolute", "continuous", "prismatic")  # the joints a <mimic> makes follow another


def joints_of(loaded: Loaded, kinds: tuple[str, ...]) -> tuple:
    """The joints of these types, listed once per model (most consumers' rules ask)."""
    return memo(loaded, _joints_of, kinds)


def _joints_of(loaded: Loaded, kinds: tuple[str, ...]) -> tuple:
    return tuple(joint for joint in loaded.robot.joints.values() if joint.type in kinds)


def inverted_limits(loaded: Loaded) -> list:
    """Revolute and prismatic joints whose lower limit is above the upper one."""
    return [joint for joint in joints_of(loaded, BOUNDED) if joint.limit is not None and joint.limit.lower > joint.limit.upper]


def without_limit(loaded: Loaded) -> list:
    """Revolute and prismatic joints without a ``<limit>`` (urdfdom rejects them: J003)."""
    return [joint for joint in joints_of(loaded, BOUNDED) if joint.limit is None]


def add_limit(joint) -> str:
    """The hint for a joint without ``<limit>``."""
    return 'add <limit lower="..." upper="..." effort="..." velocity="..."/>' + (", or make it continuous" if joint.type == "revolute" else "")


def mimic_joints(loaded: Loaded) -> list:
    return [joint for joint in joints_of(loaded, MIMICKED) if joint.mimic is not None]


def once(loaded: Loaded, code: str, meshes: list, kind: str, what: str, hint: str):
    """One diagnostic for every mesh of a kind (``meshes``: (link, geometry) pairs): placed at
    the first, about every link that has one. ``what`` reads "CONSUMER rejects link 'L': WHY",
    the first mesh's name and how many more follow it."""
    name, geometry = meshes[0]
    more = f" (and {len(meshes) - 1} more {kind} meshes)" if len(meshes) > 1 else ""
    return loaded.diagnostic(code, f"{what.format(link=name)} '{geometry.filename}'{more}", geometry.at, hint,
                             subjects=tuple(dict.fromkeys(n for n, _ in meshes)))


def mimics_said_once(loaded: Loaded, code: str, what: str, hint: str, taken_care_of: frozenset[str] = frozenset()):
    """One diagnostic naming every mimic joint (but those ``taken_care_of``): ``what`` reads "CONSUMER makes ... {joints} ...",
    at the first joint's <mimic>, about each mimic joint and the joints they follow."""
    joints = [joint for joint in mimic_joints(loaded) if joint.name not in taken_care_of]
    if not joints:
        return
    several = len(joints) > 1
    listed = f"{len(joints)} mimic joints ({names(j.name for j in joints)})" if several else f"mimic joint '{joints[0].name}' (of '{joints[0].mimic.joint}')"
    yield loaded.diagnostic(code, what.format(joints=listed, they="they move" if several else "it moves"), mimic_at(joints[0]), hint,
                            subjects=tuple(dict.fromkeys(name for j in joints for name in (j.name, j.mimic.joint))))


__all__ = ["BOUNDED", "MIMICKED", "about_joint", "add_limit", "inertial_at", "inverted_limits", "joints_of", "limit_at", "link_at", "mimic_at", "mimic_joints", "mimics_said_once", "names", "number", "once", "without_limit"]
