"""A colcon workspace of several repositories (tests/ros_ws, built by
ros_workspace.make_ros_workspace): fragments are checked through the models that read
them, a library is attributed only to the models whose includes reach it, and a
workspace lint says nothing false, nothing twice and nothing about another repository."""

from __future__ import annotations

import json
import shutil
import textwrap

import pytest
from conftest import run_cli
from differential import real_xacro
from ros_workspace import make_ros_workspace

BAXTER = "src/baxter_common/baxter_description/urdf"
TALOS = "src/talos_robot/talos_description/urdf"


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    return make_ros_workspace(tmp_path_factory.mktemp("ros")).parent


def lint_json(*args, cwd):
    done = run_cli("lint", "--format", "json", *args, cwd=cwd)
    return done, json.loads(done.stdout)


def test_no_fragment_is_expanded_alone_in_a_workspace_lint(built):
    """Baxter's end effectors (whose joints hang from the base's links), TALOS's common
    parts (which read an argument its models declare) and its arms' transmissions (which
    read the macro's 'name', included through ${side}): checked through their models."""
    done, document = lint_json("src", cwd=built)
    paths = [f["path"] for f in document["files"] if not (f.get("notes") and not f.get("checked_through") and not f["diagnostics"])]
    for fragment in ("left_end_effector.urdf.xacro", "right_end_effector.urdf.xacro", "baxter_base.urdf.xacro", "talos_full_common.urdf.xacro",
                     "left_arm.transmissions.urdf.xacro", "foot_collision_default.urdf.xacro"):
        assert not any(p.endswith(fragment) for p in paths), fragment
    found = [(d["code"], d["path"]) for f in document["files"] for d in f["diagnostics"]]
    assert not [c for c in found if c[0] in ("J005", "R004", "M002", "I011") and "talos" not in c[1] and "franka" not in c[1]]
    assert [c for c in found if c[0] == "X003"] == [
        ("X003", "src/Universal_Robots_ROS2_Description/ur_description/urdf/ur.urdf.xacro"),  # needs name:=, as xacro says too
        ("X003", "src/Universal_Robots_ROS2_Driver/ur_moveit_config/srdf/ur.srdf.xacro"),
    ]
    # what no model read is said once, with the include that could have named it
    notes = {f["path"]: f["notes"] for f in document["files"] if f.get("notes")}
    assert notes == {
        "src/Universal_Robots_ROS2_Driver/ur_moveit_config/srdf/ur_macro.srdf.xacro": [
            "not checked: included by src/Universal_Robots_ROS2_Driver/ur_moveit_config/srdf/ur.srdf.xacro, whose expansion did not read it (see what it says)"
        ],
        f"{TALOS}/leg/foot_collision_thinbox.urdf.xacro": [
            f"not checked: no model read it; {TALOS}/talos_full_common.urdf.xacro includes "
            "'$(find talos_description)/urdf/leg/foot_collision_$(arg foot_collision).urdf.xacro', a file name computed from what it is given"
        ],
    }
    assert document["summary"]["files"] == 13  # the models, SRDFs and generated URDFs: not the notes


@pytest.mark.parametrize(
    ("fragment", "model"),
    [
        (f"{BAXTER}/left_end_effector.urdf.xacro", f"{BAXTER}/baxter.urdf.xacro"),
        (f"{TALOS}/arm/left_arm.transmissions.urdf.xacro", "src/talos_robot/talos_description/robots/talos_full.urdf.xacro"),
        (f"{TALOS}/talos_full_common.urdf.xacro", "src/talos_robot/talos_description/robots/talos_full.urdf.xacro"),
    ],
)
def test_a_fragment_named_alone_is_checked_through_its_model(built, fragment, model):
    """As the pre-commit hook names a changed file: no 'parent link does not exist', no
    'name is not defined', no 'needs xacro argument'."""
    done = run_cli("check", fragment, cwd=built)
    assert done.returncode == 0
    assert done.stderr.decode().splitlines() == [f"{fragment}: fragment, checked through {model}", "1 file checked: 0 errors, 0 warnings"]
    assert done.stdout == b""


@pytest.mark.parametrize("model", ["src/franka_ros/franka_description/robots/panda/panda.urdf.xacro", f"{BAXTER}/baxter_base/baxter_base.urdf.xacro"])
def test_a_whole_model_that_another_includes_is_still_checked_as_itself(built, model):
    done = run_cli("check", model, cwd=built)
    assert done.returncode == 0 and done.stdout.decode().startswith("robot name is: ")


