"""The expat reading of small documents gives lxml's reading, or leaves the document to lxml.

urdfcli.lightxml answers None where it could differ from lxml; everywhere else
its elements must read as lxml's: the same tags, prefixes, attributes in order,
texts (stripped: lxml drops some white space between elements) and children,
and the root's namespaces. Each document here is read both ways.
"""

from __future__ import annotations

import random
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from conftest import FIXTURES, ROOT, example_robot_data
from test_fuzz import mutate
from urdfcli import lightxml
from urdfcli.xmlsafe import XmlError, parse_bytes


def shape(element) -> tuple:
    return (element.tag, element.prefix, list(element.attrib.items()), (element.text or "").strip(), [shape(child) for child in element])


def assert_read_as_lxml_reads(data: bytes) -> bool:
    """Whether expat read ``data``; when it did, lxml reads the same document."""
    root = lightxml.read(data)
    if root is None:
        return False
    try:
        expected = parse_bytes(data, keep_blank_text=False, elements_only=True)
    except XmlError as error:
        pytest.fail(f"expat read a document lxml refuses ({error.message}): {data[:200]!r}")
    assert shape(root) == shape(expected)
    assert root.nsmap == expected.nsmap
    return True


def test_every_fixture_and_test_document_reads_as_lxml_reads_it():
    files = sorted(p for folder in (FIXTURES, ROOT / "tests") for p in folder.rglob("*") if p.suffix in (".urdf", ".xacro"))
    assert len(files) >= 30
    assert all(assert_read_as_lxml_reads(file.read_bytes()) for file in files)


def test_every_published_model_reads_as_lxml_reads_it():
    files = sorted((example_robot_data() / "robots").rglob("*.urdf"))
    assert len(files) == 69
    assert all(assert_read_as_lxml_reads(file.read_bytes()) for file in files)


ODD = {
    "namespaces": b'<robot xmlns:c="urn:c" name="r"><c:thing c:at="1" xml:lang="en" a="3"/><link xmlns="urn:d" name="l"><visual/></link></robot>',
    "two prefixes, one namespace": b'<robot xmlns:c="urn:c"><a xmlns:d="urn:c"><d:b/><c:b/></a></robot>',
    "xml prefix declared": b'<a xmlns:xml="http://www.w3.org/XML/1998/namespace"/>',
    "default namespace undeclared": b'<a xmlns="urn:a"><b xmlns=""><c/></b></a>',
    "comment inside text": b"<a> x <!--c--> y <b/> </a>",
    "blank text around a comment": b"<a>  <!-- c --> </a>",
    "CDATA": b"<a><![CDATA[ <x> ]]><b/></a>",
    "processing instruction": b"<a> <?pi x?> <b/></a>",
    "references": b"<a>&#32;<b/>&amp;&lt;&#x4e2d;</a>",
    "latin-1": b'<?xml version="1.0" encoding="latin1"?><a b="\xe9"/>',
    "byte-order mark": b"\xef\xbb\xbf<a/>",
    "XML 1.1": b'<?xml version="1.1"?><a/>',
    "declaration in single quotes": b"\xef\xbb\xbf<?xml  version = '1.0'  encoding='UTF-8' standalone='yes' ?>\n<a/>",
    "new lines in an attribute": b'<a b="1\n2\r\n3\t4"/>',
    "CRLF": b'<robot name="r">\r\n  <link name="a"/>\r\n</robot>\r\n',
}
REFUSED = {
    "unbound element prefix": b"<robot><u:other/></robot>",
    "unbound attribute prefix": b'<robot><a q:x="1"/></robot>',
    "empty prefixed namespace": b'<robot><x xmlns:e=""/></robot>',
    "undefined entity": b"<a>&foo;</a>",
    "attribute twice": b'<a b="1" b="2"/>',
    "namespaced attribute twice": b'<a xmlns:x="u" xmlns:y="u"><b x:c="1" y:c="2"/></a>',
    "xml prefix rebound": b'<a xmlns:xml="urn:x"/>',
    "two colons": b'<a:b:c xmlns:a="u"/>',
    "two roots": b"<a/><b/>",
    "version not 1.x": b'<?xml version="-nan"?><a/>',
    "version 2.0": b'<?xml version="2.0"?><a/>',
    "namespace not a URI": b'<robot xmlns:xacro=" "/>',
    "namespace with a bad port": b'<robot xmlns="http://a:b:c"/>',
    "control character": b"<a>\x01</a>",
    "not UTF-8": b"<a>\xff</a>",
    "]]> in text": b"<a>]]></a>",
    "DOCTYPE": b'<!DOCTYPE a [<!ENTITY e "x">]><a>&e;</a>',
    "DOCTYPE without entities": b"<!DOCTYPE a><a/>",
    "UTF-16": "<a/>".encode("utf-16"),
    "too deep": b"<a>" * (lightxml.MAX_DEPTH + 1) + b"</a>" * (lightxml.MAX_DEPTH + 1),
}


