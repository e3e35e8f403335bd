"""The rule registry is documented: four sections per rule, docs/rules.md in sync, `rules` and `rule` commands."""

from __future__ import annotations

import json
import re

import pytest
from conftest import ROOT, run_cli

import urdfcli
from urdfcli.report.rules import markdown
from urdfcli.rules import REGISTRY, SECTIONS

RULES = sorted(REGISTRY.values(), key=lambda r: r.code)


def test_every_rule_has_the_four_documentation_sections():
    missing = {
        rule.code: [section for section in SECTIONS if not rule.sections().get(section)]
        for rule in RULES
    }
    missing = {code: sections for code, sections in missing.items() if sections}
    assert not missing, "rules whose documentation lacks sections: " + "; ".join(f"{code}: {', '.join(s)}" for code, s in missing.items())


def test_codes_and_names_are_distinct_and_well_formed():
    assert all(re.fullmatch(r"[A-Z]\d{3}", rule.code) for rule in RULES)
    assert all(re.fullmatch(r"[a-z0-9]+(-[a-z0-9]+)*", rule.name) for rule in RULES)
    names = [rule.name for rule in RULES]
    assert len(names) == len(set(names))


def test_every_option_is_documented():
    for rule in RULES:
        for option in rule.options:
            assert option.doc, f"{rule.code} option {option.name} has no description"


def test_docs_rules_md_is_generated_from_the_registry():
    committed = (ROOT / "docs" / "rules.md").read_text(encoding="utf-8")
    assert committed == markdown(RULES), "docs/rules.md is stale: run `urdfcli rules --format markdown > docs/rules.md`"


def test_rules_table_lists_every_rule():
    done = run_cli("rules", env={"COLUMNS": "250"})
    assert done.returncode == 0
    lines = done.stdout.decode().splitlines()
    assert lines[0].split() == ["Code", "Name", "Severity", "Default", "In", "check", "Fix", "Summary"]
    listed = [line.split()[0] for line in lines[1:]]
    assert sorted(listed) == [rule.code for rule in RULES]
    s001 = next(line for line in lines if line.startswith("S001"))
    assert s001.split()[:5] == ["S001", "link-name-suffix", "warning", "off", "no"]
    j010 = next(line for line in lines if line.startswith("J010"))
    assert j010.split()[:6] == ["J010", "limit-lower-above-upper", "warning", "on", "yes", "unsafe"]
    p001 = next(line for line in lines if line.startswith("P001"))
    assert p001.split()[:6] == ["P001", "package-dependency-undeclared", "warning", "on", "no", "safe"]


def test_rules_json():
    document = json.loads(run_cli("rules", "--format", "json").stdout)
    assert document["version"] == 1 and document["urdfcli"] == urdfcli.__version__
    listed = document["rules"]
    assert sorted(r["code"] for r in listed) == [rule.code for rule in RULES]
    style = next(r for r in listed if r["code"] == "S001")
    assert style["default"] is False and style["options"][0] == {
        "name": "suffix", "type": "string", "default": "_link", "doc": "The suffix every link name ends in."
    }


@pytest.mark.parametrize("asked", ["D002", "d002", "unknown-attribute"])
def test_rule_prints_one_rules_documentation(asked):
    done = run_cli("rule", asked)
    assert done.returncode == 0
    text = done.stdout.decode()
    assert text.startswith("# D002 unknown-attribute\n")
    for section in SECTIONS:
        assert f"\n## {section}\n" in text
    assert '<color rgb="1 0.5 0 1"/>' in text


def test_unknown_rule_is_exit_2_with_a_suggestion():
    done = run_cli("rule", "unknown-atribute")
    assert done.returncode == 2
    assert done.stderr.decode() == "urdfcli: unknown rule 'unknown-atribute' (did you mean 'unknown-attribute'?); `urdfcli rules` lists them\n"
