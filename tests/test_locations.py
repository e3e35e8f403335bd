"""Every diagnostic points at the ``<`` of its element: plain URDF, xacro includes,
macro bodies and standard input; macro call sites are traced."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import model
from hypothesis import given, settings
from hypothesis import strategies as st
from lxml import etree

from urdfcli.read.document import tag_name
from urdfcli.read.positions import Text
from urdfcli.read.xml import parse as parse_bytes

XACRO = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'


class Writer:
    """Builds a source text and records where each tag's ``<`` is, as it writes it."""

    def __init__(self, first_line: int = 1):
        self.lines: list[str] = []
        self.first_line = first_line
        self.expected: list[tuple[str, int, int]] = []  # (id, line, column) in document order

    def raw(self, text: str) -> None:
        self.lines.append(text)

    def tag(self, indent: int, name: str, ident: str, spread: int, close: bool = True) -> None:
        """``<name id=... a1=... a2=...>`` over ``spread`` lines, an attribute on each line."""
        line = self.first_line + len(self.lines)
        self.expected.append((ident, line, indent + 1))
        attributes = [f'id="{ident}"'] + [f'a{i}="{i}"' for i in range(1, spread)]
        parts = [" " * indent + f"<{name} {attributes[0]}"]
        parts += [" " * (indent + 4) + attribute for attribute in attributes[1:]]
        parts[-1] += "/>" if close else ">"
        self.lines.extend(parts)

    def text(self) -> str:
        return "\n".join(self.lines) + "\n"


def body(writer: Writer, prefix: str, indent: int) -> None:
    """A link with nested elements whose start tags take one to five lines,
    some sharing a line with a sibling."""
    writer.tag(indent, "link", f"{prefix}link", 1, close=False)
    for spread in range(1, 6):
        writer.tag(indent + 2, "visual", f"{prefix}visual{spread}", spread, close=False)
        writer.tag(indent + 4, "origin", f"{prefix}origin{spread}", 6 - spread)
        writer.raw(" " * (indent + 2) + "</visual>")
    line = writer.first_line + len(writer.lines)
    writer.raw(" " * (indent + 2) + '<collision id="' + prefix + 'c1"/><collision id="' + prefix + 'c2"/>')
    writer.expected += [(f"{prefix}c1", line, indent + 3), (f"{prefix}c2", line, indent + 3 + len(f'<collision id="{prefix}c1"/>'))]
    writer.raw(" " * indent + "</link>")


def positions_of(path, ids: set[str]) -> dict[str, tuple[str, int, int]]:
    loaded = model(str(path))
    assert loaded.document.readable, loaded.diagnostics
    found = {}
    text = loaded.document.expanded_text.encode() if loaded.document.is_xacro else Path(path).read_bytes()
    for at, element in enumerate(parse_bytes(text).iter(etree.Element)):
        if element.get("id") in ids:
            where = loaded.document.locate(at)
            found[element.get("id")] = (where.file, where.line, where.column)
    return found


