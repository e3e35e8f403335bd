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


def test_a_job_that_cannot_be_pickled_runs_in_a_child_of_its_own():
    assert sandbox.bounded(lambda: os.getpid()) != os.getpid()


XACRO_FIXTURES = sorted(FIXTURES.rglob("*.xacro"))


def expansion_of(expand, path: Path, mappings: dict[str, str]):
    try:
        result = expand(path.read_bytes(), str(path), mappings, PackageResolver((), path))
    except expanded.ExpansionError as error:
        return ("error", error.message, error.origin, error.file, error.code)
    return (result.text, list(result.origins), result.includes, result.warnings)


@pytest.mark.parametrize("path", XACRO_FIXTURES, ids=lambda p: str(p.relative_to(FIXTURES)))
def test_expansion_in_the_worker_is_the_expansion_in_process(path: Path):
    assert expansion_of(expanded.expand, path, {}) == expansion_of(expansion.expand_here, path, {})


def test_a_job_sent_now_is_answered_when_asked_for():
    sent = sandbox.Sent(os.getpid)
    assert sent.result() == sandbox.bounded(os.getpid) != os.getpid()


def answered(sent: sandbox.Sent) -> bool:
    deadline = time.monotonic() + 10
    while not sent.worker.answered():
        assert time.monotonic() < deadline, "the worker did not answer"
        time.sleep(0.01)
    return True


def test_a_job_given_up_after_its_answer_leaves_the_worker_to_the_next_job():
    worker = sandbox.bounded(os.getpid)
    sent = sandbox.Sent(sum, [1, 2])
    assert answered(sent)
    sent.drop()
    assert sandbox.bounded(os.getpid) == worker


def test_a_job_given_up_before_its_answer_stops_the_worker_and_the_next_job_starts_another():
    worker = sandbox.bounded(os.getpid)
    sent = sandbox.Sent(time.sleep, 30)
    started = time.monotonic()
    sent.drop()
    assert sandbox.bounded(os.getpid) != worker
    assert time.monotonic() - started < 5


CAR = FIXTURES / "urdf01_rviz" / "urdf" / "xacro" / "car.urdf.xacro"


@pytest.fixture
def two_cpus(monkeypatch):
    monkeypatch.setattr(os, "sched_getaffinity", lambda pid: {0, 1}, raising=False)


def test_the_first_expansion_of_a_run_takes_the_answer_sent_ahead_for_it(two_cpus, monkeypatch):
    with expanded.started(str(CAR), {"unused": "1"}):
        monkeypatch.setattr(sandbox, "bounded", None)  # no job is sent again
        assert expanded._ahead is not None
        assert expansion_of(expanded.expand, CAR, {"unused": "1"}) == expansion_of(expansion.expand_here, CAR, {"unused": "1"})
        assert expanded._ahead is None


@pytest.mark.parametrize("first", [CAR.with_name("demo05_car_base.urdf.xacro"), CAR], ids=["another file", "other arguments"])
def test_another_first_expansion_drops_the_one_sent_ahead(two_cpus, first):
    with expanded.started(str(CAR), {"unused": "1"}):
        assert expansion_of(expanded.expand, first, {}) == expansion_of(expansion.expand_here, first, {})
        assert expanded._ahead is None
        assert expansion_of(expanded.expand, CAR, {"unused": "1"}) == expansion_of(expansion.expand_here, CAR, {"unused": "1"})


def test_an_expansion_sent_ahead_and_not_asked_for_is_dropped_at_the_end_of_the_run(two_cpus):
    with expanded.started(str(CAR), {}):
        assert expanded._ahead is not None
    assert expanded._ahead is None
    assert expansion_of(expanded.expand, CAR, {}) == expansion_of(expansion.expand_here, CAR, {})


ODD_DOCUMENTS = [
    '<?xml version="1.0" encoding="UTF-8"?>\r\n<!-- a <link> in a comment -->\r\n<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
    '<?pi <x>?><link\n   name="é&amp;&#x41;" a="1&#10;2"><![CDATA[ <joint> ]]></link>\t<xacro:if value="1"><link name="b"/></xacro:if></robot>',
    '<?xml version="1.0" encoding="ISO-8859-1"?><robot name="r"><link name="\xe9"/></robot>',
]


def readings(data: bytes) -> tuple[str, str]:
    """The document xacro is given, read by minidom alone and through urdfcli's reader."""
    from urdfcli.positions import Source, decode

    return (expansion.tagged_dom(data, "f").toxml(), expansion._tagged_by_reader(data, "f", Source(decode(data))).toxml())


@pytest.mark.parametrize(
    "data",
    [*(p.read_bytes() for p in XACRO_FIXTURES), *(d.encode("latin-1" if "8859" in d else "utf-8") for d in ODD_DOCUMENTS)],
    ids=[*(str(p.relative_to(FIXTURES)) for p in XACRO_FIXTURES), "odd-markup", "latin-1"],
)
def test_minidom_alone_reads_and_marks_a_document_as_urdfcli_s_reader_does(data):
    alone, through_reader = readings(data)
    assert alone == through_reader
    assert expansion.ORIGIN in alone
