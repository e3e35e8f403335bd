"""Fixes for the mass-property audit: a uniform body's ``<inertial>`` for a flagged link, and,
for a model written with xacro, the macro that wrote its ``<inertial>`` and a call of it
that gives the tensor the link's geometry implies (read from the xacro sources, and found
by expanding the macro with each candidate call)."""

from __future__ import annotations

import itertools
from typing import NamedTuple

from lxml import etree

from ..read.document import XACRO_NAMESPACES
from ..read.xacro import Expander
from ..read.xacro_scan import macro_parameters
from ..read.xml import parse
from . import massprops
from .audit import Audit, LinkAudit
from .inertia import implied, suggested
from .load import Loaded
from .massprops import Matrix, number
from .numbers import NumberError, parse_double, parse_vector
from .robot import INERTIA_KEYS, Link
from .written import escape_attribute


def suggestion(loaded: Loaded, entry: LinkAudit, density: float | None = None) -> str:
    """A ready-to-paste ``<inertial>`` for a link, in the frame of its current one: the
    uniform body its geometry makes, said to be an estimate, never a correction; an XML
    comment saying why when the geometry cannot tell."""
    link = entry.link
    found = suggested(loaded, link, density)
    if isinstance(found, str):
        return f"<!-- link '{link.name}': no suggestion: {found} -->"
    return "\n".join(
        [
            f"<!-- link '{link.name}': a uniform body filling its {found.source} (an estimate: the part's CAD values are better) -->",
            "<inertial>",
            f'  <origin xyz="{" ".join(map(number, found.xyz))}" rpy="{" ".join(map(number, found.rpy))}"/>',
            f'  <mass value="{number(found.mass)}"/>',
            "  <inertia " + " ".join(f'{k}="{number(found.tensor[k])}"' for k in massprops.KEYS) + "/>",
            "</inertial>",
        ]
    )


# -- xacro macros ----------------------------------------------------------------------
class MacroUse(NamedTuple):
    """The xacro macro whose body wrote a link's <inertial>, and the call that used it."""

    name: str
    params: str
    defined_at: str  # FILE:LINE
    call: str | None  # the call as written, e.g. <xacro:box_inertia m="${mass}" .../>
    called_at: str | None
    written_at: str = ""  # FILE:LINE of the <inertial> in the macro's body
    inertial_only: bool = True  # the macro writes the <inertial> alone (not a whole link, or a gripper, around it)
    blocks: tuple[str, ...] = ()  # the elements the call gives its block parameters (*origin), as written


def _call(name: str, attributes: dict[str, str], blocks: tuple[str, ...] = ()) -> str:
    """A macro call as XML: the blocks it gives its block parameters are its children."""
    written = " ".join([f"<xacro:{name}", *(f'{k}="{escape_attribute(v)}"' for k, v in attributes.items())])
    return f"{written}>{''.join(blocks)}</xacro:{name}>" if blocks else f"{written}/>"


def _as_written(element) -> str:
    """An element of a xacro source as XML, without the namespaces its document declares."""
    alone = etree.fromstring(etree.tostring(element, with_tail=False))
    etree.cleanup_namespaces(alone)
    return etree.tostring(alone, encoding="unicode")


def _written(loaded: Loaded, file: str, line: int, tag: str):
    """The element of that tag written at file:line, in the xacro source."""
    source = loaded.document.files.get(file)
    if source is None:
        return None
    return next((e for e in source.elements if source.place_of(e)[0] == line and etree.QName(e).localname == tag), None)


def _line(loaded: Loaded, file: str, element) -> int:
    """The line where an element of a xacro source starts."""
    return loaded.document.files.get(file).place_of(element)[0]


def _is_xacro(element, name: str) -> bool:
    qname = etree.QName(element)
    return qname.namespace in XACRO_NAMESPACES and qname.localname == name


def macro_use(loaded: Loaded, link: Link) -> MacroUse | None:
    """Which xacro macro produced the link's <inertial> (None when it was written in place)."""
    if link.inertial is None or loaded.document.origins is None:
        return None
    where = loaded.document.locate(link.inertial.at)
    written = _written(loaded, where.file, where.line, "inertial") if where.line and not where.expanded else None
    macro = next((a for a in written.iterancestors() if _is_xacro(a, "macro")), None) if written is not None else None
    if macro is None:
        return None
    name = macro.get("name", "")
    inside = list(itertools.takewhile(lambda a: a is not macro, written.iterancestors()))
    if any(etree.QName(a).localname == "link" for a in inside):  # the macro makes the link (or a gripper): its call is no <inertial>
        return MacroUse(name, macro.get("params", ""), f"{where.file}:{_line(loaded, where.file, macro)}", None, None,
                        f"{where.file}:{where.line}", inertial_only=False)
    call, called_at, blocks = None, None, ()
    link_where = loaded.document.locate(link.at)
    source_link = _written(loaded, link_where.file, link_where.line, "link") if link_where.line and not link_where.expanded else None
    if source_link is not None:
        found = next((e for e in source_link.iter(etree.Element) if _is_xacro(e, name)), None)
        if found is not None:
            blocks = tuple(_as_written(child) for child in found.iterchildren(etree.Element))
            call, called_at = _call(name, dict(found.attrib), blocks), f"{link_where.file}:{_line(loaded, link_where.file, found)}"
    return MacroUse(name, macro.get("params", ""), f"{where.file}:{_line(loaded, where.file, macro)}", call, called_at,
                    f"{where.file}:{where.line}", blocks=blocks)