def test_plain_urdf_elements_point_at_their_opening_bracket(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    writer = Writer()
    writer.raw('<?xml version="1.0"?>')
    writer.raw("<!-- a comment with <link> inside -->")
    writer.raw('<robot name="r">')
    body(writer, "", 2)
    writer.raw("</robot>")
    (tmp_path / "r.urdf").write_text(writer.text())
    expected = {ident: ("r.urdf", line, column) for ident, line, column in writer.expected}
    assert positions_of("r.urdf", set(expected)) == expected


def test_included_file_and_macro_body_point_at_their_opening_bracket(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    included = Writer()
    included.raw(f"<robot {XACRO}>")
    body(included, "inc_", 2)
    included.raw('  <xacro:macro name="part" params="n">')
    body(included, "macro_", 4)
    included.raw("  </xacro:macro>")
    included.raw("</robot>")
    (tmp_path / "parts.xacro").write_text(included.text())
    top = Writer()
    top.raw(f'<robot name="r" {XACRO}>')
    top.raw('  <xacro:include filename="parts.xacro"/>')
    body(top, "top_", 2)
    top.raw('  <xacro:part n="1"/>')
    top.raw("</robot>")
    (tmp_path / "r.urdf.xacro").write_text(top.text())
    expected = {ident: ("parts.xacro", line, column) for ident, line, column in included.expected}
    expected |= {ident: ("r.urdf.xacro", line, column) for ident, line, column in top.expected}
    assert positions_of("r.urdf.xacro", set(expected)) == expected


MULTILINE = """<?xml version="1.0"?>
<robot name="r">
  <link name="a">
    <inertial>
      <mass value="1"/>
      <inertia ixx="1"
               iyy="1"
               izz="5"
               ixy="0" ixz="0" iyz="0"/>
    </inertial>
  </link>
</robot>
"""


def run(*args, stdin: bytes | None = None, cwd=None) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "urdfcli", *args], input=stdin, capture_output=True, cwd=cwd)


@pytest.mark.parametrize("fmt", ["json", "sarif", "github"])
def test_machine_formats_carry_the_column_of_a_multiline_tag(tmp_path, fmt):
    path = tmp_path / "ml.urdf"
    path.write_text(MULTILINE)
    out = run("lint", str(path), "--format", fmt).stdout.decode()
    if fmt == "json":
        (found,) = [d for d in json.loads(out)["files"][0]["diagnostics"] if d["code"] == "I006"]
        assert (found["line"], found["column"]) == (6, 7)
    elif fmt == "sarif":
        (found,) = [r for r in json.loads(out)["runs"][0]["results"] if r["ruleId"] == "I006"]
        assert found["locations"][0]["physicalLocation"]["region"] == {"startLine": 6, "startColumn": 7}
    else:
        assert any(line.startswith("::warning ") and "line=6,col=7,title=I006" in line for line in out.splitlines())


def test_standard_input_gets_the_excerpt_and_column_of_a_file(tmp_path):
    path = tmp_path / "ml.urdf"
    path.write_text(MULTILINE)
    by_path = run("lint", str(path)).stdout.decode().replace(str(path), "FILE")
    by_stdin = run("lint", "-", stdin=MULTILINE.encode()).stdout.decode().replace("<stdin>", "FILE")
    assert "FILE:6:7: I006" in by_path
    assert "     6 |       <inertia ixx=\"1\"\n       |       ^" in by_path
    assert by_stdin == by_path


def test_standard_input_xacro_is_located_like_a_file(tmp_path):
    text = f'<robot name="r" {XACRO}>\n  <xacro:property name="x" value="1"/>\n  <link name="a">\n    <visual>\n      <geometry>\n        <box size="${{y}} 1 1"/>\n      </geometry>\n    </visual>\n  </link>\n</robot>\n'
    path = tmp_path / "undef.urdf.xacro"
    path.write_text(text)
    by_path = run("check", path.name, cwd=tmp_path).stderr.decode().replace(path.name, "FILE")
    by_stdin = run("check", "-", stdin=text.encode(), cwd=tmp_path).stderr.decode().replace("<stdin>", "FILE")
    assert "FILE:6:" in by_path and "^" in by_path
    assert by_stdin == by_path


def wheel_robot(tmp_path):
    (tmp_path / "wheel.xacro").write_text(
        f'<robot {XACRO}>\n'
        '  <xacro:macro name="wheel" params="side z">\n'
        '    <link name="${side}_wheel">\n'
        "      <inertial><mass value=\"1\"/>\n"
        '        <inertia ixx="1" iyy="1" izz="${z}"\n'
        '                 ixy="0" ixz="0" iyz="0"/>\n'
        "      </inertial>\n"
        "    </link>\n"
        '    <joint name="${side}_joint" type="continuous"><parent link="base"/><child link="${side}_wheel"/></joint>\n'
        "  </xacro:macro>\n"
        '  <xacro:macro name="axle">\n'
        '    <xacro:wheel side="left" z="5"/>\n'
        "  </xacro:macro>\n"
        "</robot>\n"
    )
    top = tmp_path / "robot.urdf.xacro"
    top.write_text(
        f'<robot name="r" {XACRO}>\n'
        '  <xacro:include filename="wheel.xacro"/>\n'
        '  <link name="base"/>\n'
        "  <xacro:axle/>\n"
        '  <xacro:wheel\n'
        '      side="right" z="6"/>\n'
        "</robot>\n"
    )
    return top


