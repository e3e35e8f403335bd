"""`urdfcli rules` and `urdfcli rule CODE`: the documented rule registry."""

from __future__ import annotations

from typing import Annotated

import typer

from ..report.console import Output
from .common import ColorOption, choose, fail, format_option

FORMATS = ("table", "json", "markdown")


def rules(
    output_format: format_option("table, json, or markdown (the text of docs/rules.md).") = "table",
    color: ColorOption = "auto",
) -> None:
    """List every rule: code, name, default severity, on or off by default, fixable (safe or unsafe), summary."""
    from rich.table import Table
    from rich.text import Text

    from ..report import rules as rules_format
    from ..rules import REGISTRY

    output_format = choose(output_format, FORMATS)
    registry = rules_format.ordered(REGISTRY.values())
    output = Output.standard(color)
    if output_format == "json":
        output.out.file.write(rules_format.as_json(registry) + "\n")
    elif output_format == "markdown":
        output.out.file.write(rules_format.markdown(registry))
    else:
        table = Table("Code", "Name", "Severity", "Default", "In check", "Fix", "Summary", box=None, pad_edge=False, header_style="bold")
        for rule in registry:
            fix = rule.fixable.value if rule.fixable is not None else ""
            cells = (rule.code, rule.name, rule.severity.value, "on" if rule.default else "off", "yes" if rules_format.in_check(rule) else "no", fix, rule.summary)
            table.add_row(*(Text(cell) for cell in cells))
        output.out.print(table)


def rule(
    code: Annotated[str, typer.Argument(metavar="CODE", help="A rule code (D002) or name (unknown-attribute).", show_default=False)],
    color: ColorOption = "auto",
) -> None:
    """Print one rule's documentation (Markdown)."""
    from ..report import rules as rules_format
    from ..rules import UnknownRule, lookup

    try:
        found = lookup(code)
    except UnknownRule as error:
        raise fail(str(error)) from None
    Output.standard(color).out.file.write(rules_format.page(found))
