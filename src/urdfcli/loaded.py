"""A description once loaded: document, model, kinematic graph and diagnostics."""

from __future__ import annotations

from functools import cached_property
from typing import TYPE_CHECKING

from .diagnostics import Diagnostic, Severity
from .document import Document

if TYPE_CHECKING:
    import networkx as nx

    from .model import Joint, Robot
    from .packages import PackageResolver


class Loaded:
    def __init__(
        self,
        document: Document,
        robot: Robot | None = None,
        diagnostics: list[Diagnostic] | None = None,
        resolver: PackageResolver | None = None,  # finds package:// files (meshes) with the run's -P options
    ) -> None:
        self.document = document
        self.robot = robot
        self.diagnostics = diagnostics if diagnostics is not None else []
        self.resolver = resolver

    def remembered(self, key, compute):
        """``compute()``, once for this model (see :meth:`Robot.remembered`)."""
        return self.robot.remembered(key, compute)

    @property
    def path(self) -> str:
        return self.document.path

    @property
    def ok(self) -> bool:
        return not any(d.severity is Severity.ERROR for d in self.diagnostics)

    def diagnostic(self, code: str, message: str, at: int | None, hint: str | None = None, attribute: str | None = None) -> Diagnostic:
        """A diagnostic about the element ``at`` (see :class:`Document`)."""
        return self.document.diagnostic(code, message, at, hint, attribute)

    @cached_property
    def parent_joints(self) -> dict[str, Joint]:
        """Each link's parent joint: the first written, when a link has several."""
        found: dict[str, Joint] = {}
        if self.robot is not None:
            for joint in self.robot.joints.values():
                if joint.child is not None:
                    found.setdefault(joint.child, joint)
        return found

    def parent_joint(self, link: str) -> Joint | None:
        return self.parent_joints.get(link)

    @cached_property
    def graph(self) -> nx.DiGraph | None:
        """The kinematic tree as a networkx DiGraph (links as nodes, joints on the
        edges), built on first use: most runs never need networkx."""
        if self.robot is None or self.robot.at is None:
            return None
        from .kinematics import build_graph

        return build_graph(self.robot)

    @cached_property
    def root(self) -> str | None:
        if self.robot is None or self.robot.at is None:
            return None
        from .kinematics import roots

        found = roots(self.robot)
        return found[0] if len(found) == 1 else None
