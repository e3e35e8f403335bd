"""SPEC section 4: the JSON contract of check and lint."""

from __future__ import annotations

import json

from ..diagnostics import Diagnostic
from ..escape import json_escape
from ..loaded import Loaded
from . import counts


def diagnostic_dict(diagnostic: Diagnostic) -> dict:
    return {
        "code": diagnostic.code,
        "severity": diagnostic.severity.value,
        "message": diagnostic.message,
        "path": diagnostic.location.file,
        "line": diagnostic.location.line,
        "column": diagnostic.location.column,
        "element": diagnostic.element,
        "trace": [
            {"path": call.file, "line": call.line, "column": call.column, "macro": call.macro}
            for call in diagnostic.location.trace
        ],
    }


def file_dict(loaded: Loaded) -> dict:
    entry = {
        "path": loaded.path,
        "ok": loaded.ok,
        "robot": loaded.robot.name if loaded.robot is not None else None,
        "diagnostics": [diagnostic_dict(d) for d in loaded.diagnostics],
    }
    if getattr(loaded, "checked_through", None) is not None:  # a xacro library
        entry["checked_through"] = loaded.checked_through
        entry["notes"] = loaded.notes
    if getattr(loaded, "arguments", None):  # a model run with an argument set from [tool.urdfcli] models
        entry["arguments"] = loaded.arguments
    return entry


def render(results: list[Loaded]) -> str:
    errors, warnings, _ = counts(results)
    document = {
        "version": 1,
        "files": [
            file_dict(loaded)
            for loaded in results
        ],
        "summary": {"files": len(results), "errors": errors, "warnings": warnings},
    }
    return json_escape(json.dumps(document, indent=2, ensure_ascii=False))
