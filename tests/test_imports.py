"""The package's modules import each other in layers, shown by its folders:
read -> model -> rules -> report -> project -> the library (api, session) -> the
editor server (lsp) -> cli,
each importing only those below it, and no module importing itself through others.
The consumers' folder (targets/) holds one package per consumer whose modules sit in
the layers their names say (TARGET_MODULES); its registry is in the model layer.

Every import counts: at the top of a module, inside a function, and by name
(``importlib.import_module("urdfcli...")``, ``sys.modules["urdfcli..."]``); only
those under ``if TYPE_CHECKING:`` are for annotations and do not.
"""

from __future__ import annotations

import ast
import importlib.util
from pathlib import Path

import networkx as nx

import urdfcli

PACKAGE = Path(urdfcli.__file__).parent
LAYERS = ("read", "model", "rules", "report", "project", "library", "lsp", "cli")
FOUNDATION = ("urdfcli.diagnostics", "urdfcli.version")  # imported by every layer, importing none
LIBRARY = ("urdfcli.api", "urdfcli.options", "urdfcli.session")  # what a program calls; the command line is a shell over it
ENTRY_POINTS = ("urdfcli", "urdfcli.__main__")
TARGETS = "targets"  # one package per consumer (urdfcli.targets.NAME), its registry in urdfcli.targets
TARGET_MODULES = {"build": "model", "rules": "rules", "load": "project"}  # a consumer's module -> its layer


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


def _named(node: ast.AST, package: str) -> str | None:
    """A module named by a string, wherever it is written: given to
    ``importlib.import_module``, looked up in ``sys.modules``, or kept in a
    constant that a worker imports (``"urdfcli.read.expansion"``); a relative name
    given to ``import_module`` with its package."""
    if isinstance(node, ast.Call) and node.args and isinstance(node.args[0], ast.Constant) and isinstance(node.args[0].value, str):
        text = node.args[0].value
        if text.startswith(".") and ast.unparse(node.func).endswith("import_module"):
            return importlib.util.resolve_name(text, package)
    if isinstance(node, ast.Constant) and isinstance(node.value, str) and node.value.startswith("urdfcli.") and _is_module(node.value):
        return node.value
    return None


def _imported(path: Path, annotations: bool = False) -> set[str]:
    """The package's modules that ``path`` imports when it runs (with ``annotations``,
    also those it names for annotations only)."""
    name = _module_name(path)
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    tree = ast.parse(path.read_text(encoding="utf-8"))
    skipped = set() if annotations else _annotation_only(tree)
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
        elif (named := _named(node, package)) is not None and named.startswith("urdfcli"):
            found.add(named)
    return found - {name}


def import_graph(annotations: bool = False) -> nx.DiGraph:
    graph = nx.DiGraph()
    for path in PACKAGE.rglob("*.py"):
        graph.add_node(_module_name(path))
        graph.add_edges_from((_module_name(path), target) for target in _imported(path, annotations))
    return graph


def layer(module: str) -> int:
    """0 for the foundation, then 1 + the index of the layer in LAYERS; above all for the entry points."""
    if module in FOUNDATION:
        return 0
    if module in ENTRY_POINTS:
        return len(LAYERS) + 1
    if module in LIBRARY:
        return LAYERS.index("library") + 1
    parts = module.split(".")
    if parts[1] == TARGETS:  # the registry and each consumer's package in the model layer, its modules in theirs
        return LAYERS.index(TARGET_MODULES[parts[3]] if len(parts) > 3 else "model") + 1
    return LAYERS.index(parts[1]) + 1


def test_the_graph_sees_the_imports_it_should():
    graph = import_graph()
    assert graph.has_edge("urdfcli.read.document", "urdfcli.read.xacro")  # at the top
    assert graph.has_edge("urdfcli.model.load", "urdfcli.model.kinematics")  # inside a function
    assert not graph.has_edge("urdfcli.report.lines", "urdfcli.model.result")  # for annotations only
    assert graph.has_edge("urdfcli.read.xacro", "urdfcli.read.expansion")  # by name: the module its worker imports


def test_names_in_strings_are_imports():
    code = "import importlib, sys\nimportlib.import_module('urdfcli.rules')\nsys.modules.get('urdfcli.model')\n'urdfcli.cli' in sys.modules\n"
    code += "importlib.import_module('.report', 'urdfcli')\nWORKER = 'urdfcli.read.expansion'\nTEXT = 'urdfcli.no_such_module'"
    found = {_named(node, "urdfcli") for node in ast.walk(ast.parse(code))} - {None}
    assert found == {"urdfcli.rules", "urdfcli.model", "urdfcli.cli", "urdfcli.report", "urdfcli.read.expansion"}


def test_no_module_imports_itself_through_others():
    """Not even for annotations: a module a type comes from is below every module that names it."""
    circles = [sorted(c) for c in nx.strongly_connected_components(import_graph(annotations=True)) if len(c) > 1]
    assert circles == []


def test_each_folder_imports_only_the_folders_below_it():
    upward = [(a, b) for a, b in import_graph().edges if layer(b) > layer(a)]
    assert upward == []


def test_the_folders_show_the_layers():
    tops = sorted(p.name for p in PACKAGE.glob("*.py"))
    assert len(tops) <= 8, tops
    assert {p.name for p in PACKAGE.iterdir() if (p / "__init__.py").exists()} == set(LAYERS) - {"library"} | {TARGETS}


def test_each_consumer_holds_one_module_per_layer():
    """targets/NAME/ holds build.py, rules.py and load.py (and data such as kdl_tree.cpp), its
    __init__ imports nothing: one place to read a consumer, each module in its layer."""
    graph = import_graph()
    consumers = [p for p in (PACKAGE / TARGETS).iterdir() if (p / "__init__.py").exists()]
    assert len(consumers) >= 7
    for folder in consumers:
        modules = {p.stem for p in folder.glob("*.py")} - {"__init__"}
        assert modules == set(TARGET_MODULES), (folder.name, modules)
        assert list(graph.successors(f"urdfcli.{TARGETS}.{folder.name}")) == []


def test_nothing_below_the_rules_reads_the_rule_registry():
    graph = import_graph()
    below = [m for m in graph if layer(m) < LAYERS.index("rules") + 1]
    assert [m for m in below if any(t.startswith("urdfcli.rules") for t in graph.successors(m))] == []
