"""Libraries and models in real repository layouts: how files are classified, which
models a library is checked through, and $(find) across a colcon workspace."""

from __future__ import annotations

import json
import re
import shutil
import textwrap
from pathlib import Path

import pytest
from conftest import run_cli
from ros_workspace import INERTIA, WHEEL, XACRO, edit, install_package, line_of, make_colcon_workspace, make_repository, package_xml

from urdfcli.api import configured
from urdfcli.options import Options
from urdfcli.project.workspace import Index, plan, resolve_include, workspace_file
from urdfcli.read.files import SourceFiles
from urdfcli.read.packages import PackageIndex, PackageResolver
from urdfcli.session import Session


def read_source(path):
    """What reading a file (not expanding it) tells."""
    return workspace_file(path, SourceFiles().get(path))


def write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(textwrap.dedent(text))
    return path


def check_json(*args, cwd):
    done = run_cli("check", "--format", "json", *args, cwd=cwd)
    return done, json.loads(done.stdout or b"null")


@pytest.mark.parametrize(
    ("body", "kind"),
    [
        ('<xacro:macro name="m" params=""><link name="a"/></xacro:macro>', "library"),
        ('<xacro:property name="r" value="1"/><material name="grey"><color rgba="1 1 1 1"/></material>', "library"),
        ('<xacro:include filename="other.xacro"/>', "library"),  # an include that leads nowhere known
        ('<gazebo reference="a"><xacro:sensor_plugin/></gazebo>', "library"),  # a call inside a Gazebo block makes no link
        ('<link name="a"/>', "model"),
        ('<xacro:if value="true"><joint name="j" type="fixed"/></xacro:if>', "model"),
        ('<xacro:macro name="m" params=""/><xacro:m/>', "model"),  # calls a macro at its top level
        ('<xacro:insert_block name="body"/>', "model"),
    ],
)
def test_a_file_is_a_library_when_it_makes_nothing_outside_its_macros(tmp_path, body, kind):
    path = write(tmp_path / "file.xacro", f"<robot {XACRO}>{body}</robot>")
    assert read_source(path).kind == kind


def test_plain_urdf_and_unreadable_files_are_models(tmp_path):
    assert read_source(write(tmp_path / "empty.urdf", '<robot name="r"/>')).kind == "model"
    assert read_source(write(tmp_path / "broken.xacro", f"<robot {XACRO}><xacro:macro")).kind == "model"


def test_a_file_assembled_from_included_models_is_a_model(tmp_path):
    write(tmp_path / "base.urdf.xacro", f'<robot {XACRO}><link name="base_link"/></robot>')
    car = write(tmp_path / "car.urdf.xacro", f'<robot name="car" {XACRO}><xacro:include filename="base.urdf.xacro"/></robot>')
    assert read_source(car).kind == "library"  # by itself
    assert Index().kind(car.resolve()) == "model"  # through what it includes


def test_includes_resolve_find_arg_defaults_properties_and_dirname(tmp_path):
    package = tmp_path / "repo" / "parts"
    write(package / "package.xml", package_xml("acme_parts"))
    source = read_source(
        write(
            package / "urdf" / "robot.urdf.xacro",
            f"""\
            <robot name="r" {XACRO}>
              <xacro:arg name="kind" default="wheel"/>
              <xacro:property name="folder" value="$(find acme_parts)/urdf"/>
              <link name="a"/>
              <xacro:include filename="$(find acme_parts)/urdf/inertia.xacro"/>
              <xacro:include filename="${{folder}}/$(arg kind).xacro"/>
              <xacro:include filename="$(dirname)/sensors/*.xacro"/>
              <xacro:include filename="$(find nowhere)/urdf/gripper.xacro"/>
              <xacro:include filename="${{python.computed()}}"/>
              <xacro:macro name="arm" params="side">
                <xacro:include filename="$(find acme_parts)/urdf/${{side}}_arm.xacro"/>
              </xacro:macro>
            </robot>
            """,
        )
    )
    find = PackageResolver((), source.path).find
    urdf = (package / "urdf").resolve()
    kinds = [resolve_include(text, source, find) for text in source.includes]
    assert [(i.kind, i.value) for i in kinds] == [
        ("path", str(urdf / "inertia.xacro")),
        ("path", str(urdf / "wheel.xacro")),
        ("glob", str(urdf / "sensors" / "*.xacro")),
        # a package not found here, or a name computed whole: the include may be any file, so it is none
        ("unknown", "$(find nowhere)/urdf/gripper.xacro"),
        ("unknown", "${python.computed()}"),
        # a name computed from a macro parameter: the files of that folder whose name fits
        ("pattern", str(urdf / "*_arm.xacro")),
    ]
    assert not kinds[3].may_be(urdf / "gripper.xacro") and not kinds[4].may_be(urdf / "inertia.xacro")
    assert kinds[5].may_be(urdf / "left_arm.xacro") and not kinds[5].may_be(urdf / "wheel.xacro")
    assert resolve_include(source.includes[1], source, find, {"kind": "caster"}).value == str(urdf / "caster.xacro")


@pytest.fixture
def repository(tmp_path):
    root = make_repository(tmp_path / "acme_robots")
    (root / ".git").mkdir()
    return root


def test_a_library_is_checked_through_every_model_that_includes_it(repository):
    done, report = check_json("common/urdf/wheel.xacro", "common/urdf/inertia.xacro", cwd=repository)
    assert done.returncode == 0, done.stderr.decode()
    through = [f["checked_through"] for f in report["files"]]
    models = ["description/urdf/arm.urdf.xacro [arm_type:=small]", "description/urdf/arm.urdf.xacro [arm_type:=large]", "description/urdf/rover.urdf.xacro"]
    assert through == [models, models]  # inertia.xacro is reached through wheel.xacro
    assert all(f["diagnostics"] == [] for f in report["files"])


def test_a_mistake_in_a_macro_is_reported_once_in_the_library(repository):
    wheel = repository / "common/urdf/wheel.xacro"
    edit(wheel, '<parent link="${parent}"/>', '<parent link="${parent}_mount"/>')
    done, report = check_json("common/urdf/wheel.xacro", cwd=repository)
    assert done.returncode == 1
    [file] = report["files"]
    j005 = [d for d in file["diagnostics"] if d["code"] == "J005"]
    # three models (two argument sets of one, and another) and three calls: one diagnostic
    assert [(d["path"], d["line"]) for d in j005] == [("common/urdf/wheel.xacro", line_of(wheel, "_mount"))]
    assert all(d["path"] == "common/urdf/wheel.xacro" for d in file["diagnostics"])
    text = run_cli("check", "common/urdf/wheel.xacro", cwd=repository).stderr.decode()
    assert "common/urdf/wheel.xacro: xacro library, checked through description/urdf/arm.urdf.xacro [arm_type:=small]" in text
    assert "R002" not in text and "R004" not in text


def test_a_model_given_too_reports_the_library_mistake_once(repository):
    wheel = repository / "common/urdf/wheel.xacro"
    edit(wheel, 'radius="${radius}"', 'radius="${wheel_radius}"')
    done, report = check_json("description/urdf/rover.urdf.xacro", "common/urdf/wheel.xacro", cwd=repository)
    assert done.returncode == 1
    located = [(f["path"], d["code"], d["path"], d["line"]) for f in report["files"] for d in f["diagnostics"]]
    assert located == [("description/urdf/rover.urdf.xacro", "X003", "common/urdf/wheel.xacro", line_of(wheel, "wheel_radius"))]


def test_a_changed_interface_breaks_the_model_and_fails_the_library(repository):
    edit(repository / "common/urdf/wheel.xacro", 'params="prefix parent radius *origin"', 'params="prefix parent diameter *origin"')
    done = run_cli("check", "common/urdf/wheel.xacro", cwd=repository)
    assert done.returncode == 1
    assert "X003 error" in done.stderr.decode()


def test_the_models_including_a_deleted_file_are_planned_as_if_given(repository, monkeypatch):
    """A file a commit deletes (pre-commit passes none): the models that include it, directly
    or through another file, are run as if given, each once, with their argument sets; a model
    given too is run once; the deletion of a file no model includes runs nothing."""
    monkeypatch.chdir(repository)
    rover, arm = "description/urdf/rover.urdf.xacro", "description/urdf/arm.urdf.xacro"
    inertia, sensor = repository / "common/urdf/inertia.xacro", repository / "common/urdf/sensor.xacro"
    inertia.unlink()  # wheel.xacro includes it, and both models include wheel.xacro
    sensor.unlink()
    with Session(Options()) as session:
        def planned(paths, deleted):
            entries = plan(paths, configured(session), packages=session.packages, files=session.files, deleted=tuple(map(str, deleted)))
            return [(entry.path, [dict(target.arguments) for target in entry.targets], entry.library) for entry in entries]

        assert planned([], [inertia]) == [(arm, [{"arm_type": "small"}, {"arm_type": "large"}], False), (rover, [{}], False)]
        assert planned([rover], [inertia, repository / "common/urdf/wheel.xacro"]) == [(rover, [{}], False), (arm, [{"arm_type": "small"}, {"arm_type": "large"}], False)]
        assert planned([], [sensor]) == []


