"""Physics rules on declared mass properties (warnings: the model loads, but is wrong)."""

from __future__ import annotations

from .. import massprops
from ..numbers import format_number
from . import WARNING, check


def _inertials(loaded):
    for link in loaded.robot.links.values():
        inertial = link.inertial
        if inertial is not None and inertial.mass is not None:
            yield link, inertial


def moved_by_joint(loaded, link_name: str) -> bool:
    joint = loaded.parent_joint(link_name)
    return joint is not None and joint.moving


@check("I001", "negative-mass", WARNING, "A link with negative mass.")
def negative_mass(loaded):
    """Mass is never negative; simulators reject or explode on it."""
    for link, inertial in _inertials(loaded):
        if inertial.mass < 0:
            yield loaded.diagnostic("I001", f"link '{link.name}' has negative mass {format_number(inertial.mass)}", inertial.element.find("mass"))


@check("I002", "massless-moving-link", WARNING, "A link with zero mass moved by a non-fixed joint.")
def massless_moving_link(loaded):
    """A massless body driven by a joint has no dynamics: Gazebo drops it, KDL cannot solve it.

    A purely kinematic model (no link declares any ``<inertial>``) is not flagged."""
    if not any(link.inertial is not None for link in loaded.robot.links.values()):
        return
    for link in loaded.robot.links.values():
        inertial = link.inertial
        massless = inertial is None or inertial.mass == 0
        if massless and moved_by_joint(loaded, link.name):
            element = inertial.element.find("mass") if inertial is not None else link.element
            yield loaded.diagnostic("I002", f"link '{link.name}' has no mass but is moved by joint '{loaded.parent_joint(link.name).name}'", element, hint="give it a mass and inertia, or attach it with a fixed joint")


@check("I003", "massless-with-inertia", WARNING, "A link with zero mass but a non-zero inertia tensor.")
def massless_with_inertia(loaded):
    """A tensor without mass is contradictory: one of the two values is wrong."""
    for link, inertial in _inertials(loaded):
        if inertial.mass == 0 and inertial.inertia and not massprops.is_zero(massprops.matrix(inertial.inertia)):
            yield loaded.diagnostic("I003", f"link '{link.name}' has mass 0 but a non-zero inertia tensor", inertial.element.find("inertia"))


@check("I004", "point-mass", WARNING, "A link with positive mass and an all-zero inertia tensor.")
def point_mass(loaded):
    """A real body has extent; a zero tensor makes rotation about its centre cost nothing."""
    for link, inertial in _inertials(loaded):
        if inertial.mass > 0 and inertial.inertia and massprops.is_zero(massprops.matrix(inertial.inertia)):
            yield loaded.diagnostic("I004", f"link '{link.name}' has mass {format_number(inertial.mass)} but a zero inertia tensor", inertial.element.find("inertia"))


@check("I005", "inertia-not-positive-semidefinite", WARNING, "An inertia tensor with a negative principal moment.")
def not_positive_semidefinite(loaded):
    """Principal moments of inertia are never negative."""
    for link, inertial in _inertials(loaded):
        if inertial.inertia:
            tensor = massprops.matrix(inertial.inertia)
            if not massprops.is_positive_semidefinite(tensor):
                moments = ", ".join(f"{m:.6g}" for m in massprops.principal_moments(tensor))
                yield loaded.diagnostic("I005", f"inertia of link '{link.name}' is not positive semi-definite (principal moments {moments})", inertial.element.find("inertia"))


@check("I006", "inertia-triangle-inequality", WARNING, "Principal moments that break the triangle inequality.")
def triangle_inequality(loaded):
    """For any rigid body the two smaller principal moments sum to at least the largest."""
    for link, inertial in _inertials(loaded):
        if inertial.inertia:
            tensor = massprops.matrix(inertial.inertia)
            if massprops.is_positive_semidefinite(tensor):
                broken = massprops.triangle_violation(tensor)
                if broken:
                    a, b, c = broken
                    yield loaded.diagnostic("I006", f"inertia of link '{link.name}' breaks the triangle inequality: {a:.6g} + {b:.6g} < {c:.6g}", inertial.element.find("inertia"))