def test_a_macro_body_diagnostic_names_each_call_site_innermost_first(tmp_path):
    wheel_robot(tmp_path)
    report = json.loads(run("lint", "robot.urdf.xacro", "--format", "json", cwd=tmp_path).stdout)
    found = sorted((d for d in report["files"][0]["diagnostics"] if d["code"] == "I006"), key=lambda d: d["message"])
    assert [(d["path"], d["line"], d["column"]) for d in found] == [("wheel.xacro", 5, 9)] * 2
    assert [d["trace"] for d in found] == [
        [
            {"path": "wheel.xacro", "line": 12, "column": 5, "macro": "wheel"},
            {"path": "robot.urdf.xacro", "line": 4, "column": 3, "macro": "axle"},
        ],
        [{"path": "robot.urdf.xacro", "line": 5, "column": 3, "macro": "wheel"}],
    ]
    text = run("lint", "robot.urdf.xacro", "--format", "text", cwd=tmp_path).stdout.decode()
    assert (
        "wheel.xacro:5:9: I006 warning: inertia of link 'left_wheel' breaks the triangle inequality: 1 + 1 < 5\n"
        "    note: in macro 'wheel' called at wheel.xacro:12:5\n"
        "    note: in macro 'axle' called at robot.urdf.xacro:4:3\n"
    ) in text
    assert "note: in macro 'wheel' called at robot.urdf.xacro:5:3\n" in text
    sarif = json.loads(run("lint", "robot.urdf.xacro", "--format", "sarif", cwd=tmp_path).stdout)
    related = [r.get("relatedLocations", []) for r in sarif["runs"][0]["results"] if r["ruleId"] == "I006"]
    assert sorted(len(r) for r in related) == [1, 2]
    assert all(r[0]["message"]["text"].startswith("in macro 'wheel'") for r in related)
    github = run("lint", "robot.urdf.xacro", "--format", "github", cwd=tmp_path).stdout.decode()
    assert "breaks the triangle inequality: 1 + 1 < 6%0Ain macro 'wheel' called at robot.urdf.xacro:5:3\n" in github
    concise = run("lint", "robot.urdf.xacro", "--format", "concise", cwd=tmp_path).stdout.decode()
    # one line each, as a pre-commit hook prints them: the innermost call tells the copies apart
    assert "1 + 1 < 5 (in macro 'wheel' called at wheel.xacro:12:5)\n" in concise
    assert "1 + 1 < 6 (in macro 'wheel' called at robot.urdf.xacro:5:3)\n" in concise


def test_a_deep_trace_is_cut_after_three_levels(tmp_path):
    macros = "".join(
        f'  <xacro:macro name="m{i}"><xacro:m{i - 1}/></xacro:macro>\n' for i in range(1, 6)
    )
    (tmp_path / "deep.urdf.xacro").write_text(
        f'<robot name="r" {XACRO}>\n'
        '  <xacro:macro name="m0"><link name="a"><inertial><mass value="1"/>'
        '<inertia ixx="1" iyy="1" izz="5" ixy="0" ixz="0" iyz="0"/></inertial></link></xacro:macro>\n'
        f"{macros}"
        "  <xacro:m5/>\n"
        "</robot>\n"
    )
    text = run("lint", "deep.urdf.xacro", cwd=tmp_path).stdout.decode()
    notes = [line for line in text.splitlines() if line.startswith("    note:")]
    assert notes[:3] == [
        "    note: in macro 'm0' called at deep.urdf.xacro:3:26",
        "    note: in macro 'm1' called at deep.urdf.xacro:4:26",
        "    note: in macro 'm2' called at deep.urdf.xacro:5:26",
    ]
    assert notes[3] == "    note: ... and 3 more macro calls"


