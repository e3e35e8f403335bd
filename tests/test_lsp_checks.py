"""What the editor server's checks do per edit: each model whose sources changed
expanded once, whatever files are open; nothing expanded for what did not change.

The checks are driven as the server drives them (the edited file first, then the
open files whose last check read it), and xacro's expansions counted where they
reach the session's worker."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from urdfcli.lsp.engine import Checker
from urdfcli.read.xacro import Expander

XACRO_NS = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'
LIBRARY = f"""<?xml version="1.0"?>
<robot {XACRO_NS}>
  <xacro:property name="arm_mass" value="2.0"/>
  <xacro:macro name="arm" params="prefix parent">
    <link name="${{prefix}}upper">
      <inertial><mass value="${{arm_mass}}"/><inertia ixx="0.03" ixy="0" ixz="0" iyy="0.03" iyz="0" izz="0.0025"/></inertial>
      <collision><geometry><cylinder radius="0.05" length="0.4"/></geometry></collision>
    </link>
    <joint name="${{prefix}}joint" type="fixed"><parent link="${{parent}}"/><child link="${{prefix}}upper"/></joint>
  </xacro:macro>
</robot>
"""


def model(index: int) -> str:
    return (f'<?xml version="1.0"?>\n<robot name="robot_{index}" {XACRO_NS}>\n'
            '  <xacro:include filename="$(find arms)/urdf/arm_macro.xacro"/>\n  <link name="world"/>\n'
            '  <xacro:arm prefix="left_" parent="world"/>\n</robot>\n')


@pytest.fixture
def workspace(tmp_path: Path) -> Path:
    """A repository: a package whose macro library three models include, and a model of its own that includes nothing."""
    (tmp_path / ".git").mkdir()  # (the repository's models are those a library is checked through)
    (tmp_path / "urdf").mkdir()
    (tmp_path / "package.xml").write_text('<?xml version="1.0"?>\n<package format="3"><name>arms</name><version>0.1.0</version>'
                                          '<description>arms</description><maintainer email="a@b.c">a</maintainer><license>BSD</license></package>\n')
    (tmp_path / "urdf" / "arm_macro.xacro").write_text(LIBRARY)
    for index in range(3):
        (tmp_path / "urdf" / f"robot_{index}.urdf.xacro").write_text(model(index))
    (tmp_path / "urdf" / "alone.urdf.xacro").write_text(f'<robot name="alone" {XACRO_NS}>\n  <xacro:property name="m" value="1"/>\n  <link name="base"/>\n</robot>\n')
    return tmp_path


class Counted:
    """The expansions that reached the worker, by file."""

    def __init__(self, monkeypatch) -> None:
        self.files: list[str] = []
        expand = Expander.expand

        def counted(expander, data, file, *args, **kwargs):
            self.files.append(Path(file).name if file else "")
            return expand(expander, data, file, *args, **kwargs)

        monkeypatch.setattr(Expander, "expand", counted)

    def taken(self) -> list[str]:
        found, self.files = sorted(self.files), []
        return found


def check_after_edit(checker: Checker, edited: str, texts: dict[str, str]) -> None:
    """As the server checks after an edit of ``edited``: that file first, then the open files whose last check read it."""
    assert checker.check(edited, texts) is not None
    for path in sorted(texts):
        if path != edited and _reads(checker, path, edited):
            assert checker.check(path, texts) is not None


def _reads(checker: Checker, path: str, edited: str) -> bool:
    run = checker.runs.get(path)
    return run is None or any(edited == str(Path(f).resolve()) for model in run.models for f in (model.path, *model.includes))


def test_an_edit_expands_each_model_whose_sources_changed_once(workspace, monkeypatch):
    monkeypatch.chdir(workspace)  # the server's working folder: a library's models are found by relative names
    library = str(workspace / "urdf" / "arm_macro.xacro")
    first, alone = (str(workspace / "urdf" / name) for name in ("robot_0.urdf.xacro", "alone.urdf.xacro"))
    texts = {path: Path(path).read_text() for path in (library, first, alone)}
    checker = Checker()
    try:
        for path in texts:  # opened
            checker.check(path, texts)
        counted = Counted(monkeypatch)

        # the library: the models its check goes through, each once (the open one's own check expands nothing again)
        texts[library] = texts[library].replace('value="2.0"', 'value="2.5"')
        check_after_edit(checker, library, texts)
        expanded = counted.taken()
        assert "robot_0.urdf.xacro" in expanded and len(expanded) == len(set(expanded)) and "alone.urdf.xacro" not in expanded, expanded

        # the open model: itself, once; the library's check goes through it and the two unchanged models
        texts[first] = texts[first].replace('prefix="left_"', 'prefix="right_"')
        check_after_edit(checker, first, texts)
        assert checker.check(library, texts) is not None
        assert counted.taken() == ["robot_0.urdf.xacro"]

        # a model that includes nothing: itself only
        texts[alone] = texts[alone].replace('value="1"', 'value="2"')
        check_after_edit(checker, alone, texts)
        assert checker.check(library, texts) is not None
        assert counted.taken() == ["alone.urdf.xacro"]

        # the library's text back as it was on disk, then the file changed on disk: expanded again
        (workspace / "urdf" / "arm_macro.xacro").write_text(LIBRARY.replace('value="2.0"', 'value="3.0"'))
        del texts[library]
        checker.sync(texts)
        assert checker.check(first, texts) is not None
        assert counted.taken() == ["robot_0.urdf.xacro"]
        diagnostics = checker.check(first, texts)
        assert diagnostics is not None and counted.taken() == []  # nothing changed since
    finally:
        checker.close()


def test_a_librarys_check_names_each_model_as_the_models_own_check_does(workspace, monkeypatch):
    # (a library's check finds its models by names relative to the working folder; the server
    # publishes a model's list without waiting for a library's check only when it knows the
    # model's own check went through the same models)
    monkeypatch.chdir(workspace)
    library, first = str(workspace / "urdf" / "arm_macro.xacro"), str(workspace / "urdf" / "robot_0.urdf.xacro")
    texts = {path: Path(path).read_text() for path in (library, first)}
    checker = Checker()
    try:
        through = checker.check(library, texts)
        own = checker.check(first, texts)
        assert through.library and not own.library, through.marks
        assert set(own.models) == {(first, ())} and set(own.models) < set(through.models), (own.models, through.models)
        assert first in through.models[(first, ())] and library in through.models[(first, ())]  # what that model read
    finally:
        checker.close()


def checked_with_library(tmp_path: Path, library: str, model: str, name: str = "arm.xacro") -> tuple:
    """A repository holding a macro library (``name``) and model.urdf.xacro including it, both
    open in the editor: the model's check, and the two paths."""
    (tmp_path / ".git").mkdir()
    files = {tmp_path / name: library, tmp_path / "model.urdf.xacro": model}
    for path, text in files.items():
        path.write_text(text)
    model_path = str(tmp_path / "model.urdf.xacro")
    return Checker().check(model_path, {str(path): text for path, text in files.items()}), model_path, str(tmp_path / name)


