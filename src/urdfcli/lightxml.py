"""A small document read by expat into elements named as lxml names them.

Importing lxml takes longer than reading a small document (about 7 ms of a
50 ms run), so such a document is read by the expat of Python's standard
library where it can be. :func:`read` builds ElementTree elements that read
as lxml's do: a namespaced tag or attribute in Clark notation
(``{uri}local``), the element's ``prefix``, the root's namespace declarations
as ``nsmap``; no comments or processing instructions. Texts are as written:
lxml drops some white space between elements, which only a text that is not
stripped could tell.

It gives None wherever the two readings could differ, and lxml then reads the
document and says what is wrong with it: a DOCTYPE (which may declare
entities), an encoding whose markup is not ASCII, an XML declaration of a
version other than 1.x, anything expat refuses (among them an unbound
prefix, which lxml refuses too), a namespace URI of an unusual form (libxml2
refuses those RFC 3986 does not allow), and nesting deeper than libxml2 reads
without its huge-tree option.
"""

from __future__ import annotations

import codecs
import pyexpat
import re
from xml.etree import ElementTree

from .positions import ascii_compatible

MAX_DEPTH = 256  # libxml2's limit without XML_PARSE_HUGE

_DECLARED_VERSION = re.compile(rb"""(?:\xef\xbb\xbf)?<\?xml[ \t\r\n]+version[ \t\r\n]*=[ \t\r\n]*(["'])1\.[0-9]+\1""")
# A namespace URI libxml2 takes (RFC 3986), in a form narrower than the RFC's:
# lxml refuses a document that declares any other, and reads the rest of these.
_PCHAR = r"(?:[A-Za-z0-9\-._~!$&'()*+,;=:@]|%[0-9A-Fa-f]{2})"
_FIRST_SEGMENT = r"(?:[A-Za-z0-9\-._~!$&'()*+,;=@]|%[0-9A-Fa-f]{2})*"  # of a relative reference: no ':'
_AUTHORITY = r"//(?:[A-Za-z0-9\-._~!$&'()*+,;=]*@)?[A-Za-z0-9\-._~]*(?::[0-9]+)?(?=[/?#]|\Z)"
_URI = re.compile(
    rf"(?:[A-Za-z][A-Za-z0-9+.\-]*:(?:{_AUTHORITY}|(?!//))|(?!//){_FIRST_SEGMENT}(?=[/?#]|\Z))"
    rf"(?:{_PCHAR}|/)*(?:\?(?:{_PCHAR}|[/?])*)?(?:#(?:{_PCHAR}|[/?])*)?\Z"
)


class Element(ElementTree.Element):
    """An ElementTree element with lxml's ``prefix`` (None when its tag has none)."""

    prefix: str | None = None
    nsmap: dict[str | None, str] = {}  # the root's: the namespaces it declares


class _Refused(Exception):
    """What lxml may read otherwise: lxml reads the document."""


def read(data: bytes) -> Element | None:
    """The root element of ``data``, or None for lxml to read it (see above)."""
    if b"<!DOCTYPE" in data or not ascii_compatible(data):
        return None
    if data.startswith(b"<?xml", 3 if data.startswith(codecs.BOM_UTF8) else 0) and _DECLARED_VERSION.match(data) is None:
        return None  # (expat takes any version; libxml2 1.0, 1.1...)
    builder = ElementTree.TreeBuilder(element_factory=Element)
    parser = pyexpat.ParserCreate(namespace_separator="}")
    parser.namespace_prefixes = True  # names come as "uri}local}prefix"
    parser.buffer_text = True
    declared: dict[str | None, str] = {}
    depth = 0

    def start(name: str, attributes: dict[str, str]) -> None:
        nonlocal depth
        depth += 1
        if depth > MAX_DEPTH:
            raise _Refused
        tag, prefix = _named(name)
        if any("}" in key for key in attributes):
            attributes = {_named(key)[0]: value for key, value in attributes.items()}
        element = builder.start(tag, attributes)
        if prefix is not None:
            element.prefix = prefix
        if depth == 1 and declared:
            element.nsmap = dict(declared)

    def end(name: str) -> None:
        nonlocal depth
        depth -= 1
        builder.end(name)

    def declare(prefix: str | None, uri: str | None) -> None:
        if uri and not _URI.match(uri):
            raise _Refused
        if depth == 0 and prefix != "xml":  # (lxml lists no declaration of the xml prefix, always bound)
            declared[prefix] = uri or ""  # (expat gives None for xmlns="")

    parser.StartElementHandler = start
    parser.EndElementHandler = end
    parser.CharacterDataHandler = builder.data
    parser.StartNamespaceDeclHandler = declare
    try:
        parser.Parse(data, True)
    except (pyexpat.ExpatError, _Refused):
        return None
    return builder.close()


def _named(name: str) -> tuple[str, str | None]:
    """A name as expat gives it ("uri}local}prefix", "uri}local" or "local") as lxml
    names it, and its prefix."""
    if "}" not in name:
        return name, None
    uri, local, *prefix = name.split("}")
    return f"{{{uri}}}{local}", prefix[0] if prefix else None
