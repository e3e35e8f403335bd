"""The mass-property audit of ``urdfcli inertia``: per link the declared tensor, its
principal moments, the tensor the geometry implies and the problems; the whole
robot's total; and, when asked for, the suggested ``<inertial>`` elements and what
each consumer of ``--target`` builds. Worked out here, only written by the report."""

from __future__ import annotations

from typing import NamedTuple

from ..diagnostics import Diagnostic
from . import massprops
from .inertia import Assessment, Body, assess, implied, is_frame, total, used_body
from .load import Loaded
from .robot import Link
from .targets import Build


class LinkAudit(NamedTuple):
    link: Link
    frame: bool  # a massless frame link: listed quietly
    assessment: Assessment | None
    problems: tuple[Diagnostic, ...]  # the mass-property diagnostics about this link
    mass: float | None = None  # the mass the total counts: from --density, or as declared
    from_density: bool = False


class Audit(NamedTuple):
    loaded: Loaded
    links: tuple[LinkAudit, ...]
    total: Body | None
    problems: tuple[Diagnostic, ...]  # every mass-property diagnostic, in file order
    tolerance: float = massprops.TOLERANCE
    suggestions: tuple[str, ...] = ()  # XML for the flagged links (``--suggest``), printed after the table
    targets: tuple[Build, ...] = ()  # what each consumer of ``--target`` builds, printed after the total


def build(loaded: Loaded, problems: list[Diagnostic], tolerance: float = massprops.TOLERANCE, density: float | None = None) -> Audit:
    """The per-link table, the problems (each given to the links it is about) and the total."""
    mine: dict[str, list[Diagnostic]] = {name: [] for name in loaded.robot.links}
    for diagnostic in problems:
        for subject in dict.fromkeys(diagnostic.subjects):
            if subject in mine:
                mine[subject].append(diagnostic)
    links = []
    for link in loaded.robot.links.values():
        used = used_body(loaded, link, density)
        from_density = density is not None and implied(loaded, link, density).body is not None
        links.append(LinkAudit(link, is_frame(link), assess(loaded, link, density), tuple(mine[link.name]), used.mass if used else None, from_density))
    return Audit(loaded, tuple(links), total(loaded, density), tuple(problems), tolerance)


__all__ = ["Audit", "LinkAudit", "build"]
