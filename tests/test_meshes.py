"""Mesh rules on real mesh files (tests/support/meshes.py writes them): each finding with
the defect and with its clean counterpart; what `check` says (a stat, no mesh opened)
against what `lint` says; the JSON facts of each mesh; and the inertia rules leaving a
mesh in a wrong unit out."""

from __future__ import annotations

import json
import os
import re

import pytest
from conftest import example_robot_data, lint_file, run_cli
from support.meshes import LFS_POINTER, box, fine, open_box, write

from urdfcli.api import Target, check_target
from urdfcli.options import Options, RuleSet
from urdfcli.session import Session

INERTIAL = '<inertial><mass value="{mass}"/><inertia ixx="{i}" ixy="0" ixz="0" iyy="{i}" iyz="0" izz="{i}"/></inertial>'


def package(root, name: str = "my_robot"):
    """A ROS package folder with a package.xml, its urdf/ and meshes/ folders."""
    (root / "urdf").mkdir(parents=True, exist_ok=True)
    (root / "meshes").mkdir(exist_ok=True)
    (root / "package.xml").write_text(f'<package format="2"><name>{name}</name></package>\n')
    return root


def model(root, links: str, joints: str = "") -> str:
    path = root / "urdf" / "robot.urdf"
    path.write_text(f'<robot name="r">\n{links}\n{joints}\n</robot>\n')
    return str(path)


def mesh(uri: str, scale: str | None = None) -> str:
    return f'<geometry><mesh filename="{uri}"' + (f' scale="{scale}"' if scale else "") + "/></geometry>"


def link(name: str, visual: str = "", collision: str = "", mass: float | None = None, i: float = 0.01) -> str:
    parts = [INERTIAL.format(mass=mass, i=i)] if mass is not None else []
    parts += [f"<visual>{visual}</visual>"] if visual else []
    parts += [f"<collision>{collision}</collision>"] if collision else []
    return f'<link name="{name}">{"".join(parts)}</link>'


def found(path, code: str, rule_set: RuleSet = RuleSet.LINT):
    return [d for d in lint_file(path, rule_set=rule_set).diagnostics if d.code == code]


# -- missing, empty, LFS pointer, truncated: errors, check and lint ---------------------


@pytest.fixture
def robot(tmp_path):
    return package(tmp_path / "my_robot")


def test_a_missing_mesh_is_an_error_in_check_naming_the_file_that_differs_in_case(robot):
    write(robot / "meshes" / "Arm.STL", box())
    path = model(robot, link("arm", mesh("package://my_robot/meshes/arm.stl")))
    [error] = found(path, "D004", RuleSet.CHECK)
    assert error.severity.value == "error"
    assert error.hint.startswith("did you mean 'package://my_robot/meshes/Arm.STL'? file names are case-sensitive on Linux")
    done = run_cli("check", path)
    assert done.returncode == 1 and "D004 error" in done.stderr.decode()
    clean = model(robot, link("arm", mesh("package://my_robot/meshes/Arm.STL")))
    assert found(clean, "D004", RuleSet.CHECK) == [] and run_cli("check", clean).returncode == 0


def test_a_missing_mesh_with_no_file_like_it_has_no_hint_about_case(robot):
    write(robot / "meshes" / "base.stl", box())
    [error] = found(model(robot, link("arm", mesh("package://my_robot/meshes/arm.stl"))), "D004", RuleSet.CHECK)
    assert error.hint is None  # no file differs from it in case: saying file names are case-sensitive would send one looking for one
    assert error.fix is None  # nor a "no fix" line under each missing mesh, saying only that it is missing
    printed = run_cli("lint", model(robot, link("arm", mesh("package://my_robot/meshes/arm.stl")))).stdout.decode()
    assert "D004 error" in printed and "no fix" not in printed


def test_a_missing_mesh_names_another_extension_or_the_meshes_folder(robot):
    write(robot / "meshes" / "arm.dae", box())
    [error] = found(model(robot, link("arm", mesh("package://my_robot/meshes/arm.stl"))), "D004", RuleSet.CHECK)
    assert error.hint == "did you mean 'package://my_robot/meshes/arm.dae'?"
    [error] = found(model(robot, link("arm", mesh("meshes/arm.dae"))), "D004", RuleSet.CHECK)  # relative to urdf/
    assert error.hint == "did you mean '../meshes/arm.dae'?"