def test_a_mistake_shown_at_an_outer_call_names_the_macro_that_wrote_it(tmp_path):
    """A mesh path an inner macro builds from the outer macro's parameter, wrong at the
    model's call of the outer macro: shown there, saying it was written in macro 'inner'
    (where the line is), not 'outer' (the macro called there)."""
    checked, model, _ = checked_with_library(tmp_path, f"""<robot {XACRO_NS}>
  <xacro:macro name="inner" params="name">
    <link name="${{name}}">
      <visual><geometry><mesh filename="file://{tmp_path}/meshes/${{name}}.stl"/></geometry></visual>
    </link>
  </xacro:macro>
  <xacro:macro name="outer" params="part">
    <xacro:inner name="${{part}}"/>
  </xacro:macro>
</robot>
""", f'<robot name="r" {XACRO_NS}>\n  <xacro:include filename="lib.xacro"/>\n  <xacro:outer part="base"/>\n</robot>\n', "lib.xacro")
    [at_call] = [m for m in checked.marks[model] if m.diagnostic.code == "D004"]
    assert at_call.place.start.line + 1 == 3 and "(in macro 'inner', lib.xacro:4)" in at_call.message


def test_a_mistake_of_the_macro_body_is_not_shown_at_a_call_that_only_named_its_element(tmp_path):
    """A joint named ``${prefix}elbow`` without <limit>: the call's prefix named it, the body
    forgot the limit, so the model's call shows nothing (the library does). A parent the call
    passes that does not exist, and a prefix that makes a link twice, are the call's: shown there."""
    library = f"""<robot {XACRO_NS}>
  <xacro:macro name="arm" params="prefix parent">
    <link name="${{prefix}}upper"/>
    <joint name="${{prefix}}elbow" type="revolute">
      <parent link="${{parent}}"/><child link="${{prefix}}upper"/>
    </joint>
  </xacro:macro>
</robot>
"""
    model = f"""<robot name="r" {XACRO_NS}>
  <xacro:include filename="arm.xacro"/>
  <link name="world"/>
  <xacro:arm prefix="left_" parent="world"/>
  <xacro:arm prefix="right_" parent="wrld"/>
  <xacro:arm prefix="right_" parent="world"/>
</robot>
"""
    checked, model, library = checked_with_library(tmp_path, library, model)
    at_calls = sorted((m.place.start.line + 1, m.diagnostic.code) for m in checked.marks[model] if m.diagnostic.code[0] in "JN")
    assert at_calls == [(5, "J005"), (6, "N004"), (6, "N005")], at_calls
    assert {m.diagnostic.code for m in checked.marks[library]} >= {"J003", "J005", "N004", "N005"}


