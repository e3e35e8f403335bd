"""Fuzzing: thousands of corrupted fixture documents through every model subcommand.

A seeded mutator corrupts the fixture models (bytes cut, inserted, doubled or
flipped; numbers and attribute values replaced by absurd ones; hostile
snippets inserted). Each document goes through `check`, and through one of
`lint`, `tree`, `graph --format dot` and `inertia` in turn, in-process.
Every run must end with a documented exit code, no traceback, no internal
error, within a time bound. A failure names the seed and the document index
(and keeps the document), so it can be replayed.

URDFCLI_FUZZ_DOCUMENTS (default 2000) and URDFCLI_FUZZ_SEED (default 6) set
the budget; the hypothesis tests below cover the number and XML readers.
"""

from __future__ import annotations

import os
import random
import re
import shutil
import signal
import time
from pathlib import Path

import pytest
import typer.main
import typer.testing
from conftest import FIXTURES, all_fixture_models
from hypothesis import given, settings
from hypothesis import strategies as st

from urdfcli.model.numbers import NumberError, VectorLengthError, parse_double, parse_doubles, parse_vector
from urdfcli.read.xml import XmlError
from urdfcli.read.xml import parse as parse_bytes

DOCUMENTS = int(os.environ.get("URDFCLI_FUZZ_DOCUMENTS", "2000"))
SEED = int(os.environ.get("URDFCLI_FUZZ_SEED", "6"))
SECONDS_PER_RUN = 20
OTHERS = (("lint",), ("tree",), ("graph", "--format", "dot"), ("inertia",))

NUMBERS = ["1e999", "-1e999", "nan", "-nan", "inf", "-0", "0", "1e-400", "1e308", "", " ", "0x1F", "1,5", "1 2", "١", "+-1", "1e", ".", "-"]
VALUES = [
    "", " ", "a" * 5000, "&amp;", "&lt;x&gt;", "\t\n", "${undefined}", "$(find nowhere)", "$(arg missing)", "${1/0}",
    "${10**10**10}", "${'a'*10**10}", "package://nowhere/mesh.stl", "file:///etc/passwd", "http://127.0.0.1:9/x.stl",
    "../../../../etc/passwd", "base_link", "world", "revolute", "fixed", "floating", "bogus", "\u00e9\u4e2d\U0001f916",
]
SNIPPETS = [
    b"\x00", b"\xff\xfe", b"\xef\xbb\xbf", b"]]>", b"<!--", b"-->", b"<![CDATA[x]]>", b"&", b"&undefined;", b"&#0;", b"&#x110000;",
    b'<!DOCTYPE r [<!ENTITY e SYSTEM "file:///etc/passwd">]>', b'<!ENTITY a "b">', b"<?xml version='1.0'?>",
    b'<link name="base_link"/>', b'<joint name="j" type="revolute"><parent link="a"/><child link="a"/></joint>',
    b'<joint name="loop" type="fixed"><parent link="base_link"/><child link="base_link"/></joint>',
    b'<inertial><mass value="-1"/><inertia ixx="nan" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial>',
    b'<xacro:include filename="missing.xacro"/>', b'<xacro:include filename="/etc/passwd"/>',
    b'<xacro:macro name="m"><xacro:m/></xacro:macro><xacro:m/>', b"<xacro:undefined_macro/>",
    b'<xacro:property name="p" value="${p}"/>', b"${python.sum(python.range(10**12))}", b"${().__class__}",
    b'<xacro:if value="${1/0}"/>', b'<xacro:arg name="a"/>', b"<gazebo reference='nothing'/>",
    b'<mimic joint="nothing"/>', b'<axis xyz="0 0 0"/>', b'<limit lower="2" upper="-2" effort="1" velocity="1"/>',
]


def _span(data: bytes, rng: random.Random) -> tuple[int, int]:
    start = rng.randrange(len(data) + 1)
    return start, min(len(data), start + rng.choice((1, 2, 8, 64, 512)))


def _replace_match(data: bytes, pattern: bytes, values: list[str], rng: random.Random, group: int = 0) -> bytes:
    matches = list(re.finditer(pattern, data))
    if not matches:
        return data
    match = rng.choice(matches)
    start, end = match.span(group)
    return data[:start] + rng.choice(values).encode() + data[end:]


