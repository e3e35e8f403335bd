"""A xacro expansion as the rest of urdfcli sees it: the expanded text, where each
of its elements was written, and the errors.

xacro itself runs in :mod:`.expansion`, inside the bounded worker of
:mod:`.sandbox`, so that a runaway macro or expression stops there.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from . import sandbox
from .expanded import Expansion, ExpansionError, display_path
from .xacro_scan import XacroGlobals

if TYPE_CHECKING:
    from .packages import PackageResolver

_EXPANSION = "urdfcli.read.expansion"  # where xacro runs: only the worker imports it


class Expander:
    """Expands xacro documents for a session, each in the session's bounded worker
    (see :mod:`.sandbox`): a process forked at the first expansion, which imports
    xacro, and stopped when the session ends."""

    def __init__(self) -> None:
        self.worker = sandbox.Worker(_EXPANSION)
        self._globals: XacroGlobals | None = None

    def global_names(self) -> XacroGlobals | None:
        """The names xacro gives every expression, asked of the worker once (None when
        it cannot answer)."""
        if self._globals is None:
            try:
                names, members = self.worker.run("global_names")
            except (sandbox.LimitExceeded, OSError, EOFError):
                return None
            self._globals = XacroGlobals(frozenset(names), {name: frozenset(found) for name, found in members.items()})
        return self._globals

    def expand(
        self, data: bytes, file: str | None, mappings: dict[str, str], resolver: PackageResolver, given: dict[str, bytes] | None = None
    ) -> Expansion:
        """Expand the xacro document ``data`` read from ``file`` (None: stdin); ``given``
        texts stand for the files of those paths (an editor's unsaved buffers). Raises
        ExpansionError, also when the expansion runs out of time or memory."""
        # The names are asked before the first expansion, of a worker that is ready: after
        # a large one it frees the expansion's memory (or retires and starts again) first.
        self.global_names()
        try:
            return self.worker.run("expand_here", data, file, mappings, resolver, given or {})
        except sandbox.LimitExceeded as error:
            shown = display_path(file) if file else "<stdin>"
            raise ExpansionError(f"xacro expansion stopped: {error} (the limit for one file)", None, shown) from None

    def close(self) -> None:
        self.worker.stop()