def test_a_missing_texture_is_a_warning(robot):
    path = model(robot, '<material name="m"><texture filename="package://my_robot/meshes/skin.png"/></material><link name="a"/>')
    [warning] = found(path, "D004", RuleSet.CHECK)
    assert warning.severity.value == "warning"


@pytest.mark.parametrize("content, said, checked", [(b"", "empty (0 bytes)", True), (LFS_POINTER.encode(), "Git LFS pointer", True)])
def test_an_empty_file_or_an_lfs_pointer_is_an_error_in_check(robot, content, said, checked):
    (robot / "meshes" / "arm.stl").write_bytes(content)
    path = model(robot, link("arm", mesh("package://my_robot/meshes/arm.stl")))
    [error] = found(path, "F001", RuleSet.CHECK)
    assert said in error.message and error.severity.value == "error"
    assert ("git lfs pull" in error.hint) == (said == "Git LFS pointer")
    write(robot / "meshes" / "arm.stl", box())
    assert found(path, "F001", RuleSet.CHECK) == [] and found(path, "F001") == []


def test_check_opens_no_mesh_and_lint_reads_each_once(robot):
    whole = write(robot / "meshes" / "arm.stl", box())
    whole.write_bytes(whole.read_bytes()[:-100])  # truncated: only reading it tells
    path = model(robot, link("arm", mesh("package://my_robot/meshes/arm.stl"), mesh("package://my_robot/meshes/arm.stl"), mass=1.0))
    with Session() as session:
        checked = check_target(Target(path), session.using(Options(RuleSet.CHECK)))
        assert session.meshes.reads == 0 and not [d for d in checked.diagnostics if d.code == "F001"]
        linted = check_target(Target(path), session)
        assert session.meshes.reads == 1  # one file, used twice, read once
        [error] = [d for d in linted.diagnostics if d.code == "F001"]
        assert "binary STL is truncated: its header says 12 triangles (684 bytes), the file has 584 bytes" in error.message
        check_target(Target(path), session)
        assert session.meshes.reads == 1  # the next model reads it no more


def test_a_missing_file_of_this_machine_is_not_called_another_machines(robot, tmp_path):
    """xacro's $(find my_robot) gives this machine's path: the file is missing in the package,
    and package:// names it on any machine (file://$(find ...) in the source is portable
    already); a path in the input's repository is this machine's too; only a path in no
    folder of this machine is another machine's."""
    (tmp_path / ".git").mkdir()  # the repository holding the package
    source = robot / "urdf" / "robot.urdf.xacro"

    def hints(*uris: str) -> list[str]:
        links = "".join(link(f"l{number}", mesh(uri)) for number, uri in enumerate(uris))
        source.write_text(f'<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n{links}\n</robot>\n')
        return [d.hint for d in found(str(source), "D004", RuleSet.CHECK)]

    portable = "; write 'package://my_robot/meshes/{}' for the model to load on other machines too"
    this = "a path of this machine, in package 'my_robot', where the file is missing"
    assert hints("$(find my_robot)/meshes/gone/arm.stl", "$(find my_robot)/meshes/arm.stl") == [
        this + portable.format("gone/arm.stl"),  # its folder is missing too
        this + portable.format("arm.stl"),
    ]
    assert hints("file://$(find my_robot)/meshes/arm.stl", f"file://{robot.resolve()}/meshes/gone/arm.stl") == [
        this, this + portable.format("gone/arm.stl")]
    assert hints(f"{tmp_path}/meshes/arm.stl") == [f"a path of this machine, in {tmp_path}, where the file is missing"]
    assert hints("file:///home/alice/ws/src/my_robot/meshes/arm.stl") == [
        "a path of another machine: put the files in a ROS package and write package://PACKAGE/..."]


def test_a_file_uri_with_a_slash_too_many_names_the_folder_as_the_system_reads_it(robot):
    """file:///$(find my_robot)/... (Doosan's descriptions write it so) expands to
    file:////home/...: resource_retriever opens //home/..., which is /home/...; the missing
    file's folder is said so, not as //home/..."""
    source = robot / "urdf" / "robot.urdf.xacro"
    source.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                      + link("arm", mesh("file:///$(find my_robot)/meshes/gone/arm.stl")) + "\n</robot>\n")
    [error] = found(str(source), "D004", RuleSet.CHECK)
    assert error.message.endswith(f": folder {robot.resolve()}/meshes/gone does not exist"), error.message


