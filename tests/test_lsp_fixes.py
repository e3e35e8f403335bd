"""The fixes `lint --fix` writes, offered by `urdfcli lsp` as quick fixes on each diagnostic
and as one "fix all safe" source action, applied to the editor's unsaved text."""

from __future__ import annotations

import asyncio
from pathlib import Path

import pytest
from lsp_client import TIMEOUT, editing, uri
from models import FIXABLE_ARM
from lsprotocol import types

pytestmark = pytest.mark.filterwarnings("error::pytest_lsp.LspSpecificationWarning")

XACRO_NS = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'


async def actions_for(editor, path: Path, diagnostics: list[types.Diagnostic], only: list[str] | None = None) -> list[types.CodeAction]:
    whole = types.Range(types.Position(0, 0), types.Position(len(editor.texts[path].splitlines()), 0))
    context = types.CodeActionContext(diagnostics, only=only)
    params = types.CodeActionParams(types.TextDocumentIdentifier(uri(path)), whole, context)
    return list(await asyncio.wait_for(editor.client.text_document_code_action_async(params), TIMEOUT) or [])


@pytest.mark.asyncio
async def test_a_diagnostic_offers_the_fix_lint_writes(tmp_path):
    model = tmp_path / "arm.urdf.xacro"
    model.write_text(FIXABLE_ARM)
    async with editing(tmp_path, tmp_path / "cache") as editor:
        editor.open(model)
        found = await editor.diagnostics(model)
        (degrees,) = [d for d in found if d.code == "V009"]
        actions = await actions_for(editor, model, [degrees])
        (fix,) = [a for a in actions if a.title.startswith("Write rpy=")]
        assert fix.title == 'Write rpy="0 0 1.570796" (radians) (unsafe)' and fix.kind == types.CodeActionKind.QuickFix
        editor.apply(fix)
        assert '<origin xyz="0 0 0.1" rpy="0 0 1.570796"/>' in editor.texts[model]
        assert "V009" not in {d.code for d in await editor.diagnostics(model)}
        assert model.read_text() == FIXABLE_ARM  # the editor's text is fixed; the file is the editor's to save


@pytest.mark.asyncio
async def test_fix_all_applies_every_safe_fix_of_the_file(tmp_path):
    model = tmp_path / "arm.urdf.xacro"
    model.write_text(FIXABLE_ARM)
    async with editing(tmp_path, tmp_path / "cache") as editor:
        editor.open(model)
        found = await editor.diagnostics(model)
        assert {"X005", "V009"} <= {d.code for d in found}
        (every,) = await actions_for(editor, model, [], only=[types.CodeActionKind.SourceFixAll])  # as an editor's fix-all on save asks
        assert every.title == "Fix all safe urdfcli problems" and every.kind == "source.fixAll.urdfcli"
        assert [a.title for a in await actions_for(editor, model, [], only=["source.fixAll.urdfcli"])] == [every.title]
        assert await actions_for(editor, model, found, only=["source.fixAll.ruff"]) == []  # another server's
        quick = await actions_for(editor, model, found, only=[types.CodeActionKind.QuickFix])
        assert quick and all(a.kind == types.CodeActionKind.QuickFix for a in quick)
        editor.apply(every)
        text = editor.texts[model]
        # the deprecated forms xacro still reads, not the unsafe degrees
        assert 'name="part"' in text and "python.range(2)" in text and 'rpy="0 0 90"' in text
        after = await editor.diagnostics(model)
        assert "X005" not in {d.code for d in after} and "V009" in {d.code for d in after}
        assert await actions_for(editor, model, [], only=[types.CodeActionKind.SourceFixAll]) == []


LIBRARY = f"""<?xml version="1.0"?>
<robot {XACRO_NS}>
  <xacro:macro name="turned" params="name rpy">
    <link name="${{name}}"/>
    <joint name="${{name}}_joint" type="fixed">
      <parent link="base_link"/>
      <child link="${{name}}"/>
      <origin xyz="0 0 0.1" rpy="${{rpy}}"/>
    </joint>
  </xacro:macro>
</robot>
"""
CALLING = f"""<?xml version="1.0"?>
<robot name="arm" {XACRO_NS}>
  <xacro:include filename="turned.xacro"/>
  <link name="base_link"/>
  <xacro:turned name="camera" rpy="0 0 90"/>
</robot>
"""


@pytest.mark.asyncio
async def test_a_mistake_shown_at_the_macro_call_that_caused_it_offers_its_fix_there(tmp_path):
    (tmp_path / "turned.xacro").write_text(LIBRARY)
    model = tmp_path / "arm.urdf.xacro"
    model.write_text(CALLING)
    async with editing(tmp_path, tmp_path / "cache") as editor:
        editor.open(model)
        found = await editor.diagnostics(model)
        call = CALLING.splitlines().index('  <xacro:turned name="camera" rpy="0 0 90"/>')
        (at_call,) = [d for d in found if d.code == "V009" and d.range.start.line == call]  # where it was typed
        (fix,) = [a for a in await actions_for(editor, model, [at_call]) if "radians" in a.title]
        editor.apply(fix)
        assert '<xacro:turned name="camera" rpy="0 0 1.570796"/>' in editor.texts[model]  # the value, where it was written
        assert "V009" not in {d.code for d in await editor.diagnostics(model)}
        assert (tmp_path / "turned.xacro").read_text() == LIBRARY
