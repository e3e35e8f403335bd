"""SARIF 2.1.0, for code-scanning services (GitHub, GitLab, Azure DevOps).

One run; ``tool.driver.rules`` lists every rule of the registry with its
documentation; each result names its rule by id and index, its level, and a
region whose ``startLine`` is the diagnostic's line (1 when it has none).
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import TYPE_CHECKING

from ..diagnostics import Diagnostic
from ..rules import REGISTRY, Rule
from ..version import __version__
from .base import Reporter
from .escape import json_escape
from .lines import severity_name

if TYPE_CHECKING:
    from ..model.result import Result

SCHEMA = "https://json.schemastore.org/sarif-2.1.0.json"
LEVELS = {"error": "error", "warning": "warning", "info": "note"}


def rule_descriptor(rule: Rule) -> dict:
    return {
        "id": rule.code,
        "name": rule.name,
        "shortDescription": {"text": rule.summary},
        "fullDescription": {"text": rule.sections().get("What it does", rule.summary)},
        "help": {"text": rule.doc, "markdown": rule.doc},
        "defaultConfiguration": {"level": LEVELS[rule.severity.value], "enabled": rule.default},
        "properties": {"tags": ["urdf"]},
    }


def artifact_uri(file: str) -> str:
    path = Path(file)
    return path.as_uri() if path.is_absolute() else path.as_posix()


def result(diagnostic: Diagnostic, index: dict[str, int]) -> dict:
    location = diagnostic.location
    region = {"startLine": location.line or 1}
    if location.column:
        region["startColumn"] = location.column
    notes = [diagnostic.through] if diagnostic.through else []
    notes += [f"hint: {diagnostic.hint}"] if diagnostic.hint else []
    message = "\n".join([diagnostic.message, *notes])
    physical = {"artifactLocation": {"uri": artifact_uri(location.file)}, "region": region}
    found = {
        "ruleId": diagnostic.code,
        "level": LEVELS[severity_name(diagnostic)],
        "message": {"text": message},
        "locations": [{"physicalLocation": physical}],
    }
    if diagnostic.code in index:
        found["ruleIndex"] = index[diagnostic.code]
    if diagnostic.element:
        found["locations"][0]["logicalLocations"] = [{"fullyQualifiedName": diagnostic.element, "kind": "element"}]
    if diagnostic.model:
        found["properties"] = {"model": diagnostic.model}
    if location.trace:
        found["relatedLocations"] = [related(i, call) for i, call in enumerate(location.trace)]
    return found


def related(index: int, call) -> dict:
    """A macro call that made the element: innermost first."""
    region = {"startLine": call.line or 1}
    if call.column:
        region["startColumn"] = call.column
    return {
        "id": index,
        "physicalLocation": {"artifactLocation": {"uri": artifact_uri(call.file)}, "region": region},
        "message": {"text": f"in macro '{call.macro}' called here"},
    }


def render(results) -> str:
    rules = sorted(REGISTRY.values(), key=lambda r: r.code)
    index = {rule.code: i for i, rule in enumerate(rules)}
    document = {
        "$schema": SCHEMA,
        "version": "2.1.0",
        "runs": [
            {
                "tool": {
                    "driver": {
                        "name": "urdfcli",
                        "version": __version__,
                        "rules": [rule_descriptor(rule) for rule in rules],
                    }
                },
                "results": [result(d, index) for found in results for d in found.displayed],
                "columnKind": "unicodeCodePoints",
            }
        ],
    }
    return json_escape(json.dumps(document, indent=2, ensure_ascii=False))


class SarifReporter(Reporter):
    """A SARIF 2.1.0 log on standard output."""

    name = "sarif"

    def lint(self, results: list[Result]) -> None:
        self.output.out.file.write(render(results) + "\n")
