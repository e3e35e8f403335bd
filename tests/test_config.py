"""Project configuration: discovery, selection, options, severities, paths, xacro args, errors."""

from __future__ import annotations

import json
import textwrap

import pytest
from conftest import lint_file, run_cli
from support.meshes import box
from support.meshes import write as write_mesh

from urdfcli.project.config import Config, ConfigError, Configurations, parse
from urdfcli.rules import REGISTRY

# A model with a typo (D002), an undefined material (M002), and names that break the style rules (S001, S002).
MODEL = """<robot name="r">
  <link name="base_link">
    <visual>
      <geometry><box size="1 1 1"/></geometry>
      <material name="grey"><color rgb="0.5 0.5 0.5 1"/></material>
    </visual>
  </link>
  <link name="arm"/>
  <joint name="shoulder" type="fixed">
    <parent link="base_link"/>
    <child link="arm"/>
  </joint>
</robot>
"""


def write(folder, name, text):
    path = folder / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(textwrap.dedent(text))
    return path


def codes(path, config=None):
    config = Configurations().for_input(str(path)) if config is None else config
    return sorted({d.code for d in lint_file(str(path), config).diagnostics})


def lint_json(*args, cwd=None):
    done = run_cli("lint", "--format", "json", *args, cwd=cwd)
    return done, json.loads(done.stdout or b"null")


def test_defaults_leave_style_rules_off(tmp_path):
    model = write(tmp_path, "robot.urdf", MODEL)
    assert codes(model) == ["D002", "M002"]


def test_nearest_pyproject_with_a_urdfcli_table_wins(tmp_path):
    write(tmp_path, "pyproject.toml", '[tool.urdfcli]\nextend-select = ["S"]\n')
    write(tmp_path, "sub/pyproject.toml", '[project]\nname = "x"\n')  # no [tool.urdfcli]: skipped
    model = write(tmp_path, "sub/urdf/robot.urdf", MODEL)
    assert {"S001", "S002"} <= set(codes(model))
    write(tmp_path, "sub/urdf/urdfcli.toml", 'ignore = ["D"]\n')
    assert "D002" not in codes(model) and "S001" not in codes(model)


@pytest.mark.parametrize(
    "toml",
    [
        '[tool.urdfcli]\nextend-select = ["S"]\n',
        '[ tool . "urdfcli" ]\nextend-select = ["S"]\n',
        "['tool'.'urdfcli']\nextend-select = ['S']\n",
        '[tool]\nurdfcli = { extend-select = ["S"] }\n',
        'tool.urdfcli.extend-select = ["S"]\n[project]\nname = "x"\n',
        'tool = { urdfcli = { extend-select = ["S"] } }\n',
    ],
)
def test_every_toml_spelling_of_the_table_is_found(tmp_path, toml):
    write(tmp_path, "pyproject.toml", toml)
    model = write(tmp_path, "urdf/robot.urdf", MODEL)
    assert {"S001", "S002"} <= set(codes(model))


def test_a_pyproject_without_the_table_is_not_parsed(tmp_path, monkeypatch):
    """Most pyproject.toml files are another tool's: naming urdfcli elsewhere does not make one ours."""
    from urdfcli.project import config

    write(tmp_path, "pyproject.toml", '[project]\nname = "urdfcli"\n[project.scripts]\nurdfcli = "x:y"\n[tool.ruff]\nline-length = 1\n')
    model = write(tmp_path, "urdf/robot.urdf", MODEL)
    monkeypatch.setattr(config, "_read_toml", lambda path, data: pytest.fail(f"{path} parsed"))
    assert config.Configurations().find(model.parent) is None


