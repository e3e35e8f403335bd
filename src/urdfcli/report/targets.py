"""What a consumer builds from a model, for people: ``tree --target`` marks each link
with what the consumer makes of it, ``inertia --target`` lists the masses and
tensors it will use. The build itself is :mod:`urdfcli.model.targets`."""

from __future__ import annotations

from ..model.massprops import number
from ..model.targets import Build
from .console import Line
from .escape import escape
from .tree import plural


def link_notes(built: Build) -> dict[str, str]:
    """Each link the consumer does not keep as a body of its own -> what happens to it."""
    notes = dict(built.dropped)
    for body in built.bodies:
        for link in body.links[1:]:
            notes[link] = f"fused into {body.top}"
    return {link: _dropped(note) for link, note in notes.items()}


def _dropped(note: str) -> str:
    return note if note.startswith(("fused", "the root")) else f"dropped: {note}"


def joint_notes(built: Build) -> dict[str, str]:
    return {joint: f"becomes {what}" for joint, what in built.changed.items()}


def summary(built: Build) -> str:
    """``MuJoCo: 7 bodies (3 links fused or dropped), fixed base, 6 DOF``."""
    left = sum(len(body.links) - 1 for body in built.bodies) + len(built.dropped)
    fused = f" ({plural(left, 'link')} fused or dropped)" if left else ""
    return f"{built.profile.name} ({built.profile.text()}): {len(built.bodies)} {'body' if len(built.bodies) == 1 else 'bodies'}{fused}, {built.base} base, {built.dof} DOF"


def _moments(moments) -> str:
    return " ".join(number(m) for m in moments) if moments is not None else "unknown"


def inertia_lines(built: Build) -> list[Line]:
    """The masses and principal moments the consumer will use, body by body, and the total mass."""
    lines: list[Line] = [[(f"{built.profile.name} ({built.profile.text()}) uses", "bold")]]
    for body in built.bodies:
        fused = f" + {', '.join(escape(n) for n in body.links[1:])}" if len(body.links) > 1 else ""
        mass = number(body.mass) if body.mass is not None else "unknown"
        lines.append([
            (f"    {escape(body.top)}{fused}", "bold"),
            (f"  mass {mass}  moments {_moments(body.moments)}", ""),
            (f"  ({body.source})", "dim"),
        ])
    for link, why in built.dropped.items():
        lines.append([(f"    {escape(link)}", "bold"), (f"  {_dropped(why)}", "yellow")])
    masses = [b.mass for b in built.bodies]
    total = number(sum(m for m in masses if m is not None)) + (" and the bodies of unknown mass" if None in masses else "")
    lines.append([("    total", "bold"), (f"  mass {total}, {built.base} base, {built.dof} DOF", "")])
    return lines


def build_dict(built: Build) -> dict:
    return {
        "target": built.profile.text(),
        "base": built.base,
        "dof": built.dof,
        "bodies": [
            {"links": list(b.links), "joint": b.joint.name if b.joint is not None else None, "mass": b.mass,
             "moments": list(b.moments) if b.moments is not None else None, "source": b.source}
            for b in built.bodies
        ],
        "dropped": built.dropped,
        "changed": built.changed,
        "total_mass": sum(b.mass for b in built.bodies if b.mass is not None),
    }