def test_a_description_model_a_moveit_config_wraps_is_checked_as_its_packages_robot(built, tmp_path):
    """panda_moveit_config's panda.urdf.xacro includes franka_description's panda.urdf.xacro,
    the robot the description launches, to add its ros2_control: the description's model is
    a model of the workspace lint, and what it finds stands when the wrapper cannot be
    expanded (the YAML it loads is gone); each finding is said once either way."""
    franka = "src/franka_ros/franka_description/robots/panda/panda.urdf.xacro"
    done, document = lint_json("src", cwd=built)
    kdl = [(f["path"], d["path"]) for f in document["files"] for d in f["diagnostics"] if d["code"] == "I011" and "franka" in d["path"]]
    assert kdl == [(franka, "src/franka_ros/franka_description/robots/common/utils.xacro")]
    workspace = tmp_path / "ws"
    shutil.copytree(built, workspace)
    (workspace / "src/panda_moveit_config/config/initial_positions.yaml").unlink()
    done, document = lint_json("src", cwd=workspace)
    codes = {(f["path"], d["code"]) for f in document["files"] for d in f["diagnostics"]}
    assert ("src/panda_moveit_config/config/panda.urdf.xacro", "X003") in codes and (franka, "I011") in codes
    # a change to the description's arm macros is checked through both, as the pre-commit hook names it
    done = run_cli("check", "src/franka_ros/franka_description/robots/common/franka_arm.xacro", cwd=built)
    assert done.stderr.decode().splitlines()[0] == (
        f"src/franka_ros/franka_description/robots/common/franka_arm.xacro: xacro library, checked through {franka}, src/panda_moveit_config/config/panda.urdf.xacro"
    )

def test_a_library_is_attributed_only_to_the_models_whose_includes_reach_it(built):
    """PR2's base: a Kinova or TALOS model whose include is computed does not include it."""
    done = run_cli("check", "src/pr2_common/pr2_description/urdf/base_v0/base.urdf.xacro", cwd=built)
    lines = done.stderr.decode().splitlines()
    assert lines == [
        "src/pr2_common/pr2_description/urdf/base_v0/base.urdf.xacro: xacro library, checked through src/pr2_common/pr2_description/robots/pr2.urdf.xacro",
        "1 file checked: 0 errors, 0 warnings",
    ]
    # A variant chosen by an argument: the model that may read it, and no other
    done = run_cli("check", f"{TALOS}/leg/foot_collision_thinbox.urdf.xacro", cwd=built)
    text = done.stderr.decode()
    assert "talos_full.urdf.xacro" in text and "baxter" not in text and "franka" not in text and "pr2" not in text


def test_a_package_missing_deep_in_an_expression_is_named_as_missing(tmp_path):
    """load_yaml('$(find pkg)/...') in a property: X004 naming the package, and a library the
    model includes is said not to be checked through it for that reason, not for its arguments."""
    package = tmp_path / "repo" / "desc"
    (tmp_path / "repo" / ".git").mkdir(parents=True)
    (package / "urdf").mkdir(parents=True)
    (package / "package.xml").write_text('<package format="2"><name>desc</name></package>\n')
    (package / "urdf" / "wheel.xacro").write_text(
        '<robot xmlns:xacro="http://ros.org/wiki/xacro"><xacro:macro name="wheel"><link name="w"/></xacro:macro></robot>\n'
    )
    (package / "urdf" / "robot.urdf.xacro").write_text(textwrap.dedent("""\
        <robot name="r" xmlns:xacro="http://ros.org/wiki/xacro">
          <xacro:property name="limits" value="${xacro.load_yaml('$(find lms1xx)/config/limits.yaml')}"/>
          <link name="base${limits['suffix']}"/>
          <xacro:include filename="$(find desc)/urdf/wheel.xacro"/>
          <xacro:wheel/>
        </robot>
        """))
    done = run_cli("check", "--format", "concise", "desc/urdf/robot.urdf.xacro", cwd=tmp_path / "repo")
    assert done.stdout.decode() == f"desc/urdf/robot.urdf.xacro:2:3: X004 error: package 'lms1xx' not found (looked in {tmp_path / 'repo'})\n"
    done = run_cli("check", "desc/urdf/wheel.xacro", cwd=tmp_path / "repo")
    assert done.returncode == 0
    assert done.stderr.decode().splitlines()[0] == (
        f"desc/urdf/wheel.xacro: not checked through desc/urdf/robot.urdf.xacro: package 'lms1xx' not found (looked in {tmp_path / 'repo'})"
    )


