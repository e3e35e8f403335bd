"""xacro runs in one bounded worker per session: the same answers as in this process,
each job bounded in time and memory, and a worker that fails is replaced."""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
import time
import xml.dom.minidom
from pathlib import Path

import pytest
from conftest import FIXTURES

from urdfcli.read import expansion, sandbox
from urdfcli.read.packages import PackageResolver
from urdfcli.read.xacro import Expander, ExpansionError

PROBE = "worker_probe"  # tests/support/worker_probe.py: functions for the worker to run


@pytest.fixture
def worker(monkeypatch):
    support = Path(__file__).parent / "support"
    monkeypatch.syspath_prepend(str(support))
    found = sandbox.Worker(PROBE)
    yield found
    found.stop()


def test_jobs_share_one_worker_that_is_not_this_process(worker):
    first, second = worker.run("pid"), worker.run("pid")
    assert first == second != os.getpid()


def test_a_worker_returns_results_and_raises_errors():
    builtins = sandbox.Worker("operator")
    try:
        assert builtins.run("add", 1, 2) == 3
        with pytest.raises(ZeroDivisionError):
            builtins.run("truediv", 1, 0)
    finally:
        builtins.stop()


def test_a_worker_that_dies_is_reported_and_replaced(worker):
    before = worker.run("pid")
    with pytest.raises(sandbox.LimitExceeded, match="ended without a result"):
        worker.run("die", 3)
    after = worker.run("pid")
    assert after != before
    assert worker.run("pid") == after


def test_the_job_after_an_interrupt_between_jobs_runs_in_a_new_process(worker):
    """An interrupt that comes when no job runs (the check it meant to stop had just
    expanded) is not the next job's failure, however soon that job comes."""
    for _ in range(20):
        before = worker.run("pid")
        worker.interrupt()
        after = worker.run("pid")  # at once: the killed process may not be gone yet
        assert after != before


IN_A_NEW_PROCESS = """
import os, sys
sys.path.insert(0, sys.argv[1])
from urdfcli.read import sandbox
worker = sandbox.Worker("worker_probe")
{body}
"""


def in_a_new_process(body: str, **env: str) -> None:
    """``body`` run with ``worker``, a Worker forked from a small new process (as a command's
    is): the memory a long test process has freed, which a child reuses, does not count."""
    support = Path(__file__).parent / "support"
    code = IN_A_NEW_PROCESS.format(body=textwrap.dedent(body))
    done = subprocess.run([sys.executable, "-c", code, str(support)], capture_output=True, text=True, timeout=120, env={**os.environ, **env})
    assert done.returncode == 0, done.stderr


def test_a_worker_that_kept_much_memory_retires_and_the_next_job_runs_in_a_new_one():
    in_a_new_process("""
        kept_in = worker.run("keep", (sandbox.RETIRE_MIB + 16) * 1024 * 1024)
        assert worker.run("pid") != kept_in
        assert worker.run("pid") == worker.run("pid")
    """)


def test_a_worker_out_of_time_is_stopped_and_replaced(worker, monkeypatch):
    monkeypatch.setenv("URDFCLI_XACRO_TIMEOUT", "0.5")
    before = worker.run("pid")
    started = time.monotonic()
    with pytest.raises(sandbox.LimitExceeded, match="took longer than 0.5 s"):
        worker.run("sleep", 30)
    assert time.monotonic() - started < 5
    assert worker.run("pid") != before


def test_the_memory_bound_holds_in_the_worker():
    in_a_new_process("""
        try:
            worker.run("allocate", 256 * 1024 * 1024)
        except sandbox.LimitExceeded as error:
            assert "more than 64 MiB" in str(error), error
        else:
            raise AssertionError("256 MiB allocated under a limit of 64")
        assert worker.run("pid") != os.getpid()
    """, URDFCLI_XACRO_MEMORY_MIB="64")


def test_the_worker_sees_the_environment_and_folder_of_each_job(worker, monkeypatch, tmp_path):
    worker.run("pid")  # a worker started before the changes below
    monkeypatch.setenv("URDFCLI_TEST_VARIABLE", "now")
    monkeypatch.chdir(tmp_path)
    assert worker.run("variable", "URDFCLI_TEST_VARIABLE") == "now"
    assert worker.run("folder") == str(tmp_path)


def test_a_stopped_worker_process_is_gone(worker):
    pid = worker.run("pid")
    worker.stop()
    with pytest.raises(ChildProcessError):
        os.waitpid(pid, os.WNOHANG)


XACRO_FIXTURES = sorted(FIXTURES.rglob("*.xacro"))


def expansion_of(expand, path: Path, mappings: dict[str, str]):
    try:
        result = expand(path.read_bytes(), str(path), mappings, PackageResolver((), path), {})
    except ExpansionError as error:
        return ("error", error.message, error.origin, error.file, error.code)
    return (result.text, list(result.origins), result.includes, result.warnings)


@pytest.mark.parametrize("path", XACRO_FIXTURES, ids=lambda p: str(p.relative_to(FIXTURES)))
def test_expansion_in_the_worker_is_the_expansion_in_process(path: Path):
    expander = Expander()
    try:
        assert expansion_of(expander.expand, path, {}) == expansion_of(expansion.expand_here, path, {})
    finally:
        expander.close()


def test_the_names_xacro_gives_expressions_are_known_before_the_first_expansion_ends(monkeypatch):
    """The source rules ask for them after the model is read: by then the worker may be
    freeing a large expansion, or have retired; they were asked of it while it was ready."""
    model = FIXTURES / "urdf02_gazebo" / "urdf" / "car.urdf.xacro"
    expander = Expander()
    asked = []
    run = expander.worker.run
    monkeypatch.setattr(expander.worker, "run", lambda function, *args: asked.append(function) or run(function, *args))
    try:
        expander.expand(model.read_bytes(), str(model), {}, PackageResolver((), model))
        names = expander.global_names()
        expander.expand(model.read_bytes(), str(model), {}, PackageResolver((), model))
    finally:
        expander.close()
    assert asked == ["global_names", "expand_here", "expand_here"]  # once, first
    assert names is not None and "math" in names.names


ODD_DOCUMENTS = [
    '<?xml version="1.0" encoding="UTF-8"?>\r\n<!-- a <link> in a comment -->\r\n<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
    '<?pi <x>?><link\n   name="é&amp;&#x41;" a="1&#10;2"><![CDATA[ <joint> ]]></link>\t<xacro:if value="1"><link name="b"/></xacro:if></robot>',
    '<?xml version="1.0" encoding="ISO-8859-1"?><robot name="r"><link name="\xe9"/></robot>',
]


@pytest.mark.parametrize(
    "data",
    [*(p.read_bytes() for p in XACRO_FIXTURES), *(d.encode("latin-1" if "8859" in d else "utf-8") for d in ODD_DOCUMENTS)],
    ids=[*(str(p.relative_to(FIXTURES)) for p in XACRO_FIXTURES), "odd-markup", "latin-1"],
)
def test_xacro_is_given_the_document_it_would_read_itself_with_each_element_marked(data):
    """Read by urdfcli's reader and marked with where each element was written, the
    document is the one xacro's own parser (minidom) reads: the marks are no part of it."""
    marked = expansion.tagged_dom(data, "f")
    assert all(e.getUserData(expansion.ORIGIN) or e.getUserData(expansion.XACRO_TAG_ORIGIN) for e in marked.getElementsByTagName("*"))
    assert marked.toxml() == xml.dom.minidom.parseString(data).toxml()