def test_a_run_looks_at_each_folder_once(tmp_path, monkeypatch):
    """Inputs of one repository share their ancestors: a session asks each folder once
    for its configuration, and a new session asks anew."""
    from urdfcli.project.config import Configurations

    write(tmp_path, "pyproject.toml", '[tool.urdfcli]\nextend-select = ["S"]\n')
    models = [write(tmp_path, f"robots/{name}/urdf/robot.urdf", MODEL) for name in ("a", "b")]
    asked = []
    own_config = Configurations._own
    monkeypatch.setattr(Configurations, "_own", lambda self, folder: asked.append(folder) or own_config(self, folder))
    session = Configurations()
    found = {session.find(model.parent) for model in models}
    assert found == {tmp_path / "pyproject.toml"}
    assert len(asked) == len(set(asked)) == 6  # a/urdf, a, robots, the root; then b/urdf and b only
    asked.clear()
    Configurations().find(models[0].parent)
    Configurations().find(models[0].parent)
    assert len(asked) == 2 * 4


def test_select_ignore_and_prefix_specificity(tmp_path):
    model = write(tmp_path, "robot.urdf", MODEL)
    root = tmp_path
    assert codes(model, parse({"select": ["S"]}, "t", root)) == ["S001", "S002"]
    assert codes(model, parse({"select": ["S"], "ignore": ["S002"]}, "t", root)) == ["S001"]
    # the more specific selector wins: ignore S, but select S001
    assert codes(model, parse({"extend-select": ["S001"], "ignore": ["S"]}, "t", root)) == ["D002", "M002", "S001"]
    assert codes(model, parse({"select": ["ALL"], "ignore": ["D", "M"]}, "t", root)) == ["S001", "S002"]


def test_per_file_ignores_match_globs_relative_to_the_config(tmp_path):
    write(tmp_path, "urdfcli.toml", '[per-file-ignores]\n"legacy/*.urdf" = ["D002"]\n')
    legacy = write(tmp_path, "legacy/old.urdf", MODEL)
    current = write(tmp_path, "new/robot.urdf", MODEL)
    assert "D002" not in codes(legacy)
    assert "D002" in codes(current)


def test_severity_overrides_decide_the_exit_code(tmp_path):
    model = write(tmp_path, "robot.urdf", MODEL)
    write(tmp_path, "urdfcli.toml", '[severity]\nD = "info"\nM002 = "info"\n')
    done, report = lint_json(str(model))
    assert {d["severity"] for d in report["files"][0]["diagnostics"]} == {"info"}
    assert done.returncode == 0
    write(tmp_path, "urdfcli.toml", '[severity]\nM002 = "error"\n')
    done, report = lint_json(str(model))
    assert done.returncode == 1 and report["files"][0]["ok"] is False


def test_rule_options_change_what_the_style_rules_accept(tmp_path):
    model = write(tmp_path, "robot.urdf", MODEL)
    config = parse({"select": ["S"], "options": {"link-name-suffix": {"exempt": ["arm"]}, "S002": {"suffix": "_j"}}}, "t", tmp_path)
    diagnostics = lint_file(str(model), config).diagnostics
    assert [d.code for d in diagnostics] == ["S002"]
    assert "does not end in '_j'" in diagnostics[0].message


def test_package_paths_are_relative_to_the_config(tmp_path):
    write(tmp_path, "vendor/arm_pkg/package.xml", "<package><name>arm_pkg</name></package>")
    write_mesh(tmp_path / "vendor/arm_pkg/meshes/arm.stl", box())
    model = write(tmp_path, "urdf/robot.urdf", '<robot name="r"><link name="a"><visual><geometry><mesh filename="package://arm_pkg/meshes/arm.stl"/></geometry></visual></link></robot>')
    assert "D005" in codes(model)
    write(tmp_path, "urdfcli.toml", 'package-paths = ["vendor"]\n')
    assert codes(model) == []


