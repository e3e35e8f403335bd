"""noqa comments silence an element and everything inside it, whatever line a
diagnostic points at; codes, prefixes and rule names; bare noqa; macro calls."""

from __future__ import annotations

import textwrap

from conftest import lint_file, run_cli

from urdfcli.project.config import Config

# I006 points at the <inertia> line, four lines below the <link>.
SENSOR = """\
<robot name="r">
  <link name="base_link"/>
  {comment}
  <link name="sensor_mount_link">
    <inertial>
      <mass value="1"/>
      <inertia ixx="1" iyy="1"
               izz="5" ixy="0" ixz="0" iyz="0"/>
    </inertial>
  </link>
  <joint name="j" type="fixed"><parent link="base_link"/><child link="sensor_mount_link"/></joint>
</robot>
"""


def codes(tmp_path, text, name="robot.urdf", config=Config(select=("I006", "U"))):
    path = tmp_path / name
    path.write_text(textwrap.dedent(text))
    return [(d.line, d.code) for d in lint_file(str(path), config).diagnostics]


def test_the_unsuppressed_model_has_the_defect(tmp_path):
    assert codes(tmp_path, SENSOR.format(comment="")) == [(7, "I006")]


def test_a_comment_above_an_element_silences_what_points_inside_it(tmp_path):
    for words in ("I006", "I", "inertia-triangle-inequality", "I006, I009", "i006", ""):
        comment = f"<!-- urdfcli: noqa: {words} -->" if words else "<!-- urdfcli: noqa -->"
        assert codes(tmp_path, SENSOR.format(comment=comment)) == [], comment


def test_a_comment_in_a_utf16_file_silences_too(tmp_path):
    """The comments are looked for in the text, whatever the bytes: a file in UTF-16
    cannot be ruled out by searching its bytes for the word urdfcli."""
    path = tmp_path / "robot.urdf"
    text = '<?xml version="1.0" encoding="UTF-16"?>\n' + SENSOR.format(comment="<!-- urdfcli: noqa: I006 -->")
    path.write_bytes(text.encode("utf-16"))
    assert [d.code for d in lint_file(str(path), Config(select=("I006", "U"))).diagnostics] == []


def test_a_file_whose_bytes_hold_no_comment_is_not_read_again(tmp_path, monkeypatch):
    """The input's bytes tell, while they are read, that no suppression comment is in them."""
    from urdfcli.project import linter

    asked = []
    text_of = linter._text_holding
    monkeypatch.setattr(linter, "_text_holding", lambda files, name, mark: asked.append(name) or text_of(files, name, mark))
    assert codes(tmp_path, SENSOR.format(comment="")) == [(7, "I006")]
    assert asked == []
    assert codes(tmp_path, SENSOR.format(comment="<!-- urdfcli: noqa: I006 -->")) == []
    assert asked == [str(tmp_path / "robot.urdf")]


def test_the_rule_name_is_the_registered_one():
    from urdfcli.rules import REGISTRY

    assert REGISTRY["I006"].name == "inertia-triangle-inequality"


def test_a_comment_naming_another_rule_silences_nothing(tmp_path):
    found = codes(tmp_path, SENSOR.format(comment="<!-- urdfcli: noqa: I009 -->"), config=Config(select=("I006", "I009", "U")))
    assert found == [(3, "U001"), (7, "I006")]


def test_a_comment_on_any_line_of_a_start_tag_written_over_several(tmp_path):
    text = SENSOR.format(comment="").replace(
        '      <inertia ixx="1" iyy="1"\n               izz="5" ixy="0" ixz="0" iyz="0"/>',
        '      <inertia ixx="1" iyy="1"\n               izz="5" ixy="0" ixz="0" iyz="0"/> <!-- urdfcli: noqa: I006 -->',
    )
    assert codes(tmp_path, text) == []
    multiline = SENSOR.format(comment="").replace(
        '  <link name="sensor_mount_link">', '  <link\n      name="sensor_mount_link">  <!-- urdfcli: noqa: I006 -->'
    )
    assert codes(tmp_path, multiline) == []


