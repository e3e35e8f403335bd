"""The rule registry is documented: four sections per rule, docs/rules.md in sync, `rules` and `rule` commands."""

from __future__ import annotations

import json
import re

import pytest
from conftest import ROOT, run_cli
from hypothesis import given
from hypothesis import strategies as st

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
    assert lines[0].split() == ["Code", "Name", "Severity", "Default", "In", "check", "Summary"]
    listed = [line.split()[0] for line in lines[1:]]
    assert sorted(listed) == [rule.code for rule in RULES]
    s001 = next(line for line in lines if line.startswith("S001"))
    assert s001.split()[:5] == ["S001", "link-name-suffix", "warning", "off", "no"]


def test_rules_json():
    listed = json.loads(run_cli("rules", "--format", "json").stdout)
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


def _docstrings():
    """Every docstring of urdfcli's modules and of a few standard ones: real text of every shape."""
    import importlib
    import inspect as inspect_module
    import pkgutil

    import urdfcli

    names = [m.name for m in pkgutil.walk_packages(urdfcli.__path__, "urdfcli.") if not m.name.endswith("__main__")]  # (which runs)
    names += ["inspect", "textwrap", "pathlib", "argparse"]
    for name in names:
        module = importlib.import_module(name)
        for value in (module, *vars(module).values()):
            doc = getattr(value, "__doc__", None)
            if isinstance(doc, str) and inspect_module.getmodule(value) in (module, None):
                yield doc


def test_rule_docs_are_cleaned_as_inspect_cleans_them():
    """rules.cleandoc stands in for inspect.cleandoc on the start path (inspect is not imported there)."""
    import inspect

    from urdfcli.rules import cleandoc

    docs = [*_docstrings(), "", "\n", "   ", "one", "  one\n    two\n  three", "\tx\n\t\ty\n\t", "a\n\n   \n  b\n    c\n   \n", " \n \n"]
    assert len(docs) > 500
    differing = [doc for doc in docs if cleandoc(doc) != inspect.cleandoc(doc)]
    assert not differing, differing[:3]


@given(st.text(alphabet=" \t\na#", max_size=40))
def test_cleandoc_reads_any_text_as_inspect_does(text):
    import inspect

    from urdfcli.rules import cleandoc

    assert cleandoc(text) == inspect.cleandoc(text)