def test_xacro_args_per_file(tmp_path):
    model = write(
        tmp_path,
        "urdf/robot.urdf.xacro",
        """\
        <robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
          <xacro:arg name="prefix" default=""/>
          <link name="$(arg prefix)base_link"/>
        </robot>
        """,
    )
    write(tmp_path, "urdfcli.toml", '[xacro-args]\n"urdf/*.urdf.xacro" = { prefix = "Left" }\n')
    config = Configurations().for_input(str(model)).overridden(select=["S003"])
    [diagnostic] = lint_file(str(model), config).diagnostics
    assert diagnostic.message == "link name 'Leftbase_link' is not snake_case"


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ('selct = ["D"]\n', "unknown key 'selct' (did you mean 'select'?)"),
        ('select = ["Q123"]\n', "unknown rule code or prefix 'Q123'"),
        ('ignore = "D001"\n', None),  # a comma-separated string is accepted
        ('[severity]\nD001 = "fatal"\n', "'fatal' is not error, warning or info"),
        ('[options.S001]\nsufix = "_l"\n', "has no option 'sufix' (did you mean 'suffix'?)"),
        ('[options.S001]\nsuffix = 3\n', "option 'suffix' must be a string, not 3"),
        ('[options.Z999]\nsuffix = "_l"\n', "unknown rule 'Z999'"),
        ('select = [\n', "not valid TOML"),
    ],
)
def test_configuration_mistakes_are_one_line_and_exit_2(tmp_path, text, message):
    write(tmp_path, "urdfcli.toml", text)
    model = write(tmp_path, "robot.urdf", MODEL)
    done = run_cli("lint", str(model))
    if message is None:
        assert done.returncode in (0, 1)
        return
    assert done.returncode == 2
    err = done.stderr.decode()
    assert message in err and "Traceback" not in err and len(err.strip().splitlines()) == 1
    assert str(tmp_path / "urdfcli.toml") in err


def test_command_line_overrides_the_file(tmp_path):
    write(tmp_path, "urdfcli.toml", 'select = ["D"]\n')
    model = write(tmp_path, "robot.urdf", MODEL)
    _, report = lint_json(str(model))
    assert {d["code"] for d in report["files"][0]["diagnostics"]} == {"D002"}
    _, report = lint_json("--select", "S001,M", str(model))
    assert {d["code"] for d in report["files"][0]["diagnostics"]} == {"S001", "M002"}
    _, report = lint_json("--ignore", "D002", str(model))
    assert report["files"][0]["diagnostics"] == []
    done = run_cli("lint", "--select", "NOPE", str(model))
    assert done.returncode == 2 and "unknown rule code or prefix 'NOPE'" in done.stderr.decode()


def test_explicit_config_file(tmp_path):
    other = write(tmp_path, "elsewhere/settings.toml", 'select = ["S002"]\n')
    model = write(tmp_path, "robot.urdf", MODEL)
    _, report = lint_json("--config", str(other), str(model))
    assert [d["code"] for d in report["files"][0]["diagnostics"]] == ["S002"]
    done = run_cli("lint", "--config", str(tmp_path / "missing.toml"), str(model))
    assert done.returncode == 2 and "no such configuration file" in done.stderr.decode()


def test_everything_selects_every_rule():
    config = Config.everything()
    assert all(config.enabled(rule, "x.urdf") for rule in REGISTRY.values())
    with pytest.raises(ConfigError):
        Config().overridden(select=["not-a-code"])


def test_the_readme_example_configuration_is_valid(tmp_path):
    import re
    import tomllib

    from conftest import ROOT

    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    [example] = [block for block in re.findall(r"```toml\n(.*?)```", readme, re.DOTALL) if "[tool.urdfcli]" in block]
    config = parse(tomllib.loads(example)["tool"]["urdfcli"], "README", tmp_path)
    assert config.select == ("ALL",) and config.mappings_for(str(tmp_path / "urdf/robot.urdf.xacro")) == {"use_gpu": "false", "prefix": ""}
    assert config.package_paths == (str(tmp_path.parent / "vendor"), f"my_robot={tmp_path / 'src/my_robot'}")