def test_a_comment_after_an_element_on_its_line_silences_only_it(tmp_path):
    text = """\
    <robot name="r">
      <link name="a"/> <link name="b" colour="red"/>  <!-- urdfcli: noqa: D -->
      <link name="c" colour="blue"/>
    </robot>
    """
    assert codes(tmp_path, text.replace("<!-- urdfcli: noqa: D -->", ""), config=Config(select=("D", "U")))[0][0] == 2
    found = codes(tmp_path, text, config=Config(select=("D", "U")))
    assert [line for line, _ in found] == [3]


def test_stacked_comments_above_one_element_all_apply(tmp_path):
    text = SENSOR.format(comment="<!-- urdfcli: noqa: I006 -->\n  <!-- urdfcli: noqa: I009 -->")
    found = codes(tmp_path, text, config=Config(select=("I006", "I009", "U")))
    assert found == [(4, "U001")]  # I009 has nothing there; I006 is silenced


def test_unknown_words_are_reported_and_silence_nothing(tmp_path):
    found = codes(tmp_path, SENSOR.format(comment="<!-- urdfcli: noqa: I0066 -->"))
    assert found == [(3, "U002"), (7, "I006")]


def test_a_bare_noqa_that_silences_nothing_is_reported(tmp_path):
    path = tmp_path / "robot.urdf"
    path.write_text('<robot name="r">\n  <!-- urdfcli: noqa -->\n  <link name="base_link"/>\n</robot>\n')
    found = [(d.line, d.code, d.message) for d in lint_file(str(path), Config()).diagnostics]
    assert found == [(2, "U001", "'noqa' silences nothing: no diagnostic on the element at line 3")]


def test_a_comment_on_a_macro_call_silences_what_the_call_made(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "wheel.xacro").write_text(
        '<robot xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
        '  <xacro:macro name="wheel" params="side z">\n'
        '    <link name="${side}"><inertial><mass value="1"/>\n'
        '      <inertia ixx="1" iyy="1" izz="${z}" ixy="0" ixz="0" iyz="0"/></inertial></link>\n'
        '    <joint name="${side}_j" type="fixed"><parent link="base"/><child link="${side}"/></joint>\n'
        "  </xacro:macro>\n"
        "</robot>\n"
    )
    text = """\
    <robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
      <xacro:include filename="wheel.xacro"/>
      <link name="base"/>
      <!-- urdfcli: noqa: I006 -->
      <xacro:wheel side="left" z="5"/>
      <xacro:wheel side="right" z="6"/>
    </robot>
    """
    (tmp_path / "robot.urdf.xacro").write_text(textwrap.dedent(text))
    found = [(d.file, d.line, d.code, d.location.trace[0].line) for d in lint_file("robot.urdf.xacro", Config(select=("I006", "U"))).diagnostics]
    assert found == [("wheel.xacro", 4, "I006", 6)]


def test_select_never_hides_malformed_xml(tmp_path):
    path = tmp_path / "broken.urdf"
    path.write_text('<robot name="r">\n  <link name="a">\n</robot>\n')
    done = run_cli("lint", "--select", "I", "--format", "concise", str(path))
    assert done.returncode == 1
    assert ": X001 error: " in done.stdout.decode()
    path.write_text('<robot name="r"> <!-- urdfcli: noqa-file -->\n  <link name="a">\n</robot>\n')
    done = run_cli("lint", "--format", "concise", str(path))
    assert done.returncode == 1
    assert ": X001 error: " in done.stdout.decode()


def test_a_comment_in_a_library_found_through_find_silences_and_is_not_called_unused(tmp_path):
    """The library is named relative to the working folder by the diagnostics and
    absolutely by the expansion's includes: one file all the same (no U001)."""
    from ros_workspace import edit, make_repository

    root = make_repository(tmp_path / "acme")
    wheel = root / "common" / "urdf" / "wheel.xacro"
    edit(wheel, '<axis xyz="0 0 1"/>', '<axis xyz="0 0 0"/>')
    model = "description/urdf/rover.urdf.xacro"
    done = run_cli("lint", "--format", "concise", model, cwd=root)
    assert ": J007 error: " in done.stdout.decode()
    edit(wheel, '<axis xyz="0 0 0"/>', '<!-- urdfcli: noqa: J007 -->\n      <axis xyz="0 0 0"/>')
    for given in (model, str(root / model)):  # as a path relative to the working folder, and absolute (an editor's)
        done = run_cli("lint", "--format", "concise", given, cwd=root)
        assert ": J007 " not in done.stdout.decode() and ": U001 " not in done.stdout.decode()