# Everything a careful engineer reads in a lint of the whole workspace, and why each is true.
EXPECTED = [
    # ur.urdf.xacro and ur.srdf.xacro name the robot $(arg name) before declaring it: the real xacro fails too
    ("X003", "error", "Universal_Robots_ROS2_Description/ur_description/urdf/ur.urdf.xacro", 2),
    ("X003", "error", "Universal_Robots_ROS2_Driver/ur_moveit_config/srdf/ur.srdf.xacro", 2),
    # Baxter writes <xacro:arg> inside <xacro:include>, which xacro ignores and says so
    ("X005", "warning", "baxter_common/baxter_description/urdf/baxter.urdf.xacro", 5),
    # husky_decorate makes fixed names: one info for the macro (it can be called once per robot)
    ("X105", "info", "husky/husky_description/urdf/decorations.urdf.xacro", 5),
    # clearpath_platform_description (found) and sick_description (not found) used, not declared
    ("P001", "warning", "husky/husky_description/urdf/decorations.urdf.xacro", 9),
    ("D005", "warning", "husky/husky_description/urdf/decorations.urdf.xacro", 40),
    ("P001", "warning", "husky/husky_description/urdf/decorations.urdf.xacro", 40),
    # realsense2_description, included under a condition: a fresh workspace would not install it either
    ("P001", "warning", "husky/husky_description/urdf/husky.urdf.xacro", 78),
    ("D010", "info", "husky/husky_description/urdf/wheel.urdf.xacro", 43),  # <axis rpy>, which nothing reads
    ("I011", "info", "franka_ros/franka_description/robots/common/utils.xacro", 5),  # a root with mass: KDL ignores it
    # franka_ros2's hand SRDF writes <passive_joint> inside <group>, where MoveIt never reads it
    ("K009", "warning", "panda_moveit_config/config/hand.xacro", 9),
    # PR2's wheels carry the 3.47 kg caster body's tensor: only the wheels are named
    ("I008", "warning", "pr2_common/pr2_description/urdf/base_v0/base.urdf.xacro", 38),
    ("X105", "info", "talos_robot/talos_description/urdf/torso/torso.urdf.xacro", 4),
    ("I011", "info", "talos_robot/talos_description/urdf/torso/torso.urdf.xacro", 5),
]


@pytest.mark.parametrize("absolute", [False, True], ids=["relative", "absolute"])
def test_a_workspace_lint_says_what_is_true_once_and_nothing_else(built, absolute):
    """Given as src or as its absolute path: each finding once, named relative to the
    working folder, and nothing about fragments, SRDFs read as URDFs, or other repositories."""
    done, document = lint_json(str(built / "src") if absolute else "src", cwd=built)
    found = [(d["code"], d["severity"], d["path"], d["line"]) for f in document["files"] for d in f["diagnostics"]]
    assert sorted(found) == sorted((code, severity, f"src/{path}", line) for code, severity, path, line in EXPECTED)
    assert len(found) == len(set(found))
    assert all(f["path"].startswith("src/") for f in document["files"])
    pr2 = next(d for f in document["files"] for d in f["diagnostics"] if d["code"] == "I008")
    assert "caster_rotation" not in pr2["message"] and "of 4 other links (3.473082 kg)" in pr2["message"]
    assert done.returncode == 1


def test_a_generated_urdf_says_only_what_its_source_does_not(built, tmp_path):
    """pr2.urdf, generated from pr2.urdf.xacro: the wheels' copied tensor is said once, at
    the xacro line that writes it. A copy edited by hand since says what the edit broke."""
    import shutil

    root = tmp_path / "ws"
    shutil.copytree(built, root)
    urdf = root / "src/pr2_common/pr2_description/robots/pr2.urdf"
    text = urdf.read_text()
    urdf.write_text(text.replace('<mass value="116.0"/>', '<mass value="-116.0"/>', 1))
    done, document = lint_json("src/pr2_common", cwd=root)
    found = sorted((d["code"], d["path"].split("/")[-1]) for f in document["files"] for d in f["diagnostics"])
    assert ("I008", "base.urdf.xacro") in found and ("I008", "pr2.urdf") not in found
    assert ("I001", "pr2.urdf") in found  # the negative mass is the copy's own


