"""`urdfcli lsp` driven over stdio by a real LSP client (pytest-lsp's, see lsp_client.py),
on a repository laid out as real ones are: a model in one package, the macro library
it includes from another (tests/ros_workspace.py)."""

from __future__ import annotations

import asyncio
import io
import json
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path
from urllib.parse import urlparse
from urllib.request import url2pathname

import pytest
from conftest import FIXTURES, run_cli
from models import CRATE
from lsp_client import Wire, editing, position, process_alive, process_tree, server_memory_kib, uri
from lsprotocol import types
from ros_workspace import line_of, make_repository

pytestmark = pytest.mark.filterwarnings("error::pytest_lsp.LspSpecificationWarning")


@pytest.fixture
def repository(tmp_path: Path) -> Path:
    root = make_repository(tmp_path / "acme")
    (root / ".git").mkdir()
    return root


@pytest.fixture
def cache(tmp_path: Path) -> Path:
    """The server's cache folder (its rule pages), apart from the files it checks."""
    return tmp_path / "cache"


def rover(root: Path) -> Path:
    return root / "description" / "urdf" / "rover.urdf.xacro"


def wheel(root: Path) -> Path:
    return root / "common" / "urdf" / "wheel.xacro"


def codes(diagnostics) -> list[tuple[str | None, int]]:
    """Each diagnostic's code and 1-based line, sorted."""
    return sorted((d.code, d.range.start.line + 1) for d in diagnostics)


def line_in(text: str, needle: str) -> int:
    """The 1-based line of the first ``needle`` in ``text``."""
    return text[: text.index(needle)].count("\n") + 1


def path_of(location_uri: str) -> Path:
    return Path(url2pathname(urlparse(location_uri).path))


# -- diagnostics ----------------------------------------------------------------------------
@pytest.mark.asyncio
async def test_a_library_is_checked_through_the_models_that_include_it_with_its_unsaved_text(repository, cache):
    async with editing(repository, cache) as editor:
        editor.open(rover(repository))
        editor.open(wheel(repository))
        assert await editor.diagnostics(rover(repository)) == []
        assert await editor.diagnostics(wheel(repository)) == []
        mark = editor.mark()
        editor.edit(wheel(repository), 'length="${wheel_length}"/></geometry>\n      </visual>', 'length="${wheel_lenth}"/></geometry>\n      </visual>')
        await editor.diagnostics(wheel(repository))  # not saved: the editor's text stands for the file
        await editor.diagnostics(rover(repository), mark)  # the model that reads it is checked again too
        found = editor.latest(wheel(repository))
        assert codes(found) == [("X003", line_of(wheel(repository), '<geometry><cylinder radius="${radius}" length="${wheel_length}"/></geometry>'))]
        (error,) = found
        assert error.severity == types.DiagnosticSeverity.Error and error.source == "urdfcli"
        assert "wheel_lenth" in error.message
        # the macro call that ran into it, in the model of the other package
        calls = {(path_of(r.location.uri), r.location.range.start.line + 1) for r in error.related_information}
        assert (rover(repository), line_of(rover(repository), '<xacro:wheel prefix="left"')) in calls
        assert all("in macro 'wheel' called here" == r.message for r in error.related_information)
        # the code links to the rule's documentation, a page the client can open
        page = path_of(error.code_description.href).read_text()
        assert page.startswith("# X003 ") and "## What it does" in page
        mark = editor.mark()
        editor.save(wheel(repository))
        assert codes(await editor.diagnostics(wheel(repository), mark)) == codes(found)
        editor.edit(wheel(repository), "${wheel_lenth}", "${wheel_length}")
        assert await editor.diagnostics(wheel(repository)) == []