def _macro_element(loaded: Loaded, use: MacroUse):
    file, _, line = use.defined_at.rpartition(":")
    return _written(loaded, file, int(line), "macro")


def _dimensions(geometry) -> tuple[float, ...]:
    if geometry.kind == "box":
        return tuple(geometry.size)
    if geometry.kind == "cylinder":
        return geometry.radius, geometry.length
    return (geometry.radius,)


def matching_call(loaded: Loaded, link: Link, use: MacroUse, expander: Expander) -> str | None:
    """A call of the macro that writes the tensor the link's geometry implies, found by
    expanding the macro with the mass and each ordering of the shape's dimensions;
    None when no call does (e.g. the macro cannot rotate its tensor with the shape)."""
    found = implied(loaded, link)
    macro = _macro_element(loaded, use)
    if found.body is None or len(found.shapes) != 1 or found.shapes[0].geometry.kind == "mesh" or macro is None:
        return None
    parameters = macro_parameters(use.params)
    if any(p.block for p in parameters) and not use.blocks:  # the blocks a call gives are unknown: xacro expands none without them
        return None
    required = [p.name for p in parameters if not p.block and p.default is None and not p.forward]
    masses = [p for p in required if p.lower() in ("m", "mass") or "mass" in p.lower()]
    others = [p for p in required if p not in masses]
    dimensions = _dimensions(found.shapes[0].geometry)
    if len(masses) != 1 or len(others) != len(dimensions):
        return None
    calls = []
    for order in dict.fromkeys(itertools.permutations(dimensions)):
        values = {masses[0]: found.body.mass, **dict(zip(others, order))}
        # the call's own blocks: an <origin> given to the macro turns the tensor with it
        calls.append(_call(use.name, {k: number(v) for k, v in values.items()}, use.blocks))
    namespace = etree.QName(macro).namespace
    probe = f'<robot name="probe" xmlns:xacro="{namespace}">{etree.tostring(macro, encoding="unicode", with_tail=False)}'
    probe += "".join(f'<link name="c{i}">{call}</link>' for i, call in enumerate(calls)) + "</robot>"
    try:
        text = expander.expand(probe.encode(), None, {}, loaded.resolver).text
        links = parse(text.encode()).findall("link")
    except Exception:  # noqa: BLE001  (a macro that needs more than its parameters)
        return None
    for call, probe_link in zip(calls, links):
        tensor = _probe_tensor(probe_link)
        if tensor is not None and massprops.relative_difference(tensor, found.body.tensor) <= 1e-3:
            return call
    return None


def _probe_tensor(link) -> Matrix | None:
    """The link-frame tensor of an expanded probe link's <inertial>."""
    try:
        inertia = link.find("inertial/inertia")
        values = {k: parse_double(inertia.get(k)) for k in INERTIA_KEYS}
        origin = link.find("inertial/origin")
        rpy = parse_vector(origin.get("rpy", "0 0 0")) if origin is not None else (0.0, 0.0, 0.0)
    except (AttributeError, TypeError, NumberError, ValueError):
        return None
    return massprops.rotate(massprops.matrix(values), massprops.rotation(rpy))


def suggestions(audit: Audit, flagged: list[LinkAudit], expander: Expander, density: float | None, xacro: bool) -> tuple[str, ...]:
    """For each flagged link, the <inertial> of a uniform body filling its geometry;
    with ``xacro``, the macro that wrote the link's <inertial> and the call of it that gives those values."""
    found = []
    loaded = audit.loaded
    for entry in flagged:
        use = macro_use(loaded, entry.link) if xacro else None
        if use is not None and not use.inertial_only:  # a macro that makes the whole link: the <inertial> is edited in its body
            found.append(f"<!-- link '{entry.link.name}': its <inertial> is written at {use.written_at}, in the body of xacro macro '{use.name}': replace it there with -->")
        elif use is not None:
            called = f", called at {use.called_at} as {use.call}" if use.call else ""
            found.append(f"<!-- link '{entry.link.name}': its <inertial> comes from xacro macro '{use.name}' ({use.defined_at}){called} -->")
            call = matching_call(loaded, entry.link, use, expander) if density is None else None
            if call is not None:
                found.append(f"<!-- the call that gives the geometry's values: -->\n{call}")
                continue
            found.append(f"<!-- no call of '{use.name}' gives the geometry's values: replace the call with -->")
        found.append(suggestion(loaded, entry, density))
    return tuple(found)