@pytest.mark.parametrize("data", ODD.values(), ids=ODD.keys())
def test_odd_markup_reads_as_lxml_reads_it(data):
    assert assert_read_as_lxml_reads(data)


@pytest.mark.parametrize("data", REFUSED.values(), ids=REFUSED.keys())
def test_what_lxml_refuses_or_may_read_otherwise_is_left_to_it(data):
    assert lightxml.read(data) is None


def test_the_deepest_document_lxml_reads_is_read():
    deepest = b"<a>" * lightxml.MAX_DEPTH + b"</a>" * lightxml.MAX_DEPTH
    assert assert_read_as_lxml_reads(deepest)


def test_corrupted_fixtures_are_read_as_lxml_reads_them_or_left_to_it():
    """The fuzzing mutator's corruptions of every fixture: none is read otherwise than lxml reads it."""
    rng = random.Random(11)
    files = sorted(p for p in FIXTURES.rglob("*") if p.suffix in (".urdf", ".xacro"))
    read = sum(assert_read_as_lxml_reads(mutate(rng.choice(files).read_bytes(), rng)[0]) for _ in range(3000))
    assert read > 300  # some corruptions leave a well-formed document


TOKENS = st.sampled_from([
    "<a", "<b", "<x:c", "<y:d", "</a>", "</b>", "</x:c>", "</y:d>", ">", "/>", " ", "\n", "\t", "text", "é",
    ' n="1"', ' x:n="2"', ' y:n="3"', ' xmlns:x="urn:x"', ' xmlns:y="urn:x"', ' xmlns:y="urn:y"', ' xmlns="urn:d"', ' xmlns=""',
    "&amp;", "&#32;", "&#x4e2d;", "<![CDATA[ c ]]>", "<!-- c -->", "<?p i?>", '<robot name="r">', "</robot>",
])


@settings(max_examples=2000, deadline=None)
@given(st.lists(TOKENS, max_size=40).map(lambda tokens: "".join(tokens).encode()))
def test_generated_markup_is_read_as_lxml_reads_it_or_left_to_it(data):
    assert_read_as_lxml_reads(data)


URI = st.text(alphabet="ab1:/?#@%20Ff[]. |\\é-_~!$&'()*+,;=", max_size=16)


@settings(max_examples=2000, deadline=None)
@given(URI, st.booleans())
def test_a_namespace_is_declared_as_lxml_takes_it_or_left_to_it(uri, prefixed):
    """libxml2 refuses a namespace URI that RFC 3986 does not allow."""
    attribute = "xmlns:p" if prefixed else "xmlns"
    assert_read_as_lxml_reads(f'<a {attribute}="{uri}"><b/></a>'.encode())


@pytest.mark.parametrize("uri", ["http://www.ros.org/wiki/xacro", "http://playerstage.sourceforge.net/gazebo/xmlschema/#sensor", "urn:a:b", "a:", "u", "?", "#", "http://u@a:80/b?c#d", "a%20b"])
def test_usual_namespaces_are_read(uri):
    assert assert_read_as_lxml_reads(f'<a xmlns:p="{uri}"><p:b/></a>'.encode())


def test_a_file_path_is_no_document():
    assert lightxml.read(str(Path(__file__)).encode()) is None
