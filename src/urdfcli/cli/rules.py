"""`urdfcli rules` and `urdfcli rule CODE`: the documented rule registry."""

from __future__ import annotations

import sys
from typing import Annotated

from rich.table import Table
from rich.text import Text

from ..formatters import rules as rules_format
from ..rules import UnknownRule, load_all, lookup
from .common import fail, stdout
from .options import Argument, Option

RULE_FORMATS = ("table", "json", "markdown")


def rules(
    output_format: Annotated[str, Option("--format", "-f", metavar="FORMAT", help="table, json, or markdown (the text of docs/rules.md).", case_sensitive=False)] = "table",
) -> None:
    """List every rule: code, name, default severity, on or off by default, summary."""
    registry = rules_format.ordered(load_all().values())
    if output_format == "json":
        sys.stdout.write(rules_format.as_json(registry) + "\n")
    elif output_format == "markdown":
        sys.stdout.write(rules_format.markdown(registry))
    elif output_format == "table":
        table = Table("Code", "Name", "Severity", "Default", "In check", "Summary", box=None, pad_edge=False, header_style="bold")
        for rule in registry:
            cells = (rule.code, rule.name, rule.severity.value, "on" if rule.default else "off", "yes" if rule.in_check else "no", rule.summary)
            table.add_row(*(Text(cell) for cell in cells))
        stdout.print(table)
    else:
        raise fail(f"unknown format {output_format!r}; choose from {', '.join(RULE_FORMATS)}")


def rule(code: Annotated[str, Argument(metavar="CODE", help="A rule code (D002) or name (unknown-attribute).", show_default=False)]) -> None:
    """Print one rule's documentation (Markdown)."""
    try:
        found = lookup(code)
    except UnknownRule as error:
        raise fail(str(error)) from None
    sys.stdout.write(rules_format.page(found))