@pytest.mark.asyncio
async def test_a_library_edit_checks_and_publishes_first_the_model_the_user_looked_at_last(repository, cache):
    library, rover_model, arm_model = wheel(repository), rover(repository), repository / "description" / "urdf" / "arm.urdf.xacro"
    async with editing(repository, cache) as editor:
        for model in (rover_model, arm_model):
            editor.open(model)
            await editor.diagnostics(model)
        # the library opened from one model (its macro's definition), then from the other
        for looked, other in ((arm_model, rover_model), (rover_model, arm_model)):
            value = "0.04"  # (as on disk)
            assert await editor.definition(looked, "<xacro:wheel ", 8)  # the user in this model
            mark = editor.mark()
            editor.open(library)
            for path in (library, looked, other):  # the library, and the models that read it checked again
                await editor.diagnostics(path, mark)
            for typed in ("0.05", "0.06"):  # keystrokes in the library
                mark = editor.mark()
                editor.edit(library, f'name="wheel_length" value="{value}"', f'name="wheel_length" value="{typed}"')
                value = typed
                await editor.diagnostics(library, mark)
                await editor.diagnostics(other, mark)
                published = [(p.uri, p.version) for p in editor.published[mark:]]
                first = {uri(path): next(i for i, (u, version) in enumerate(published) if u == uri(path) and version == editor.versions[path]) for path in (looked, library, other)}
                assert first[uri(looked)] < first[uri(library)] < first[uri(other)], (looked.name, published)
            editor.close(library)


@pytest.mark.asyncio
async def test_a_model_publishes_each_diagnostic_to_the_file_it_points_into(repository, cache):
    model, library = rover(repository), wheel(repository)
    async with editing(repository, cache) as editor:
        editor.open(model)
        assert await editor.diagnostics(model) == []
        mark = editor.mark()
        editor.edit(model, '<xacro:wheel prefix="left" parent="base_link" radius="0.1">', '<xacro:wheel prefix="left" parent="base_link" radius="-0.1">')
        call = line_of(model, '<xacro:wheel prefix="left"')
        at_call = await editor.diagnostics(model)  # where the argument was typed, the macro's lines as related information
        assert [(d.code, d.range.start.line + 1) for d in at_call] == [("V006", call)]
        cylinders = {line_of(library, "<visual>") + 1, line_of(library, "<collision>") + 1}
        assert {(path_of(r.location.uri), r.location.range.start.line + 1) for r in at_call[0].related_information} == {(library, line) for line in cylinders}
        in_library = await editor.diagnostics(library, mark)  # the library is not even open
        assert {d.code for d in in_library} >= {"V006"}
        assert {d.range.start.line + 1 for d in in_library if d.code == "V006"} == cylinders
        assert all((path_of(r.location.uri), r.location.range.start.line + 1) == (model, call) for d in in_library for r in d.related_information)
        mark = editor.mark()
        editor.edit(model, 'radius="-0.1"', 'radius="0.1"')
        assert await editor.diagnostics(library, mark) == []  # cleared once nothing points there


@pytest.mark.asyncio
async def test_configuration_and_noqa_apply_as_on_the_command_line(tmp_path, cache):
    """The fixture models with a configuration and a noqa comment: what the server
    publishes, file by file, is what `urdfcli lint` prints."""
    root = tmp_path / "fixtures"
    for folder in ("seed000", "urdf02_gazebo"):
        shutil.copytree(FIXTURES / folder, root / folder)
    (root / "urdfcli.toml").write_text('extend-select = ["S"]\nignore = ["D003"]\n[severity]\nI009 = "error"\n')
    my_robot = root / "seed000" / "my_robot.urdf"
    my_robot.write_text(my_robot.read_text().replace('  <link name="link1">', '  <!-- urdfcli: noqa: I002 -->\n  <link name="link1">'))
    models = sorted(p for p in root.rglob("*") if p.name.endswith((".urdf", ".urdf.xacro")))
    expected: dict[Path, set] = {}
    for model in models:
        report = json.loads(run_cli("lint", "--format", "json", str(model), cwd=root).stdout)
        for file in report["files"]:
            for d in file["diagnostics"]:
                expected.setdefault((root / d["path"]).resolve(), set()).add((d["code"], d["severity"], d["line"] or 1, d["message"]))
    found = {code for diagnostics in expected.values() for code, *_ in diagnostics}
    assert {"S001", "I009"} <= found and not {"D003", "I002", "U001"} & found  # the configuration and the comment at work
    assert ("I009", "error") in {(code, severity) for diagnostics in expected.values() for code, severity, *_ in diagnostics}
    severities = {types.DiagnosticSeverity.Error: "error", types.DiagnosticSeverity.Warning: "warning", types.DiagnosticSeverity.Information: "info"}
    async with editing(root, cache) as editor:
        published: dict[Path, dict] = {}
        for model in models:
            mark = editor.mark()
            editor.open(model)
            await editor.diagnostics(model)
            for params in editor.published[mark:]:
                file = path_of(params.uri).resolve()
                for d in params.diagnostics:
                    # a diagnostic shown again at the macro call in the open file that caused it: the
                    # command line says so in a note under the diagnostic (a fragment, demo06_car_camera,
                    # is checked through the car models, whose macros it calls)
                    at_call = re.search(r" \(in macro '[^']*', [^()]*:\d+\)", d.message)
                    if d.code and not at_call:
                        published.setdefault(file, {})[(d.code, severities[d.severity], d.range.start.line + 1)] = d.message.split("\nhint: ")[0]
            editor.close(model)
    # one diagnostic per rule and line, the others on that line counted in it
    lines: dict[Path, dict] = {}
    for file, found in expected.items():
        for code, severity, line, message in found:
            lines.setdefault(file, {}).setdefault((code, severity, line), set()).add(message)
    assert {p: set(found) for p, found in published.items() if found} == {p: set(found) for p, found in lines.items()}
    for file, found in published.items():
        for key, message in found.items():
            first, _, more = message.partition("\n(and ")
            assert first in lines[file][key]
            # a library's or fragment's mistake written once in a macro is said once, whatever the calls
            # that copied it (as the command line says it for that file): never more than the models found
            assert 1 + (int(more.split()[0]) if more else 0) <= len(lines[file][key])


