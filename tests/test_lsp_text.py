"""What the editor server reads from a text without expanding it: outlines, the text
at a cursor (also in a tag being typed), and the edits of its quick fixes."""

from __future__ import annotations

from urdfcli.lsp.actions import noqa, replace_element
from urdfcli.lsp import outline as outlines
from urdfcli.lsp.outline import cursor, encoded, expression_name, substitution
from urdfcli.read.files import SourceFile
from urdfcli.read.positions import Text
from urdfcli.read.xacro_scan import macro_parameters

LIBRARY = """<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="$(find parts)/urdf/inertia.xacro"/>
  <xacro:arg name="prefix" default="left_"/>
  <xacro:property name="radius" value="0.1"/>
  <xacro:macro name="wheel" params="side parent *origin length:=0.04">
    <xacro:property name="mass" value="${2 * radius}"/>
    <link name="${side}_wheel"/>
    <link name="hub"/>
    <joint name="${side}_joint" type="continuous"/>
  </xacro:macro>
  <transmission name="t"><joint name="not_a_definition"/></transmission>
</robot>
"""


def outline(file: str, text: str):
    return outlines.outline(file, SourceFile(file, encoded(text)))


def at(text: str, needle: str, offset: int = 0) -> int:
    return text.index(needle) + offset


def test_an_outline_lists_definitions_where_they_were_written():
    found = outline("/lib.xacro", LIBRARY)
    assert [(d.kind, d.name, d.line, d.column, d.detail, d.macro) for d in found.definitions] == [
        ("arg", "prefix", 3, 3, "left_", None),
        ("property", "radius", 4, 3, "0.1", None),
        ("macro", "wheel", 5, 3, "side parent *origin length:=0.04", None),
        ("property", "mass", 6, 5, "${2 * radius}", "wheel"),
        ("link", "${side}_wheel", 7, 5, "", "wheel"),  # a name made in a macro's body, as written
        ("link", "hub", 8, 5, "", "wheel"),
        ("joint", "${side}_joint", 9, 5, "continuous", "wheel"),
    ]
    assert [(i.value, i.line) for i in found.includes] == [("$(find parts)/urdf/inertia.xacro", 2)]


def test_a_text_that_is_not_well_formed_has_no_outline():
    assert outline("/lib.xacro", LIBRARY.replace("</robot>", "")) is None


def test_macro_parameters_keep_blocks_and_defaults():
    assert [(p.shown, p.shown_default) for p in macro_parameters("side parent *origin length:=0.04 mass=1 ^outer:=^|2")] == [
        ("side", None), ("parent", None), ("*origin", None), ("length", "0.04"), ("mass", "1"), ("^outer", "^|2"),
    ]


def test_the_cursor_in_a_tag_being_typed():
    text = '<robot>\n  <joint name="j" type="fixed">\n    <parent link="bas\n    <child link="c"/>\n'
    found = cursor(text, at(text, 'link="bas', 9))
    assert (found.tag, found.attribute, found.value) == ("parent", "link", "bas")
    assert text[found.value_start : found.value_end] == "bas"
    assert cursor(text, at(text, "<child", 3)).on_name
    assert cursor(text, at(text, '<joint name="j"', 13)).value == "j"


def test_no_cursor_in_text_comments_end_tags_or_after_a_tag():
    text = '<robot> some text <!-- <link name="x"/> --> <link name="a"/> </robot>'
    assert cursor(text, at(text, "some", 2)) is None
    assert cursor(text, at(text, '<link name="a"/>', 17)) is None
    assert cursor(text, at(text, "</robot>", 3)) is None
    assert cursor(text, at(text, "<!--", 2)) is None


def test_names_in_expressions_and_substitutions():
    value = "${2 * radius + python.pi} $(arg prefix)"
    assert expression_name(value, value.index("radius") + 2) == "radius"
    assert expression_name(value, value.index("pi")) is None  # an attribute, not a name
    assert expression_name(value, value.index("$(arg") + 3) is None
    assert substitution(value, value.index("prefix")) == ("arg", "prefix")
    assert substitution(value, value.index("radius")) is None