def repository_package(root, name: str):
    """A package ``name`` with its urdf/ folder, in a git repository at ``root``/repo."""
    package = root / "repo" / name
    (root / "repo" / ".git").mkdir(parents=True, exist_ok=True)
    (package / "urdf").mkdir(parents=True)
    (package / "package.xml").write_text(f'<package format="2"><name>{name}</name></package>\n')
    return package


def test_a_fragment_nothing_includes_is_named_once_without_its_missing_context(tmp_path):
    """TALOS's left_arm.transmissions.urdf.xacro without the arm that includes it: its
    <robot> has no name and it reads the macro's 'name'; one note, no error, not counted."""
    package = repository_package(tmp_path, "pkg")
    (package / "urdf" / "t.xacro").write_text(
        '<robot xmlns:xacro="http://ros.org/wiki/xacro"><xacro:macro name="trans" params="name side">'
        '<transmission name="${name}_${side}"/></xacro:macro></robot>\n'
    )
    fragment = package / "urdf" / "left_arm.transmissions.urdf.xacro"
    fragment.write_text(
        '<robot xmlns:xacro="http://ros.org/wiki/xacro">\n  <xacro:include filename="$(find pkg)/urdf/t.xacro"/>\n'
        '  <xacro:trans name="${name}" side="left"/>\n</robot>\n'
    )
    for given in ("pkg", "pkg/urdf/left_arm.transmissions.urdf.xacro"):
        done = run_cli("lint", given, cwd=tmp_path / "repo")
        assert done.returncode == 0, done.stdout.decode()
        assert done.stdout.decode().splitlines() == [
            "pkg/urdf/left_arm.transmissions.urdf.xacro: a fragment (its <robot> has no name) that no model includes: "
            "not checked (name 'name' is not defined, when evaluating expression 'name')",
            "0 files checked: 0 errors, 0 warnings",
        ]


def _arm_with_fragment(root, reads: str):
    """A package like ur_description: ur5e.xacro declares robot_model and includes ur.xacro, a
    fragment that declares prefix and calls the arm's macro with ``reads`` for its prefix."""
    package = repository_package(root, "arm_description")
    (package / "urdf" / "arm_macro.xacro").write_text(
        '<robot xmlns:xacro="http://ros.org/wiki/xacro">\n  <xacro:macro name="arm" params="prefix">\n'
        '    <link name="${prefix}base_link"/>\n  </xacro:macro>\n</robot>\n'
    )
    (package / "urdf" / "ur.xacro").write_text(
        '<robot xmlns:xacro="http://ros.org/wiki/xacro" name="$(arg robot_model)">\n'
        '  <xacro:arg name="prefix" default=""/>\n  <xacro:include filename="$(find arm_description)/urdf/arm_macro.xacro"/>\n'
        f'  <xacro:arm\n    prefix="{reads}"/>\n</robot>\n'
    )
    (package / "urdf" / "ur5e.xacro").write_text(
        '<robot xmlns:xacro="http://ros.org/wiki/xacro" name="ur5e">\n  <xacro:arg name="robot_model" default="ur5e"/>\n'
        '  <xacro:include filename="$(find arm_description)/urdf/ur.xacro"/>\n</robot>\n'
    )
    return package


def test_an_argument_misspelt_in_a_fragment_is_an_error_with_the_name_meant(tmp_path):
    """$(arg prefx) where only prefix is declared: xacro refuses every model, and no
    [tool.urdfcli] models setting can be what is missing: an error at the call, naming prefix."""
    package = _arm_with_fragment(tmp_path, "$(arg prefx)")
    (package / "urdf" / "alone.xacro").write_text(  # the real xacro, on the fragment made whole ($(find) aside)
        (package / "urdf" / "ur.xacro").read_text().replace("$(find arm_description)/urdf/", "").replace("$(arg robot_model)", "ur5e"))
    xacro = real_xacro(package / "urdf" / "alone.xacro")
    (package / "urdf" / "alone.xacro").unlink()
    assert xacro.returncode != 0 and "Undefined substitution argument prefx" in xacro.stderr
    for command in ("check", "lint"):
        done = run_cli(command, "--format", "concise", "arm_description/urdf/ur.xacro", cwd=tmp_path / "repo")
        out = (done.stdout + done.stderr).decode()
        assert done.returncode == 1, out
        assert "arm_description/urdf/ur.xacro:4:3: X003 error: Undefined substitution argument prefx (" in out
        assert "hint: did you mean $(arg prefix)? No <xacro:arg> declares 'prefx')" in out
        assert "needs xacro argument" not in out