def mutate(data: bytes, rng: random.Random) -> tuple[bytes, list[str]]:
    """One to three corruptions of ``data``, and their names."""
    done = []
    for _ in range(rng.randint(1, 3)):
        kind = rng.choice(
            ("truncate", "delete", "insert-bytes", "insert-snippet", "duplicate", "flip", "number", "value", "value", "swap-lines", "tag")
        )
        done.append(kind)
        if kind == "truncate":
            data = data[: rng.randrange(len(data) + 1)]
        elif kind == "delete":
            start, end = _span(data, rng)
            data = data[:start] + data[end:]
        elif kind == "insert-bytes":
            position = rng.randrange(len(data) + 1)
            data = data[:position] + rng.randbytes(rng.choice((1, 4, 32))) + data[position:]
        elif kind == "insert-snippet":
            position = rng.randrange(len(data) + 1)
            data = data[:position] + rng.choice(SNIPPETS) + data[position:]
        elif kind == "duplicate":
            start, end = _span(data, rng)
            data = data[:end] + data[start:end] + data[end:]
        elif kind == "flip" and data:
            position = rng.randrange(len(data))
            data = data[:position] + bytes([data[position] ^ (1 << rng.randrange(8))]) + data[position + 1 :]
        elif kind == "number":
            data = _replace_match(data, rb"[-+]?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?", NUMBERS, rng)
        elif kind == "value":
            data = _replace_match(data, rb'="([^"]*)"', VALUES, rng, group=1)
        elif kind == "swap-lines":
            lines = data.split(b"\n")
            i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
            lines[i], lines[j] = lines[j], lines[i]
            data = b"\n".join(lines)
        elif kind == "tag":
            data = _replace_match(data, rb"<(/?)(link|joint|robot|inertial|origin|geometry|xacro:\w+)\b", ["link", "joint", "robot", "material", "xacro:macro", "x"], rng, group=2)
    return data, done


@pytest.fixture(scope="module")
def corpus(tmp_path_factory) -> list[tuple[Path, Path]]:
    """Each fixture model and where its mutants go: beside a copy of it, so that includes resolve."""
    copy = tmp_path_factory.mktemp("fuzz") / "fixtures"
    shutil.copytree(FIXTURES, copy)
    models = []
    for model in all_fixture_models():
        twin = copy / model.relative_to(FIXTURES)
        suffix = ".urdf.xacro" if model.name.endswith(".xacro") else ".urdf"
        models.append((twin, twin.with_name("fuzzed" + suffix)))
    return models


def document(corpus, index: int) -> tuple[Path, str]:
    """The index-th corrupted document, written beside its model; and how it was made."""
    rng = random.Random(SEED * 1_000_003 + index)
    model, target = corpus[index % len(corpus)]
    data, done = mutate(model.read_bytes(), rng)
    target.write_bytes(data)
    return target, f"document {index} (URDFCLI_FUZZ_SEED={SEED}): {'+'.join(done)} of {model.name}"


class TookTooLong(Exception):
    pass


def _alarm(signum, frame):
    raise TookTooLong


@pytest.fixture
def invoke(monkeypatch):
    """Run a subcommand in-process under a time bound; exceptions are failures."""
    from urdfcli.cli import app

    command = typer.main.get_command(app)
    monkeypatch.setattr(typer.testing, "_get_command", lambda _: command)  # build the click command once
    monkeypatch.setenv("URDFCLI_XACRO_TIMEOUT", "5")
    runner = typer.testing.CliRunner()
    previous = signal.signal(signal.SIGALRM, _alarm)

    def run(args: tuple[str, ...], path: Path, about: str):
        started = time.monotonic()
        signal.setitimer(signal.ITIMER_REAL, SECONDS_PER_RUN)
        try:
            result = runner.invoke(app, [*args, str(path)], catch_exceptions=False)
        except TookTooLong:
            keep(path, about)
            pytest.fail(f"{' '.join(args)} ran over {SECONDS_PER_RUN} s on {about}")
        except Exception as error:  # noqa: BLE001 - any escape is the failure being looked for
            keep(path, about)
            pytest.fail(f"{' '.join(args)} raised {type(error).__name__}: {error} on {about}")
        finally:
            signal.setitimer(signal.ITIMER_REAL, 0)
        output = result.stdout + result.stderr
        problem = None
        if result.exit_code not in (0, 1, 2):
            problem = f"exit code {result.exit_code}"
        elif "Traceback" in output or "internal error" in output:
            problem = "a traceback or internal error"
        elif result.exit_code == 2 and not any(line.startswith("urdfcli: ") for line in result.stderr.splitlines()):
            problem = "exit 2 without its one-line message"
        if problem:
            keep(path, about)
            pytest.fail(f"{' '.join(args)}: {problem} on {about}:\n{output[-2000:]}")
        return time.monotonic() - started

    yield run
    signal.signal(signal.SIGALRM, previous)