def test_an_unused_library_is_expanded_alone_and_named_once(repository):
    done = run_cli("lint", "common/urdf/sensor.xacro", cwd=repository)
    err = done.stdout.decode()  # lint reports on standard output
    assert done.returncode == 0, err
    assert err.count("sensor.xacro: a xacro library") == 1 and "no model includes" in err
    assert "X104 info: macro 'sensor' is called nowhere" in err  # a library's macro nothing calls is only noted
    edit(repository / "common/urdf/sensor.xacro", '<xacro:property name="sensor_size" value="0.05"/>', '<xacro:include filename="camera.xacro"/>')
    done, report = check_json("common/urdf/sensor.xacro", cwd=repository)
    assert done.returncode == 1
    [diagnostic] = report["files"][0]["diagnostics"]
    assert (diagnostic["code"], diagnostic["path"], diagnostic["line"]) == ("X003", "common/urdf/sensor.xacro", 3)


def test_a_model_needing_an_argument_names_the_models_setting(repository):
    (repository / "pyproject.toml").unlink()
    done = run_cli("check", "common/urdf/wheel.xacro", cwd=repository)
    err = done.stderr.decode()
    assert done.returncode == 0, err  # the library itself is fine, and rover.urdf.xacro shows it
    assert "checked through description/urdf/rover.urdf.xacro" in err
    assert ("not checked through description/urdf/arm.urdf.xacro: it needs xacro argument 'arm_type'; "
            "list the argument sets it is checked with in [tool.urdfcli] models") in err


def test_a_library_whose_models_all_need_arguments_is_a_gap_the_models_setting_closes(repository):
    # X006's Example and Use instead: only arm.urdf.xacro includes the wheel now, and it needs arm_type
    config = (repository / "pyproject.toml").read_text()
    (repository / "pyproject.toml").unlink()
    (repository / "description/urdf/rover.urdf.xacro").unlink()
    done = run_cli("lint", "--format", "concise", "common/urdf/wheel.xacro", cwd=repository)
    out = done.stdout.decode()
    assert done.returncode == 1, done.stderr.decode()
    assert out.startswith("common/urdf/wheel.xacro: X006 warning: xacro library checked on its own only: ")
    assert "description/urdf/arm.urdf.xacro needs 'arm_type'" in out
    assert run_cli("check", "common/urdf/wheel.xacro", cwd=repository).returncode == 0  # a warning: check passes
    (repository / "pyproject.toml").write_text(config)
    done = run_cli("lint", "--format", "concise", "common/urdf/wheel.xacro", cwd=repository)
    assert "X006" not in done.stdout.decode() and "checked through description/urdf/arm.urdf.xacro" in done.stderr.decode()


def test_a_library_its_models_include_only_with_an_argument_is_a_gap_the_models_setting_closes(tmp_path):
    """franka_description includes its hand only with hand:=true: with the default
    arguments no model reads the hand's macros, and a broken hand would pass."""
    (tmp_path / ".git").mkdir()
    write(tmp_path / "urdf" / "hand.xacro", f"""\
        <robot {XACRO}>
          <xacro:macro name="hand" params="parent">
            <joint name="hand_joint" type="fixed"><parent link="${{parent}}"/><child link="hand"/></joint>
            <link name="hand"/>
          </xacro:macro>
        </robot>
        """)
    write(tmp_path / "urdf" / "arm.urdf.xacro", f"""\
        <robot name="arm" {XACRO}>
          <xacro:arg name="hand" default="false"/>
          <link name="base_link"/>
          <xacro:if value="$(arg hand)">
            <xacro:include filename="hand.xacro"/>
            <xacro:hand parent="base_link"/>
          </xacro:if>
        </robot>
        """)
    done = run_cli("check", "--format", "concise", "urdf/hand.xacro", cwd=tmp_path)
    assert done.returncode == 0  # a warning
    assert done.stdout.decode().startswith(
        "urdf/hand.xacro: X006 warning: xacro library checked on its own only: no model that includes it could check it "
        "(urdf/arm.urdf.xacro does not read it with its default arguments)"
    )
    assert "not checked through" not in done.stderr.decode()  # X006 says it, once
    # the hint is the setting to write: the model, and the argument its xacro:if reads
    assert 'e.g. models = { "urdf/arm.urdf.xacro" = [[], ["hand:=true"]] }' in done.stdout.decode()
    (tmp_path / "pyproject.toml").write_text('[tool.urdfcli]\nmodels = { "urdf/arm.urdf.xacro" = [[], ["hand:=true"]] }\n')
    done, report = check_json("urdf/hand.xacro", cwd=tmp_path)
    assert done.returncode == 0 and report["files"][0]["diagnostics"] == []
    assert report["files"][0]["checked_through"] == ["urdf/arm.urdf.xacro [hand:=true]"]
    edit(tmp_path / "urdf" / "hand.xacro", '<link name="hand"/>', '<link name="palm"/>')
    done, report = check_json("urdf/hand.xacro", cwd=tmp_path)
    assert done.returncode == 1 and "J005" in [d["code"] for d in report["files"][0]["diagnostics"]]  # its joint names no link "hand"


ONE_WHEEL = f"""\
        <robot name="r" {XACRO}>
          <xacro:include filename="$(find acme_wheels)/urdf/wheel.xacro"/>
          <link name="base_link"/>
          <xacro:wheel prefix="left" parent="base_link" radius="0.1"><origin xyz="0 0 0"/></xacro:wheel>
        </robot>
        """  # a model of one workspace package calling a macro of another (make_colcon_workspace's acme_wheels)


def test_a_colcon_workspace_resolves_packages_across_repositories(tmp_path):
    repo_a, repo_b = make_colcon_workspace(tmp_path)
    model = write(repo_a / "robot" / "urdf" / "robot.urdf.xacro", ONE_WHEEL)
    done = run_cli("check", str(model), cwd=tmp_path)
    assert done.returncode == 0, done.stderr.decode()
    # and a library of repo_b is checked through the model in repo_a
    done, report = check_json(str(repo_b / "wheels/urdf/wheel.xacro"), cwd=tmp_path)
    assert done.returncode == 0 and report["files"][0]["checked_through"] == [str(model.relative_to(tmp_path))]


def test_a_setup_folder_in_no_package_finds_the_packages_of_its_workspace(tmp_path):
    """Clearpath's generated robot.urdf.xacro in a robot's setup folder (a repository of
    its own, no package.xml) beside the description packages in ws/src: xacro in the
    sourced workspace finds them, and their libraries are checked through it."""
    _, repo_b = make_colcon_workspace(tmp_path)
    setup = tmp_path / "ws" / "src" / "robot_setup"
    (setup / ".git").mkdir(parents=True)
    model = write(setup / "robot.urdf.xacro", ONE_WHEEL)
    done = run_cli("check", str(model), cwd=tmp_path)
    assert done.returncode == 0, done.stderr.decode()
    done, report = check_json(str(repo_b / "wheels/urdf/wheel.xacro"), cwd=tmp_path)
    assert done.returncode == 0 and report["files"][0]["checked_through"] == [str(model.relative_to(tmp_path))]


def test_a_part_whose_links_hang_from_its_includers_macro_is_a_fragment_of_the_model(tmp_path):
    """Clearpath's w200.urdf.xacro makes the wheels outside its macro, on the diff units the
    macro makes: read alone, every wheel hangs from a missing link. A model of another
    package includes it and calls the macro: it is checked through that model."""
    src = tmp_path / "ws" / "src"
    (src / ".git").mkdir(parents=True)
    write(src / "base" / "package.xml", package_xml("acme_base"))
    write(src / "base" / "urdf" / "base.urdf.xacro", f"""\
        <robot {XACRO}>
          <xacro:macro name="base">
            <link name="base_link"/>
            <link name="axle"/>
            <joint name="axle_joint" type="fixed"><parent link="base_link"/><child link="axle"/></joint>
          </xacro:macro>
          <link name="left_wheel"/>
          <joint name="left_wheel_joint" type="fixed"><parent link="axle"/><child link="left_wheel"/></joint>
          <link name="right_wheel"/>
          <joint name="right_wheel_joint" type="fixed"><parent link="axle"/><child link="right_wheel"/></joint>
        </robot>
        """)
    write(src / "robot" / "package.xml", package_xml("acme_robot", depends=("acme_base",)))
    write(src / "robot" / "urdf" / "robot.urdf.xacro", f"""\
        <robot name="r" {XACRO}>
          <xacro:include filename="$(find acme_base)/urdf/base.urdf.xacro"/>
          <xacro:base/>
        </robot>
        """)
    done = run_cli("lint", "src", cwd=tmp_path / "ws")
    out = done.stdout.decode()
    assert done.returncode == 0, out
    assert "base/urdf/base.urdf.xacro: fragment, checked through src/robot/urdf/robot.urdf.xacro" in out



