"""The one problem type every part of urdfcli reports, and where it points."""

from __future__ import annotations

from dataclasses import dataclass, replace
from enum import Enum


class Severity(str, Enum):
    ERROR = "error"
    WARNING = "warning"
    INFO = "info"

    @property
    def rank(self) -> int:
        return {"error": 2, "warning": 1, "info": 0}[self.value]


@dataclass(frozen=True, slots=True)
class Location:
    """Where an element was written.

    ``expanded`` is true when the line is in the xacro-expanded document
    because the element's origin in the sources could not be determined.
    """

    file: str
    line: int | None = None
    column: int | None = None
    expanded: bool = False


@dataclass(frozen=True, slots=True)
class Diagnostic:
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
        from .rules import rule

        return cls(code, rule(code).severity, message, location, element, hint)

    def with_severity(self, severity: Severity) -> "Diagnostic":
        return replace(self, severity=severity)

    def sort_key(self) -> tuple:
        return (self.file, self.line or 0, self.location.column or 0, self.code)
