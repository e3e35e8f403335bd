"""``--statistics``: how many diagnostics each rule gave, most first (as ruff prints them)."""

from __future__ import annotations

import json
from collections import Counter
from typing import TYPE_CHECKING

from ..rules import REGISTRY
from .console import Output, write
from .escape import json_escape
from .lines import STYLES, summary_line

if TYPE_CHECKING:
    from ..model.result import Result


def statistics(results: list[Result]) -> list[tuple[str, str, str, int]]:
    """(code, name, severity, count) for each code found, most first, then by code."""
    found = Counter((d.code, (d.severity.value if d.severity else "info")) for r in results for d in r.diagnostics)
    rows = [(code, REGISTRY[code].name if code in REGISTRY else "", severity, count) for (code, severity), count in found.items()]
    return sorted(rows, key=lambda row: (-row[3], row[0], row[2]))


def report(results: list[Result], output: Output, view: str = "lint", output_format: str = "text") -> None:
    """The table (or JSON) of :func:`statistics`, then the summary line where the command writes it."""
    rows = statistics(results)
    if output_format == "json":
        document = [{"code": code, "name": name, "severity": severity, "count": count} for code, name, severity, count in rows]
        output.out.file.write(json_escape(json.dumps(document, indent=2)) + "\n")
        return
    width = max((len(str(count)) for *_, count in rows), default=1)
    named = max((len(name) for _, name, _, _ in rows), default=0)
    write(output.out, ([(f"{count:>{width}}  ", ""), (code, STYLES[severity]), (f"  {severity:<7}  ", STYLES[severity]), (name.ljust(named).rstrip(), "")]
                       for code, name, severity, count in rows))
    if results:
        write(output.err if view == "check" else output.out, [[(summary_line(results), "bold")]])