def test_noqa_adds_a_comment_above_indented_as_the_element():
    source = Text("<robot>\n    <axis xyz='0 0 0'/>\n</robot>\n")
    edit = noqa(source, 2, "J007")
    text = source.text[: edit.start] + edit.text + source.text[edit.end :]
    assert text == "<robot>\n    <!-- urdfcli: noqa: J007 -->\n    <axis xyz='0 0 0'/>\n</robot>\n"


def test_noqa_adds_the_code_to_a_comment_there_already():
    above = Text("<robot>\n  <!-- urdfcli: noqa: I006 -->\n  <link name='a'/>\n</robot>")
    edit = noqa(above, 3, "I009")
    assert above.text[: edit.start] + edit.text + above.text[edit.end :] == "<robot>\n  <!-- urdfcli: noqa: I006, I009 -->\n  <link name='a'/>\n</robot>"
    same_line = Text("<robot>\n  <link name='a'/>  <!-- urdfcli: noqa: S001 -->\n</robot>")
    edit = noqa(same_line, 2, "I009")
    assert edit.text == "<!-- urdfcli: noqa: S001, I009 -->" and same_line.text[edit.start : edit.end] == "<!-- urdfcli: noqa: S001 -->"


def test_noqa_gives_no_edit_where_it_cannot_silence():
    bare = Text("<robot>\n  <!-- urdfcli: noqa -->\n  <link name='a'/>\n</robot>")
    assert noqa(bare, 3, "I009") is None  # silenced already
    assert noqa(Text("<robot>\n"), 1, "X001") is None  # an unreadable file is reported whatever comments say
    assert noqa(Text("<robot/>"), 5, "I009") is None


def test_an_element_is_replaced_whole_and_indented():
    source = Text('<robot>\n  <link name="a">\n    <inertial>\n      <mass value="1"/>\n    </inertial>\n  </link>\n</robot>\n')
    edit = replace_element(source, 3, 5, "<inertial>\n  <mass value='2'/>\n</inertial>")
    replaced = source.text[: edit.start] + edit.text + source.text[edit.end :]
    assert replaced == "<robot>\n  <link name=\"a\">\n    <inertial>\n      <mass value='2'/>\n    </inertial>\n  </link>\n</robot>\n"
    assert replace_element(source, 3, 4, "<x/>") is None  # no element starts there
    assert replace_element(Text("<robot>\n  <link>\n"), 2, 3, "<x/>") is None  # not well-formed


def test_an_editors_text_is_encoded_as_its_declaration_says():
    assert encoded('<?xml version="1.0" encoding="ISO-8859-1"?><robot name="größe"/>').endswith('"gr\xf6\xdfe"/>'.encode("latin-1"))
    assert encoded('<robot name="größe"/>') == '<robot name="größe"/>'.encode()
    assert encoded('<?xml version="1.0" encoding="ascii"?><robot name="größe"/>').endswith("größe\"/>".encode())  # cannot hold it: UTF-8


def test_values_from_an_input_are_shown_as_code_that_cannot_break_out():
    from urdfcli.lsp.navigation import code

    assert code("0.04") == "`0.04`"
    assert code("a`b``c") == "``` a`b``c ```"  # a fence longer than any run inside
    assert code("x\u202ey\x1b[2J") == "`x\\u202ey\\x1b[2J`"  # bidi overrides and escapes shown, not obeyed
    assert code("") == '`""`'


def test_completion_offers_only_names_that_can_be_typed():
    from urdfcli.diagnostics import Location
    from urdfcli.lsp.navigation import Scope, completion

    text = '<robot>\n  <joint name="j" type="fixed"><parent link=""/></joint>\n</robot>\n'
    links = {"base_link": (Location("/m.urdf", 1, 1),), "evil\u202eknil": (Location("/m.urdf", 2, 1),)}
    scope = Scope((), links, {}, lambda name: None, lambda value: None)
    offset = text.index('link=""') + len('link="')
    assert [(i.label, i.start, i.end) for i in completion(text, offset, scope)] == [("base_link", offset, offset)]