# -- paths that work on one machine, or not in rviz ------------------------------------


def test_relative_absolute_and_file_paths_name_the_package_uri(robot):
    target = write(robot / "meshes" / "arm.stl", box())
    for uri, said in [("../meshes/arm.stl", "a relative path"), (str(target), "an absolute path"), (f"file://{target}", "a file:// URI")]:
        [warning] = found(model(robot, link("arm", mesh(uri))), "F002")
        assert said in warning.message and warning.hint == "write package://my_robot/meshes/arm.stl"
    assert found(model(robot, link("arm", mesh("package://my_robot/meshes/arm.stl"))), "F002") == []


def test_a_file_uri_made_with_find_in_a_xacro_source_is_portable(robot):
    """file://$(find my_robot)/... in the xacro: each machine's expansion names its own
    folder, and Gazebo is given the file so on purpose. The URDF it expands to, or a
    file:// path written out, is still flagged."""
    write(robot / "meshes" / "arm.stl", box())
    source = robot / "urdf" / "robot.urdf.xacro"
    source.write_text(
        '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
        + link("arm", mesh("file://$(find my_robot)/meshes/arm.stl")) + "\n</robot>\n"
    )
    assert found(str(source), "F002") == []
    source.write_text(
        '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
        + link("arm", mesh(f"file://{robot.resolve()}/meshes/arm.stl")) + "\n</robot>\n"
    )
    assert len(found(str(source), "F002")) == 1


def test_a_file_outside_any_package_is_told_to_go_in_one(tmp_path):
    write(tmp_path / "meshes" / "arm.stl", box())
    (tmp_path / "urdf").mkdir()
    [warning] = found(model(tmp_path, link("arm", mesh("../meshes/arm.stl"))), "F002")
    assert warning.hint.startswith("put the files in a ROS package")


# -- units ------------------------------------------------------------------------------

# a 0.4 x 0.3 x 0.1 m body of 5 kg and its tensor
BODY = dict(mass=5.0, i=0.05)


def test_a_millimetre_mesh_on_a_5_kg_link_is_named_with_its_scale(robot):
    write(robot / "meshes" / "base.stl", box((0.4, 0.3, 0.1)), scale=1000)
    path = model(robot, link("base", collision=mesh("package://my_robot/meshes/base.stl"), **BODY))
    [warning] = found(path, "F003")
    assert warning.message == "mesh 'base.stl' looks like millimetres: 400 m across on a 5 kg link"
    assert warning.hint == 'add scale="0.001 0.001 0.001"'
    # reported once, as a unit problem: the inertia rules leave its volume out
    assert not [d for d in lint_file(path).diagnostics if d.code.startswith("I") and d.code != "I011"]
    fixed = model(robot, link("base", collision=mesh("package://my_robot/meshes/base.stl", "0.001 0.001 0.001"), **BODY))
    assert found(fixed, "F003") == []


def test_the_same_mesh_as_a_visual_is_reported_too(robot):
    write(robot / "meshes" / "base.stl", box((0.4, 0.3, 0.1)), scale=1000)
    [warning] = found(model(robot, link("base", visual=mesh("package://my_robot/meshes/base.stl"), **BODY)), "F003")
    assert "millimetres" in warning.message


@pytest.mark.parametrize("factor, unit", [(100, "centimetres"), (25.4, "inches")])
def test_centimetres_and_inches_are_told_apart(robot, factor, unit):
    # a 0.4 m arm of 2 kg hung 5 cm from its base, its collision a box of the right size:
    # its visual mesh, exported in another unit, is too large for each, and fits all once converted
    write(robot / "meshes" / "arm.stl", box((0.1, 0.1, 0.4)), scale=factor)
    arm = link("arm", visual=mesh("package://my_robot/meshes/arm.stl"), collision='<geometry><box size="0.1 0.1 0.4"/></geometry>', mass=2.0, i=0.03)
    joints = '<joint name="shoulder" type="fixed"><parent link="base"/><child link="arm"/><origin xyz="0 0 0.05"/></joint>'
    [warning] = found(model(robot, link("base") + arm, joints), "F003")
    assert f"looks like {unit}" in warning.message
    assert warning.hint == f'add scale="{1 / factor:.6g} {1 / factor:.6g} {1 / factor:.6g}"'


