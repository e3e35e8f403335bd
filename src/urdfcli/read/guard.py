"""No way from a xacro expression to Python's internals.

xacro evaluates ``${...}`` with Python's ``eval`` and only forbids names that
start with ``__``; an expression can still walk from an object to the
interpreter (``python.vars(...)``, a generator's frame, ``'{0.x}'.format``)
and run a program, or ask for a number or a string too big to build.
urdfcli evaluates every expression through :func:`safe_eval` instead:

- every ``a.b`` goes through :func:`attribute`, which refuses names starting
  with ``_`` and the attributes of frames, code, generators, functions,
  classes and modules; the guard is a parameter of the compiled expression,
  so no symbol can replace it;
- ``python.vars`` is taken out of xacro's symbols and ``python.type`` takes
  one argument (:func:`restrict`), so that ``python['vars']`` finds nothing;
- ``str.format`` and ``format_map`` refuse fields that reach into an
  attribute or an item (``{0.x}``, ``{0[k]}``);
- ``**``, ``*`` and ``<<`` refuse integers beyond :data:`MAX_BITS` bits and
  sequences beyond :data:`MAX_ITEMS` items.

Whatever gets past these is stopped by :func:`urdfcli.sandbox.bounded`, which
runs the whole expansion in a process limited in time and memory. Only that
process imports this module.
"""

from __future__ import annotations

import ast
import types
from functools import lru_cache

MAX_BITS = 65_536  # about 20,000 decimal digits
MAX_ITEMS = 10_000_000  # characters or elements in one string, list or tuple

_CLOSED_TYPES = (
    types.FrameType,
    types.CodeType,
    types.GeneratorType,
    types.CoroutineType,
    types.AsyncGeneratorType,
    types.TracebackType,
    types.FunctionType,
    types.MethodType,
    types.ModuleType,
    type,
)
_GUARD = "__urdfcli_guard__"


class Refused(Exception):
    """An expression asks for something urdfcli does not evaluate."""


def attribute(obj, name: str):
    """``obj.name``, unless it leads to Python's internals."""
    if name.startswith("_") or isinstance(obj, _CLOSED_TYPES):
        raise Refused(f"access to '{name}' is not allowed in xacro expressions")
    value = getattr(obj, name)
    if value is vars:
        raise Refused("vars() is not allowed in xacro expressions")
    if value is type:
        return _type_of
    if isinstance(obj, str) and name in ("format", "format_map"):
        return _checked_format(value)
    return value


def _type_of(obj):
    """``type`` with one argument only: creating classes is not allowed."""
    return type(obj)


def _checked_format(method):
    def format_checked(*args, **kwargs):
        _check_fields(method.__self__)
        return method(*args, **kwargs)

    return format_checked


def _check_fields(template: str) -> None:
    import string

    for _, field, spec, _ in string.Formatter().parse(template):
        if field is not None and ("." in field or "[" in field):
            raise Refused(f"format field '{{{field}}}' is not allowed in xacro expressions")
        if spec:
            _check_fields(spec)


def _size(value) -> int | None:
    if isinstance(value, (str, bytes, list, tuple)):
        return len(value)
    return None


def binary(op: str, left, right):
    """``left op right`` for ``**``, ``*`` and ``<<``, refusing results too large to build."""
    both_int = isinstance(left, int) and isinstance(right, int)
    if op == "**":
        if both_int and right > 0 and abs(left) > 1 and right * max(abs(left).bit_length() - 1, 1) > MAX_BITS:
            raise Refused(f"{left} ** {right} is too large (more than {MAX_BITS} bits)")
        return left**right
    if op == "<<":
        if both_int and right > MAX_BITS:
            raise Refused(f"shift by {right} is too large (more than {MAX_BITS} bits)")
        return left << right
    if both_int and left.bit_length() + right.bit_length() > MAX_BITS:
        raise Refused(f"product is too large (more than {MAX_BITS} bits)")
    for sequence, count in ((left, right), (right, left)):
        size = _size(sequence)
        if size is not None and isinstance(count, int) and size * count > MAX_ITEMS:
            raise Refused(f"a {type(sequence).__name__} of length {size} repeated {count} times is too large (more than {MAX_ITEMS})")
    return left * right


_OPS = {ast.Pow: "**", ast.Mult: "*", ast.LShift: "<<"}


class _Rewrite(ast.NodeTransformer):
    def visit_Attribute(self, node: ast.Attribute):
        self.generic_visit(node)
        if not isinstance(node.ctx, ast.Load):
            raise Refused("assigning attributes is not allowed in xacro expressions")
        call = ast.Call(_guard("attribute"), [node.value, ast.Constant(node.attr)], [])
        return ast.copy_location(call, node)

    def visit_BinOp(self, node: ast.BinOp):
        self.generic_visit(node)
        op = _OPS.get(type(node.op))
        if op is None:
            return node
        return ast.copy_location(ast.Call(_guard("binary"), [ast.Constant(op), node.left, node.right], []), node)


def _guard(name: str) -> ast.Attribute:
    return ast.Attribute(ast.Name(_GUARD, ast.Load()), name, ast.Load())


class _Guard:
    attribute = staticmethod(attribute)
    binary = staticmethod(binary)


@lru_cache(maxsize=4096)
def _compile(expression: str) -> types.CodeType:
    tree = ast.parse(expression, "<expression>", "eval")
    invalid = [n for n in _names(tree) if n.startswith("__")]
    if invalid:
        import xacro

        raise xacro.XacroException("Use of invalid name(s): ", ", ".join(invalid))
    body = _Rewrite().visit(tree).body
    guarded = ast.Lambda(ast.arguments([], [ast.arg(_GUARD)], None, [], [], None, []), body)
    return compile(ast.fix_missing_locations(ast.Expression(guarded)), "<expression>", "eval")


def _names(tree: ast.AST) -> list[str]:
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Name):
            found.append(node.id)
        elif isinstance(node, ast.Attribute):
            found.append(node.attr)
    return list(dict.fromkeys(found))


def safe_eval(expr, globals, locals=None):
    """Drop-in for ``xacro.safe_eval``: the same names allowed, nothing reachable beyond them."""
    code = _compile(expr.strip())
    dict.update(globals, __builtins__={})
    return eval(code, globals, locals)(_Guard)


def restrict(symbols: dict) -> None:
    """Take out of xacro's global symbols what leads to Python's internals."""
    python = symbols.get("python")
    if isinstance(python, dict):
        dict.pop(python, "vars", None)
        dict.__setitem__(python, "type", _type_of)
