"""The pieces every text format is made of: a diagnostic's position and line, the
macro calls that made its element, its source excerpt, a library's notes, the summary."""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING

from ..diagnostics import Diagnostic, Severity
from ..read.positions import Sources
from .console import Line
from .escape import escape

if TYPE_CHECKING:
    from .result import Result

TRACE_LEVELS = 3  # macro calls shown under a diagnostic


def counts(results: Iterable[Result]) -> dict[Severity, int]:
    found = dict.fromkeys(Severity, 0)
    for result in results:
        for diagnostic in result.diagnostics:
            found[diagnostic.severity or Severity.INFO] += 1
    return found


def position(diagnostic: Diagnostic) -> str:
    """``PATH:LINE:COL`` (line and column only when known)."""
    location = diagnostic.location
    parts = [location.file]
    if location.line:
        parts.append(str(location.line))
        parts.append(str(location.column or 1))
    return ":".join(parts)


def severity_name(diagnostic: Diagnostic) -> str:
    return (diagnostic.severity or Severity.INFO).value


def plain_line(diagnostic: Diagnostic) -> str:
    expanded = " (line in the xacro-expanded document)" if diagnostic.location.expanded else ""
    return escape(f"{position(diagnostic)}: {diagnostic.code} {severity_name(diagnostic)}: {diagnostic.message}{expanded}")


def call_phrase(call) -> str:
    """Where a macro call that made an element was written: ``in macro 'wheel' called at FILE:LINE:COL``."""
    where = ":".join([call.file] + ([str(call.line), str(call.column or 1)] if call.line else []))
    return f"in macro '{call.macro}' called at {where}"


def concise_line(diagnostic: Diagnostic) -> str:
    """``plain_line`` and, for an element a macro made, the call that made it: still one line."""
    trace = diagnostic.location.trace
    return plain_line(diagnostic) + (escape(f" ({call_phrase(trace[0])})") if trace else "")


def trace_notes(diagnostic: Diagnostic, levels: int = TRACE_LEVELS) -> list[str]:
    """One ``note:`` line per macro call that made the element, innermost first."""
    trace = diagnostic.location.trace
    notes = [escape(f"    note: {call_phrase(call)}") for call in trace[:levels]]
    if len(trace) > levels:
        notes.append(f"    note: ... and {len(trace) - levels} more macro call{'s' if len(trace) - levels > 1 else ''}")
    return notes


def excerpt_lines(diagnostic: Diagnostic, sources: Sources, width: int = 160) -> list[str]:
    """The diagnostic's source line, numbered, with a caret under its column."""
    location = diagnostic.location
    if location.expanded or not location.line:
        return []
    text = sources.line(location.file, location.line)
    if text is None:
        return []
    text = text.replace("\t", " ").rstrip()
    safe = escape(text)  # the caret moves right by what the escapes before it add
    shown = safe if len(safe) <= width else safe[: width - 3] + "..."
    width = max(4, len(str(location.line)))
    lines = [f"  {location.line:>{width}} | {shown}"]
    caret = len(escape(text[: location.column - 1])) if location.column else None
    if caret is not None and caret <= len(shown):
        lines.append(f"  {'':>{width}} | {' ' * caret}^")
    return lines


def details(diagnostic: Diagnostic, sources: Sources | None) -> list[str]:
    """The lines under a diagnostic: its macro calls, its hint, its source excerpt."""
    hint = ["    hint: " + escape(diagnostic.hint)] if diagnostic.hint else []
    excerpt = excerpt_lines(diagnostic, sources) if sources is not None else []
    return trace_notes(diagnostic) + hint + excerpt


def library_lines(result: Result) -> list[str]:
    """For a xacro library: which models it was checked through, and why one could not be."""
    library = result.library
    if library is None:
        return []
    lines = [f"{result.path}: xacro library, checked through {', '.join(library.checked_through)}"] if library.checked_through else []
    return [escape(line) for line in lines + [f"{result.path}: {note}" for note in library.notes]]


def plural(n: int, word: str) -> str:
    return f"{n} {word}{'' if n == 1 else 's'}"


def summary_line(results: list[Result]) -> str:
    found = counts(results)
    text = f"{plural(len(results), 'file')} checked: {plural(found[Severity.ERROR], 'error')}, {plural(found[Severity.WARNING], 'warning')}"
    infos = found[Severity.INFO]
    return text + (f", {infos} info" if infos else "")


STYLES = {"error": "bold red", "warning": "yellow", "info": "cyan"}


def diagnostic_lines(diagnostic: Diagnostic, sources: Sources | None) -> list[Line]:
    """A diagnostic, its macro calls and hint, and (given the sources) its source line."""
    style = STYLES[severity_name(diagnostic)]
    first: Line = [
        (escape(position(diagnostic)), "bold"), (": ", ""), (diagnostic.code, style),
        (f" {severity_name(diagnostic)}: ", style), (escape(diagnostic.message), ""),
    ]
    if diagnostic.location.expanded:
        first.append((" (line in the xacro-expanded document)", "dim"))
    return [first, *([(line, "dim")] for line in details(diagnostic, sources))]
