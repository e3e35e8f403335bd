"""Hostile input is refused without harm: entities, DTDs, xacro expressions, runaway expansion.

Every case asserts the exact exit code, a short message naming the file, and
that nothing secret or dangerous came out of it.
"""

from __future__ import annotations

import time
import tracemalloc
from pathlib import Path

import pytest
from conftest import load, run_cli

from urdfcli.read import guard

XACRO = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'
SECRET = "TOPSECRET-7f3a9c"


@pytest.fixture
def secret(tmp_path: Path) -> Path:
    path = tmp_path / "secret.txt"
    path.write_text(SECRET)
    return path


def write(folder: Path, name: str, text: str | bytes) -> Path:
    path = folder / name
    path.write_bytes(text.encode() if isinstance(text, str) else text)
    return path


def assert_clean(result, *names: str) -> None:
    """No traceback, nothing secret, and every name in the output."""
    output = result.stdout + result.stderr
    assert "Traceback" not in output
    assert SECRET not in output
    for name in names:
        assert name in result.stderr


# xacro's ${...} cannot contain braces: format strings come from properties.
FORMATS = (
    '<xacro:property name="attribute_field" value="{0.gi_frame}"/>'
    '<xacro:property name="item_field" value="{x[0]}"/>'
    '<xacro:property name="spec_field" value="{0:{1.gi_code}}"/>'
    '<xacro:property name="plain" value="{} {:.2f} {name}"/>'
)


def xacro_robot(expression: str) -> str:
    """A one-line xacro robot whose only link is named by ``expression``."""
    return f'<robot {XACRO} name="r">{FORMATS}<link name="{expression}"/></robot>'


BILLION_LAUGHS = (
    '<?xml version="1.0"?><!DOCTYPE lolz [<!ENTITY lol "lol">'
    + "".join(f'<!ENTITY lol{i} "{f"&lol{i - 1};" * 10 if i > 1 else "&lol;" * 10}">' for i in range(1, 10))
    + ']><robot name="&lol9;"><link name="a"/></robot>'
)
QUADRATIC_BLOWUP = '<!DOCTYPE r [<!ENTITY a "' + "x" * 50_000 + '">]><robot name="' + "&a;" * 50_000 + '"><link name="a"/></robot>'


@pytest.mark.parametrize("document", [BILLION_LAUGHS, QUADRATIC_BLOWUP], ids=["billion-laughs", "quadratic-blowup"])
def test_entity_bombs_are_refused_fast_with_bounded_memory(cli, tmp_path, document):
    path = write(tmp_path, "bomb.urdf", document)
    tracemalloc.start()
    started = time.monotonic()
    result = cli("check", str(path))
    elapsed = time.monotonic() - started
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    assert result.exit_code == 1
    assert f"{path}:1:" in result.stderr and "error" in result.stderr
    assert elapsed < 5
    assert peak < 50 * 1024 * 1024
    assert_clean(result)


def test_a_declared_internal_entity_is_refused_not_expanded(cli, tmp_path):
    path = write(tmp_path, "entity.urdf", '<!DOCTYPE r [<!ENTITY n "base">]><robot name="r"><link name="&n;"/></robot>')
    result = cli("check", str(path))
    assert result.exit_code == 1
    assert f"{path}:1:1: X002 error:" in result.stderr
    assert "never expands entities" in result.stderr


