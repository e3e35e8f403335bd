"""What ``urdfcli diff`` shows: the changes between two robots, in four formats.

``text`` groups the changes by element (``+`` added, ``-`` removed, ``~`` changed
or renamed), each with where it was written; ``json`` gives each change with its
kind, element, field, old and new values and location; ``markdown`` is a table
for a pull-request comment; ``github`` one workflow annotation per change, at
the new robot's line (a removal at the closest element the new robot has).
"""

from __future__ import annotations

import re
from collections.abc import Callable
from functools import partial
from typing import Any, NamedTuple

from ..diagnostics import Location
from ..model.compare import PARTS, Change, Comparison, Totals, text
from ..model.numbers import NumberError, parse_double
from . import DIFF_FORMATS
from .console import Line, Output, write
from .escape import escape
from .github import escape_data, escape_property
from .json import dumps
from .lines import plural
from .repository import RepositoryPaths
from .tree import readable, short, significant_digits

FORMATS = DIFF_FORMATS
MARKS = {"added": "+", "removed": "-", "renamed": "~", "changed": "~"}
STYLES = {"+": "green", "-": "red", "~": "yellow"}
WRITTEN = 12
"""A number of at most this many significant digits is shown as written (a person types
no more); what xacro computes has 15 to 17 (``${radians(170)}``: 2.9670597283903604) and
is shown to 6, or as many more as tell the old value from the new. JSON keeps them all."""
_ELEMENT = re.compile(r"""^(?P<tag>[\w:.-]+)(?:\[@(?P<attribute>name|reference)=(?P<quote>['"])(?P<name>.*)(?P=quote)\])?(?:\[(?P<rank>\d+)\])?$""")


class Difference(NamedTuple):
    """Two robots compared: the inputs as given, what changed, and what a reader should
    know of how they were read (a package of a revision read as it is now)."""

    old: str
    new: str
    comparison: Comparison
    notes: tuple[str, ...] = ()

    @property
    def same(self) -> bool:
        return self.comparison.same


def element_words(element: str) -> str:
    """``link[@name='arm']`` as ``link 'arm'``; ``gazebo[@reference='arm']`` as ``gazebo reference 'arm'``."""
    match = _ELEMENT.match(element)
    if match is None:
        return element
    words = match["tag"]
    if match["name"] is not None:
        words += f" '{match['name']}'" if match["attribute"] == "name" else f" reference '{match['name']}'"
    if match["rank"]:
        words += f" (#{match['rank']})"
    return words


def where(location: Location | None) -> str:
    """``PATH:LINE:COL`` of a change ('' when unknown)."""
    if location is None:
        return ""
    parts = [location.file]
    if location.line:
        parts += [str(location.line), str(location.column or 1)]
    return ":".join(parts)


def where_made(location: Location | None) -> str:
    """:func:`where`, and the macro call that made the element: ``PATH:LINE:COL (in macro 'm' called at ...)``."""
    said = where(location)
    return f"{said} ({location.trace[0].phrase})" if location is not None and location.trace else said


def number_text(value: float, digits: int = 6) -> str:
    return readable(value, digits, WRITTEN)


def amount(value: float) -> str:
    """A displacement (mm) or a turn (degrees) to 3 significant digits, written out:
    a link moved by a metre reads ``1000 mm``, not ``1e+03 mm``."""
    said = short(value, 3)
    return f"{value:.0f}" if "e+" in said else said


def value_text(value: Any, digits: int = 6) -> str:
    """A value of a change as people read it (:data:`WRITTEN`): a number, the numbers of a
    list, and those of a text (a shape ``box 0.30000000000000004 0.1 0.1``, a colour, a
    gazebo value xacro computed) alike; a short number of a text is kept as written."""
    if not isinstance(value, str):
        return text(value, partial(number_text, digits=digits))
    return " ".join(_token_text(token, digits) for token in value.split(" "))


def _token_text(token: str, digits: int) -> str:
    if significant_digits(token) <= WRITTEN:
        return token
    try:
        return number_text(parse_double(token), digits)
    except NumberError:  # a word with many digits in it: a name, a file
        return token


def values_text(old: Any, new: Any, show: Callable[[Any, int], str] = value_text) -> tuple[str, str]:
    """``old`` and ``new`` as ``show`` (:func:`value_text`) writes them to some digits, with as many
    digits as tell them apart (``0.3 -> 0.3000001`` at the default tolerance, more at a smaller one)."""
    for digits in range(6, 18):
        said = show(old, digits), show(new, digits)
        if said[0] != said[1]:
            return said
    return show(old, 6), show(new, 6)  # the same number: a change of something else


def percent(fraction: float) -> str:
    value = fraction * 100
    digits = 2 if abs(value) >= 0.1 else 2 - int(f"{abs(value):e}".split("e")[1]) if value else 0
    return f"{value:+.{max(digits, 0)}f} %"