def test_a_file_opened_at_its_symlink_in_the_install_space_gets_its_diagnostics(tmp_path, monkeypatch):
    """After `colcon build --symlink-install`, a library opened at install/.../share/PKG/urdf
    (where $(find) and go-to-definition in another tool lead) is a link to its source in src/,
    where diagnostics are placed: the buffer the user has open shows them."""
    from ros_workspace import install_package, make_colcon_workspace
    from test_workspace import CASTER, WHEELED

    repo_a, repo_b = make_colcon_workspace(tmp_path)
    wheels = repo_b / "wheels"
    (wheels / "description" / "urdf").mkdir(parents=True)
    (wheels / "description" / "urdf" / "caster.xacro").write_text(textwrap.dedent(CASTER))
    share = install_package(tmp_path / "ws", wheels, "acme_wheels", {"urdf": "urdf", "description/urdf": "urdf"})
    model = repo_a / "robot" / "urdf" / "robot.urdf.xacro"
    model.parent.mkdir(parents=True)
    model.write_text(textwrap.dedent(WHEELED))
    monkeypatch.chdir(tmp_path / "ws")
    opened = str(share / "urdf" / "caster.xacro")
    checked = Checker().check(opened, {opened: Path(opened).read_text(), str(model): model.read_text()})
    assert "V009" in [m.diagnostic.code for m in checked.marks[opened]], checked.marks
    assert not [file for file in checked.marks if "/src/" in file and file.endswith("caster.xacro")], list(checked.marks)
    # its unsaved text is what the check reads ($(find) reads the source the link points to)
    checker = Checker()
    unsaved = Path(opened).read_text().replace('rpy="0 0 90"', 'rpy="0 0 1.5708"')
    checked = checker.check(opened, {opened: unsaved, str(model): model.read_text()})
    assert "V009" not in [m.diagnostic.code for m in checked.marks.get(opened, [])], checked.marks


def test_a_mistake_typed_at_a_call_of_a_macro_whose_params_span_lines_is_shown_there(tmp_path):
    """xArm's other_geometry writes its params over several lines: the third and later were
    lost to the editor, and a negative mass passed at the call showed only in the library."""
    library = f"""<robot {XACRO_NS}>
  <xacro:macro name="part" params="prefix:=''
      parent:=base_link
      mass:=0.1">
    <link name="${{prefix}}part"><inertial><mass value="${{mass}}"/><inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial></link>
    <joint name="${{prefix}}joint" type="fixed"><parent link="${{parent}}"/><child link="${{prefix}}part"/></joint>
  </xacro:macro>
</robot>
"""
    model = f'<robot name="r" {XACRO_NS}>\n  <xacro:include filename="part.xacro"/>\n  <link name="base_link"/>\n  <xacro:part mass="-0.3"/>\n</robot>\n'
    checked, model, library = checked_with_library(tmp_path, library, model, "part.xacro")
    assert [(m.place.start.line + 1, m.diagnostic.code) for m in checked.marks[model] if m.diagnostic.code == "I001"] == [(4, "I001")]


def test_a_missing_name_whose_literal_text_no_name_has_is_the_macro_bodys(tmp_path):
    """Motoman's arm_macro: <parent link="${prefix}link_2_x"/> in the body names a link no
    call makes, whatever its prefix: the body's text is wrong, shown in the library only.
    A flange named from the call's arm ("lft" beside the model's left_flange) is the call's."""
    library = f"""<robot {XACRO_NS}>
  <xacro:macro name="arm" params="prefix">
    <link name="${{prefix}}link_1"/>
    <link name="${{prefix}}link_2"/>
    <joint name="${{prefix}}joint_2" type="fixed">
      <parent link="${{prefix}}link_1x"/><child link="${{prefix}}link_2"/>
    </joint>
  </xacro:macro>
  <xacro:macro name="tool" params="arm">
    <link name="${{arm}}_tool"/>
    <joint name="${{arm}}_tool_joint" type="fixed"><parent link="${{arm}}_link_2"/><child link="${{arm}}_tool"/></joint>
  </xacro:macro>
</robot>
"""
    model = f"""<robot name="r" {XACRO_NS}>
  <xacro:include filename="arm.xacro"/>
  <link name="world"/>
  <xacro:arm prefix="left_"/>
  <xacro:tool arm="lft"/>
</robot>
"""
    checked, model, library = checked_with_library(tmp_path, library, model)
    at_calls = sorted((m.place.start.line + 1, m.diagnostic.code, m.diagnostic.message.split("'")[1]) for m in checked.marks[model] if m.diagnostic.code == "J005")
    assert at_calls == [(5, "J005", "lft_link_2")], at_calls
    assert {m.diagnostic.message.split("'")[1] for m in checked.marks[library] if m.diagnostic.code == "J005"} == {"left_link_1x", "lft_link_2"}