@pytest.mark.asyncio
async def test_configuration_files_and_changes_on_disk_are_picked_up(repository, cache):
    model = rover(repository)
    async with editing(repository, cache) as editor:
        editor.open(model)
        assert await editor.diagnostics(model) == []
        # a checkout changes the library on disk, not open in the editor
        library = wheel(repository)
        library.write_text(library.read_text().replace('<axis xyz="0 0 1"/>', '<axis xyz="0 0 0"/>'))
        editor.changed_on_disk(library)
        mark = editor.mark()
        found = await editor.diagnostics(library, mark)
        assert "J007" in {d.code for d in found}
        # a configuration that ignores the rule, written next to the repository's pyproject.toml
        (repository / "urdfcli.toml").write_text('ignore = ["J007"]\n')
        editor.changed_on_disk(repository / "urdfcli.toml")
        mark = editor.mark()
        assert await editor.diagnostics(library, mark) == []
        assert [r.method for r in editor.registrations] == [types.WORKSPACE_DID_CHANGE_WATCHED_FILES]


# -- navigation -------------------------------------------------------------------------------
@pytest.mark.asyncio
async def test_hover_shows_rule_docs_property_values_and_macro_parameters(repository, cache):
    model, library = rover(repository), wheel(repository)
    async with editing(repository, cache) as editor:
        editor.open(model)
        editor.open(library)
        await editor.diagnostics(library)
        editor.edit(library, '<axis xyz="0 0 1"/>', '<axis xyz="0 0 0"/>')
        assert "J007" in {d.code for d in await editor.diagnostics(library)}
        text = await editor.hover(library, '<axis xyz="0 0 0"/>', 1)
        assert "**J007**" in text and "### What it does" in text and "zero" in text
        assert "`wheel_length` = `0.04`" in await editor.hover(library, "${wheel_length}", 3)
        defined = line_of(library, 'name="wheel_length"')
        assert f"wheel.xacro:{defined}" in await editor.hover(library, "${wheel_length}", 3)
        macro = await editor.hover(model, "<xacro:wheel", 8)
        assert "**macro** `wheel`" in macro and "`prefix`, `parent`, `radius`, `*origin`" in macro
        assert "**parameter** `radius` of macro `wheel`" in await editor.hover(library, 'radius="${radius}"', 11)
        assert await editor.hover(model, "<robot", 2) is None
        assert await editor.hover(model, "$(find acme_common)", 9) == f"**package** `acme_common`: `{repository / 'common'}`"
        editor.edit(model, '<link name="base_footprint"/>', '<xacro:arg name="footprint" default="base_footprint"/>\n  <link name="$(arg footprint)"/>')
        argument = await editor.hover(model, "$(arg footprint)", 8)
        assert argument.startswith("**argument** `footprint`, default `base_footprint`") and "rover.urdf.xacro:4" in argument