def _whole_text(field: str, value: Any) -> str:
    """A value added or removed whole; a joint's <limit>, <dynamics> or <safety_controller>
    with each value named (``damping 1``), those it does not write left out."""
    keys = PARTS.get(field)
    if keys is None or not isinstance(value, list):
        return value_text(value)
    return ", ".join(f"{key} {value_text(part)}" for key, part in zip(keys, value) if part is not None) or "no values"


def describe(change: Change) -> str:
    """What changed, in words: ``limit upper: 3.1415 -> 3.1416 (+0.0029 %)``."""
    field = change.field
    if change.kind == "renamed":
        return f"renamed from '{change.old}'"
    if field is None:
        return change.kind
    if change.kind == "added":
        return f"{field} added" + (f": {_whole_text(field, change.new)}" if change.new is not None else "")
    if change.kind == "removed":
        return f"{field} removed" + (f" (was {_whole_text(field, change.old)})" if change.old is not None else "")
    if field == "pose":
        millimetres, degrees = change.moved or (0.0, 0.0)
        return f"pose at zero joint positions: moved {amount(millimetres)} mm, turned {amount(degrees)}°"
    said = "{}: {} -> {}".format(field, *values_text(change.old, change.new))
    if change.relative is not None:
        said += f" ({percent(change.relative)})"
    elif change.moved is not None:
        millimetres, degrees = change.moved
        said += f" (moved {amount(millimetres)} mm)" if millimetres else f" (turned {amount(degrees)}°)"
    return said


def groups(changes: tuple[Change, ...]) -> dict[str, list[Change]]:
    """The changes of each element, the elements in the order the comparison met them."""
    found: dict[str, list[Change]] = {}
    for change in changes:
        found.setdefault(change.element, []).append(change)
    return found


def mark(changes: list[Change]) -> str:
    whole = next((c for c in changes if c.field is None), None)
    return MARKS[whole.kind] if whole is not None else "~"


def totals_texts(comparison: Comparison) -> tuple[str, str]:
    """What the old and the new robot amount to, their masses told apart."""
    masses = masses_text(comparison)
    return totals_text(comparison.old, masses[0]), totals_text(comparison.new, masses[1])


def masses_text(comparison: Comparison) -> tuple[str, str]:
    """The total masses, sums nobody wrote: to 6 significant digits, or as many more as tell
    them apart (17.4117 kg for Franka's links, 0.1 + 0.2 kg as 0.3 kg)."""
    return values_text(comparison.old.mass, comparison.new.mass, short)


def totals_text(totals: Totals, mass: str) -> str:
    name = f"robot '{totals.name}'" if totals.name is not None else "robot (no name)"
    return f"{name}: {plural(totals.links, 'link')}, {plural(totals.joints, 'joint')}, {totals.dof} DOF, {mass} kg"


def summary_text(comparison: Comparison) -> str:
    if comparison.same:
        return "same robot: no change"
    counts = [f"{count} {kind}" for kind in ("added", "removed", "renamed", "changed") if (count := comparison.count(kind))]
    old, new = comparison.old, comparison.new
    follows = []
    if abs(old.mass - new.mass) > 1e-9 * max(old.mass, new.mass, 1.0):
        change = f" ({percent((new.mass - old.mass) / old.mass)})" if old.mass else ""
        follows.append("mass {} kg -> {} kg".format(*masses_text(comparison)) + change)
    if old.dof != new.dof:
        follows.append(f"{old.dof} DOF -> {new.dof}")
    if comparison.moved:
        follows.append(f"{plural(comparison.moved, 'link')} moved at zero joint positions")
    return ", ".join(counts) + (f"; {'; '.join(follows)}" if follows else "")


# -- text --------------------------------------------------------------------------------
def text_lines(difference: Difference) -> list[Line]:
    comparison = difference.comparison
    old, new = totals_texts(comparison)
    lines: list[Line] = [
        [("--- ", "red"), (escape(difference.old), "bold"), (f"  {escape(old)}", "dim")],
        [("+++ ", "green"), (escape(difference.new), "bold"), (f"  {escape(new)}", "dim")],
        *([(f"note: {escape(note)}", "dim")] for note in difference.notes),
    ]
    poses = [change for change in comparison.changes if change.field == "pose"]
    for element, changes in groups(tuple(c for c in comparison.changes if c.field != "pose")).items():
        sign = mark(changes)
        whole = next((c for c in changes if c.field is None), None)
        head: Line = [(f"{sign} ", STYLES[sign]), (escape(element_words(element)), "bold")]
        if whole is not None:
            head.append((f"  {escape(where_made(whole.location))}", "dim"))
        lines.append(head)
        for change in changes:
            if change is whole:
                continue
            style = STYLES[MARKS[change.kind]] if change.kind in ("added", "removed") else ""
            lines.append([(f"    {escape(describe(change))}", style), (f"  {escape(where_made(change.location))}", "dim")])
    if poses:
        lines.append([("at zero joint positions:", "bold")])
        for change in poses:
            millimetres, degrees = change.moved or (0.0, 0.0)
            lines.append([
                ("~ ", STYLES["~"]), (escape(element_words(change.element)), "bold"),
                (f" moved {amount(millimetres)} mm, turned {amount(degrees)}°", ""), (f"  {escape(where_made(change.location))}", "dim"),
            ])
    lines.append([(summary_text(comparison), "bold")])
    return lines