def test_a_joint_that_finds_the_mesh_plausible_keeps_it_silent(robot):
    write(robot / "meshes" / "arm.stl", box((0.1, 0.1, 0.4)), scale=25.4)
    links = link("arm", visual=mesh("package://my_robot/meshes/arm.stl"), mass=2.0, i=0.03) + link("tool")
    joints = '<joint name="wrist" type="fixed"><parent link="arm"/><child link="tool"/><origin xyz="0 0 0.35"/></joint>'
    assert found(model(robot, links, joints), "F003") == []  # 10 m of mesh, 0.35 m to the child: within the band (up to 50 times)


def test_a_mesh_in_metres_is_never_reported(robot):
    write(robot / "meshes" / "crane.stl", box((20.0, 0.5, 0.5)))  # a crane boom: large, and in metres
    links = link("boom", collision=mesh("package://my_robot/meshes/crane.stl"), mass=800.0, i=27000.0) + link("hook")
    joints = '<joint name="trolley" type="fixed"><parent link="boom"/><child link="hook"/><origin xyz="19 0 0"/></joint>'
    assert found(model(robot, links, joints), "F003") == []


def test_conflicting_evidence_says_nothing(robot):
    write(robot / "meshes" / "base.stl", box((0.4, 0.3, 0.1)), scale=1000)
    # mass says millimetres; a primitive of the same size on the link says metres
    path = model(robot, link("base", visual=mesh("package://my_robot/meshes/base.stl"), collision='<geometry><box size="400 300 100"/></geometry>', **BODY))
    assert found(path, "F003") == []


def test_a_collada_unit_is_applied_before_judging(robot):
    write(robot / "meshes" / "declared.dae", box((0.4, 0.3, 0.1)), scale=1000, unit=0.001)
    assert found(model(robot, link("base", visual=mesh("package://my_robot/meshes/declared.dae"), **BODY)), "F003") == []
    write(robot / "meshes" / "undeclared.dae", box((0.4, 0.3, 0.1)), scale=1000, unit=1.0)
    [warning] = found(model(robot, link("base", visual=mesh("package://my_robot/meshes/undeclared.dae"), **BODY)), "F003")
    assert "millimetres" in warning.message


def test_a_scale_applied_to_a_mesh_already_in_metres_is_too_small(robot):
    write(robot / "meshes" / "base.stl", box((0.4, 0.3, 0.1)))
    [warning] = found(model(robot, link("base", visual=mesh("package://my_robot/meshes/base.stl", "0.001 0.001 0.001"), **BODY)), "F003")
    assert warning.message == "mesh 'base.stl' is 1000 times too small: 0.0004 m across on a 5 kg link"
    assert warning.hint.endswith('make its scale "1 1 1"')
    write(robot / "meshes" / "declared.dae", box((0.4, 0.3, 0.1)), scale=1000, unit=0.001)  # the unit and a scale: converted twice
    [warning] = found(model(robot, link("base", visual=mesh("package://my_robot/meshes/declared.dae", "0.001 0.001 0.001"), **BODY)), "F003")
    assert "too small" in warning.message


def test_inertia_suggest_does_not_use_a_mis_scaled_mesh(robot):
    write(robot / "meshes" / "base.stl", box((0.4, 0.3, 0.1)), scale=1000)
    path = model(robot, link("base", collision=mesh("package://my_robot/meshes/base.stl"), mass=5.0, i=1.0))  # the identity: I007
    done = run_cli("inertia", "--suggest", path)
    out = done.stdout.decode()
    assert "no suggestion: a collision mesh is in a wrong unit (F003)" in out and "104167" not in out


# -- collision against visual -------------------------------------------------------------


def test_a_collision_far_larger_than_its_visual(robot):
    path = model(robot, link("arm", '<geometry><box size="0.1 0.1 0.4"/></geometry>', '<geometry><box size="0.4 0.4 1.6"/></geometry>'))
    [warning] = found(path, "F004")
    assert warning.message == "collision of link 'arm' is 4 times larger than its visual: 1.7 against 0.424 m across"
    simplified = model(robot, link("arm", '<geometry><box size="0.1 0.1 0.4"/></geometry>', '<geometry><cylinder radius="0.08" length="0.45"/></geometry>'))
    assert found(simplified, "F004") == []