def keep(path: Path, about: str) -> None:
    """Keep the failing document next to the test's temporary folder for replay."""
    kept = path.with_name(f"failing-{path.name}")
    shutil.copyfile(path, kept)
    print(f"kept {kept} ({about})")


def test_fuzz_check(corpus, invoke):
    """Every corrupted document through `check`."""
    slowest = max(invoke(("check",), *document(corpus, index)) for index in range(DOCUMENTS))
    assert slowest < SECONDS_PER_RUN


@pytest.mark.parametrize("args", OTHERS, ids=[a[0] for a in OTHERS])
def test_fuzz_other_subcommands(corpus, invoke, args):
    """A quarter of the corrupted documents through each other subcommand."""
    turn = OTHERS.index(args)
    slowest = max(invoke(args, *document(corpus, index)) for index in range(turn, DOCUMENTS, len(OTHERS)))
    assert slowest < SECONDS_PER_RUN


@settings(max_examples=500, deadline=None)
@given(st.text())
def test_numbers_are_read_or_refused(text):
    try:
        value = parse_double(text)
    except NumberError as error:
        assert error.code in ("V001", "V002")
    else:
        assert value == value and abs(value) != float("inf")
    try:
        values = parse_vector(text)
    except (NumberError, VectorLengthError):
        pass
    else:
        assert len(values) == 3


@settings(max_examples=1000, deadline=None)
@given(st.text(alphabet="0123456789.eE+- ", max_size=40) | st.lists(st.floats(allow_nan=False, width=64).map(repr), max_size=4).map(" ".join))
def test_a_vector_reads_as_its_components_do(text):
    """The whole-vector fast path gives what reading each space-separated component gives."""
    try:
        expected = tuple(parse_double(piece) for piece in text.split(" ") if piece)
    except NumberError as error:
        with pytest.raises(NumberError) as raised:
            parse_vector(text)
        assert raised.value.code == error.code
        return
    if len(expected) != 3:
        with pytest.raises(VectorLengthError):
            parse_vector(text)
    else:
        assert parse_vector(text) == expected


_NUMBER_TEXT = st.text(alphabet="0123456789.eE+- ", max_size=12) | st.floats(width=64).map(repr) | st.sampled_from(["0", "1e400", "nan", "", " 1"])


@settings(max_examples=1000, deadline=None)
@given(st.lists(_NUMBER_TEXT | st.none(), min_size=1, max_size=6).map(tuple))
def test_several_numbers_read_at_once_as_each_reads(texts):
    """The one-step read of several numbers (an inertia tensor's) gives what parse_double
    gives for each, or leaves them to parse_double when one is missing or refused."""
    values = parse_doubles(texts)
    try:
        expected = tuple(parse_double(text) for text in texts) if None not in texts else None
    except NumberError:
        expected = None
    if expected is None:
        assert values is None
    elif any(text.strip() != text for text in texts):  # white space around a number: left to parse_double
        assert values is None
    else:
        assert values == expected


@settings(max_examples=300, deadline=None)
@given(st.binary(max_size=400) | st.text(max_size=200).map(lambda t: f'<robot name="r">{t}</robot>'.encode()))
def test_xml_is_parsed_or_refused_with_a_line(data):
    try:
        parse_bytes(data)
    except XmlError as error:
        assert error.message and (error.line is None or error.line >= 1)