@pytest.mark.asyncio
async def test_go_to_definition_of_macros_properties_arguments_includes_and_links(repository, cache):
    model, library = rover(repository), wheel(repository)
    inertia = repository / "common" / "urdf" / "inertia.xacro"
    async with editing(repository, cache) as editor:
        text = model.read_text().replace('<link name="base_footprint"/>', '<xacro:arg name="footprint" default="base_footprint"/>\n  <link name="$(arg footprint)"/>')
        text = text.replace("</robot>", '  <link name="caster"><visual><geometry><mesh filename="package://acme_common/meshes/caster.stl"/></geometry></visual></link>\n'
                            '  <joint name="caster_joint" type="fixed"><parent link="left_wheel_link"/><child link="caster"/></joint>\n</robot>')
        (repository / "common" / "meshes").mkdir()
        (repository / "common" / "meshes" / "caster.stl").write_text("solid caster\nendsolid caster\n")
        editor.open(model, text)
        editor.open(library)
        await editor.diagnostics(model)

        def places(found):
            return [(path_of(f.uri), f.range.start.line + 1) for f in found]

        assert places(await editor.definition(model, "<xacro:wheel", 8)) == [(library, line_of(library, '<xacro:macro name="wheel"'))]
        assert places(await editor.definition(model, "<xacro:box_inertial", 8)) == [(inertia, line_of(inertia, '<xacro:macro name="box_inertial"'))]
        assert places(await editor.definition(library, "${wheel_length}", 3)) == [(library, line_of(library, 'name="wheel_length"'))]
        assert places(await editor.definition(library, 'radius="${radius}"', 11)) == [(library, line_of(library, '<xacro:macro name="wheel"'))]
        assert places(await editor.definition(model, "$(arg footprint)", 8)) == [(model, 4)]
        assert places(await editor.definition(model, "$(find acme_common)/urdf/wheel.xacro", 25)) == [(library, 1)]
        editor.edit(model, "<link name=\"$(arg footprint)\"/>", '<link name="$(arg footprint)"/>\n  <xacro:include filename="../../common/urdf/inertia.xacro"/>')
        assert places(await editor.definition(model, "../../common/urdf/inertia.xacro", 3)) == [(inertia, 1)]
        assert places(await editor.definition(model, "$(find acme_common)", 9)) == [(repository / "common" / "package.xml", 1)]
        assert places(await editor.definition(model, "package://acme_common/meshes", 5)) == [(repository / "common" / "meshes" / "caster.stl", 1)]
        assert places(await editor.definition(model, 'parent="base_link"', 9)) == [(model, line_in(editor.texts[model], '<link name="base_link"'))]
        # a link made by a macro: the call that made it, then where the macro writes it
        assert places(await editor.definition(model, '<parent link="left_wheel_link"', 16)) == [
            (model, line_in(editor.texts[model], '<xacro:wheel prefix="left"')),
            (library, line_of(library, '<link name="${prefix}_wheel_link">')),
        ]


@pytest.mark.asyncio
async def test_completion_of_link_names_and_macro_names(repository, cache):
    model = rover(repository)
    async with editing(repository, cache) as editor:
        editor.open(model)
        await editor.diagnostics(model)
        editor.edit(model, "</robot>", '  <joint name="extra" type="fixed"><parent link=""/><child link="base_"/></joint>\n  <xacro:\n</robot>')
        links = [item.label for item in await editor.completion(model, '<parent link=""', 14)]
        assert links == ["base_footprint", "base_link", "left_wheel_link", "right_wheel_link"]
        child = await editor.completion(model, '<child link="base_"', 18)
        typed = types.Range(position(editor.texts[model], 'base_"/>'), position(editor.texts[model], 'base_"/>', len("base_")))
        assert child and all(item.text_edit.range == typed for item in child)  # the link's name replaces what was typed
        macros = await editor.completion(model, "  <xacro:\n", 9)
        labels = [item.label for item in macros]
        assert labels[:3] == ["box_inertial", "cylinder_inertial", "wheel"] and "property" in labels
        assert macros[2].detail.startswith("wheel(prefix parent radius *origin)")
        assert await editor.completion(model, "<robot", 3) == []


