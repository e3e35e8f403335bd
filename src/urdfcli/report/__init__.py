"""Reports: the formats of check and lint by name, the tree, the graph, the inertia audit.

Every format is a module with one function, ``report(results, output, view,
sources)``, made from the one :class:`~urdfcli.result.Result` type; ``view``
is the command (``check``, ``lint`` or ``inertia``). Machine formats are
written plain, never through rich.
"""

from __future__ import annotations

import os

from . import check_urdf, concise, github, json, sarif, text

FORMATS = {
    "text": text.report,
    "concise": concise.report,
    "json": json.report,
    "sarif": sarif.report,
    "github": github.report,
    "check_urdf": check_urdf.report,
}


def resolve(name: str) -> str:
    """A format's name; ``auto`` is github under GitHub Actions, else text."""
    name = name.lower()
    if name == "auto":
        return "github" if os.environ.get("GITHUB_ACTIONS") == "true" else "text"
    return name


def reporter(name: str):
    """The report function of a format (``auto`` resolved)."""
    return FORMATS[resolve(name)]
