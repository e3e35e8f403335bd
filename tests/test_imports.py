"""The package's modules import each other in layers: no circle, counting the imports
made inside functions too (those under ``if TYPE_CHECKING:`` are for annotations only)."""

from __future__ import annotations

import ast
import importlib.util
from pathlib import Path

import networkx as nx

import urdfcli

PACKAGE = Path(urdfcli.__file__).parent


def _module_name(path: Path) -> str:
    parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _is_module(name: str) -> bool:
    relative = PACKAGE.parent / name.replace(".", "/")
    return relative.with_suffix(".py").exists() or (relative / "__init__.py").exists()


def _annotation_only(tree: ast.AST) -> set[int]:
    return {
        id(node)
        for block in ast.walk(tree)
        if isinstance(block, ast.If) and "TYPE_CHECKING" in ast.unparse(block.test)
        for node in ast.walk(block)
    }


def _imported(path: Path) -> set[str]:
    """The package's modules that ``path`` imports when it runs."""
    name = _module_name(path)
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    tree = ast.parse(path.read_text(encoding="utf-8"))
    skipped = _annotation_only(tree)
    found = set()
    for node in ast.walk(tree):
        if id(node) in skipped:
            continue
        if isinstance(node, ast.Import):
            found |= {alias.name for alias in node.names if alias.name.startswith("urdfcli")}
        elif isinstance(node, ast.ImportFrom):
            target = importlib.util.resolve_name("." * node.level + (node.module or ""), package)
            if target.startswith("urdfcli"):
                found |= {f"{target}.{a.name}" if _is_module(f"{target}.{a.name}") else target for a in node.names}
    return found - {name}


def import_graph() -> nx.DiGraph:
    graph = nx.DiGraph()
    for path in PACKAGE.rglob("*.py"):
        graph.add_node(_module_name(path))
        graph.add_edges_from((_module_name(path), target) for target in _imported(path))
    return graph


def test_the_graph_sees_the_imports_it_should():
    graph = import_graph()
    assert graph.has_edge("urdfcli.cli.fast", "urdfcli.cli.commands")  # at the top
    assert graph.has_edge("urdfcli.load", "urdfcli.expanded")  # inside a function
    assert not graph.has_edge("urdfcli.rules", "urdfcli.diagnostics")  # for annotations only


def test_no_module_imports_itself_through_others():
    circles = [sorted(c) for c in nx.strongly_connected_components(import_graph()) if len(c) > 1]
    assert circles == []