# -- every command reads the same configuration -----------------------------------
# A zero axis on a revolute joint: an error for check, tree, graph and lint alike.
ZERO_AXIS = """<robot name="r">
  <link name="base_link"/>
  <link name="arm"/>
  <joint name="shoulder" type="revolute">
    <parent link="base_link"/>
    <child link="arm"/>
    <axis xyz="0 0 0"/>  <!-- urdfcli: noqa: J007 -->
    <limit lower="-1" upper="1" effort="1" velocity="1"/>
  </joint>
</robot>
"""


def test_check_honours_noqa_severity_ignore_and_isolated(tmp_path):
    quiet = write(tmp_path, "quiet/robot.urdf", ZERO_AXIS)
    assert run_cli("check", str(quiet)).returncode == 0  # the noqa comment silences J007
    loud = write(tmp_path, "loud/robot.urdf", ZERO_AXIS.replace("  <!-- urdfcli: noqa: J007 -->", ""))
    done = run_cli("check", str(loud))
    assert done.returncode == 1 and "J007 error" in done.stderr.decode()
    write(tmp_path, "loud/pyproject.toml", '[tool.urdfcli.severity]\nJ007 = "warning"\n')
    done = run_cli("check", str(loud))
    assert done.returncode == 0 and "J007 warning" in done.stderr.decode()
    assert run_cli("check", "--strict", str(loud)).returncode == 1
    write(tmp_path, "loud/pyproject.toml", '[tool.urdfcli]\nignore = ["J007"]\n')
    done = run_cli("check", str(loud))
    assert done.returncode == 0 and "J007" not in done.stderr.decode()
    done = run_cli("check", "--isolated", str(loud))
    assert done.returncode == 1 and "J007 error" in done.stderr.decode()


def test_inertia_honours_noqa_and_severity(tmp_path):
    heavy_root = """<robot name="r">
  <link name="base_link">
    <inertial><mass value="5"/>  <!-- urdfcli: noqa: I011 --><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>
  </link>
</robot>
"""
    model = write(tmp_path, "robot.urdf", heavy_root)
    plain = write(tmp_path, "plain/robot.urdf", heavy_root.replace("  <!-- urdfcli: noqa: I011 -->", ""))
    found = run_cli("inertia", "--format", "json", "--isolated", str(plain))
    codes_found = {p["code"] for link in json.loads(found.stdout)["links"] for p in link["problems"]}
    assert "I011" in codes_found
    silenced = run_cli("inertia", "--format", "json", str(model))
    assert "I011" not in {p["code"] for link in json.loads(silenced.stdout)["links"] for p in link["problems"]}
    write(tmp_path, "plain/urdfcli.toml", 'ignore = ["I011"]\n')
    ignored = run_cli("inertia", "--format", "json", str(plain))
    assert "I011" not in {p["code"] for link in json.loads(ignored.stdout)["links"] for p in link["problems"]}
    again = run_cli("inertia", "--format", "json", "--isolated", str(plain))
    assert {p["code"] for link in json.loads(again.stdout)["links"] for p in link["problems"]} == codes_found


def test_tree_and_graph_read_xacro_args_and_package_paths_from_the_config(tmp_path):
    write(tmp_path, "vendor/parts/package.xml", "<package><name>acme_parts</name></package>")
    write(tmp_path, "vendor/parts/urdf/arm.xacro", """\
        <robot xmlns:xacro="http://www.ros.org/wiki/xacro">
          <link name="$(arg prefix)arm"/>
          <joint name="$(arg prefix)shoulder" type="fixed"><parent link="base_link"/><child link="$(arg prefix)arm"/></joint>
        </robot>
        """)
    model = write(tmp_path, "robots/urdf/robot.urdf.xacro", """\
        <robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
          <link name="base_link"/>
          <xacro:include filename="$(find acme_parts)/urdf/arm.xacro"/>
        </robot>
        """)
    write(tmp_path, "robots/pyproject.toml", '[tool.urdfcli]\npackage-paths = ["../vendor"]\n[tool.urdfcli.xacro-args]\n"urdf/*.urdf.xacro" = { prefix = "left_" }\n')
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    for cwd in (elsewhere, model.parent):  # globs and paths are relative to the config's folder
        done = run_cli("tree", "--ascii", str(model), cwd=cwd)
        assert done.returncode == 0, done.stderr.decode()
        assert "left_arm" in done.stdout.decode()
        done = run_cli("graph", "--format", "dot", str(model), cwd=cwd)
        assert done.returncode == 0 and "left_arm" in done.stdout.decode()
    isolated = run_cli("tree", "--isolated", str(model), cwd=elsewhere)
    assert isolated.returncode != 0 and "acme_parts" in isolated.stderr.decode()