def test_a_fragment_a_model_picks_by_an_argument_names_the_model_and_the_argument(tmp_path):
    """SO-ARM100's model includes grippers/gripper_$(arg gripper_type).xacro: the gripper
    its default does not name is not 'included by no model' (a change to it would pass
    unchecked, said so wrongly), but may be included by that model with another value: the
    note names the argument set to list, and with it listed the fragment is checked through it."""
    package = tmp_path / "arm"
    (tmp_path / ".git").mkdir()
    write(package / "package.xml", package_xml("arm"))
    write(package / "urdf" / "arm.urdf.xacro", f"""\
        <robot name="arm" {XACRO}>
          <xacro:arg name="gripper_type" default="jaw"/>
          <link name="wrist"/>
          <xacro:include filename="grippers/gripper_$(arg gripper_type).xacro"/>
        </robot>
        """)
    for gripper in ("jaw", "none"):
        write(package / "urdf" / "grippers" / f"gripper_{gripper}.xacro", f"""\
            <robot {XACRO}>
              <link name="{gripper}_tool"/>
              <joint name="{gripper}_joint" type="fixed"><parent link="wrist"/><child link="{gripper}_tool"/></joint>
            </robot>
            """)
    fragment = "arm/urdf/grippers/gripper_none.xacro"
    out = run_cli("lint", fragment, cwd=tmp_path).stdout.decode()
    assert "no model includes" not in out
    assert (f"{fragment}: may be included by arm/urdf/arm.urdf.xacro through 'grippers/gripper_$(arg gripper_type).xacro', a file name "
            "computed from what it is given, and that model reads another file with its default arguments: not checked; list the argument "
            'sets it is checked with in [tool.urdfcli] models, e.g. models = { "arm/urdf/arm.urdf.xacro" = [["gripper_type:=none"]] }') in out
    write(tmp_path / "pyproject.toml", '[tool.urdfcli]\nmodels = { "arm/urdf/arm.urdf.xacro" = [["gripper_type:=none"]] }\n')
    done = run_cli("lint", fragment, cwd=tmp_path)
    assert done.returncode == 0 and f"{fragment}: fragment, checked through arm/urdf/arm.urdf.xacro [gripper_type:=none]" in done.stdout.decode()


def test_a_library_a_macro_fragment_includes_is_checked_through_the_model_not_the_fragment(tmp_path):
    """TALOS: the arm's macro includes ${side}_arm.transmissions.urdf.xacro, which calls the
    transmission macro of arm.transmission.xacro with the macro's ${name}. Given with that
    library (a commit changing both), the fragment is checked through the robot that reads
    it, not expanded as a robot of its own (a false "name 'name' is not defined")."""
    package = tmp_path / "talos_description"
    write(package / "package.xml", package_xml("talos_description"))
    write(package / "urdf" / "arm.transmission.xacro", f"""\
        <robot {XACRO}>
          <xacro:macro name="arm_transmission" params="name side">
            <transmission name="${{name}}_${{side}}_trans"><type>transmission_interface/SimpleTransmission</type>
              <joint name="${{name}}_${{side}}_joint"><hardwareInterface>EffortJointInterface</hardwareInterface></joint>
              <actuator name="${{name}}_${{side}}_motor"/></transmission>
          </xacro:macro>
        </robot>
        """)
    write(package / "urdf" / "left_arm.transmissions.urdf.xacro", f"""\
        <robot {XACRO}>
          <xacro:include filename="$(find talos_description)/urdf/arm.transmission.xacro"/>
          <xacro:arm_transmission name="${{name}}" side="left"/>
        </robot>
        """)
    write(package / "urdf" / "arm.urdf.xacro", f"""\
        <robot {XACRO}>
          <xacro:include filename="$(find talos_description)/urdf/arm.transmission.xacro"/>
          <xacro:macro name="talos_arm" params="name side">
            <link name="${{name}}_${{side}}_link"/>
            <joint name="${{name}}_${{side}}_joint" type="revolute"><parent link="torso"/><child link="${{name}}_${{side}}_link"/>
              <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
            <xacro:include filename="$(find talos_description)/urdf/${{side}}_arm.transmissions.urdf.xacro"/>
          </xacro:macro>
        </robot>
        """)
    write(package / "robots" / "talos.urdf.xacro", f"""\
        <robot name="talos" {XACRO}>
          <xacro:include filename="$(find talos_description)/urdf/arm.urdf.xacro"/>
          <link name="torso"/>
          <xacro:talos_arm name="arm" side="left"/>
        </robot>
        """)
    done = run_cli("check", "--format", "concise", "urdf/left_arm.transmissions.urdf.xacro", "urdf/arm.transmission.xacro", cwd=package)
    out = (done.stdout + done.stderr).decode()
    assert done.returncode == 0, out
    assert "X003" not in out and "checked through robots/talos.urdf.xacro" in out, out


def test_a_fragment_with_a_mistake_of_its_own_is_still_checked_through_its_models(tmp_path):
    """A part without a robot name (R002 alone) whose mass a user typed negative: the
    negative mass is said through the models that include it, not beside a false "no
    name" on the part read alone; so is what a target says of the whole model."""
    package = tmp_path / "grip"
    write(package / "package.xml", package_xml("grip"))
    write(package / "urdf" / "hand.xacro", f"""\
        <robot {XACRO}>
          <link name="palm"><inertial><mass value="-0.4"/><inertia ixx="1e-4" ixy="0" ixz="0" iyy="1e-4" iyz="0" izz="1e-4"/></inertial></link>
          <link name="finger"/>
          <joint name="finger_joint" type="fixed"><parent link="palm"/><child link="finger"/></joint>
        </robot>
        """)
    for name in ("left", "right"):
        write(package / "urdf" / f"{name}.urdf.xacro", f"""\
            <robot name="{name}" {XACRO}>
              <xacro:include filename="$(find grip)/urdf/hand.xacro"/>
            </robot>
            """)
    done = run_cli("lint", "--format", "concise", "urdf/hand.xacro", cwd=package)
    out = (done.stdout + done.stderr).decode()
    assert done.returncode == 1, out
    assert "R002" not in out
    assert "urdf/hand.xacro: fragment, checked through urdf/left.urdf.xacro, urdf/right.urdf.xacro" in out
    assert re.search(r"urdf/hand.xacro:2:\d+: I001 error: .*found through model urdf/left.urdf.xacro", out), out

def test_a_workspace_kept_as_a_repository_finds_the_packages_of_the_workspace_it_is_cloned_into(tmp_path):
    # A cell whose repository is a workspace of its own (cell/src/cell_description), cloned
    # beside the vendor's repository: colcon builds both, so $(find acme_wheels) resolves.
    _, repo_b = make_colcon_workspace(tmp_path)
    cell = repo_b.parent / "cell"
    (cell / ".git").mkdir(parents=True)
    description = cell / "src" / "cell_description"
    write(description / "package.xml", package_xml("cell_description"))
    model = write(
        description / "urdf" / "cell.urdf.xacro",
        f"""\
        <robot name="cell" {XACRO}>
          <xacro:include filename="$(find acme_wheels)/urdf/wheel.xacro"/>
          <link name="base_link"/>
          <xacro:wheel prefix="left" parent="base_link" radius="0.1"><origin xyz="0 0 0"/></xacro:wheel>
        </robot>
        """,
    )
    assert PackageResolver((), model).find("acme_wheels") == repo_b / "wheels"
    done = run_cli("check", str(model), cwd=tmp_path)
    assert done.returncode == 0, done.stderr.decode()


# A caster macro kept in description/urdf, which the package installs to share/acme_wheels/urdf
# (as ros2_control_demos installs description/ros2_control): its joint's yaw is in degrees (V009).
CASTER = f"""\
    <robot {XACRO}>
      <xacro:macro name="caster" params="parent">
        <link name="caster_link">
          <visual><geometry><sphere radius="0.05"/></geometry></visual>
          <collision><geometry><sphere radius="0.05"/></geometry></collision>
          <inertial><mass value="0.2"/><inertia ixx="0.0002" ixy="0" ixz="0" iyy="0.0002" iyz="0" izz="0.0002"/></inertial>
        </link>
        <joint name="caster_joint" type="fixed">
          <parent link="${{parent}}"/>
          <child link="caster_link"/>
          <origin xyz="0.2 0 -0.05" rpy="0 0 90"/>
        </joint>
      </xacro:macro>
    </robot>
    """

WHEELED = f"""\
    <robot name="r" {XACRO}>
      <xacro:include filename="$(find acme_wheels)/urdf/wheel.xacro"/>
      <xacro:include filename="$(find acme_wheels)/urdf/caster.xacro"/>
      <link name="base_link"/>
      <xacro:wheel prefix="left" parent="base_link" radius="0.1"><origin xyz="0 0 0"/></xacro:wheel>
      <xacro:caster parent="base_link"/>
    </robot>
    """