@pytest.mark.parametrize(
    "document",
    [
        '<!DOCTYPE r [<!ENTITY s SYSTEM "file://{secret}">]><robot name="&s;"><link name="a"/></robot>',
        '<!DOCTYPE r [<!ENTITY s SYSTEM "file://{secret}">]><robot name="r"><link name="a">&s;</link></robot>',
        '<!DOCTYPE r [<!ENTITY % p SYSTEM "file://{secret}"> %p;]><robot name="r"><link name="a"/></robot>',
        '<!DOCTYPE robot SYSTEM "file://{secret}"><robot name="r"><link name="a"/></robot>',
        '<!DOCTYPE robot SYSTEM "http://127.0.0.1:9/robot.dtd"><robot name="r"><link name="a"/></robot>',
        '<!DOCTYPE r [<!ENTITY s SYSTEM "http://127.0.0.1:9/secret">]><robot name="&s;"><link name="a"/></robot>',
        '<robot name="r" xmlns:xi="http://www.w3.org/2001/XInclude"><link name="a"/>'
        '<xi:include href="{secret}" parse="text"/></robot>',
    ],
    ids=["entity-attribute", "entity-text", "parameter-entity", "external-dtd", "network-dtd", "network-entity", "xinclude"],
)
@pytest.mark.parametrize("suffix", [".urdf", ".urdf.xacro"])
@pytest.mark.parametrize("command", [["check"], ["check", "--format", "json"], ["expand"]])
def test_external_entities_and_dtds_are_never_read(cli, tmp_path, secret, document, suffix, command):
    text = document.format(secret=secret)
    if suffix == ".urdf.xacro":
        text = text.replace("<robot ", f"<robot {XACRO} ", 1)
    path = write(tmp_path, "hostile" + suffix, text)
    result = cli(*command, str(path))
    assert_clean(result)
    if "xi:include" in text:  # XInclude is never processed: an unknown element, the file untouched
        assert result.exit_code == 0
        return
    assert result.exit_code == 1
    assert str(path) in (result.stderr if command[-1] != "json" else result.stdout)


@pytest.mark.parametrize(
    "included",
    [BILLION_LAUGHS, '<!DOCTYPE r [<!ENTITY s SYSTEM "file://{secret}">]><robot name="&s;"><link name="a"/></robot>', '<robot name="&s;"/>'],
    ids=["billion-laughs", "external-entity", "undefined-entity"],
)
def test_an_included_file_declaring_or_using_entities_is_refused(cli, tmp_path, secret, included):
    """xacro's worker reads an included file with minidom only when it has no DOCTYPE
    and minidom reads it; anything else goes through urdfcli's reader, which refuses."""
    write(tmp_path, "part.xacro", included.format(secret=secret))
    path = write(tmp_path, "main.urdf.xacro", f'<robot {XACRO} name="r"><xacro:include filename="part.xacro"/><link name="b"/></robot>')
    started = time.monotonic()
    result = cli("check", str(path))
    assert time.monotonic() - started < 5
    assert result.exit_code == 1
    assert "X001 error: XML syntax error in included file" in result.stderr
    assert_clean(result)


def test_xacro_include_of_a_non_xml_file_does_not_show_its_content(cli, tmp_path, secret):
    path = write(tmp_path, "inc.urdf.xacro", f'<robot {XACRO} name="r"><xacro:include filename="{secret}"/><link name="a"/></robot>')
    result = cli("check", str(path))
    assert result.exit_code == 1
    assert f"{path}:1:" in result.stderr
    assert f"X003 error: cannot include {secret}: it is not an XML file" in result.stderr
    assert_clean(result)


ESCAPES = {
    "import": ("${__import__('os').system('touch {marker}')}", "Use of invalid name(s): __import__"),
    "class-walk": ("${().__class__.__bases__[0].__subclasses__()}", "Use of invalid name(s): "),
    "base-walk": ("${[].__class__.__base__}", "Use of invalid name(s): "),
    "vars-subclasses": (
        "${[c for c in python.vars(python.type)['__subclasses__'](python.int.mro()[1]) "
        "if 'Popen' in python.repr(c)][0](['touch', '{marker}'])}",
        "name 'vars' is not defined",
    ),
    "vars-by-subscript": ("${python['vars'](python['type'])['_' + '_subclasses__'](python.int.mro()[1])}", "'vars'"),
    "type-by-subscript": ("${python['type']('A', (), dict())}", "takes 1 positional argument but 3 were given"),
    "type-three-args": ("${python.type('A', (), dict())}", "takes 1 positional argument but 3 were given"),
    "generator-frame": ("${python.list((x for x in [1]).gi_frame.f_globals)}", "access to 'gi_frame' is not allowed"),
    "class-method": ("${python.int.mro()[1]}", "access to 'mro' is not allowed"),
    "format-field": ("${attribute_field.format((x for x in [1]))}", "format field '{0.gi_frame}' is not allowed"),
    "format-map": ("${item_field.format_map(dict(x=[(y for y in [1])]))}", "format field '{x[0]}' is not allowed"),
    "format-spec": ("${spec_field.format(1, (x for x in [1]))}", "format field '{1.gi_code}' is not allowed"),
    "open": ("${open('{marker}', 'w')}", "name 'open' is not defined"),
    "private-attribute": ("${xacro._symbols}", "access to '_symbols' is not allowed"),
    "lambda-globals": ("${(lambda: 0).__globals__}", "Use of invalid name(s): __globals__"),
    "function-attribute": ("${xacro.load_yaml.func_globals}", "access to 'func_globals' is not allowed"),
}


