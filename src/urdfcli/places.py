"""Where something was written in the sources: a xacro macro call, and the origin of
an element of an expansion.

Named tuples of the standard library: xacro's worker makes them and sends them to
the run, and imports nothing for them that Python does not start with.
"""

from __future__ import annotations

from collections import namedtuple


class Call(namedtuple("Call", "file line column macro")):
    """A xacro macro call: where it was written (``line`` and ``column`` may be
    None), and the name of the macro it called."""

    __slots__ = ()


class Origin(namedtuple("Origin", "file line column trace", defaults=(None, ()))):
    """Where an element was written (line and column of its ``<``; ``column`` may
    be None), and the macro calls that made it (``trace``), innermost first."""

    __slots__ = ()