@pytest.mark.parametrize("symlink", [True, False], ids=["symlink-install", "copies"])
def test_a_built_workspace_reports_and_fixes_its_packages_at_their_sources_not_their_install_copies(tmp_path, symlink):
    """After `colcon build [--symlink-install]`, $(find acme_wheels) is the install space's
    share folder, as ROS gives it (caster.xacro is only there at urdf/); what is wrong in
    the files read there is said, and fixed, in the sources the user edits."""
    repo_a, repo_b = make_colcon_workspace(tmp_path)
    wheels = repo_b / "wheels"
    write(wheels / "description" / "urdf" / "caster.xacro", CASTER)
    edit(wheels / "urdf" / "wheel.xacro", '<axis xyz="0 0 1"/>', '<axis xyz="0 0 2"/>')
    install_package(tmp_path / "ws", wheels, "acme_wheels", {"urdf": "urdf", "description/urdf": "urdf"}, symlink=symlink)
    model = write(repo_a / "robot" / "urdf" / "robot.urdf.xacro", WHEELED)
    done = run_cli("lint", "--format", "json", str(model), cwd=tmp_path / "ws")
    found = {(d["code"], d["path"]) for f in json.loads(done.stdout)["files"] for d in f["diagnostics"]}
    assert {("J011", "src/repo_b/wheels/urdf/wheel.xacro"), ("V009", "src/repo_b/wheels/description/urdf/caster.xacro")} <= found, found
    assert not [path for _, path in found if path.startswith("install")], found
    diff = run_cli("lint", "--fix", "--diff", "--unsafe-fixes", "--select", "V009", str(model), cwd=tmp_path / "ws").stdout.decode()
    assert "--- a/src/repo_b/wheels/description/urdf/caster.xacro\n+++ b/src/repo_b/wheels/description/urdf/caster.xacro\n" in diff, diff
    assert "install/" not in diff


def test_an_include_of_a_layout_only_the_build_makes_says_where_the_sources_have_it(tmp_path):
    """A fresh clone, not built: $(find acme_wheels)/urdf/caster.xacro is not in the sources,
    which keep it in description/urdf. xacro fails the same way; the hint says where the
    file is and how to check against the installed layout."""
    from differential import real_xacro

    repo_a, repo_b = make_colcon_workspace(tmp_path)
    wheels = repo_b / "wheels"
    write(wheels / "description" / "urdf" / "caster.xacro", CASTER)
    model = write(repo_a / "robot" / "urdf" / "robot.urdf.xacro", WHEELED)
    assert real_xacro(model, packages={"acme_wheels": str(wheels)}).returncode != 0
    done, report = check_json(str(model), cwd=tmp_path / "ws")
    [error] = report["files"][0]["diagnostics"]
    assert (error["code"], error["message"]) == ("X003", "cannot include src/repo_b/wheels/urdf/caster.xacro: No such file or directory")
    assert error["hint"] == (
        "package 'acme_wheels' installs its files to other folders than its sources, which have it at "
        "src/repo_b/wheels/description/urdf/caster.xacro: build the workspace (colcon build) and check again, "
        "or give its installed share folder with -P acme_wheels=DIR"
    )
    share = install_package(tmp_path / "built", wheels, "acme_wheels", {"urdf": "urdf", "description/urdf": "urdf"})  # another workspace's build
    assert run_cli("check", "-P", f"acme_wheels={share}", str(model), cwd=tmp_path / "ws").returncode == 0
    # an include whose file the package holds nowhere: no hint
    edit(model, "urdf/caster.xacro", "urdf/castor.xacro")
    done, report = check_json(str(model), cwd=tmp_path / "ws")
    assert [(d["code"], d.get("hint")) for d in report["files"][0]["diagnostics"]] == [("X003", None)]


def test_an_include_of_a_layout_the_install_rules_make_reads_the_source_before_the_build(tmp_path):
    """ros2_control_demos on a fresh clone, or in a CI job that does not build: the package
    installs description/urdf to share/NAME/urdf (its CMakeLists.txt says so), so
    $(find acme_wheels)/urdf/caster.xacro is its description/urdf/caster.xacro. The model
    expands as xacro expands it once built, and the caster's mistake is said in its source.
    A rule written only in a comment, or for another destination, maps nothing."""
    from differential import canonical, real_xacro

    repo_a, repo_b = make_colcon_workspace(tmp_path)
    wheels = repo_b / "wheels"
    write(wheels / "description" / "urdf" / "caster.xacro", CASTER)
    rules = ("cmake_minimum_required(VERSION 3.8)\nproject(acme_wheels)\n"
             "install(\n  DIRECTORY urdf description/urdf  # the layout launch files read\n  DESTINATION share/${PROJECT_NAME}\n)\n")
    write(wheels / "CMakeLists.txt", rules)
    model = write(repo_a / "robot" / "urdf" / "robot.urdf.xacro", WHEELED)
    done, report = check_json(str(model), cwd=tmp_path / "ws")
    assert [(d["code"], d["path"]) for d in report["files"][0]["diagnostics"]] == [("V009", "src/repo_b/wheels/description/urdf/caster.xacro")]
    share = install_package(tmp_path / "built", wheels, "acme_wheels", {"urdf": "urdf", "description/urdf": "urdf"})
    real = real_xacro(model, packages={"acme_wheels": str(share)})
    assert real.returncode == 0, real.stderr
    assert canonical(run_cli("expand", str(model), cwd=tmp_path / "ws").stdout.decode()) == canonical(real.stdout)
    resolver = PackageResolver((), model)  # a mesh named by its installed path is found so too
    assert resolver.resolve_uri("package://acme_wheels/urdf/caster.xacro") == wheels / "description" / "urdf" / "caster.xacro"
    for unmapped in (rules.replace("install(", "# install("), rules.replace("share/${PROJECT_NAME}", "lib/${PROJECT_NAME}")):
        write(wheels / "CMakeLists.txt", unmapped)
        done, report = check_json(str(model), cwd=tmp_path / "ws")
        assert [d["code"] for d in report["files"][0]["diagnostics"]] == ["X003"], report


def test_an_include_a_substitution_left_empty_says_which_not_that_the_build_moves_files(tmp_path):
    """ros2_kortex's gen3.xacro: dof defaults to "", so kortex_robot.xacro's
    $(find kortex_description)/arms/${arm}/${dof}dof/urdf/... reads arms/gen3/dof/urdf/...,
    which is no file; the sources have arms/gen3/7dof/urdf/..., but no build moves it there.
    The hint names the empty substitution and the argument to give, as xacro fails the same way."""
    from differential import real_xacro

    package = tmp_path / "ws" / "src" / "kortex" / "kortex_description"
    write(package / "package.xml", package_xml("kortex_description"))
    write(package / "arms" / "gen3" / "7dof" / "urdf" / "gen3_macro.xacro", """\
        <robot xmlns:xacro="http://ros.org/wiki/xacro">
          <xacro:macro name="load_arm"><link name="base_link"/></xacro:macro>
        </robot>
        """)
    write(package / "robots" / "kortex_robot.xacro", """\
        <robot xmlns:xacro="http://ros.org/wiki/xacro">
          <xacro:macro name="load_robot" params="arm dof">
            <xacro:include filename="$(find kortex_description)/arms/${arm}/${dof}dof/urdf/${arm}_macro.xacro"/>
            <xacro:load_arm/>
          </xacro:macro>
        </robot>
        """)
    model = write(package / "robots" / "gen3.xacro", """\
        <robot name="gen3" xmlns:xacro="http://ros.org/wiki/xacro">
          <xacro:arg name="dof" default=""/>
          <xacro:include filename="$(find kortex_description)/robots/kortex_robot.xacro"/>
          <xacro:load_robot arm="gen3" dof="$(arg dof)"/>
        </robot>
        """)
    assert real_xacro(model, packages={"kortex_description": str(package)}).returncode != 0
    done, report = check_json(str(model), cwd=tmp_path / "ws")
    [error] = report["files"][0]["diagnostics"]
    assert error["message"] == "cannot include src/kortex/kortex_description/arms/gen3/dof/urdf/gen3_macro.xacro: No such file or directory"
    assert error["hint"] == "${dof} is empty here, which leaves it out of the path: xacro argument 'dof' is empty; pass dof:=VALUE"
    assert check_json(str(model), "dof:=7", cwd=tmp_path / "ws")[0].returncode == 0


def test_an_include_of_a_variant_the_package_lacks_is_not_said_to_be_installed_elsewhere(tmp_path):
    """kortex_description has arms/gen3/7dof/urdf/gen3_transmission_macro.xacro and no 6dof
    one: $(find)/arms/gen3/6dof/urdf/... is missing, not installed from the 7dof folder
    (no install rule keeps arms/gen3 and swaps the folder below it), so no hint says so."""
    repo_a, repo_b = make_colcon_workspace(tmp_path)
    write(repo_b / "wheels" / "arms" / "gen3" / "7dof" / "urdf" / "caster.xacro", CASTER)
    model = write(repo_a / "robot" / "urdf" / "robot.urdf.xacro", WHEELED.replace("/urdf/caster.xacro", "/arms/gen3/6dof/urdf/caster.xacro"))
    done, report = check_json(str(model), cwd=tmp_path / "ws")
    [error] = report["files"][0]["diagnostics"]
    assert (error["code"], error.get("hint")) == ("X003", None), error
    assert error["message"] == "cannot include src/repo_b/wheels/arms/gen3/6dof/urdf/caster.xacro: No such file or directory"