# -- quick fixes --------------------------------------------------------------------------------
@pytest.mark.asyncio
async def test_a_code_action_adds_a_noqa_comment_that_silences_the_diagnostic(repository, cache):
    library = wheel(repository)
    async with editing(repository, cache) as editor:
        editor.open(rover(repository))
        editor.open(library)
        await editor.diagnostics(library)
        editor.edit(library, '<axis xyz="0 0 1"/>', '<axis xyz="0 0 0"/>')
        found = await editor.diagnostics(library)
        (zero_axis,) = [d for d in found if d.code == "J007"]
        actions = await editor.code_actions(library, [zero_axis])
        (noqa,) = [a for a in actions if "noqa" in a.title]
        editor.apply(noqa)
        assert '      <!-- urdfcli: noqa: J007 -->\n      <axis xyz="0 0 0"/>' in editor.texts[library]
        assert "J007" not in {d.code for d in await editor.diagnostics(library)}
        assert "U001" not in {d.code for d in editor.latest(library)}  # the comment silences something


@pytest.mark.asyncio
async def test_a_code_action_replaces_an_inertial_by_the_one_inertia_suggest_gives(tmp_path, cache):
    model = tmp_path / "crate.urdf"
    model.write_text(CRATE)
    suggested = run_cli("inertia", "--suggest", str(model)).stdout.decode()
    async with editing(tmp_path, cache) as editor:
        editor.open(model)
        found = await editor.diagnostics(model)
        flagged = [d for d in found if d.code in ("I007", "I009")]
        assert flagged
        actions = [a for a in await editor.code_actions(model, flagged) if "<inertial>" in a.title]
        assert actions
        editor.apply(actions[0])
        written = editor.texts[model]
        assert 'ixx="1"' not in written
        assert written[written.index("<inertial>") : written.index("</inertial>")].split() == suggested[suggested.index("<inertial>") : suggested.index("</inertial>")].split()
        assert not {"I007", "I009"} & {d.code for d in await editor.diagnostics(model)}


@pytest.mark.asyncio
async def test_a_code_action_gives_the_macro_call_with_the_geometrys_values(repository, cache):
    model, library = rover(repository), repository / "common" / "urdf" / "inertia.xacro"
    async with editing(repository, cache) as editor:
        editor.open(model)
        editor.open(library)
        await editor.diagnostics(model)
        await editor.diagnostics(library)
        mark = editor.mark()
        editor.edit(model, '<xacro:box_inertial mass="5" x="0.4" y="0.3" z="0.1"/>', '<xacro:box_inertial mass="5" x="0.1" y="0.3" z="0.4"/>')
        # the tensor is written in the library's macro: the diagnostic is there, with the call
        flagged = [d for d in await editor.diagnostics(library, mark) if d.code == "I009"]
        assert [r.location.uri for d in flagged for r in d.related_information] == [uri(model)]
        (call,) = [a for a in await editor.code_actions(library, flagged) if a.title.startswith("Call box_inertial")]
        assert list(call.edit.changes) == [uri(model)]  # the fix is the call, in the model
        mark = editor.mark()
        editor.apply(call)
        assert '<xacro:box_inertial mass="5" x="0.4" y="0.3" z="0.1"/>' in editor.texts[model]
        await editor.diagnostics(model)
        assert "I009" not in {d.code for d in await editor.diagnostics(library, mark)}


# -- robustness -----------------------------------------------------------------------------------
@pytest.mark.asyncio
async def test_half_typed_xml_a_runaway_xacro_and_a_huge_paste_never_stop_it(repository, cache):
    model = rover(repository)
    async with editing(repository, cache, env={"URDFCLI_XACRO_TIMEOUT": "1"}) as editor:
        editor.open(model)
        await editor.diagnostics(model)
        editor.edit(model, '<link name="base_footprint"/>', '<link name="base_footprint"/>\n  <link name="half')
        assert [d.code for d in await editor.diagnostics(model)] == ["X001"]
        assert "**macro** `wheel`" in await editor.hover(model, "<xacro:wheel", 8)  # still answering
        editor.edit(model, '<link name="half', '<xacro:property name="spin" value="${python.sum(python.range(10**12))}"/>')
        editor.edit(model, 'radius="0.1">', 'radius="${spin}">')
        (stopped,) = await editor.diagnostics(model)
        assert stopped.code == "X003" and "took longer than 1 s" in stopped.message
        editor.edit(model, "${python.sum(python.range(10**12))}", "0.1")
        assert await editor.diagnostics(model) == []


