"""Reading XML: one function reads a document, keeping source lines and reaching
nothing outside the input.

No external entity, DTD or network access, ever; a document that declares
entities is refused outright, which also disarms entity-expansion bombs.
Every reader of urdfcli goes through :func:`parse` (the model, the xacro
worker, the workspace scan, the inertia fixes); :func:`top_level` hands the
model a document one top-level element at a time, parsing a small document
whole and streaming a large one, so that which way a document is read depends
only on its size.

The elements are lxml's. What urdfcli relies on: ``tag`` (a namespaced name
in Clark notation, ``{uri}local``), ``prefix``, ``nsmap``, ``get``,
``attrib``, ``text``, iteration over the children, ``iter``, ``find``,
``findall`` and ``iterfind``, ``sourceline``. Read with ``as_written=False``
(the default) a tree holds elements only: no comments, processing
instructions or white space between elements.
"""

from __future__ import annotations

import codecs
import io
import re
from collections.abc import Iterator

from lxml import etree

from .positions import declared_encoding

Element = etree._Element

_PARSER_OPTIONS = dict(
    resolve_entities=False,
    no_network=True,
    load_dtd=False,
    dtd_validation=False,
    huge_tree=False,
    collect_ids=False,
    strip_cdata=False,  # kept as written: xacro prints a CDATA section as one
)


_CONFLICT = re.compile(rb"^<{7}(?: |$)", re.MULTILINE)  # the first line git writes in a file whose merge it could not finish


class XmlError(ValueError):
    """``code`` is the rule: X001 (not well-formed) or X002 (entity declarations)."""

    def __init__(self, message: str, line: int | None = None, column: int | None = None, code: str = "X001"):
        super().__init__(message)
        self.message = message
        self.line = line
        self.column = column
        self.code = code


def parse(data: bytes, as_written: bool = False, huge: bool = False) -> Element:
    """The root element of ``data``; raises XmlError with a line on any problem.

    By default the tree holds elements only: the white space between elements
    (a fifth of the memory of a large model), comments and processing
    instructions are dropped. ``as_written`` keeps them all, for xacro, which
    prints them. ``huge`` lifts libxml2's limit of 10 MB on one text node, which
    a COLLADA mesh's coordinates exceed (entities stay refused)."""
    if not data or data.isspace():  # (strip() would copy a large document)
        raise XmlError("the document is empty", 1, 1)
    dropped = not as_written
    options = dict(_PARSER_OPTIONS, remove_blank_text=dropped, remove_comments=dropped, remove_pis=dropped, huge_tree=huge)
    try:
        try:
            root = etree.fromstring(data, etree.XMLParser(**options))
        except etree.XMLSyntaxError as error:
            if not (error.msg or "").startswith("Unsupported encoding"):
                raise
            # libxml2 does not know the name (latin-1, cp1252 without iconv...): Python may.
            root = etree.fromstring(recoded(data), etree.XMLParser(**options, encoding="utf-8"))
    except etree.XMLSyntaxError as error:
        if dropped and (error.msg or "").startswith("Double hyphen within comment"):
            blanked = _blanked_comments(data)
            if blanked != data:  # read as urdfdom reads it; the model says so (X007)
                return parse(blanked, huge=huge)
        conflict = _CONFLICT.search(data)
        if conflict is not None:  # what libxml2 says there ("StartTag: invalid element name") names no cause
            line = data.count(b"\n", 0, conflict.start()) + 1
            raise XmlError("an unresolved merge conflict: git's conflict markers (<<<<<<<, =======, >>>>>>>) are in the file", line, 1) from None
        line, column = error.position if error.position else (error.lineno, None)
        message = error.msg or str(error)
        message = message.split(", line ")[0] if ", line " in message else message
        raise XmlError(_said_plainly(message), line or 1, column) from None
    except XmlError:
        raise
    except ValueError as error:  # lxml refuses some inputs before parsing
        raise XmlError(str(error), 1, 1) from None
    dtd = root.getroottree().docinfo.internalDTD
    if dtd is not None and any(True for _ in dtd.iterentities()):
        raise XmlError("the document declares XML entities; urdfcli never expands entities", 1, 1, code="X002")
    for node in root.iter(etree.Entity):
        raise XmlError(f"undefined entity reference {node.text}", node.sourceline, None)
    return root


_UNDECLARED = re.compile(r"Namespace prefix (\S+) on (\S+) is not defined")
_NAMESPACES = {"xacro": "http://www.ros.org/wiki/xacro"}


def _said_plainly(message: str) -> str:
    """libxml2's message, with the fix where libxml2 names none."""
    undeclared = _UNDECLARED.fullmatch(message)
    if undeclared is None:
        return message
    prefix, tag = undeclared.groups()
    uri = _NAMESPACES.get(prefix, "...")
    return f'<{prefix}:{tag}> uses the prefix \'{prefix}\', declared nowhere: declare xmlns:{prefix}="{uri}" on the root element'