@pytest.mark.parametrize("expression, refusal", ESCAPES.values(), ids=ESCAPES.keys())
def test_xacro_expressions_cannot_reach_python_internals(cli, tmp_path, expression, refusal):
    marker = tmp_path / "PWNED"
    path = write(tmp_path, "escape.urdf.xacro", xacro_robot(expression.replace("{marker}", str(marker))))
    for command in ("check", "expand"):
        result = cli(command, str(path))
        assert result.exit_code == 1, result.stdout
        assert f"{path}:1:" in result.stderr
        assert "X003 error" in result.stderr and refusal in result.stderr
        assert len(result.stderr.strip().splitlines()) <= 4
        assert_clean(result)
    assert not marker.exists()


def test_no_symbol_can_replace_the_expression_guard():
    """The guard is a parameter of the compiled expression, not a name looked up in the symbols."""

    class Fake:
        @staticmethod
        def attribute(obj, name):
            return "replaced"

    with pytest.raises(guard.Refused, match="access to 'gi_frame' is not allowed"):
        guard.safe_eval("(x for x in [1]).gi_frame", {"__urdfcli_guard__": Fake})


@pytest.mark.parametrize(
    "expression",
    [
        "${2 * 3 + 2 ** 10}",
        "${plain.format('a', 1.5, name='b')}",
        "${plain.format_map(dict(name='b')) if False else 1}",
        "${python.isinstance(1, python.int) and python.type(1) == python.int}",
        "${math.pi * 2 / python.len([1, 2])}",
        "${' '.join([str(x) for x in python.range(3)])}",
        "${'ab' * 3}",
        "${[0] * 4}",
        "${xacro.arg('n') if False else 1}",
        "${math.radians(90)}",
    ],
)
def test_ordinary_xacro_expressions_still_work(tmp_path, expression):
    path = write(tmp_path, "ok.urdf.xacro", xacro_robot(expression))
    result = load(path)
    assert result.diagnostics == ()
    assert result.robot is not None and list(result.robot.links)


@pytest.mark.parametrize(
    "expression, message",
    [
        ("${10**10**10}", "is too large"),
        ("${'a'*10**10}", "is too large"),
        ("${[1]*10**10}", "is too large"),
        ("${1 &lt;&lt; 10**10}", "is too large"),
        ("${(10**1000) * (10**1000) * (10**10000) * (10**10000)}", "is too large"),
        ("${'a'.ljust(10**11)}", "out of memory"),
        ("${python.len(python.list(python.range(10**10)))}", "out of memory"),
    ],
)
def test_xacro_expressions_that_would_run_forever_or_eat_memory_are_stopped(cli, tmp_path, expression, message):
    path = write(tmp_path, "big.urdf.xacro", xacro_robot(expression))
    started = time.monotonic()
    result = cli("check", str(path))
    assert time.monotonic() - started < 10
    assert result.exit_code == 1
    assert f"{path}:1:" in result.stderr and "X003 error:" in result.stderr
    assert message in result.stderr
    assert_clean(result)


def test_expansion_is_stopped_at_its_time_limit(cli, tmp_path, monkeypatch):
    """What no syntactic guard catches (a long loop, an exponential macro) meets the time limit."""
    monkeypatch.setenv("URDFCLI_XACRO_TIMEOUT", "2")
    loop = write(tmp_path, "loop.urdf.xacro", xacro_robot("${python.sum(python.range(10**12))}"))
    macros = "".join(f'<xacro:macro name="m{i}">' + f"<xacro:m{i - 1}/>" * 10 + "</xacro:macro>" for i in range(1, 10))
    bomb = write(
        tmp_path,
        "macro_bomb.urdf.xacro",
        f'<robot {XACRO} name="r"><xacro:macro name="m0"><link name="x"/></xacro:macro>{macros}<xacro:m9/></robot>',
    )
    for path in (loop, bomb):
        started = time.monotonic()
        result = cli("check", str(path))
        assert time.monotonic() - started < 6
        assert result.exit_code == 1
        assert f"{path}: X003 error: xacro expansion stopped: it took longer than 2 s (the limit for one file)" in result.stderr
        assert_clean(result)