def test_xacro_warnings_name_the_element_that_caused_them(tmp_path):
    (tmp_path / "inc.xacro").write_text(
        f'<robot {XACRO}>\n'
        '  <xacro:macro name="m">\n'
        '    <link name="a">\n'
        '      <visual><origin xyz="${len(range(3))} 0 0"/><geometry><box size="1 1 1"/></geometry></visual>\n'
        "    </link>\n"
        "  </xacro:macro>\n"
        "</robot>\n"
    )
    (tmp_path / "top.urdf.xacro").write_text(
        f'<robot name="r" {XACRO}>\n  <xacro:include filename="inc.xacro"/>\n  <xacro:m/>\n</robot>\n'
    )
    report = json.loads(run("check", "top.urdf.xacro", "--format", "json", cwd=tmp_path).stdout)
    (warning,) = [d for d in report["files"][0]["diagnostics"] if d["code"] == "X005"]
    assert "range() directly is deprecated" in warning["message"]
    assert (warning["path"], warning["line"], warning["column"]) == ("inc.xacro", 4, 34)  # the deprecated call itself, range(
    assert warning["trace"] == [{"path": "top.urdf.xacro", "line": 3, "column": 3, "macro": "m"}]


def test_what_a_lazy_property_reports_is_located_at_its_definition(tmp_path):
    """xacro evaluates a property where it is first used, but a warning or an error from
    its value belongs to the line that defines it (ur_description loads its yaml files
    so, in properties of a macro)."""
    model = (
        f'<robot name="r" {XACRO}>\n'
        '  <xacro:property name="n" value="${len(range(3))}"/>\n'
        '  <xacro:macro name="m" params="k">\n'
        '    <xacro:property name="p" value="${k * VALUE}"/>\n'
        '    <link name="a${n}_${p}"/>\n'
        "  </xacro:macro>\n"
        '  <xacro:m k="2"/>\n'
        "</robot>\n"
    )
    (tmp_path / "warns.urdf.xacro").write_text(model.replace("VALUE", "2"))
    (tmp_path / "fails.urdf.xacro").write_text(model.replace("VALUE", "missing"))
    report = json.loads(run("check", "warns.urdf.xacro", "fails.urdf.xacro", "--format", "json", cwd=tmp_path).stdout)
    (warning,), (error,) = (file["diagnostics"] for file in report["files"])
    assert (warning["code"], warning["path"], warning["line"], warning["column"], warning["trace"]) == ("X005", "warns.urdf.xacro", 2, 41, [])
    assert "range() directly is deprecated" in warning["message"]
    assert (error["code"], error["path"], error["line"], error["column"]) == ("X003", "fails.urdf.xacro", 4, 5)
    assert "name 'missing' is not defined" in error["message"]
    assert error["trace"] == [{"path": "fails.urdf.xacro", "line": 7, "column": 3, "macro": "m"}]


def test_positions_skip_markup_that_opens_no_element():
    text = (
        '<?xml version="1.0"?>\n<!DOCTYPE robot [ <!ELEMENT robot ANY> ]>\n'
        "<robot><!-- <link> --><![CDATA[ <joint> ]]><?pi <x> ?>\r\n  <link a='>'\n/></robot>"
    )
    source = Text(text)
    assert [source.position(start) for start in source.starts] == [(3, 1), (4, 3)]
    assert [(source.position(a), source.position(b), source.position(c)) for a, b, c in source.spans] == [
        ((3, 1), (3, 8), (5, 11)),
        ((4, 3), (5, 3), (5, 3)),
    ]