def test_per_file_ignores_do_not_depend_on_the_working_directory(tmp_path):
    write(tmp_path, "urdfcli.toml", '[per-file-ignores]\n"legacy/*.urdf" = ["D002"]\n"robot.urdf" = ["M002"]\n')
    legacy = write(tmp_path, "legacy/robot.urdf", MODEL)
    other = write(tmp_path, "other/legacy/robot.urdf", MODEL)  # legacy/robot.urdf only from other/
    for cwd in (tmp_path, legacy.parent, other.parent.parent):
        _, report = lint_json(str(legacy), str(other), cwd=cwd)
        found = [{d["code"] for d in f["diagnostics"]} for f in report["files"]]
        assert found == [set(), {"D002"}]  # a glob with no '/' matches the name anywhere


def test_a_missing_argument_names_the_others_the_files_read_without_a_default(tmp_path):
    """xacro stops at the first argument without a value: the hint gives the others the
    files read too (not those declared with a default, nor those given), all at once."""
    write(tmp_path, "pkg/urdf/sensor.xacro", """\
        <robot xmlns:xacro="http://www.ros.org/wiki/xacro">
          <link name="$(arg sensor)"/>
          <joint name="sensor_joint" type="fixed"><parent link="base"/><child link="$(arg sensor)"/></joint>
        </robot>
        """)
    model = write(tmp_path, "pkg/urdf/arm.urdf.xacro", """\
        <robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">
          <xacro:arg name="prefix" default=""/>
          <link name="base"/>
          <xacro:include filename="sensor.xacro"/>
          <link name="$(arg prefix)$(arg arm_type)_arm"/>
          <joint name="arm_joint" type="fixed"><parent link="base"/><child link="$(arg prefix)$(arg arm_type)_arm"/></joint>
          <link name="$(arg tool)"/>
          <joint name="tool_joint" type="fixed"><parent link="base"/><child link="$(arg tool)"/></joint>
        </robot>
        """)
    done = run_cli("check", "--format", "json", str(model), "tool:=flange")
    [diagnostic] = json.loads(done.stdout)["files"][0]["diagnostics"]
    assert diagnostic["message"].startswith("needs xacro argument 'sensor'")
    assert diagnostic["hint"].startswith("give sensor:=VALUE arm_type:=VALUE after the file on the command line "
                                         "(the files also read 'arm_type' without a <xacro:arg> default: they may be needed too)")
    assert '{ sensor = "VALUE", arm_type = "VALUE" }' in diagnostic["hint"]
    done = run_cli("check", str(model), "tool:=flange", "sensor:=camera", "arm_type:=small")
    assert done.returncode == 0, done.stdout.decode()


def test_models_are_checked_once_per_argument_set(tmp_path):
    model = write(tmp_path, "pkg/urdf/arm.urdf.xacro", """\
        <robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">
          <link name="$(arg arm_type)_base"/>
        </robot>
        """)
    done = run_cli("check", "--format", "json", str(model))
    [file] = json.loads(done.stdout)["files"]
    assert done.returncode == 1
    [diagnostic] = file["diagnostics"]
    assert diagnostic["code"] == "X003" and diagnostic["message"].startswith("needs xacro argument 'arm_type': it has no value where it is used")
    assert "give it in the configuration" in diagnostic["message"] and "[tool.urdfcli] models" in diagnostic["hint"]
    write(tmp_path, "pyproject.toml", '[tool.urdfcli]\nmodels = { "pkg/urdf/arm.urdf.xacro" = [["arm_type:=small"], ["arm_type:=large"]] }\n')
    done = run_cli("check", "--format", "json", str(model), cwd=model.parent)
    assert done.returncode == 0, done.stdout.decode()
    files = json.loads(done.stdout)["files"]
    assert [(f["arguments"], f["diagnostics"]) for f in files] == [({"arm_type": "small"}, []), ({"arm_type": "large"}, [])]
    done = run_cli("check", str(model))
    assert "==> " in done.stdout.decode() and "[arm_type:=large] <==" in done.stdout.decode()


