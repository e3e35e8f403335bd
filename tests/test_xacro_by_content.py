"""A document is expanded with xacro only when it uses xacro, and skipping xacro for
one that merely declares the namespace changes no diagnostic."""

from __future__ import annotations

import importlib.metadata
from pathlib import Path

import pytest
from conftest import load
from hypothesis import given, settings
from hypothesis import strategies as st

from urdfcli.read import document as load_module
from urdfcli.read import document
from urdfcli.read.document import XACRO_NAMESPACES
from urdfcli.read.files import SourceFile
from urdfcli.read.xml import XmlError
from urdfcli.read.xml import parse as parse_bytes

XACRO_NS = "http://www.ros.org/wiki/xacro"

# The definition, in XPath: a xacro element, or a substitution in an attribute or in text.
_XACRO_ELEMENT = "//*[" + " or ".join(f"namespace-uri() = '{ns}'" for ns in sorted(XACRO_NAMESPACES)) + " or (namespace-uri() != '' and starts-with(name(), 'xacro:'))]"
USES_XACRO = f"boolean({_XACRO_ELEMENT} | //@*[contains(., '${{') or contains(., '$(')] | //text()[contains(., '${{') or contains(., '$(')])"


def is_xacro(data: bytes) -> bool:
    return document.is_xacro(SourceFile("robot.urdf", data))


def corpus() -> list[Path]:
    """The URDFs of the installed example-robot-data package (empty when it is missing)."""
    try:
        robots = Path(importlib.metadata.distribution("example-robot-data").locate_file("cmeel.prefix/share/example-robot-data/robots"))
    except importlib.metadata.PackageNotFoundError:
        return []
    return sorted(robots.rglob("*.urdf"))


def declares_xacro(path: Path) -> bool:
    return bool(XACRO_NAMESPACES & set(parse_bytes(path.read_bytes()).nsmap.values()))


@pytest.mark.parametrize(
    "body, uses",
    [
        ('<link name="a"/>', False),
        ('<link name="a"/><!-- ${not evaluated} $(nor this) -->', False),
        ('<link name="${n}"/>', True),
        ('<link name="a"><visual><geometry><mesh filename="$(find p)/m.stl"/></geometry></visual></link>', True),
        ("<link name='a'/><gazebo>${x}</gazebo>", True),
        ('<xacro:property name="n" value="1"/>', True),
        ('<x:property xmlns:x="http://ros.org/wiki/xacro" name="n" value="1"/>', True),  # another prefix
        ('<link name="a" data="$ {not} $"/>', False),
    ],
)
def test_xacro_is_use_not_declaration(body, uses):
    data = f'<robot name="r" xmlns:xacro="{XACRO_NS}">{body}</robot>'.encode()
    assert is_xacro(data) is uses


def test_a_declared_but_unused_namespace_is_read_as_plain_urdf(tmp_path):
    path = tmp_path / "robot.urdf"
    path.write_text(f'<robot name="r" xmlns:xacro="{XACRO_NS}"><link name="a"/></robot>')
    loaded = load(str(path))
    assert not loaded.loaded.document.is_xacro
    assert list(loaded.robot.links) == ["a"]


DECLARING = [p for p in corpus() if declares_xacro(p)]


@pytest.mark.skipif(not DECLARING, reason="example-robot-data is not installed")
@pytest.mark.parametrize("path", DECLARING, ids=lambda p: p.name)
def test_corpus_diagnostics_are_the_same_with_or_without_xacro(path, monkeypatch, tmp_path):
    """The published URDFs that declare xmlns:xacro and use nothing of it: expanding them
    with xacro (as a namespace declaration used to decide) gives the same diagnostics."""
    # xacro names a file under the working directory by its relative path: work from
    # elsewhere, so that both runs name the input as given, wherever the package is installed
    monkeypatch.chdir(tmp_path)
    plain = load(str(path))
    assert not plain.loaded.document.is_xacro
    monkeypatch.setattr(load_module, "is_xacro", lambda file: True)  # every document taken for xacro
    expanded = load(str(path))
    assert expanded.loaded.document.is_xacro
    assert expanded.diagnostics == plain.diagnostics


@pytest.mark.parametrize(
    "data, uses",
    [
        (b'<robot name="r"><!-- <origin xyz="${x}"/> $(arg a) --><link name="a"/></robot>', False),  # kept from the xacro source
        (b'<robot name="r"><!-- ${x} --><link name="${x}"/></robot>', True),
        (b'<robot name="r" xmlns:xacro="http://wiki.ros.org/xacro"><!-- http://wiki.ros.org/xacro --><link name="a"/></robot>', False),
        (b'<robot name="r"><macro xmlns="http://www.ros.org/wiki/xacro" name="m"/></robot>', True),  # a default namespace
        (b'<robot name="r"><!-- <xacro:property name="n" value="1"/> --><link name="a"/></robot>', False),
        (b'<robot name="r" xmlns:xacro="http://wiki.ros.org/xacro"><![CDATA[ <!-- ]]><xacro:property name="n" value="1"/><!-- --></robot>', True),
        (b'<?xml version="1.0"?>\n<robot name="r"><!-- generated: $(find p)/r.xacro --><link name="a"/></robot>', False),
        (b'<?xml-stylesheet href="<!--"?><robot name="r"><link name="${x}"/><!-- --></robot>', True),
    ],
)
def test_xacro_use_is_told_apart_from_comments_and_declarations(data, uses):
    assert is_xacro(data) is uses


_PIECES = [
    "<!-- ", " -->", " ${a} ", "$(b)", "$", '<xacro:if value="1"/>', "xacro", '<link name="a"/>', "<!-- c -->",
    "http://wiki.ros.org/xacro", "http://ros.org/wiki/xacro", '<x:y xmlns:x="http://www.ros.org/wiki/xacro"/>',
    "<![CDATA[${q}]]>", '<a b="${c}"/>', '<a b="$(c)"/>', "<?pi <!-- ?>",
]
_DECLARATIONS = ['xmlns:xacro="http://wiki.ros.org/xacro"', "xmlns:xacro = 'http://ros.org/wiki/xacro'", "", 'xmlns:xacro="http://example.com"']


@settings(max_examples=1000, deadline=None)
@given(st.sampled_from(_DECLARATIONS), st.lists(st.sampled_from(_PIECES), max_size=8))
def test_the_bytes_tell_what_the_parsed_document_says(declaration, pieces):
    """The byte tests stand in for the definition: a xacro element, or a substitution
    in an attribute or in text, in the parsed document."""
    data = f"<robot {declaration}>{''.join(pieces)}</robot>".encode()
    try:
        root = parse_bytes(data)
    except XmlError:
        assert not is_xacro(data)
        return
    assert is_xacro(data) is root.xpath(USES_XACRO)


def test_a_launch_file_given_is_no_robot_not_a_xacro_file_to_expand(tmp_path):
    """fanuc_m10ia_support's load_m10ia.launch holds $(find xacro): given to check, it is not
    expanded (xacro would fail on package 'xacro') but said not to be a robot (R001)."""
    from conftest import run_cli

    launch = tmp_path / "load_m10ia.launch"
    launch.write_text('<?xml version="1.0"?>\n<launch>\n  <param name="robot_description" '
                      "command=\"$(find xacro)/xacro '$(find fanuc_m10ia_support)/urdf/m10ia.xacro'\" />\n</launch>\n")
    done = run_cli("check", str(launch))
    assert done.returncode == 1
    assert done.stderr.decode().startswith(f"{launch}:2:1: R001 error: the root element is <launch>, not <robot>\n")
    assert "X004" not in done.stderr.decode()