@pytest.mark.asyncio
async def test_a_huge_paste_is_checked_and_taken_back(tmp_path, cache):
    model = tmp_path / "robot.urdf"
    model.write_text('<robot name="r">\n  <link name="base_link"/>\n</robot>\n')
    async with editing(tmp_path, cache) as editor:
        editor.open(model)
        assert await editor.diagnostics(model) == []
        chain = "".join(
            f'  <link name="l{i}"><collision><geometry><box size="1 1 1"/></geometry></collision></link>\n'
            f'  <joint name="j{i}" type="fixed"><parent link="{f"l{i - 1}" if i else "base_link"}"/><child link="l{i}"/></joint>\n'
            for i in range(20_000)
        )
        editor.edit(model, "</robot>", chain + '  <link name="l5"/>\n</robot>')  # 3 MB, and one link twice
        assert codes(await editor.diagnostics(model)) == [("N004", 40_003)]
        assert "N004" in await editor.hover(model, '<link name="l5"/>', 1)  # the diagnostic's rule, on a 3 MB text
        editor.edit(model, chain + '  <link name="l5"/>\n', "")
        assert await editor.diagnostics(model) == []


@pytest.mark.asyncio
async def test_memory_stays_flat_over_two_thousand_edits(repository, cache):
    model = rover(repository)
    # 20 more wheels: a model whose check leaves enough behind that keeping it would show
    wheels = "".join(f'  <xacro:wheel prefix="w{i}" parent="base_link" radius="0.1"><origin xyz="0 0 {i}"/></xacro:wheel>\n' for i in range(20))
    model.write_text(model.read_text().replace("</robot>", wheels + "</robot>"))
    async with editing(repository, cache) as editor:
        editor.open(model)
        await editor.diagnostics(model)
        await asyncio.sleep(0.5)
        samples = [server_memory_kib(editor, "Pss_Anon")]  # once the model is open and checked: the heaps, where a leak grows
        radius = 'parent="base_link" radius="0.1">'
        for edit in range(1, 2001):
            typed = f'parent="base_link" radius="0.{edit % 9 + 1}{edit}">'  # each text new
            editor.edit(model, radius, typed)
            radius = typed
            if edit % 20 == 0:
                await editor.diagnostics(model)  # each twentieth edit waits for its check: a hundred checks at least
            if edit in (400, 2000):
                await asyncio.sleep(0.5)  # the server idle: its garbage collected
                samples.append(server_memory_kib(editor, "Pss_Anon"))
        print(f"server memory once open, after 400 and after 2,000 edits: {samples} KiB")
        assert samples[2] - samples[0] < 1024, samples  # KiB: less than 1 MiB over 2,000 edits and 100 checks or more
        # and from the 400th edit: the xacro worker forked again by then shares fewer pages with the server (-11 MiB)
        assert samples[2] - samples[1] < 1024, samples


def test_without_pygls_one_line_says_how_to_install_it():
    code = "import sys; sys.modules['pygls'] = None; from urdfcli.cli import main; sys.exit(main(['lsp']))"
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert done.returncode == 2
    assert done.stdout == ""
    assert done.stderr == "urdfcli: urdfcli lsp needs pygls and lsprotocol: pip install 'urdfcli[lsp]'\n"


def test_a_bad_package_path_is_one_line():
    done = subprocess.run([sys.executable, "-m", "urdfcli", "lsp", "-P", "/no/such/folder"], capture_output=True, text=True, timeout=60, stdin=subprocess.DEVNULL)
    assert done.returncode == 2
    assert done.stderr == "urdfcli: --package-path '/no/such/folder': not a directory\n"