def test_a_package_only_installed_in_the_workspace_is_found_there(tmp_path):
    """A package the workspace's install space holds and its src/ does not (built from
    elsewhere): read from the install space, and no source is made up for it."""
    repo_a, repo_b = make_colcon_workspace(tmp_path)
    shutil.rmtree(repo_b / "wheels")
    elsewhere = tmp_path / "elsewhere" / "acme_wheels"
    write(elsewhere / "package.xml", package_xml("acme_wheels"))
    write(elsewhere / "urdf" / "wheel.xacro", WHEEL.replace("$(find acme_common)/urdf/inertia.xacro", "inertia.xacro"))
    write(elsewhere / "urdf" / "inertia.xacro", INERTIA)
    write(elsewhere / "urdf" / "caster.xacro", CASTER)
    install_package(tmp_path / "ws", elsewhere, "acme_wheels", {"urdf": "urdf"}, symlink=False)
    model = write(repo_a / "robot" / "urdf" / "robot.urdf.xacro", WHEELED)
    resolver = PackageResolver((), model)
    share = tmp_path / "ws" / "install" / "acme_wheels" / "share" / "acme_wheels"
    assert resolver.find("acme_wheels") == share
    assert resolver.source_of(str(share / "urdf" / "caster.xacro")) == str(share / "urdf" / "caster.xacro")
    done = run_cli("check", str(model), cwd=tmp_path / "ws")
    assert done.returncode == 0, done.stderr.decode()


@pytest.mark.parametrize("output_format", ["text", "concise", "json", "sarif", "github", "check_urdf"])
def test_every_format_shows_a_library(repository, output_format):
    edit(repository / "common/urdf/wheel.xacro", '<parent link="${parent}"/>', '<parent link="${parent}_mount"/>')
    done = run_cli("check", "--format", output_format, "common/urdf/wheel.xacro", "description/urdf/rover.urdf.xacro", cwd=repository)
    out = done.stdout.decode() + done.stderr.decode()
    assert done.returncode == 1 and "Traceback" not in out and "internal error" not in out
    assert "base_link_mount" in out


def test_a_model_whose_packages_are_missing_here_is_named_not_failed(repository):
    edit(repository / "description/urdf/rover.urdf.xacro", '<link name="base_footprint"/>', '<link name="base_footprint"/>\n  <xacro:include filename="$(find acme_sensors)/urdf/lidar.xacro"/>')
    (repository / "pyproject.toml").unlink()
    done = run_cli("check", "common/urdf/wheel.xacro", cwd=repository)
    err = done.stderr.decode()
    assert done.returncode == 0, err
    assert "not checked through description/urdf/rover.urdf.xacro: package 'acme_sensors' not found" in err


def test_a_repository_in_a_folder_named_src_is_searched_alone_unless_that_is_a_workspace(tmp_path):
    from urdfcli.project.workspace import search_roots

    src = tmp_path / "home" / "src"
    library = write(src / "my_robot" / "description" / "urdf" / "wheel.xacro", WHEEL)
    write(src / "my_robot" / "description" / "package.xml", package_xml("my_robot_description"))
    (src / "my_robot" / ".git").mkdir()
    (src / "website" / "pages").mkdir(parents=True)  # ~/src holds other projects
    assert search_roots(library, PackageIndex()) == ([src / "my_robot"], True)
    write(src / "other_robot" / "arm" / "package.xml", package_xml("arm"))  # a second repository of packages
    assert search_roots(library, PackageIndex()) == ([src / "my_robot", src], True)


def test_a_workspace_is_told_by_a_repository_that_groups_its_packages_a_level_deeper(tmp_path):
    """An unbuilt workspace (no build/ nor install/ beside src) whose second repository keeps
    its packages in a group folder: the first repository's models are still looked for there."""
    from urdfcli.project.workspace import search_roots

    src = tmp_path / "ws" / "src"
    library = write(src / "base_sim" / "base_common" / "base_description" / "urdf" / "wheel.xacro", WHEEL)
    write(src / "base_sim" / "base_common" / "base_description" / "package.xml", package_xml("base_description"))
    (src / "base_sim" / ".git").mkdir()
    write(src / "rover" / "rover_description" / "package.xml", package_xml("rover_description"))
    assert search_roots(library, PackageIndex()) == ([src / "base_sim", src], True)


def test_a_repository_that_is_one_package_is_searched_alone(tmp_path):
    """A package whose own folder is its repository, in no workspace (~/code/my_robot_description):
    the folder beside it holds other repositories, none of them searched for its models."""
    from urdfcli.project.workspace import search_roots

    code = tmp_path / "code"
    library = write(code / "my_robot_description" / "urdf" / "wheel.xacro", WHEEL)
    write(code / "my_robot_description" / "package.xml", package_xml("my_robot_description"))
    (code / "my_robot_description" / ".git").mkdir()
    write(code / "other_robot" / "package.xml", package_xml("other_robot"))
    (code / "other_robot" / ".git").mkdir()
    write(code / "other_robot" / "urdf" / "other.urdf.xacro", f'<robot name="other" {XACRO}><link name="a"/></robot>\n')
    assert search_roots(library, PackageIndex()) == ([code / "my_robot_description"], True)


def test_only_the_models_that_include_the_library_are_expanded(repository):
    # a broken model that includes only inertia.xacro: expanding it would fail
    write(repository / "description/urdf/broken.urdf.xacro", f"""\
        <robot name="broken" {XACRO}>
          <xacro:include filename="$(find acme_common)/urdf/inertia.xacro"/>
          <link name="${{undefined_name}}"/>
        </robot>
        """)
    done, report = check_json("common/urdf/wheel.xacro", cwd=repository)
    assert done.returncode == 0, done.stderr.decode()
    assert "description/urdf/broken.urdf.xacro" not in report["files"][0]["checked_through"]
    done, report = check_json("common/urdf/inertia.xacro", cwd=repository)
    assert done.returncode == 1  # it does include inertia.xacro, and is broken
    assert "description/urdf/broken.urdf.xacro" in report["files"][0]["checked_through"]


@pytest.mark.parametrize("mark", ["COLCON_IGNORE", "CATKIN_IGNORE"])
def test_a_folder_marked_ignored_is_left_out_of_the_search_and_the_package_scan(tmp_path, mark):
    """colcon and catkin skip a folder that holds COLCON_IGNORE or CATKIN_IGNORE, and all below
    it: its models are not checked and its packages are found nowhere."""
    from urdfcli.project.workspace import source_files

    for name in ("kept", "ignored"):
        package = tmp_path / "src" / name / f"{name}_description"
        (package / "urdf").mkdir(parents=True)
        (package / "package.xml").write_text(package_xml(f"{name}_description"))
        (package / "urdf" / f"{name}.urdf").write_text(f'<robot name="{name}"><link name="base"/></robot>\n')
    (tmp_path / "src" / "ignored" / mark).write_text("")
    found = [path.relative_to(tmp_path).as_posix() for path in source_files(tmp_path / "src")]
    assert found == ["src/kept/kept_description/urdf/kept.urdf"]
    assert [name for name, _ in PackageIndex().scan(tmp_path / "src")] == ["kept_description"]


def husky(root: Path, extras: str) -> Path:
    """Husky's description: the model includes ``$(arg urdf_extras)``, whose default
    (empty.urdf, a placeholder) a file it includes declares: no search follows it,
    the model's expansion reads it."""
    (root / ".git").mkdir(parents=True)
    package = root / "husky_description"
    write(package / "package.xml", package_xml("husky_description"))
    write(package / "urdf" / "husky_macro.urdf.xacro", f"""\
        <?xml version="1.0"?>
        <robot {XACRO}>
          <xacro:arg name="urdf_extras" default="$(optenv CPR_URDF_EXTRAS empty.urdf)"/>
          <xacro:macro name="husky" params="prefix">
            <link name="${{prefix}}base_link"/>
          </xacro:macro>
        </robot>
        """)
    write(package / "urdf" / "husky.urdf.xacro", f"""\
        <?xml version="1.0"?>
        <robot name="husky" {XACRO}>
          <xacro:include filename="$(find husky_description)/urdf/husky_macro.urdf.xacro"/>
          <xacro:husky prefix=""/>
          <xacro:include filename="$(arg urdf_extras)"/>
        </robot>
        """)
    write(package / "urdf" / "empty.urdf", extras)
    return package


PLACEHOLDER = "<robot>\n  <!-- a placeholder which is included by default from husky.urdf.xacro -->\n</robot>\n"