def test_a_collision_on_a_fixed_child_counts_for_the_body(robot):
    links = link("arm", '<geometry><box size="0.1 0.1 0.4"/></geometry>', '<origin xyz="0 0 -0.1"/><geometry><box size="0.1 0.1 0.2"/></geometry>')
    links += link("arm_rest", collision='<geometry><box size="0.1 0.1 0.2"/></geometry>')
    joint = '<joint name="j" type="fixed"><parent link="arm"/><child link="arm_rest"/><origin xyz="0 0 0.1"/></joint>'
    assert found(model(robot, links, joint), "F004") == []
    alone = model(robot, link("arm", '<geometry><box size="0.1 0.1 0.4"/></geometry>', '<origin xyz="0 0 -0.15"/><geometry><box size="0.02 0.05 0.05"/></geometry>'))
    [warning] = found(alone, "F004")
    assert "times smaller than its visual" in warning.message


def test_a_collision_displaced_from_its_visual(robot):
    write(robot / "meshes" / "nub.stl", box((0.05, 0.05, 0.15)))
    uri = "package://my_robot/meshes/nub.stl"
    # alex_nub_hands.urdf in example-robot-data: the rotation written as a translation
    wrong = model(robot, link("nub", f'<origin rpy="0 1.57 0"/>{mesh(uri)}', f'<origin xyz="0 1.57 0"/>{mesh(uri)}'))
    [warning] = found(wrong, "F004")
    assert warning.message.startswith("collision of link 'nub' is 1.57 m from its visual, farther than either is large")
    right = model(robot, link("nub", f'<origin rpy="0 1.57 0"/>{mesh(uri)}', f'<origin rpy="0 1.57 0"/>{mesh(uri)}'))
    assert found(right, "F004") == []


def test_placeholder_dots_are_left_alone(robot):
    # baxter.urdf: a 1 mm sphere keeps Gazebo from dropping a link shown by a large mesh
    path = model(robot, link("head", '<geometry><box size="0.3 0.2 0.2"/></geometry>', '<geometry><sphere radius="0.001"/></geometry>'))
    assert found(path, "F004") == []


# -- heavy and open collision meshes (info) ----------------------------------------------


def test_a_heavy_visual_mesh_reused_as_collision(robot):
    write(robot / "meshes" / "fine.stl", fine())
    write(robot / "meshes" / "coarse.stl", fine(subdivisions=2))
    fine_uri, coarse_uri = "package://my_robot/meshes/fine.stl", "package://my_robot/meshes/coarse.stl"
    [note] = found(model(robot, link("arm", mesh(fine_uri), mesh(fine_uri))), "F005")
    assert note.severity.value == "info" and "20,480 triangles" in note.message
    assert found(model(robot, link("arm", mesh(fine_uri), mesh(coarse_uri))), "F005") == []
    assert found(model(robot, link("arm", mesh(coarse_uri), mesh(coarse_uri))), "F005") == []  # 320 triangles


def test_an_open_collision_mesh_where_its_volume_is_needed(robot):
    write(robot / "meshes" / "open.stl", open_box())
    uri = "package://my_robot/meshes/open.stl"
    [note] = found(model(robot, link("arm", collision=mesh(uri), mass=2.0)), "F006")
    assert note.severity.value == "info" and "not watertight" in note.message
    assert found(model(robot, link("arm", collision=mesh(uri), mass=0.0, i=0.0)), "F006") == []  # massless: no volume needed
    assert found(model(robot, link("arm", visual=mesh(uri), mass=2.0)), "F006") == []  # a visual
    write(robot / "meshes" / "open.stl", box())
    assert found(model(robot, link("arm", collision=mesh(uri), mass=2.0)), "F006") == []


def test_the_open_collision_meshes_of_a_model_are_one_note(robot):
    write(robot / "meshes" / "open.stl", open_box())
    write(robot / "meshes" / "open_too.stl", open_box((0.1, 0.1, 0.3)))
    links = link("arm", collision=mesh("package://my_robot/meshes/open.stl"), mass=2.0) + link(
        "hand", collision=mesh("package://my_robot/meshes/open_too.stl"), mass=1.0
    )
    joint = '<joint name="j" type="fixed"><parent link="arm"/><child link="hand"/></joint>'
    [note] = found(model(robot, links, joint), "F006")
    assert note.message.startswith("collision mesh 'open.stl' and 1 other collision mesh are not watertight"), note.message
    assert note.subjects == ("arm", "hand")