# A comment as urdfdom's parser (tinyxml2) reads one: from `<!--` to the next `-->`,
# whatever `--` it holds, which XML forbids and libxml2 and expat refuse.
_COMMENT = re.compile(rb"<!--(.*?)-->", re.DOTALL)


def hyphenated_comment(data: bytes) -> int | None:
    """The offset of the first comment holding `--` (or ending `--->`), or None."""
    for match in _COMMENT.finditer(data):
        if b"--" in match.group(1) or match.group(1).endswith(b"-"):
            return match.start()
    return None


def _blanked_comments(data: bytes) -> bytes:
    """``data`` with the text of each comment blanked, lines and columns kept: the
    comments urdfdom reads, which are dropped from the tree anyway."""
    return _COMMENT.sub(lambda match: b"<!--" + re.sub(rb"[^\n]", b" ", match.group(1)) + b"-->", data)


# A document up to this size is parsed whole, which is faster on small documents
# (streaming sets up a parser per document and hands each link and joint to Python
# as it ends). A larger one is streamed, so that its tree (about twelve times its
# size) is never whole in memory; the two take about as long there.
WHOLE_UP_TO = 1 << 20


def top_level(data: bytes, parsed: Element | None = None) -> Iterator[Element]:
    """The document's root element (read its attributes only), then each element
    written at the top level, whole, in document order; blank text, comments and
    processing instructions dropped. Each top-level element is taken out of the tree
    once the next one is asked for, and a document larger than WHOLE_UP_TO is
    streamed, so that no more than one is held at a time. Raises XmlError as
    :func:`parse` would, when the problem is met. ``parsed`` is the root of the
    same document read by :func:`parse` already, if it was."""
    if parsed is not None:
        yield parsed
        yield from _finished(parsed, None)
        return
    if not data or data.isspace():  # (strip() would copy a large document)
        raise XmlError("the document is empty", 1, 1)
    if len(data) <= WHOLE_UP_TO:
        root = parse(data)
        yield root
        yield from _finished(root, None)  # taken out as they are read: a block the model keeps holds no more
        return
    if b"<!DOCTYPE" in data or b"<!ENTITY" in data:
        parse(data)  # entity declarations are refused there, with their own message
    if hyphenated_comment(data) is not None:
        data = _blanked_comments(data)  # as parse reads it
    given = 0
    try:
        for element in _streamed(data):
            given += 1
            yield element
    except (etree.XMLSyntaxError, ValueError) as error:
        parse(data)  # the message and position parse gives, as for any reading
        if given:  # cannot happen for a document parse reads: say so rather than lose the error
            raise XmlError(str(error), getattr(error, "lineno", None) or 1, None) from None
        yield from _streamed(recoded(data), encoding="utf-8")  # an encoding only Python knows


# The elements URDF writes at the top level: lxml reports only the ends of elements
# of these names (in C), and the reader takes each top-level element at the first
# such end after it, so that Python sees a few events per link instead of one per element.
_MARKERS = ("link", "joint", "material", "gazebo", "transmission", "ros2_control")


def _streamed(data: bytes, encoding: str | None = None) -> Iterator[Element]:
    events = etree.iterparse(
        io.BytesIO(data), events=("end",), tag=_MARKERS, remove_blank_text=True, remove_comments=True, remove_pis=True,
        encoding=encoding, **_PARSER_OPTIONS,
    )
    root = None
    for _, element in events:
        parent = element.getparent()
        if parent is not root:
            if root is not None or parent is None or parent.getparent() is not None:
                continue  # the root itself, or inside a top-level element: it comes whole, at its end
            root = parent
            yield root
        yield from _finished(root, element)
    # The end of the document: the root, if no marker was met, and what follows the last marker.
    if root is None:
        root = events.root
        yield root
    yield from _finished(root, None)


def _finished(root: Element, last: Element | None) -> Iterator[Element]:
    """The top-level elements up to ``last`` (to the end with None), each taken out
    of the tree once the next one is asked for."""
    while (element := next(iter(root), None)) is not None:  # (len() would count the children each time)
        yield element
        del root[0]
        if element is last:
            return


def recoded(data: bytes) -> bytes:
    """``data`` as UTF-8, read in the encoding its XML declaration names (a name
    libxml2 does not know); lines stay where they were. Raises XmlError when
    Python does not know the encoding either, or the bytes are not in it."""
    name = declared_encoding(data) or "?"
    try:
        codec = codecs.lookup(name)
    except LookupError:
        raise XmlError(f"unknown encoding '{name}' in the XML declaration; save the file as UTF-8 and declare encoding=\"UTF-8\"", 1, 1) from None
    try:
        return data.decode(codec.name).encode("utf-8")
    except UnicodeDecodeError as error:
        line = data[: error.start].count(b"\n") + 1
        raise XmlError(f"byte 0x{data[error.start]:02x} is not {name}, the encoding the XML declaration names", line, None) from None
