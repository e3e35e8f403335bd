"""xacro runs in one bounded worker per run: the same answers and the same bounds as a
child forked per file, and a worker that fails is replaced."""

from __future__ import annotations

import os
import time
from pathlib import Path

import pytest
from conftest import FIXTURES

from urdfcli import expanded, expansion, sandbox
from urdfcli.packages import PackageResolver
from urdfcli.xmlsafe import parse_bytes


def lines_of(element) -> list:
    return [(node.tag if isinstance(node.tag, str) else "comment", node.sourceline) for node in element.iter()]


def test_jobs_share_one_worker_that_is_not_this_process():
    first, second = sandbox.bounded(os.getpid), sandbox.bounded(os.getpid)
    assert first == second != os.getpid()


def imported_here(module: str) -> bool:
    import sys

    return module in sys.modules


def test_a_worker_started_early_has_imported_what_it_was_given_when_the_first_job_comes(tmp_path, monkeypatch):
    (tmp_path / "urdfcli_early_probe.py").write_text("")
    monkeypatch.syspath_prepend(str(tmp_path))
    with pytest.raises(sandbox.LimitExceeded):
        sandbox.bounded(os._exit, 0)  # no worker runs now: the next is started afresh
    sandbox.start("urdfcli_early_probe")
    assert sandbox.bounded(imported_here, "urdfcli_early_probe")
    assert not imported_here("urdfcli_early_probe")  # the worker imported it, not this process
    assert sandbox.bounded(sandbox.call, "os", "getpid") == sandbox.bounded(os.getpid)  # one worker takes every job


def test_a_worker_that_dies_is_reported_and_replaced():
    before = sandbox.bounded(os.getpid)
    with pytest.raises(sandbox.LimitExceeded, match="ended without a result"):
        sandbox.bounded(os._exit, 3)
    after = sandbox.bounded(os.getpid)
    assert after != before
    assert sandbox.bounded(sum, [1, 2]) == 3


KEPT = []


def keep(size: int) -> int:
    KEPT.append(bytearray(size))  # memory the job leaves behind in its process
    return os.getpid()


def test_a_worker_that_kept_much_memory_retires_and_the_next_job_runs_in_a_new_one():
    kept_in = sandbox.bounded(keep, (sandbox.RETIRE_MIB + 16) * 1024 * 1024)
    assert sandbox.bounded(os.getpid) != kept_in
    assert sandbox.bounded(os.getpid) == sandbox.bounded(os.getpid)
    assert not KEPT  # nothing of the job in this process


def test_a_worker_out_of_time_is_stopped_and_replaced(monkeypatch):
    monkeypatch.setattr(sandbox, "TIMEOUT_SECONDS", 0.5)
    before = sandbox.bounded(os.getpid)
    started = time.monotonic()
    with pytest.raises(sandbox.LimitExceeded, match="took longer than 0.5 s"):
        sandbox.bounded(time.sleep, 30)
    assert time.monotonic() - started < 5
    assert sandbox.bounded(os.getpid) != before


def test_the_memory_bound_holds_in_the_worker(monkeypatch):
    monkeypatch.setattr(sandbox, "MEMORY_MIB", 64)
    with pytest.raises(sandbox.LimitExceeded, match="more than 64 MiB"):
        sandbox.bounded(bytearray, 256 * 1024 * 1024)
    assert sandbox.bounded(sum, [1, 2]) == 3


def test_the_worker_sees_the_environment_and_folder_of_each_job(monkeypatch, tmp_path):
    sandbox.bounded(os.getpid)  # a worker started before the changes below
    monkeypatch.setenv("URDFCLI_TEST_VARIABLE", "now")
    monkeypatch.chdir(tmp_path)
    assert sandbox.bounded(os.environ.get, "URDFCLI_TEST_VARIABLE") == "now"
    assert sandbox.bounded(os.getcwd) == str(tmp_path)


def test_an_element_reaches_the_worker_with_its_source_lines():
    root = parse_bytes(b'<robot name="r">\n  <!-- note -->\n  <link\n     name="a"/>\n\n  <joint name="j"/>\n</robot>')
    assert sandbox.bounded(lines_of, root) == lines_of(root)
    assert sandbox.bounded(lines_of, root[2]) == lines_of(root[2])


def test_a_job_that_cannot_be_pickled_runs_in_a_child_of_its_own():
    assert sandbox.bounded(lambda: os.getpid()) != os.getpid()


XACRO_FIXTURES = sorted(FIXTURES.rglob("*.xacro"))


@pytest.mark.parametrize("path", XACRO_FIXTURES, ids=lambda p: str(p.relative_to(FIXTURES)))
def test_expansion_in_the_worker_is_the_expansion_in_process(path: Path):
    def run(expand):
        data = path.read_bytes()
        try:
            result = expand(parse_bytes(data), str(path), {}, PackageResolver((), path), data)
        except expanded.ExpansionError as error:
            return ("error", error.message, error.origin, error.file, error.code)
        return (result.text, list(result.origins), result.includes, result.warnings)

    assert run(expanded.expand) == run(expansion.expand_here)