# -- what lint's JSON tells of each mesh -------------------------------------------------


def test_lint_json_names_format_triangles_unit_and_size(robot):
    write(robot / "meshes" / "base.dae", box((0.4, 0.3, 0.1)), scale=1000, unit=0.001)
    write(robot / "meshes" / "arm.stl", box((0.1, 0.1, 0.4)), scale=1000)
    links = link("base", visual=mesh("package://my_robot/meshes/base.dae"), **BODY)
    links += link("arm", visual=mesh("package://my_robot/meshes/arm.stl"), collision=mesh("package://my_robot/meshes/arm.stl"), mass=2.0, i=0.03)
    joint = '<joint name="j" type="fixed"><parent link="base"/><child link="arm"/><origin xyz="0 0 0.1"/></joint>'
    path = model(robot, links, joint)
    other = robot / "urdf" / "other.urdf"
    other.write_text('<robot name="o"><link name="a"/></robot>')
    for jobs in ("1", "2"):  # results sent back from other processes keep their meshes
        done = run_cli("lint", "--format", "json", "--jobs", jobs, path, str(other))
        facts = json.loads(done.stdout)["files"][0]["meshes"]
        base, arm = facts
        assert base["format"] == "dae" and base["triangles"] == 12 and base["unit"] == 0.001 and base["size"] == [0.4, 0.3, 0.1]
        assert base["watertight"] is True and base["uses"] == [{"link": "base", "role": "visual", "scale": [1.0, 1.0, 1.0], "looks_like": None}]
        assert arm["format"] == "stl" and arm["unit"] is None and arm["size"] == [100.0, 100.0, 400.0]
        assert [use["looks_like"] for use in arm["uses"]] == ["millimetres", "millimetres"]
    checked = json.loads(run_cli("check", "--format", "json", path).stdout)["files"][0]
    assert "meshes" not in checked  # check reads no mesh


# -- on the published models: none in metres reported, millimetres found -----------------


def as_if_in_millimetres(text: str) -> str:
    """A URDF whose every mesh is a thousand times larger, as if exported in millimetres
    and used without a scale: each ``<mesh>`` given (or its scale multiplied by) 1000."""

    def thousandfold(match: re.Match) -> str:
        attributes = match.group(1)
        scale = re.search(r'scale\s*=\s*"([^"]*)"', attributes)
        if scale is None:
            return f'<mesh{attributes} scale="1000 1000 1000"/>'
        values = " ".join(str(float(v) * 1000) for v in scale.group(1).split())
        return f"<mesh{attributes[:scale.start()]}scale=\"{values}\"{attributes[scale.end():]}/>"

    return re.sub(r"<mesh\b([^>]*?)/>", thousandfold, text)


def test_published_meshes_read_in_millimetres_are_found_and_named(tmp_path):
    package = example_robot_data()
    models = sorted((package / "robots").rglob("*.urdf"))[::3]  # a third of the 69, every mesh of each
    written = []
    for index, path in enumerate(models):
        written.append(tmp_path / f"{index}_{path.name}")
        written[-1].write_text(as_if_in_millimetres(path.read_text()))
    done = run_cli("lint", "--isolated", "--format", "json", "-P", f"example-robot-data={package}", *map(str, written))
    uses = [use for file in json.loads(done.stdout)["files"] for mesh in file.get("meshes", []) if mesh["size"] for use in mesh["uses"]]
    named = [use["looks_like"] for use in uses if use["looks_like"]]
    assert len(uses) > 300
    assert len(named) >= 0.9 * len(uses)  # measured on all 69 models: 95 %
    assert named.count("millimetres") >= 0.98 * len(named)  # measured: 99.4 %


def test_a_mesh_that_is_a_pipe_is_not_waited_for(robot):
    os.mkfifo(robot / "meshes" / "arm.stl")  # reading it would wait for a writer for ever
    path = model(robot, link("arm", mesh("package://my_robot/meshes/arm.stl"), mesh("package://my_robot/meshes/arm.stl"), mass=1.0))
    done = run_cli("lint", "--format", "json", path)
    assert done.returncode in (0, 1) and json.loads(done.stdout)["files"][0]["meshes"][0]["triangles"] is None
