"""The one problem type every part of urdfcli reports, and where it points."""

from __future__ import annotations

from typing import NamedTuple

from .places import Call
from .rules import rule
from .severity import Severity

__all__ = ["Call", "Diagnostic", "Location", "Severity"]


class Location(NamedTuple):
    """Where an element was written.

    ``expanded`` is true when the line is in the xacro-expanded document
    because the element's origin in the sources could not be determined.
    ``trace`` lists the macro calls that made the element, innermost first.
    """

    file: str
    line: int | None = None
    column: int | None = None
    expanded: bool = False
    trace: tuple[Call, ...] = ()


class Diagnostic(NamedTuple):
    code: str
    severity: Severity
    message: str
    location: Location
    element: str | None = None
    hint: str | None = None

    @property
    def file(self) -> str:
        return self.location.file

    @property
    def line(self) -> int | None:
        return self.location.line

    @classmethod
    def of(cls, code: str, message: str, location: Location, element: str | None = None, hint: str | None = None) -> "Diagnostic":
        """A diagnostic with its rule's default severity."""
        return cls(code, rule(code).severity, message, location, element, hint)

    def with_severity(self, severity: Severity) -> "Diagnostic":
        return self._replace(severity=severity)

    def sort_key(self) -> tuple:
        trace = tuple((c.file, c.line or 0, c.column or 0) for c in self.location.trace)
        return (self.file, self.line or 0, self.location.column or 0, self.code, trace)