def test_command_line_arguments_choose_among_the_configured_sets(tmp_path):
    # one file per arm chosen by robot_model, as Interbotix's interbotix_arm.urdf.xacro does
    model = write(tmp_path, "pkg/urdf/arm.urdf.xacro", """\
        <robot name="arm" xmlns:xacro="http://ros.org/wiki/xacro">
          <xacro:arg name="robot_model" default="small"/>
          <xacro:arg name="world" default="false"/>
          <link name="$(arg robot_model)_base"/>
          <xacro:if value="$(arg world)">
            <link name="world"/>
            <joint name="fixed" type="fixed"><parent link="world"/><child link="$(arg robot_model)_base"/></joint>
          </xacro:if>
        </robot>
        """)
    write(tmp_path, "pyproject.toml", '[tool.urdfcli]\nmodels = { "pkg/urdf/arm.urdf.xacro" = [["robot_model:=small", "world:=true"], ["robot_model:=large"]] }\n')

    def runs(*arguments):
        done = run_cli("check", "--format", "json", str(model), *arguments)
        return [f["arguments"] for f in json.loads(done.stdout)["files"]]

    # the set that agrees with what is given, not every set with the given value ignored
    assert runs("robot_model:=large") == [{"robot_model": "large"}]
    # an argument no set gives applies to each
    assert runs("world:=true") == [{"robot_model": "small", "world": "true"}, {"robot_model": "large", "world": "true"}]
    # none agrees: the model is checked once, with what is given
    assert runs("robot_model:=medium") == [{"robot_model": "medium"}]
    assert runs() == [{"robot_model": "small", "world": "true"}, {"robot_model": "large"}]
    # a model read once (tree, expand) takes the first set that agrees, not the first set
    tree = run_cli("tree", str(model), "robot_model:=large").stdout.decode()
    assert tree.splitlines()[0] == "large_base"


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ('models = { "a.urdf.xacro" = ["x:=1"] }\n', "expected a list of argument lists"),
        ('models = { "a.urdf.xacro" = [["x=1"]] }\n', "expected NAME:=VALUE, not 'x=1'"),
    ],
)
def test_models_mistakes_are_one_line(tmp_path, text, message):
    write(tmp_path, "urdfcli.toml", text)
    model = write(tmp_path, "robot.urdf", MODEL)
    done = run_cli("check", str(model))
    assert done.returncode == 2 and message in done.stderr.decode() and len(done.stderr.decode().strip().splitlines()) == 1


def test_tree_and_graph_honour_noqa_ignore_and_isolated(tmp_path):
    quiet = write(tmp_path, "quiet/robot.urdf", ZERO_AXIS)
    loud = write(tmp_path, "loud/robot.urdf", ZERO_AXIS.replace("  <!-- urdfcli: noqa: J007 -->", ""))
    for command in (["tree", "--ascii"], ["graph", "--format", "dot"]):
        assert run_cli(*command, str(quiet)).returncode == 0
        done = run_cli(*command, str(loud))
        assert done.returncode == 1 and "J007 error" in done.stderr.decode()
        write(tmp_path, "loud/urdfcli.toml", 'ignore = ["J007"]\n')
        assert run_cli(*command, str(loud)).returncode == 0
        assert run_cli(*command, "--isolated", str(loud)).returncode == 1
        (tmp_path / "loud/urdfcli.toml").unlink()