@pytest.mark.asyncio
async def test_a_client_that_counts_in_utf8_gets_its_units(tmp_path, cache):
    model = tmp_path / "robot.urdf"
    model.write_text('<robot name="r">\n  <link name="größe"/><link name="größe"/>\n</robot>\n')
    async with editing(tmp_path, cache, capabilities="neovim") as editor:
        editor.open(model)
        found = [d for d in await editor.diagnostics(model) if d.code == "N004"]
        assert found and found[0].range.start.character == len('  <link name="größe"/>'.encode())


def test_the_other_commands_never_import_the_server():
    from test_startup import imported

    server = {"pygls", "lsprotocol", "urdfcli.lsp", "urdfcli.lsp.server"}
    modules = imported("check", str(FIXTURES / "seed000" / "my_robot.urdf"))
    assert not server & set(modules)
    listed = imported("--help")
    assert "urdfcli.cli.lsp" in listed  # the command is there, for the help's list
    assert not server & set(listed)


# -- protocol hygiene ----------------------------------------------------------------------------------
def test_every_request_is_answered_and_unknown_documents_are_ignored(repository, cache):
    wire = Wire(repository, cache)
    wire.initialize(repository)
    invalid = wire.request("textDocument/hover", {"textDocument": {"uri": uri(rover(repository))}})  # no position
    assert invalid["error"]["code"] == types.ErrorCodes.InvalidParams and "textDocument/hover" in invalid["error"]["message"]
    never_opened = repository / "never.urdf"
    wire.notify("textDocument/didChange", {"textDocument": {"uri": uri(never_opened), "version": 3}, "contentChanges": [{"text": "<robot/>"}]})
    logged = wire.wait(lambda m: m.get("method") == "window/logMessage")
    assert "not open" in logged["params"]["message"]
    missing = {"textDocument": {"uri": uri(repository / "missing.urdf")}, "position": {"line": 0, "character": 0}}
    for method in ("textDocument/completion", "textDocument/hover", "textDocument/definition"):
        answer = wire.request(method, missing)
        assert "error" not in answer and answer["result"] is None
    assert not [m for m in wire.received if m.get("method") == "window/showMessage"]  # no pop-up
    assert wire.request("shutdown", None)["result"] is None
    wire.notify("exit", None)
    assert wire.exit_code() == 0
    assert b"Traceback" not in wire.process.stderr.read()


def test_exit_without_shutdown_is_exit_code_1(repository, cache):
    wire = Wire(repository, cache)
    wire.initialize(repository)
    wire.notify("exit", None)
    assert wire.exit_code() == 1


def test_a_folder_named_urdfcli_in_the_workspace_is_not_the_server_run(tmp_path, cache):
    (tmp_path / "urdfcli").mkdir()
    (tmp_path / "urdfcli" / "__init__.py").write_text("raise SystemExit('the workspace folder was imported')")
    wire = Wire(tmp_path, cache, ("-P", "-m", "urdfcli", "lsp"))  # as the urdfcli program starts: its folder, not the workspace, on the path
    assert "capabilities" in wire.request("initialize", {"processId": None, "rootUri": uri(tmp_path), "capabilities": {}})["result"]
    assert wire.request("shutdown", None)["result"] is None
    wire.notify("exit", None)
    assert wire.exit_code() == 0


def test_the_server_ends_with_its_supervisor_killed(repository, cache):
    wire = Wire(repository, cache)
    wire.initialize(repository)
    server = process_tree(wire.process.pid)
    assert len(server) == 3  # the supervisor, the server, its xacro worker
    wire.process.kill()
    wire.process.wait()
    deadline = time.monotonic() + 5
    while any(map(process_alive, server[1:])) and time.monotonic() < deadline:
        time.sleep(0.02)
    assert time.monotonic() < deadline


@pytest.mark.parametrize(
    ("stream", "bodies"),
    [
        (b"Content-Length: 2\r\n\r\n{}Content-Length: 4\r\nContent-Type: x\r\n\r\nnull", [b"{}", b"null"]),
        (b"Content-Length: 5\r\n\r\n{}", []),  # cut short: the end
        (b"X-Other: 1\r\n\r\nContent-Length: 2\r\n\r\n[]", [b"[]"]),  # a header block without a length is skipped
        (b"Content-Length: -1\r\n\r\nContent-Length: 1\r\n\r\n1", [b"1"]),
    ],
)
def test_the_supervisor_reads_messages_as_framed(stream, bodies):
    from urdfcli.lsp.supervisor import read_message

    reader = io.BytesIO(stream)
    assert list(iter(lambda: read_message(reader), None)) == bodies