def test_expansion_limits_hold_for_the_real_command(tmp_path):
    """Through the real process: the environment sets the limit, the exit code is 1."""
    path = write(tmp_path, "loop.urdf.xacro", xacro_robot("${python.sum(python.range(10**12))}"))
    started = time.monotonic()
    result = run_cli("check", str(path), env={"URDFCLI_XACRO_TIMEOUT": "1"})
    assert time.monotonic() - started < 10
    assert result.returncode == 1
    assert b"xacro expansion stopped: it took longer than 1 s" in result.stderr
    assert b"Traceback" not in result.stderr


def test_include_cycle_is_one_short_message(cli, tmp_path):
    write(tmp_path, "a.urdf.xacro", f'<robot {XACRO} name="r"><xacro:include filename="b.xacro"/><link name="a"/></robot>')
    write(tmp_path, "b.xacro", f'<robot {XACRO}><xacro:include filename="a.urdf.xacro"/></robot>')
    result = cli("check", str(tmp_path / "a.urdf.xacro"))
    assert result.exit_code == 1
    lines = result.stderr.strip().splitlines()
    assert len(lines) <= 4
    assert "X003 error: include cycle:" in result.stderr and "a.urdf.xacro -> " in result.stderr and "b.xacro" in result.stderr
    assert_clean(result)


def test_self_include_is_one_short_message(cli, tmp_path):
    path = write(tmp_path, "self.urdf.xacro", f'<robot {XACRO} name="r"><xacro:include filename="self.urdf.xacro"/></robot>')
    result = cli("check", str(path))
    assert result.exit_code == 1
    assert f"{path}:1:" in result.stderr and "include cycle" in result.stderr
    assert len(result.stderr.strip().splitlines()) <= 4


@pytest.mark.parametrize(
    "body, message",
    [
        ('<xacro:macro name="m"><xacro:m/></xacro:macro><xacro:m/>', "runaway recursion in macro 'm'"),
        (
            '<xacro:macro name="m" params="n"><link name="l${n}"/><xacro:m n="${n+1}"/></xacro:macro><xacro:m n="0"/>',
            "runaway recursion in macro 'm'",
        ),
        (
            '<xacro:macro name="p"><xacro:q/></xacro:macro><xacro:macro name="q"><xacro:p/></xacro:macro><xacro:p/>',
            "runaway recursion in macro",
        ),
        ('<xacro:property name="a" value="${b}"/><xacro:property name="b" value="${a}"/><link name="${a}"/>', "circular variable definition"),
    ],
    ids=["self", "counting", "mutual", "properties"],
)
def test_runaway_recursion_is_one_short_message(cli, tmp_path, body, message):
    path = write(tmp_path, "rec.urdf.xacro", f'<robot {XACRO} name="r">{body}</robot>')
    started = time.monotonic()
    result = cli("check", str(path))
    assert time.monotonic() - started < 20
    assert result.exit_code == 1
    assert message in result.stderr
    assert f"{path}:1:" in result.stderr
    assert len(result.stderr.strip().splitlines()) <= 4
    assert_clean(result)


def test_mesh_uris_are_never_fetched(cli, tmp_path, monkeypatch, secret):
    """http:// is never opened, file:// and package:// are looked up on disk only."""
    import socket
    import urllib.request

    def no_network(*args, **kwargs):
        raise AssertionError("urdfcli tried to use the network")

    monkeypatch.setattr(socket, "create_connection", no_network)
    monkeypatch.setattr(socket.socket, "connect", no_network)
    monkeypatch.setattr(urllib.request, "urlopen", no_network)
    meshes = [
        "http://127.0.0.1:9/arm.stl",
        "https://example.invalid/arm.dae",
        "ftp://example.invalid/arm.obj",
        "package://nowhere/meshes/arm.stl",
        f"file://{secret}",
        "file:///nonexistent/arm.stl",
    ]
    visuals = "".join(f'<visual><geometry><mesh filename="{m}"/></geometry></visual>' for m in meshes)
    path = write(tmp_path, "meshes.urdf", f'<robot name="r"><link name="a">{visuals}</link></robot>')
    for command in ("check", "lint", "tree", "inertia"):
        result = cli(command, str(path))
        if "not available in this version" in result.stderr:
            continue
        assert result.exit_code in (0, 1)
        assert_clean(result)
