"""The pieces every text format is made of: a diagnostic's position and line, the
macro calls that made its element, its source excerpt, a library's notes, the summary."""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from typing import TYPE_CHECKING

from ..diagnostics import Diagnostic, Fix, Severity
from ..rules.base import joined
from .console import Line
from .escape import escape

if TYPE_CHECKING:
    from ..model.result import Result
    from ..read.files import SourceFile, SourceFiles

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


def concise_line(diagnostic: Diagnostic) -> str:
    """``plain_line`` and, for an element a macro made, the call that made it, and the
    hint: still one line."""
    trace = diagnostic.location.trace
    notes = ([trace[0].phrase] if trace else []) + ([diagnostic.through] if diagnostic.through else [])
    notes += [f"hint: {diagnostic.hint}"] if diagnostic.hint else []
    return plain_line(diagnostic) + (escape(f" ({'; '.join(notes)})") if notes else "")


def trace_notes(diagnostic: Diagnostic, levels: int = TRACE_LEVELS) -> list[str]:
    """One ``note:`` line per macro call that made the element, innermost first."""
    trace = diagnostic.location.trace
    notes = [escape(f"    note: {call.phrase}") for call in trace[:levels]]
    if len(trace) > levels:
        notes.append(f"    note: ... and {len(trace) - levels} more macro call{'s' if len(trace) - levels > 1 else ''}")
    return notes


class SourcesOnce:
    """The session's files for one model's report, each looked up once: its diagnostics quote
    lines of the same few files, and a look-up checks the file on disk (a ``stat``)."""

    def __init__(self, files: SourceFiles) -> None:
        self.files = files
        self._found: dict[str, SourceFile | None] = {}

    def line(self, name: str, number: int) -> str | None:
        if name not in self._found:
            self._found[name] = self.files.get(name)
        found = self._found[name]
        return found.line(number) if found is not None else None