def lint_json(*args, cwd):
    done = run_cli("lint", "--format", "json", *args, cwd=cwd)
    return done, json.loads(done.stdout or b"null")


def test_a_placeholder_urdf_a_model_reads_is_its_fragment_not_a_broken_robot(tmp_path):
    """Not 'R002 no name', 'R004 no link' at Husky's empty.urdf: a part of the model that
    includes it, checked through it."""
    husky(tmp_path / "repo", PLACEHOLDER)
    for command in ("lint", "check"):
        done = run_cli(command, "husky_description", cwd=tmp_path / "repo")
        out = (done.stdout + done.stderr).decode()
        assert done.returncode == 0, out
        assert "husky_description/urdf/empty.urdf: fragment, checked through husky_description/urdf/husky.urdf.xacro" in out
        assert "R002" not in out and "R004" not in out
    # what breaks the model stays the model's, as when it is linted alone
    edit(tmp_path / "repo/husky_description/urdf/husky_macro.urdf.xacro", '<link name="${prefix}base_link"/>',
         '<link name="${prefix}base_link"/><joint name="${prefix}j" type="fixed"><parent link="${prefix}base_link"/><child link="arm"/></joint>')
    done, folder = lint_json("husky_description", cwd=tmp_path / "repo")
    _, alone = lint_json("husky_description/urdf/husky.urdf.xacro", cwd=tmp_path / "repo")
    found = {f["path"]: [(d["code"], d["path"], d["line"], d["message"]) for d in f["diagnostics"]] for f in folder["files"]}
    assert done.returncode == 1 and found["husky_description/urdf/empty.urdf"] == []
    assert found["husky_description/urdf/husky.urdf.xacro"] == [(d["code"], d["path"], d["line"], d["message"]) for d in alone["files"][0]["diagnostics"]]
    assert [code for code, *_ in found["husky_description/urdf/husky.urdf.xacro"]] == ["J005"]


def test_an_empty_urdf_nothing_includes_is_a_robot_that_failed_as_check_urdf_says(tmp_path):
    """example-robot-data's ur3.urdf: generated by xacro, and empty. Nothing includes it: it is
    a robot with no name and no link, errors as check_urdf's, not a fragment set aside."""
    from differential import check_urdf

    husky(tmp_path / "repo", PLACEHOLDER)
    empty = tmp_path / "repo" / "husky_description" / "urdf" / "ur3.urdf"
    empty.write_text('<?xml version="1.0"?>\n<!-- autogenerated by xacro from ur3.urdf.xacro -->\n<robot xmlns:xacro="http://wiki.ros.org/xacro">\n</robot>\n')
    assert check_urdf(empty).rejects
    for given in (empty, tmp_path / "repo" / "husky_description"):
        done = run_cli("check", "--format", "concise", str(given), cwd=tmp_path / "repo")
        assert done.returncode == 1
        assert "ur3.urdf:3:1: R002 error: <robot> has no 'name' attribute" in done.stdout.decode()


@pytest.mark.parametrize("include", ["$(arg urdf_extras)", "empty.urdf"])  # read by the model; found by the search too
def test_a_urdf_that_holds_a_robot_is_checked_as_one_whoever_includes_it(tmp_path, include):
    package = husky(tmp_path / "repo", '<robot>\n  <link name="camera"/>\n</robot>\n')
    edit(package / "urdf" / "husky.urdf.xacro", "$(arg urdf_extras)", include)
    done = run_cli("lint", "--format", "concise", "husky_description", cwd=tmp_path / "repo")
    assert "husky_description/urdf/empty.urdf:1:1: R002 error: <robot> has no 'name' attribute" in done.stdout.decode()


def interbotix(root: Path) -> Path:
    """Interbotix's arms: the model includes ``urdf/${robot_model}.urdf.xacro``, whose default
    names an arm of another repository; wx250s.urdf.xacro, one arm's macro, includes the
    arm's control in its body."""
    (root / ".git").mkdir(parents=True)
    package = root / "arm_descriptions"
    write(package / "package.xml", package_xml("arm_descriptions"))
    write(package / "urdf" / "arm.urdf.xacro", f"""\
        <?xml version="1.0"?>
        <robot name="arm" {XACRO}>
          <xacro:arg name="robot_model" default="px100"/>
          <xacro:property name="robot_model" value="$(arg robot_model)"/>
          <xacro:include filename="$(find arm_descriptions)/urdf/${{robot_model}}.urdf.xacro"/>
          <xacro:arm_macro/>
        </robot>
        """)
    write(package / "urdf" / "wx250s.urdf.xacro", f"""\
        <?xml version="1.0"?>
        <robot {XACRO}>
          <xacro:macro name="arm_macro">
            <link name="base_link"/>
            <xacro:include filename="$(find arm_descriptions)/urdf/control.urdf.xacro"/>
          </xacro:macro>
        </robot>
        """)
    write(package / "urdf" / "control.urdf.xacro", f'<?xml version="1.0"?>\n<robot {XACRO}>\n  <gazebo reference="base_link"/>\n</robot>\n')
    return package


def test_a_library_a_model_may_include_through_a_computed_name_says_so_and_names_the_setting(tmp_path):
    """Not 'a xacro library that no model includes': the model that computes its name did
    not expand; and the file it includes is pointed at what it says."""
    repo = tmp_path / "repo"
    interbotix(repo)
    done = run_cli("lint", "arm_descriptions", cwd=repo)
    out = done.stdout.decode()  # lint reports on standard output
    notes = [line for line in out.splitlines() if line.startswith("arm_descriptions/urdf/") and " error: " not in line]
    assert "no model includes" not in out
    assert notes[0].startswith(
        "arm_descriptions/urdf/wx250s.urdf.xacro: may be included by arm_descriptions/urdf/arm.urdf.xacro through "
        "'$(find arm_descriptions)/urdf/${robot_model}.urdf.xacro', a file name computed from what it is given, "
        "and that model did not expand with its default arguments ("
    )
    assert notes[0].endswith(
        'list the argument sets it is checked with in [tool.urdfcli] models, e.g. '
        'models = { "arm_descriptions/urdf/arm.urdf.xacro" = [["robot_model:=wx250s"]] } (paths from the configuration\'s folder)'
    )
    assert notes[1] == ("arm_descriptions/urdf/control.urdf.xacro: not checked: included by arm_descriptions/urdf/wx250s.urdf.xacro, "
                        "whose expansion did not read it (see what it says)")
    # the setting it names: the library is checked through the model, which reads both
    write(repo / "urdfcli.toml", '[models]\n"arm_descriptions/urdf/arm.urdf.xacro" = [["robot_model:=wx250s"]]\n')
    done = run_cli("lint", "arm_descriptions", cwd=repo)
    out = done.stdout.decode() + done.stderr.decode()
    assert done.returncode == 0, out
    assert "wx250s.urdf.xacro: xacro library, checked through arm_descriptions/urdf/arm.urdf.xacro [robot_model:=wx250s]" in out
    assert "not checked" not in out and "may be included" not in out


def test_a_file_its_includer_reads_only_under_a_condition_is_not_sent_to_see_what_it_says(tmp_path):
    """The includer expands cleanly and says nothing: the note names what to do instead."""
    (tmp_path / ".git").mkdir()
    write(tmp_path / "urdf" / "base.urdf.xacro", f"""\
        <robot name="base" {XACRO}>
          <xacro:arg name="gripper" default="false"/>
          <link name="base_link"/>
          <xacro:if value="$(arg gripper)"><xacro:include filename="gripper.urdf.xacro"/></xacro:if>
        </robot>
        """)
    write(tmp_path / "urdf" / "gripper.urdf.xacro", f'<robot {XACRO}>\n  <gazebo reference="base_link"/>\n</robot>\n')
    done = run_cli("lint", "urdf", cwd=tmp_path)
    assert done.returncode == 0
    assert done.stdout.decode().splitlines()[0] == (
        "urdf/gripper.urdf.xacro: not checked: included by urdf/base.urdf.xacro, whose expansion did not read it "
        "(under a condition, or in a macro not called): list argument sets of a model that reads it in [tool.urdfcli] models"
    )


def test_a_fragment_no_model_could_check_says_why_once(tmp_path):
    """RotorS's firefly.xacro: a robot's links that only firefly_base.xacro includes (it
    reads $(arg mav_name), which only that model gives), whose expansion stops at a missing
    include first. Checked by name, X006 says so with the error that stopped the model;
    two notes said it again ('not checked through ...', 'a fragment ... not checked')."""
    (tmp_path / ".git").mkdir()
    write(tmp_path / "urdf" / "firefly.xacro", f"""\
        <robot name="firefly" {XACRO}>
          <link name="$(arg mav_name)/base_link"/>
        </robot>
        """)
    write(tmp_path / "urdf" / "firefly_base.xacro", f"""\
        <robot name="firefly" {XACRO}>
          <xacro:arg name="mav_name" default="firefly"/>
          <xacro:include filename="component_snippets.xacro"/>
          <xacro:include filename="firefly.xacro"/>
        </robot>
        """)
    done = run_cli("check", "urdf/firefly.xacro", cwd=tmp_path)
    err = done.stderr.decode()
    assert "X006 warning: xacro fragment not checked: no model that includes it could check it (urdf/firefly_base.xacro stops at an error before reading it)" in err, err
    assert "component_snippets.xacro" in err and done.returncode == 1
    assert "not checked through" not in err and "none read it" not in err, err


