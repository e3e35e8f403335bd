"""What the target rules share: where a link or joint was written, and how to say a number."""

from __future__ import annotations

from ...model.load import Loaded
from ...model.massprops import number


def link_at(loaded: Loaded, name: str) -> int | None:
    link = loaded.robot.links.get(name)
    return link.at if link is not None else None


def inertial_at(loaded: Loaded, name: str) -> int | None:
    """Where a link's ``<inertial>`` is, else the link itself."""
    link = loaded.robot.links[name]
    return link.inertial.at if link.inertial is not None else link.at


def limit_at(joint) -> int:
    found = joint.part("limit")
    return found if found is not None else joint.at


def names(items, most: int = 3) -> str:
    """``'a', 'b', 'c' and 2 more``."""
    items = list(items)
    shown = ", ".join(f"'{item}'" for item in items[:most])
    return shown + (f" and {len(items) - most} more" if len(items) > most else "")


__all__ = ["inertial_at", "limit_at", "link_at", "names", "number"]
