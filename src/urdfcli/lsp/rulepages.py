"""Each rule's documentation as a file an editor can open from a diagnostic's code.

The pages are what ``urdfcli rule CODE`` prints, written once per version of
urdfcli into the user's cache folder (``$XDG_CACHE_HOME/urdfcli``, else
``~/.cache/urdfcli``): they match the installed rules, and need no network.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

from ..report.rules import page
from ..rules import REGISTRY
from ..version import __version__


def folder() -> Path:
    cache = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(cache) / "urdfcli" / __version__ / "rules"


def rule_links() -> dict[str, str]:
    """Each rule's code -> the URI of its page, written where missing or out of date;
    none when the cache folder cannot be written (the hover still shows the page)."""
    pages = folder()
    try:
        pages.mkdir(parents=True, exist_ok=True)
        for rule in REGISTRY.values():
            _write(pages / f"{rule.code}.md", page(rule))
    except OSError:
        return {}
    return {code: (pages / f"{code}.md").as_uri() for code in REGISTRY}


def _write(path: Path, text: str) -> None:
    """Write ``text`` unless the file holds it already; atomically, for servers started side by side."""
    try:
        if path.read_text(encoding="utf-8") == text:
            return
    except (OSError, UnicodeDecodeError):
        pass
    handle, temporary = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.")
    try:
        with os.fdopen(handle, "w", encoding="utf-8") as out:
            out.write(text)
        os.replace(temporary, path)
    except OSError:
        os.unlink(temporary)
        raise
