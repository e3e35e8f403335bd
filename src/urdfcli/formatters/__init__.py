"""Output formats, each a small function of the loaded files and their diagnostics.

Every format is produced from the one Diagnostic type. Machine formats are
written plain (never through rich).
"""

from __future__ import annotations

import os
from typing import TYPE_CHECKING

from ..diagnostics import Diagnostic, Severity
from ..escape import escape

if TYPE_CHECKING:
    from ..loaded import Loaded

FORMATS = ("auto", "text", "concise", "json", "sarif", "github", "check_urdf")


def resolve(name: str) -> str:
    if name == "auto":
        return "github" if os.environ.get("GITHUB_ACTIONS") == "true" else "text"
    return name


def counts(results: list[Loaded]) -> tuple[int, int, int]:
    errors = warnings = infos = 0
    for loaded in results:
        for diagnostic in loaded.diagnostics:
            if diagnostic.severity is Severity.ERROR:
                errors += 1
            elif diagnostic.severity is Severity.WARNING:
                warnings += 1
            else:
                infos += 1
    return errors, warnings, infos


def position(diagnostic: Diagnostic) -> str:
    """``PATH:LINE:COL`` (line and column only when known)."""
    location = diagnostic.location
    parts = [location.file]
    if location.line:
        parts.append(str(location.line))
        parts.append(str(location.column or 1))
    return ":".join(parts)


def plain_line(diagnostic: Diagnostic) -> str:
    expanded = " (line in the xacro-expanded document)" if diagnostic.location.expanded else ""
    return escape(f"{position(diagnostic)}: {diagnostic.code} {diagnostic.severity.value}: {diagnostic.message}{expanded}")


def call_phrase(call) -> str:
    """Where a macro call that made an element was written: ``in macro 'wheel' called at FILE:LINE:COL``."""
    where = ":".join([call.file] + ([str(call.line), str(call.column or 1)] if call.line else []))
    return f"in macro '{call.macro}' called at {where}"


def concise_line(diagnostic: Diagnostic) -> str:
    """``plain_line`` and, for an element a macro made, the call that made it: still one line."""
    trace = diagnostic.location.trace
    return plain_line(diagnostic) + (escape(f" ({call_phrase(trace[0])})") if trace else "")


def summary_line(results: list[Loaded]) -> str:
    errors, warnings, infos = counts(results)
    files = len(results)

    def plural(n: int, word: str) -> str:
        return f"{n} {word}{'' if n == 1 else 's'}"

    text = f"{plural(files, 'file')} checked: {plural(errors, 'error')}, {plural(warnings, 'warning')}"
    return text + (f", {infos} info" if infos else "")