def report_text(difference: Difference, output: Output) -> None:
    write(output.out, text_lines(difference))


# -- json --------------------------------------------------------------------------------
def change_dict(change: Change) -> dict:
    location = change.location
    entry = {
        "kind": change.kind,
        "element": change.element,
        "field": change.field,
        "old": change.old,
        "new": change.new,
        "path": location.file if location else None,
        "line": location.line if location else None,
        "column": location.column if location else None,
    }
    if change.relative is not None:
        entry["relative"] = change.relative
    if change.moved is not None:
        entry["moved_mm"], entry["turned_degrees"] = change.moved
    if location is not None and location.trace:
        entry["trace"] = [{"path": c.file, "line": c.line, "column": c.column, "macro": c.macro} for c in location.trace]
    return entry


def totals_dict(totals: Totals) -> dict:
    return {"robot": totals.name, "links": totals.links, "joints": totals.joints, "dof": totals.dof, "mass": totals.mass}


def report_json(difference: Difference, output: Output) -> None:
    comparison = difference.comparison
    document = {
        "old": difference.old,
        "new": difference.new,
        "notes": list(difference.notes),
        "changes": [change_dict(change) for change in comparison.changes],
        "summary": {
            "same": comparison.same,
            **{kind: comparison.count(kind) for kind in ("added", "removed", "renamed", "changed")},
            "moved_links": comparison.moved,
            "old": totals_dict(comparison.old),
            "new": totals_dict(comparison.new),
        },
    }
    output.out.file.write(dumps(document) + "\n")


# -- markdown ----------------------------------------------------------------------------
def cell(value: str) -> str:
    """Text for a table cell: no line breaks, pipes and backticks kept as text."""
    return escape(value).replace("\\", "\\\\").replace("|", "\\|").replace("`", "\\`").replace("<", "&lt;")


def report_markdown(difference: Difference, output: Output) -> None:
    comparison = difference.comparison
    old, new = totals_texts(comparison)
    lines = [
        f"### urdfcli diff: {cell(difference.old)} → {cell(difference.new)}",
        "",
        f"**{cell(summary_text(comparison))}**",
        "",
        f"- old: {cell(old)}",
        f"- new: {cell(new)}",
        *(f"- note: {cell(note)}" for note in difference.notes),
    ]
    if not comparison.same:
        lines += ["", "| | element | change | where |", "|---|---|---|---|"]
        for element, changes in groups(comparison.changes).items():
            for change in changes:
                sign = MARKS[change.kind] if change.field is None or change.kind in ("added", "removed") else "~"
                lines.append(f"| {sign} | {cell(element_words(element))} | {cell(describe(change))} | {cell(where_made(change.location))} |")
    output.out.file.write("\n".join(lines) + "\n")


# -- github ------------------------------------------------------------------------------
def annotation(change: Change, strip: tuple[str, ...], paths: RepositoryPaths) -> str:
    location = change.anchor if change.kind == "removed" else change.location
    props = []
    if location is not None:
        prefix = next((p for p in strip if location.file.startswith(p)), None)
        # REV:PATH names the file by its path in the repository already
        file = location.file[len(prefix):] if prefix is not None else paths.path(location.file)
        props.append(f"file={escape_property(file)}")
        if location.line:
            props.append(f"line={location.line}")
            if location.column:
                props.append(f"col={location.column}")
    props.append(f"title={escape_property('urdfcli diff: ' + element_words(change.element))}")
    return f"::notice {','.join(props)}::" + escape_data(f"{element_words(change.element)}: {describe(change)}")


def report_github(difference: Difference, output: Output, revisions: tuple[str, ...] = ()) -> None:
    strip = tuple(f"{revision}:" for revision in revisions)
    output.out.file.writelines(f"::notice title=urdfcli diff::{escape_data(note)}\n" for note in difference.notes)
    paths = RepositoryPaths.from_environment()
    output.out.file.writelines(annotation(change, strip, paths) + "\n" for change in difference.comparison.changes)


def report(difference: Difference, output: Output, name: str, revisions: tuple[str, ...] = ()) -> None:
    """``difference`` in the format ``name`` (one of FORMATS); ``revisions``: the git revisions
    whose files are named ``REV:PATH`` (github annotations name them by PATH)."""
    if name == "json":
        report_json(difference, output)
    elif name == "markdown":
        report_markdown(difference, output)
    elif name == "github":
        report_github(difference, output, revisions)
    else:
        report_text(difference, output)
