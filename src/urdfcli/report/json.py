"""The JSON contract of check and lint (``version`` 1), and the audit of inertia."""

from __future__ import annotations

import json
from typing import TYPE_CHECKING

from ..diagnostics import Severity
from .base import Reporter
from .escape import json_escape
from .lines import checked, counts, diagnostic_dict
from .targets import compatibility_dicts

if TYPE_CHECKING:
    from ..model.result import Result


def file_dict(result: Result, files=None) -> dict:
    entry = {
        "path": result.path,
        "ok": result.ok,
        "robot": result.robot_name,
        "diagnostics": [diagnostic_dict(d, files) for d in result.displayed],
    }
    if result.loaded is not None and result.loaded.semantic is not None:  # an SRDF: the URDF it was checked against
        described = result.loaded.described
        entry["checked_against"] = described.path if described is not None and described.modelled else None
    if result.library is not None:
        entry["checked_through"] = list(result.library.checked_through)
        entry["notes"] = list(result.library.notes)
    if result.arguments:  # a model run with an argument set from [tool.urdfcli] models
        entry["arguments"] = dict(result.arguments)
    if result.meshes:  # lint: each mesh file as read (format, triangles, unit, size...)
        entry["meshes"] = [mesh.as_dict() for mesh in result.meshes]
    if result.compatibility:  # --target: what each consumer does with the model
        entry["compatibility"] = compatibility_dicts(result)
    return entry


def render(results: list[Result], files=None) -> str:
    found = counts(results)
    errors, warnings, info = found[Severity.ERROR], found[Severity.WARNING], found[Severity.INFO]
    document = {
        "version": 1,
        "files": [
            file_dict(result, files)
            for result in results
        ],
        "summary": {"files": checked(results), "errors": errors, "warnings": warnings, "info": info},
    }
    return dumps(document)


def dumps(value) -> str:
    """JSON as urdfcli writes it: indented, the data unchanged, the terminal safe."""
    return json_escape(json.dumps(value, indent=2, ensure_ascii=False))


class JsonReporter(Reporter):
    """The JSON contract of check and lint; for inertia, each file's audit (a list for several)."""

    name = "json"

    def lint(self, results: list[Result]) -> None:
        self.output.out.file.write(render(results, self.files) + "\n")

    def audit(self, results: list[Result]) -> None:
        from .inertia import audit_dict

        objects = [audit_dict(result) for result in results]
        self.output.out.file.write(dumps(objects[0] if len(objects) == 1 else objects) + "\n")