def excerpt_lines(diagnostic: Diagnostic, files: SourceFiles | SourcesOnce, width: int | None = None) -> list[str]:
    """The diagnostic's source line, numbered, with a caret under its column: the line
    cut at 160 characters, or with ``width``, to fit that many columns, around the caret:
    a terminal that wrapped it would break the gutter and leave the caret under the wrong text."""
    location = diagnostic.location
    if location.expanded or not location.line:
        return []
    text = files.line(location.file, location.line)
    if text is None:
        return []
    text = text.replace("\t", " ").rstrip()
    safe = escape(text)  # the caret moves right by what the escapes before it add
    number = max(4, len(str(location.line)))
    room = 160 if width is None else max(20, width - number - 5)  # the gutter: two spaces, the number, ' | '
    caret = len(escape(text[: location.column - 1])) if location.column else None
    begin = 0
    if len(safe) <= room:
        shown = safe
    else:
        if caret is not None and caret >= room - 10:  # the caret past the cut: show the part around it
            begin = max(0, min(caret - room // 3, len(safe) - room))
        shown = safe[begin : begin + room]
        if begin > 0:
            shown = "..." + shown[3:]
        if begin + room < len(safe):
            shown = shown[:-3] + "..."
    lines = [f"  {location.line:>{number}} | {shown}"]
    if caret is not None and 0 <= caret - begin <= len(shown):
        lines.append(f"  {'':>{number}} | {' ' * (caret - begin)}^")
    return lines


def fix_line(diagnostic: Diagnostic) -> str | None:
    """``fix: TITLE``, ``fix (unsafe): TITLE`` or ``no fix: WHY``, for a diagnostic with a fix."""
    fix = diagnostic.fix
    if fix is None:
        return None
    if fix.available:
        return escape(f"    fix{'' if fix.safe else ' (unsafe)'}: {fix.title}")
    return escape(f"    no fix: {fix.reason}") if fix.reason else None


def details(diagnostic: Diagnostic) -> list[str]:
    """The lines under a diagnostic, before its source excerpt: its macro calls, its hint, its fix."""
    hint = ["    hint: " + escape(diagnostic.hint)] if diagnostic.hint else []
    through = ["    note: " + escape(diagnostic.through)] if diagnostic.through else []
    fix = [line] if (line := fix_line(diagnostic)) is not None else []
    return trace_notes(diagnostic) + through + hint + fix


def library_lines(results: list[Result]) -> list[str]:
    """For the xacro libraries of a run: one line naming the models they were checked
    through, then one line per reason a model could not check some of them."""
    libraries = [r for r in results if r.library is not None]
    checked = [r for r in libraries if r.library.checked_through]
    lines = []
    if checked:
        models = list(dict.fromkeys(m for r in checked for m in r.library.checked_through))
        fragments = sum(1 for r in checked if r.library.fragment)
        kind = "fragment" if fragments == len(checked) else "xacro library" if not fragments else "xacro library or fragment"
        what = f"{checked[0].path}: {kind}" if len(checked) == 1 else f"{len(checked)} {_plural_kind(kind)}"
        lines.append(f"{what}, checked through {listed(models)}")
    reasons: dict[str, list[str]] = {}
    for result in libraries:
        for note in result.library.notes:
            reasons.setdefault(note, []).append(result.path)
    lines += [f"{listed(paths)}: {note}" for note, paths in reasons.items()]
    return [escape(line) for line in lines]


def _plural_kind(kind: str) -> str:
    return {"fragment": "fragments", "xacro library": "xacro libraries"}.get(kind, "xacro libraries and fragments")


def listed(names: list[str], most: int = 4) -> str:
    """``a, b, c`` or ``a, b, c, d and 7 more``."""
    if len(names) <= most + 1:
        return ", ".join(names)
    return f"{', '.join(names[:most])} and {len(names) - most} more"


def plural(n: int, word: str) -> str:
    return f"{n} {word}{'' if n == 1 else 's'}"


def checked(results: list[Result]) -> int:
    """How many results are of a file checked (not one a folder set aside that no model read)."""
    return sum(1 for r in results if r.library is None or not r.library.unchecked)


def summary_line(results: list[Result]) -> str:
    found = counts(results)
    text = f"{plural(checked(results), 'file')} checked: {plural(found[Severity.ERROR], 'error')}, {plural(found[Severity.WARNING], 'warning')}"
    infos = found[Severity.INFO]
    hidden = sum(1 for r in results if not r.show_info for d in r.diagnostics if d.severity is Severity.INFO)
    return text + (f", {infos} info" if infos else "") + (" (not shown)" if hidden and hidden == infos else f" ({hidden} not shown)" if hidden else "")


STYLES = {"error": "bold red", "warning": "yellow", "info": "cyan"}


def alike_as_one(diagnostics: list[Diagnostic]) -> list[tuple[Diagnostic, list[int]]]:
    """Each diagnostic with the other lines of its file where the very same is said (its
    code, message and hint), shown once, at the first: a habit (an exporter's ``iyx`` on
    every ``<inertia>``) read as one. Those with a fix to apply stay apart: each says its own."""
    groups: dict[object, tuple[Diagnostic, list[int]]] = {}
    for number, diagnostic in enumerate(diagnostics):
        fixable = diagnostic.fix is not None and diagnostic.fix.available
        key = number if fixable or diagnostic.line is None else (diagnostic.code, diagnostic.severity, diagnostic.message, diagnostic.hint, diagnostic.path, diagnostic.model)
        found = groups.get(key)
        if found is None:
            groups[key] = (diagnostic, [])
        elif diagnostic.line != found[0].line and diagnostic.line not in found[1]:
            found[1].append(diagnostic.line)
    return list(groups.values())


def also_line(lines: list[int], most: int = 8) -> str | None:
    """``    note: also at lines 38, 66 and 95``: where else a diagnostic shown once is said."""
    if not lines:
        return None
    shown = [str(line) for line in lines[:most]] + ([f"{len(lines) - most} more"] if len(lines) > most else [])
    return f"    note: also at line{'s' if len(lines) > 1 else ''} {joined(shown)}"


def diagnostic_lines(diagnostic: Diagnostic, files: SourceFiles | SourcesOnce | None, width: int | None = None, also: Iterable[int] = ()) -> list[Line]:
    """A diagnostic, its macro calls and hint, and (given the files) its source line.
    With ``width``, a message, note or hint longer than that goes on over indented lines
    (a word, such as a path, is never cut: only a word longer than the width goes past
    it), and a source excerpt is cut to fit it around its caret; without, an excerpt is
    cut at 160 characters."""
    style = STYLES[severity_name(diagnostic)]
    where = position(diagnostic)
    head = f"{where}: {diagnostic.code} {severity_name(diagnostic)}: "
    message = escape(diagnostic.message)
    expanded = " (line in the xacro-expanded document)" if diagnostic.location.expanded else ""
    pieces = wrapped(message + expanded, width, len(head))
    first: Line = [(escape(where), "bold"), (": ", ""), (diagnostic.code, style), (f" {severity_name(diagnostic)}: ", style)]
    if len(pieces) == 1 and expanded:
        first += [(message, ""), (expanded, "dim")]
    else:
        first.append((pieces[0], ""))
    rest = [("    " + piece, "") for piece in pieces[1:]]
    lines: list[Line] = [first, *([piece] for piece in rest)]
    for line in details(diagnostic) + ([said] if (said := also_line(list(also))) else []):
        lines += [[(part, "dim")] for part in (wrap_line(line, width, " " * 10) if width else [line])]
    excerpt = excerpt_lines(diagnostic, files, width) if files is not None else []
    return lines + [[(line, "dim")] for line in excerpt]


def diagnostics_lines(diagnostics: Iterable[Diagnostic], files: SourceFiles | SourcesOnce | None, width: int | None = None) -> Iterator[Line]:
    """The diagnostics as :func:`diagnostic_lines` shows each, the alike said once (see
    :func:`alike_as_one`): ten ``<xacro:arg scope=...>`` are one warning wherever it prints."""
    return (line for diagnostic, also in alike_as_one(list(diagnostics)) for line in diagnostic_lines(diagnostic, files, width, also))


def wrapped(text: str, width: int | None, used: int = 0) -> list[str]:
    """``text`` in pieces: the first fits ``width`` after ``used`` characters (empty when
    not even a word does), the others ``width`` after an indent of four. A word is never
    cut (a path is one word)."""
    import textwrap

    if not width or used + len(text) <= width:
        return [text]
    first = (textwrap.wrap(text, width=max(1, width - used), break_long_words=False, break_on_hyphens=False) or [""])[0]
    if used + len(first) > width:
        first = ""
    rest = textwrap.wrap(text[len(first):].strip(), width=max(20, width - 4), break_long_words=False, break_on_hyphens=False)
    return [first, *rest]


def wrap_line(line: str, width: int, hanging: str = "    ") -> list[str]:
    """A line over several when it is longer than ``width``, the others indented by
    ``hanging``; a word is never cut."""
    import textwrap

    if len(line) <= width:
        return [line]
    return textwrap.wrap(line, width=width, subsequent_indent=hanging, break_long_words=False, break_on_hyphens=False) or [line]


def fixable_line(results: list[Result]) -> str | None:
    """``[*] 3 fixable with --fix (2 more with --unsafe-fixes)``, when any is."""
    safe = unsafe = 0
    for result in results:
        for diagnostic in result.diagnostics:
            fix = diagnostic.fix
            if fix is not None and fix.available:
                safe, unsafe = (safe + 1, unsafe) if fix.safe else (safe, unsafe + 1)
    if not safe and not unsafe:
        return None
    if not safe:
        return f"{unsafe} fix{'' if unsafe == 1 else 'es'} available with --fix --unsafe-fixes"
    return f"{safe} fixable with --fix" + (f" ({unsafe} more with --unsafe-fixes)" if unsafe else "")


def fix_dict(fix: Fix | None, files: SourceFiles | None = None) -> dict | None:
    """A diagnostic's fix as JSON: its title and safety, and its edits (each file with
    offsets in its text read with ``\\n`` line ends, and lines and columns, 1-based,
    where the text is at hand) or why there are none."""
    if fix is None:
        return None
    edits = []
    for edit in fix.edits if fix.available else ():
        entry = {"path": edit.file, "start_offset": edit.start, "end_offset": edit.end, "content": edit.text}
        source = files.get(edit.file) if files is not None else None
        if source is not None:
            entry["start"] = dict(zip(("line", "column"), source.position(edit.start)))
            entry["end"] = dict(zip(("line", "column"), source.position(edit.end)))
        edits.append(entry)
    return {"title": fix.title, "applicability": fix.applicability.value, "available": fix.available, "edits": edits, "reason": fix.reason}


def diagnostic_dict(diagnostic: Diagnostic, files: SourceFiles | None = None) -> dict:
    """A diagnostic as the JSON formats give it (the README, "Exit codes and JSON")."""
    return {
        "code": diagnostic.code,
        "severity": severity_name(diagnostic),
        "message": diagnostic.message,
        "path": diagnostic.location.file,
        "line": diagnostic.location.line,
        "column": diagnostic.location.column,
        "element": diagnostic.element,
        "subjects": list(diagnostic.subjects),
        "hint": diagnostic.hint,
        "model": diagnostic.model,
        "trace": [
            {"path": call.file, "line": call.line, "column": call.column, "macro": call.macro}
            for call in diagnostic.location.trace
        ],
        "fix": fix_dict(diagnostic.fix, files),
    }
