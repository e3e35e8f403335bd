"""Suppression comments in the sources of a description.

``<!-- urdfcli: noqa: CODE1, CODE2 -->`` silences those codes for diagnostics
on the line of the element it shares a line with, or else on the next line
(the element just below the comment). ``<!-- urdfcli: noqa-file: CODE1 -->``
anywhere in a file silences them for every diagnostic in that file. A
suppression that silences nothing is reported (U001), and so is a code that
no rule has (U002).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from .diagnostics import Diagnostic, Location
from .rules import load_all

COMMENT = re.compile(r"<!--\s*urdfcli\s*:\s*(noqa-file|noqa)\s*:\s*(.*?)\s*-->", re.DOTALL)


@dataclass
class Suppression:
    file: str  # as diagnostics name it
    line: int  # where the comment is
    column: int
    codes: tuple[str, ...]
    target: int | None  # the line it silences; None for the whole file
    used: set[str] = field(default_factory=set)

    def covers(self, diagnostic: Diagnostic) -> bool:
        return (
            diagnostic.code in self.codes
            and diagnostic.file == self.file
            and (self.target is None or diagnostic.line == self.target)
        )


def parse(file: str, text: str) -> list[Suppression]:
    """Every urdfcli suppression comment in one source text."""
    found = []
    for match in COMMENT.finditer(text):
        line = text.count("\n", 0, match.start()) + 1
        line_start = text.rfind("\n", 0, match.start()) + 1
        line_end = text.find("\n", match.end())
        rest = text[line_start:match.start()] + text[match.end():len(text) if line_end < 0 else line_end]
        codes = tuple(c.upper() for c in re.split(r"[,\s]+", match.group(2)) if c)
        if match.group(1) == "noqa-file":
            target = None
        else:
            target = line if "<" in rest else line + 1
        found.append(Suppression(file, line, match.start() - line_start + 1, codes, target))
    return found


def apply(diagnostics: list[Diagnostic], suppressions: list[Suppression], enabled=lambda code: True) -> list[Diagnostic]:
    """The diagnostics no suppression covers, plus U001/U002 for the suppressions themselves.

    ``enabled(code)`` tells whether a rule is on here: a suppression of a rule
    that is off is not reported as unused.
    """
    kept = []
    for diagnostic in diagnostics:
        covering = [s for s in suppressions if s.covers(diagnostic)]
        for suppression in covering:
            suppression.used.add(diagnostic.code)
        if not covering:
            kept.append(diagnostic)
    known = load_all()
    for suppression in suppressions:
        where = Location(suppression.file, suppression.line, suppression.column)
        kind = "noqa-file" if suppression.target is None else "noqa"
        for code in suppression.codes:
            if code not in known:
                kept.append(Diagnostic.of("U002", f"'{kind}: {code}' names no rule", where, hint="`urdfcli rules` lists the codes"))
            elif code not in suppression.used and enabled(code):
                scope = "in this file" if suppression.target is None else f"on line {suppression.target}"
                kept.append(Diagnostic.of("U001", f"'{kind}: {code}' silences nothing: no {code} {scope}", where, hint="remove it"))
    return kept