def test_a_fragment_whose_models_all_need_arguments_is_a_gap_lint_fails_on(tmp_path):
    """An argument no file declares and no name is close to (given on xacro's command line): the
    models cannot be expanded without it; the fragment, which cannot be read alone, is
    then checked by nothing. X006, as for a library: lint fails, check passes."""
    _arm_with_fragment(tmp_path, "$(arg prefix)$(arg arm_side)")
    done = run_cli("lint", "--format", "concise", "arm_description/urdf/ur.xacro", cwd=tmp_path / "repo")
    out = done.stdout.decode()
    assert done.returncode == 1, out
    assert out.startswith("arm_description/urdf/ur.xacro: X006 warning: xacro fragment not checked: no model that includes it "
                          "could check it (arm_description/urdf/ur5e.xacro needs 'arm_side')")
    assert 'e.g. models = { "arm_description/urdf/ur5e.xacro" = [["arm_side:=VALUE"]] }' in out  # the model and argument it needs
    done = run_cli("check", "arm_description/urdf/ur.xacro", cwd=tmp_path / "repo")
    assert done.returncode == 0 and "X006 warning" in done.stderr.decode()
    (tmp_path / "repo" / "pyproject.toml").write_text('[tool.urdfcli]\nmodels = { "arm_description/urdf/ur5e.xacro" = [["arm_side:=left_"]] }\n')
    done = run_cli("lint", "arm_description/urdf/ur.xacro", cwd=tmp_path / "repo")
    assert done.returncode == 0 and "X006" not in done.stdout.decode(), done.stdout.decode()
    assert "fragment, checked through arm_description/urdf/ur5e.xacro [arm_side:=left_]" in done.stdout.decode()


@pytest.mark.parametrize("command", ["tree", "graph", "inertia"])
def test_a_library_given_to_draw_or_audit_names_the_model_to_give_instead(built, command, tmp_path):
    """PR2's base macros make no robot by themselves: not 'R002 <robot> has no name' and
    'R004 no <link>', but one line naming the model that includes them, exit 2, no drawing."""
    library = "src/pr2_common/pr2_description/urdf/base_v0/base.urdf.xacro"
    done = run_cli(command, library, *(["-o", str(tmp_path / "base.pdf")] if command == "graph" else []), cwd=built)
    assert done.returncode == 2
    assert done.stderr.decode() == (f"urdfcli: {library}: a xacro library (macros and properties only), which makes no robot by itself; "
                                    "give a model that includes it: src/pr2_common/pr2_description/robots/pr2.urdf.xacro\n")
    assert done.stdout == b"" and not list(tmp_path.iterdir())


def test_a_nameless_file_of_transmissions_nothing_includes_is_a_fragment_not_a_robot_without_links(tmp_path):
    """turtlebot3_manipulation's transmission.xacro: one macro and its calls, transmissions of
    joints its includer makes; no model here includes it. Not 'R002 no name', 'R004 no link'
    and a D007 per transmission: one note."""
    package = repository_package(tmp_path, "arm_description")
    (package / "urdf" / "transmission.xacro").write_text(
        '<?xml version="1.0"?>\n<robot xmlns:xacro="http://ros.org/wiki/xacro">\n'
        '  <xacro:macro name="SimpleTransmission" params="trans joint actuator">\n'
        '    <transmission name="${trans}"><type>transmission_interface/SimpleTransmission</type>'
        '<joint name="${joint}"><hardwareInterface>EffortJointInterface</hardwareInterface></joint></transmission>\n'
        '  </xacro:macro>\n'
        '  <xacro:SimpleTransmission trans="tran1" joint="joint1" actuator="motor1"/>\n'
        '  <xacro:SimpleTransmission trans="tran2" joint="joint2" actuator="motor2"/>\n</robot>\n'
    )
    for command in ("check", "lint"):
        done = run_cli(command, "arm_description/urdf/transmission.xacro", cwd=tmp_path / "repo")
        out = (done.stdout + done.stderr).decode()
        assert done.returncode == 0, out
        assert ("arm_description/urdf/transmission.xacro: a fragment (its <robot> has no name) that no model includes: "
                "not checked (it makes no link)") in out
        assert "R002" not in out and "R004" not in out and "D007" not in out