_MARKUP = [
    "<!-- <link> -->", "<!---->", "<![CDATA[ <joint> ]]>", "<?pi <x> ?>", "<?pi?>", "text ?> ]] -->",
    "<a>", "</a>", "<b/>", "<c d='>'\n/>", "\n", "<!-- <!-- ",
]


@settings(max_examples=1000, deadline=None)
@given(st.lists(st.sampled_from(_MARKUP), max_size=12))
def test_element_starts_are_those_of_the_parsed_tree(pieces):
    """On any well-formed mix of elements and markup that opens none (which may hold
    a '<'), the starts found in the text are one per element, with its tag and line."""
    text = '<?xml version="1.0"?>\n<!DOCTYPE r [ <!ELEMENT r ANY> ]>\n<r>' + "".join(pieces) + "</r>"
    try:
        root = etree.fromstring(text.encode(), etree.XMLParser(resolve_entities=False, load_dtd=False))
    except etree.XMLSyntaxError:
        return
    elements = list(root.iter(etree.Element))
    source = Text(text)
    assert [source.tag(index) for index in range(len(elements))] == [element.tag for element in elements]
    assert len(source.starts) == len(elements)


def test_a_diagnostic_about_one_attribute_points_at_it(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "parts.xacro").write_text(
        f"<robot {XACRO}>\n"
        '  <xacro:macro name="part" params="n">\n'
        '    <link name="${n}"\n'
        '          colour="red"/>\n'
        "  </xacro:macro>\n"
        "</robot>\n"
    )
    (tmp_path / "r.urdf.xacro").write_text(
        f'<robot name="r" {XACRO}>\n  <xacro:include filename="parts.xacro"/>\n  <xacro:part n="a"/>\n'
        '  <link name="b" type="x" colour="blue"/>\n</robot>\n'
    )
    report = json.loads(run("lint", "r.urdf.xacro", "--select", "D010", "--format", "json", cwd=tmp_path).stdout)
    found = sorted((d["path"], d["line"], d["column"]) for d in report["files"][0]["diagnostics"])
    assert found == [("parts.xacro", 4, 11), ("r.urdf.xacro", 4, 27)]


def tree_path(element) -> str:
    """The element path as read off a parsed tree: what Document.element_path works out from the text."""
    parts = []
    node = element
    while node.getparent() is not None:
        parent = node.getparent()
        tag, name = tag_name(node), node.get("name")
        if tag in ("link", "joint", "material", "transmission", "gazebo") and name is not None and parent.getparent() is None:
            parts.append(f"{tag}[@name='{name}']")
        elif tag == "gazebo" and node.get("reference") is not None:
            parts.append(f"gazebo[@reference='{node.get('reference')}']")
        else:
            same = [s for s in parent if s.tag == node.tag]
            parts.append(f"{tag}[{same.index(node) + 1}]" if len(same) > 1 else tag)
        node = parent
    if not parts:
        return f"robot[@name='{element.get('name')}']" if element.get("name") is not None else tag_name(element)
    return "/".join(reversed(parts))


PATH_SAMPLES = ["pr2.urdf", "tiago_dual.urdf", "anymal-kinova.urdf", "icub.urdf", "alex_psyonic_hands.urdf"]


@pytest.mark.parametrize("name", PATH_SAMPLES)
def test_element_paths_from_the_text_match_the_tree(name):
    """Every element of published models, comments and all: the path worked out from the
    source text, one top-level element at a time, is the one the parsed tree gives."""
    from conftest import example_robot_data

    paths = sorted((example_robot_data() / "robots").rglob(name))
    loaded = model(str(paths[0]))
    elements = list(parse_bytes(paths[0].read_bytes()).iter(etree.Element))
    assert len(loaded.document.tops) > 10
    for at, element in enumerate(elements):
        assert loaded.document.element_path(at) == tree_path(element), at
