"""SARIF 2.1.0, for code-scanning services (GitHub, GitLab, Azure DevOps).

One run; ``tool.driver.rules`` lists every rule of the registry with its
documentation; each result names its rule by id and index, its level, and a
region whose ``startLine`` is the diagnostic's line (1 when it has none).

A file in a git repository is named by its path from the repository's top
(:mod:`.repository`), the ``uri`` GitHub code scanning matches against the
repository's files, with a ``uriBaseId`` that ``originalUriBaseIds`` resolves to
the repository's folder, as the SARIF specification asks of a relative reference
(§3.4.4; GitHub ignores both). Another file keeps its name: a relative path as
written, an absolute one as a ``file://`` URI.
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
from .repository import RepositoryPaths

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


class Artifacts:
    """The ``artifactLocation`` of each file of a run, and the repositories they name:
    ``%SRCROOT%``, then ``%SRCROOT2%``... when the files are in several."""

    def __init__(self, paths: RepositoryPaths) -> None:
        self.paths = paths
        self.bases: dict[Path, str] = {}

    def location(self, file: str) -> dict:
        root, path = self.paths.locate(file)
        if root is None:
            named = Path(file)
            return {"uri": named.as_uri() if named.is_absolute() else named.as_posix()}
        base = self.bases.setdefault(root, f"%SRCROOT{len(self.bases) + 1 if self.bases else ''}%")
        return {"uri": path, "uriBaseId": base}

    def original_uri_base_ids(self) -> dict:
        """Each base id's folder, an absolute URI ending in ``/`` as the specification asks."""
        return {base: {"uri": root.as_uri().rstrip("/") + "/"} for root, base in self.bases.items()}


def result(diagnostic: Diagnostic, index: dict[str, int], artifacts: Artifacts) -> dict:
    location = diagnostic.location
    region = {"startLine": location.line or 1}
    if location.column:
        region["startColumn"] = location.column
    notes = [diagnostic.through] if diagnostic.through else []
    notes += [f"hint: {diagnostic.hint}"] if diagnostic.hint else []
    message = "\n".join([diagnostic.message, *notes])
    physical = {"artifactLocation": artifacts.location(location.file), "region": region}
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
        found["relatedLocations"] = [related(i, call, artifacts) for i, call in enumerate(location.trace)]
    return found


def related(index: int, call, artifacts: Artifacts) -> dict:
    """A macro call that made the element: innermost first."""
    region = {"startLine": call.line or 1}
    if call.column:
        region["startColumn"] = call.column
    return {
        "id": index,
        "physicalLocation": {"artifactLocation": artifacts.location(call.file), "region": region},
        "message": {"text": f"in macro '{call.macro}' called here"},
    }


def render(results, paths: RepositoryPaths) -> str:
    rules = sorted(REGISTRY.values(), key=lambda r: r.code)
    index = {rule.code: i for i, rule in enumerate(rules)}
    artifacts = Artifacts(paths)
    run = {
        "tool": {
            "driver": {
                "name": "urdfcli",
                "version": __version__,
                "rules": [rule_descriptor(rule) for rule in rules],
            }
        },
        "results": [result(d, index, artifacts) for found in results for d in found.displayed],
        "columnKind": "unicodeCodePoints",
    }
    if artifacts.bases:
        run["originalUriBaseIds"] = artifacts.original_uri_base_ids()
    document = {"$schema": SCHEMA, "version": "2.1.0", "runs": [run]}
    return json_escape(json.dumps(document, indent=2, ensure_ascii=False))


class SarifReporter(Reporter):
    """A SARIF 2.1.0 log on standard output."""

    name = "sarif"

    def lint(self, results: list[Result]) -> None:
        self.output.out.file.write(render(results, RepositoryPaths.from_environment()) + "\n")