def test_a_file_an_expansion_never_reached_for_an_error_before_it_says_so(tmp_path):
    """Nishida's sia5: the model includes body.urdf.xacro, whose X003 stops the expansion,
    then its gazebo fragment and library. Not 'under a condition, list argument sets': the
    error stopped it before, which the library's own check shows, with the way out."""
    (tmp_path / ".git").mkdir()
    write(tmp_path / "urdf" / "robot.urdf.xacro", f"""\
        <robot name="r" {XACRO}>
          <link name="base_link"/>
          <xacro:include filename="body.urdf.xacro"/>
          <xacro:include filename="body.gazebo.xacro"/>
          <xacro:body_gazebo/>
        </robot>
        """)
    write(tmp_path / "urdf" / "body.urdf.xacro", f'<robot {XACRO}>\n  <link name="body_${{rate}}"/>\n</robot>\n')
    write(tmp_path / "urdf" / "body.gazebo.xacro", f'<robot {XACRO}>\n  <xacro:macro name="body_gazebo" params=""><gazebo reference="base_link"/></xacro:macro>\n</robot>\n')
    done = run_cli("check", "--format", "concise", "urdf/body.gazebo.xacro", cwd=tmp_path)
    out = done.stdout.decode()
    assert "(urdf/robot.urdf.xacro stops at an error before reading it)" in out and "does not read it" not in out, out
    assert "urdf/body.urdf.xacro:2:3: X003 error: name 'rate' is not defined" in out and done.returncode == 1
    hint = next(d["hint"] for d in check_json("urdf/body.gazebo.xacro", cwd=tmp_path)[1]["files"][0]["diagnostics"] if d["code"] == "X006")
    assert hint == "correct the error that stops the expansion of urdf/robot.urdf.xacro, then check again"
    # a fragment included after the error by a fragment of the model: the note says so too
    write(tmp_path / "urdf" / "arm.urdf.xacro", f'<robot {XACRO}>\n  <xacro:include filename="body.urdf.xacro"/>\n  <xacro:include filename="hand.urdf.xacro"/>\n</robot>\n')
    write(tmp_path / "urdf" / "hand.urdf.xacro", f'<robot {XACRO}>\n  <link name="hand"/>\n</robot>\n')
    edit(tmp_path / "urdf" / "robot.urdf.xacro", '<xacro:include filename="body.urdf.xacro"/>', '<xacro:include filename="arm.urdf.xacro"/>')
    out = run_cli("lint", "urdf", cwd=tmp_path).stdout.decode()
    assert ("urdf/hand.urdf.xacro: not checked: included by urdf/arm.urdf.xacro, where the expansion of urdf/robot.urdf.xacro "
            "stopped at an error before it (see what it says)") in out, out


def jackal_like(root: Path) -> None:
    """Jackal's accessories: a model that includes its accessories' libraries, one under
    conditions on environment variables ($(optenv)), and one always but calling its
    macro only under such a condition; the mount's macro writes <metrial>."""
    (root / ".git").mkdir()
    write(root / "urdf" / "accessories" / "camera_mount.urdf.xacro", f"""\
        <robot {XACRO}>
          <xacro:macro name="camera_mount" params="prefix">
            <link name="${{prefix}}_camera_mount">
              <visual><geometry><box size="0.1 0.1 0.1"/></geometry><metrial name="dark_grey"/></visual>
            </link>
          </xacro:macro>
        </robot>
        """)
    write(root / "urdf" / "accessories" / "laser.urdf.xacro", f"""\
        <robot {XACRO}>
          <xacro:macro name="laser" params="prefix">
            <link name="${{prefix}}_laser"/>
            <joint name="${{prefix}}_laser_joint" type="fixed"><parent link="${{prefix}}_mount"/><child link="${{prefix}}_laser"/></joint>
          </xacro:macro>
        </robot>
        """)
    write(root / "urdf" / "robot.urdf.xacro", f"""\
        <robot name="jackal" {XACRO}>
          <link name="base_link"/>
          <link name="front_mount"/>
          <joint name="front_mount_joint" type="fixed"><parent link="base_link"/><child link="front_mount"/></joint>
          <xacro:if value="$(optenv URDFCLI_TEST_LASER 0)">
            <xacro:unless value="$(optenv URDFCLI_TEST_LASER_OTHER 0)">
              <xacro:include filename="accessories/laser.urdf.xacro"/>
              <xacro:laser prefix="front"/>
            </xacro:unless>
          </xacro:if>
          <xacro:include filename="accessories/camera_mount.urdf.xacro"/>
          <xacro:if value="$(optenv URDFCLI_TEST_FLEA3 0)">
            <xacro:camera_mount prefix="front"/>
            <joint name="camera_joint" type="fixed"><parent link="front_mount"/><child link="front_camera_mount"/></joint>
          </xacro:if>
        </robot>
        """)


def test_a_library_read_but_none_of_whose_macros_is_called_is_not_checked_through_the_model(tmp_path):
    """Jackal's camera_mount.urdf.xacro: jackal.urdf.xacro includes it always, but calls its
    macro only with JACKAL_FLEA3=1. It was said to be checked through the model, and a
    <metrial> in its macro passed: nothing of the macro was expanded."""
    jackal_like(tmp_path)
    done = run_cli("lint", "urdf/accessories/camera_mount.urdf.xacro", cwd=tmp_path, env={"URDFCLI_TEST_FLEA3": "0"})
    out = done.stdout.decode()
    assert done.returncode == 1, out
    assert out.startswith(
        "urdf/accessories/camera_mount.urdf.xacro: X006 warning: xacro library checked on its own only: no model that includes it "
        "could check it (urdf/robot.urdf.xacro reads it but calls none of its macros ('camera_mount') with its default arguments)"
    )
    assert "e.g. URDFCLI_TEST_FLEA3=1 urdfcli lint urdf/accessories/camera_mount.urdf.xacro" in out
    assert "checked through" not in out + done.stderr.decode()
    # what the hint says to do checks the macro, and finds the typo
    done = run_cli("lint", "urdf/accessories/camera_mount.urdf.xacro", cwd=tmp_path, env={"URDFCLI_TEST_FLEA3": "1"})
    out = done.stdout.decode()
    assert "D001" in out and "<metrial>" in out and "X006" not in out
    assert "xacro library, checked through urdf/robot.urdf.xacro" in out


def test_a_library_its_models_include_under_environment_variables_names_them_once(tmp_path):
    """Jackal's accessories, included under conditions on $(optenv JACKAL_LASER 0): the
    hint said to list argument sets in [tool.urdfcli] models, which set xacro arguments
    only and cannot reach them, and the fact was said three times. It names the
    variables to set (not one whose default already opens the way), once."""
    jackal_like(tmp_path)
    done = run_cli("lint", "urdf/accessories/laser.urdf.xacro", cwd=tmp_path, env={"URDFCLI_TEST_LASER": "0"})
    out, err = done.stdout.decode(), done.stderr.decode()
    assert out.count("does not read it with its default arguments") == 1 and "not checked through" not in out + err
    assert ("hint: its models use it only under environment variables, which argument sets cannot set: check with them set, "
            "e.g. URDFCLI_TEST_LASER=1 urdfcli lint urdf/accessories/laser.urdf.xacro") in out
    assert "[tool.urdfcli] models" not in out and "URDFCLI_TEST_LASER_OTHER" not in out
    done = run_cli("lint", "urdf/accessories/laser.urdf.xacro", cwd=tmp_path, env={"URDFCLI_TEST_LASER": "1"})
    assert done.returncode == 0 and "xacro library, checked through urdf/robot.urdf.xacro" in done.stdout.decode()


def spot(root: Path, arm: str) -> None:
    """Spot's description: spot.urdf.xacro includes the arm's macro, a file named ``arm``,
    only with the argument arm:=true."""
    (root / ".git").mkdir(parents=True)
    write(root / "urdf" / "spot.urdf.xacro", f"""\
        <robot name="spot" {XACRO}>
          <xacro:arg name="arm" default="false"/>
          <link name="body"/>
          <xacro:if value="$(arg arm)">
            <xacro:include filename="{arm}"/>
            <xacro:load_arm/>
          </xacro:if>
        </robot>
        """)
    write(root / "urdf" / arm, f"""\
        <?xml version="1.0"?>
        <robot name="spot_arm" {XACRO}>
          <xacro:macro name="load_arm">
            <link name="arm_link"/>
            <joint name="arm_joint" type="fixed"><parent link="body"/><child link="arm_link"/></joint>
          </xacro:macro>
        </robot>
        """)