@pytest.mark.asyncio
async def test_completion_and_definition_of_link_names_a_macro_writes_with_its_prefix(repository, cache):
    library = wheel(repository)
    async with editing(repository, cache) as editor:
        editor.open(rover(repository))
        editor.open(library)
        await editor.diagnostics(library)
        written = line_of(library, '<link name="${prefix}_wheel_link">')
        found = await editor.definition(library, '<child link="${prefix}_wheel_link"/>', len('<child link="${prefix}_wh'))
        assert [(path_of(f.uri), f.range.start.line + 1) for f in found] == [(library, written)]
        editor.edit(library, '<child link="${prefix}_wheel_link"/>', '<child link="${prefix}_wh"/>')
        items = await editor.completion(library, '<child link="${prefix}_wh"', len('<child link="${prefix}_wh'))
        assert [item.label for item in items] == ["${prefix}_wheel_link"]  # the prefix kept, not dropped
        value = position(editor.texts[library], '${prefix}_wh"')
        assert items[0].text_edit.range == types.Range(value, position(editor.texts[library], '${prefix}_wh"', len("${prefix}_wh")))
        plain = await editor.completion(library, '<child link="${prefix}_wh"', len('<child link="'))
        assert "${prefix}_wheel_link" not in {item.label for item in plain} and "base_link" in {item.label for item in plain}


def links_urdf(path: Path, links: int) -> Path:
    """A URDF of ``links`` links in a chain, each with an inertial and a box (270 bytes a link)."""
    rows = [f'<robot name="{path.stem}">\n  <link name="l0"/>\n']
    rows += [
        f'  <link name="l{i}"><inertial><mass value="1"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>'
        f'<collision><geometry><box size="1 1 1"/></geometry></collision></link>\n'
        f'  <joint name="j{i}" type="fixed"><parent link="l{i - 1}"/><child link="l{i}"/></joint>\n'
        for i in range(1, links)
    ]
    path.write_text("".join(rows) + "</robot>\n")
    return path


@pytest.mark.asyncio
async def test_memory_is_given_back_when_a_large_file_is_closed(tmp_path, cache):
    small, large = links_urdf(tmp_path / "small.urdf", 200), links_urdf(tmp_path / "large.urdf", 20_000)  # 5.5 MB
    async with editing(tmp_path, cache) as editor:
        editor.open(small)  # what any check of such a model loads, loaded before
        await editor.diagnostics(small)
        for _ in range(2):
            editor.edit(small, 'name="l5"', 'name="l5x"')
            checked_small = await editor.diagnostics(small)
            editor.edit(small, 'name="l5x"', 'name="l5"')
            await editor.diagnostics(small)
        assert checked_small  # (the link renamed, its joint names one that is not)
        await asyncio.sleep(1)
        before = server_memory_kib(editor)
        first_server = process_tree(editor.server.pid)[1]
        editor.open(large)
        await editor.diagnostics(large)
        editor.edit(large, 'name="l5"', 'name="l5x"')
        await editor.diagnostics(large)
        opened = server_memory_kib(editor)
        mark = editor.mark()
        editor.close(large)
        assert await editor.diagnostics(large, mark) == []
        # the supervisor replaces the server, which held far less than its peak
        deadline = time.monotonic() + 60
        while (after := server_memory_kib(editor)) - before > before / 10 and time.monotonic() < deadline:
            await asyncio.sleep(0.5)
        print(f"server memory before, with and after a 5.5 MB file: {before // 1024}, {opened // 1024}, {after // 1024} MiB")
        assert opened - before > 50 * 1024  # it was held while open
        assert after - before <= before / 10, (before, after)  # within 10% of the level before
        # a new server, which checks what is open and answers as the first did
        assert process_tree(editor.server.pid)[1] != first_server
        editor.edit(small, 'name="l5"', 'name="l5x"')
        assert [d.code for d in await editor.diagnostics(small)] == [d.code for d in checked_small]
        assert "l4" in await editor.hover(small, '<parent link="l4"/>', len('<parent link="l'))
        assert len(editor.registrations) == 1  # its watched files are the first server's, registered once