def test_a_urdf_file_that_is_a_xacro_library_is_one_as_if_named_xacro(tmp_path):
    """Spot's spot_arm_macro.urdf: a <robot name=...> holding only a macro, which a model
    includes. Not 'R004 the robot has no <link>': a library, checked through the models that
    read it, exactly as the same text named .urdf.xacro."""
    said = {}
    for arm in ("spot_arm_macro.urdf", "spot_arm_macro.urdf.xacro"):
        repo = tmp_path / arm
        spot(repo, arm)
        assert read_source(repo / "urdf" / arm).kind == "library"
        write(repo / "arm.toml", '[models]\n"urdf/spot.urdf.xacro" = [["arm:=true"]]\n')  # the argument set that reads it
        runs = [run_cli(*given, cwd=repo) for given in (("lint", "urdf"), ("check", f"urdf/{arm}"), ("check", "--config", "arm.toml", f"urdf/{arm}"))]
        said[arm] = [(done.returncode, (done.stdout + done.stderr).decode().replace(arm, "ARM")) for done in runs]
    assert said["spot_arm_macro.urdf"] == said["spot_arm_macro.urdf.xacro"]
    assert [code for code, _ in said["spot_arm_macro.urdf"]] == [0, 0, 0] and "R004" not in str(said)
    assert "urdf/ARM: xacro library, checked through urdf/spot.urdf.xacro [arm:=true]" in said["spot_arm_macro.urdf"][2][1]


@pytest.mark.parametrize(("text", "kind"), [
    (f'<robot name="r" {XACRO}><xacro:property name="r" value="1"/></robot>', "library"),
    (f'<robot name="r" {XACRO}><xacro:property name="r" value="1"/><link name="a"/></robot>', "model"),  # it makes a link
    (f'<robot name="r" {XACRO}></robot>', "model"),  # the namespace alone: loading it reads a plain URDF (R004)
    ('<robot name="r"><link name="a"/></robot>', "model"),
])
def test_a_urdf_file_is_a_library_only_when_it_is_xacro_and_makes_nothing(tmp_path, text, kind):
    assert read_source(write(tmp_path / "file.urdf", text)).kind == kind


def test_a_model_run_with_two_argument_sets_shows_what_both_find_in_its_own_file_once(tmp_path):
    """Jackal's P001 at its model's $(find) showed twice when the model was listed with two
    argument sets (D006 in its included file, once): what both runs find alike is said once."""
    write(tmp_path / "parts" / "package.xml", package_xml("acme_parts"))
    write(tmp_path / "parts" / "urdf" / "parts.xacro", f'<robot {XACRO}><xacro:macro name="part" params=""><link name="part"/></xacro:macro></robot>\n')
    write(tmp_path / "robot" / "package.xml", package_xml("acme_robot"))
    write(tmp_path / "robot" / "urdf" / "robot.urdf.xacro", f"""\
        <robot name="r" {XACRO}>
          <xacro:arg name="extra" default="false"/>
          <xacro:include filename="$(find acme_parts)/urdf/parts.xacro"/>
          <link name="base_link"/>
          <xacro:part/>
          <joint name="j" type="fixed"><parent link="base_link"/><child link="part"/></joint>
        </robot>
        """)
    (tmp_path / "pyproject.toml").write_text('[tool.urdfcli]\nmodels = { "robot/urdf/robot.urdf.xacro" = [[], ["extra:=true"]] }\n')
    done = run_cli("lint", "--format", "json", "robot/urdf/robot.urdf.xacro", cwd=tmp_path)
    report = json.loads(done.stdout)
    assert [f.get("arguments") for f in report["files"]] == [None, {"extra": "true"}]
    found = [(d["code"], d["line"]) for f in report["files"] for d in f["diagnostics"] if d["code"] == "P001"]
    assert found == [("P001", 3)], report


def test_a_package_that_depends_on_the_model_s_package_is_not_offered_as_its_dependency(tmp_path):
    """open_manipulator_description's <gazebo> block names $(find open_manipulator_bringup)'s
    controller config, and open_manipulator_bringup depends on open_manipulator_description:
    the <exec_depend> P001 offered would make a cycle colcon refuses to order. It says the
    dependency cannot be declared, and offers no fix."""
    write(tmp_path / "arm_bringup" / "package.xml", package_xml("arm_bringup", ("arm_description",)))
    write(tmp_path / "arm_bringup" / "config" / "controllers.yaml", "{}\n")
    write(tmp_path / "arm_description" / "package.xml", package_xml("arm_description"))
    write(tmp_path / "arm_description" / "urdf" / "arm.urdf.xacro", f"""\
        <robot name="arm" {XACRO}>
          <link name="base_link"/>
          <gazebo><plugin filename="gz_ros2_control-system" name="gz_ros2_control::GazeboSimROS2ControlPlugin">
            <parameters>$(find arm_bringup)/config/controllers.yaml</parameters>
          </plugin></gazebo>
        </robot>
        """)
    done = run_cli("lint", "--format", "json", "arm_description/urdf/arm.urdf.xacro", cwd=tmp_path)
    found = [d for f in json.loads(done.stdout)["files"] for d in f["diagnostics"] if d["code"] == "P001"]
    assert [(d["line"], d["message"]) for d in found] == [
        (4, "package 'arm_bringup' is used here but arm_description's package.xml cannot declare it: arm_bringup depends on arm_description")]
    assert found[0].get("fix") is None
    run_cli("lint", "--fix", "arm_description/urdf/arm.urdf.xacro", cwd=tmp_path)
    assert (tmp_path / "arm_description" / "package.xml").read_text() == package_xml("arm_description")


def test_a_model_broken_by_a_library_mistake_shown_under_another_model_is_not_ok(tmp_path):
    """ROS-Industrial's sda10f and its test model share a macro whose mesh is missing: the
    batch shows the error once, under the first model, and the other's JSON said ok, though
    it fails alone. Each model's `ok` is that of all it found; the list stays shown once."""
    (tmp_path / ".git").mkdir()
    write(tmp_path / "urdf" / "arm_macro.xacro", f"""\
        <robot {XACRO}>
          <xacro:macro name="arm" params="prefix">
            <link name="${{prefix}}base"><visual><geometry><mesh filename="file://{tmp_path}/meshes/base.stl"/></geometry></visual></link>
          </xacro:macro>
        </robot>
        """)
    for name in ("arm", "arm_test"):
        write(tmp_path / "urdf" / f"{name}.urdf.xacro", f'<robot name="{name}" {XACRO}>\n  <xacro:include filename="arm_macro.xacro"/>\n  <xacro:arm prefix=""/>\n</robot>\n')
    done, report = lint_json("urdf/arm.urdf.xacro", "urdf/arm_test.urdf.xacro", cwd=tmp_path)
    files = {f["path"]: f for f in report["files"]}
    codes = {path: [d["code"] for d in f["diagnostics"] if d["severity"] == "error"] for path, f in files.items()}
    assert codes == {"urdf/arm.urdf.xacro": ["D004"], "urdf/arm_test.urdf.xacro": []}, codes
    assert [f["ok"] for f in files.values()] == [False, False]
    assert lint_json("urdf/arm_test.urdf.xacro", cwd=tmp_path)[1]["files"][0]["ok"] is False


def test_a_macro_mistake_that_one_model_copies_once_and_another_twice_is_shown_once(tmp_path):
    """Shadow's hand: the single hand's model makes the finger once (rh_), the bimanual model
    twice (rh_ and lh_); the finger's one mistake, said of one link or of two, is shown once."""
    urdf = tmp_path / "hands" / "urdf"
    write(urdf / "finger.xacro", '<robot xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <xacro:macro name="finger" params="prefix">\n'
          '    <link name="${prefix}distal">\n'
          '      <inertial><mass value="0.01"/><inertia ixx="1e-6" ixy="0" ixz="0" iyy="1e-6" iyz="0" izz="5e-6"/></inertial>\n    </link>\n'
          '    <joint name="${prefix}J1" type="fixed"><parent link="palm"/><child link="${prefix}distal"/></joint>\n'
          '  </xacro:macro>\n</robot>\n')
    for model, sides in (("hand", ["rh_"]), ("bimanual", ["rh_", "lh_"])):
        calls = "".join(f'  <xacro:finger prefix="{side}"/>\n' for side in sides)
        write(urdf / f"{model}.urdf.xacro", f'<robot name="{model}" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
              f'  <xacro:include filename="finger.xacro"/>\n  <link name="palm"/>\n{calls}</robot>\n')
    (tmp_path / "hands" / ".git").mkdir()
    done = run_cli("lint", "--format", "json", ".", cwd=tmp_path / "hands")
    found = [(d["code"], d["path"], d["line"]) for f in json.loads(done.stdout)["files"] for d in f["diagnostics"]]
    assert found == [("I006", "urdf/finger.xacro", 4)]
