"""Bounded work: xacro's expansion runs in a child process limited in time and memory.

A :class:`Worker` is a process forked at its first job and kept for the jobs
that follow (forking a child per xacro file costs tens of milliseconds, more
the larger the parent has grown). Each job is limited in time and memory, so
that whatever gets past the expression guard (:mod:`urdfcli.read.guard`: a
long loop in ``python.sum(python.range(...))``, ``'a'.ljust(...)``) stops
there. A session owns one worker and stops it when it ends.
"""

from __future__ import annotations

import contextlib
import gc
import importlib
import os
import pickle
import select
import signal
import time
import weakref

DEFAULT_SECONDS = 30.0
DEFAULT_MEMORY_MIB = 2048
RETIRE_MIB = 64  # a worker that kept this much more memory after a job is replaced
_RETIRING = b"retiring"  # the worker's last message (never a pickle: those start with 0x80)


class LimitExceeded(Exception):
    """The job ran out of its time or memory (or its process died)."""


def limits_from_environment() -> tuple[float, int]:
    """The time (seconds) and memory (MiB) a job may use: URDFCLI_XACRO_TIMEOUT and
    URDFCLI_XACRO_MEMORY_MIB, else 30 s and 2 GiB."""
    seconds = float(os.environ.get("URDFCLI_XACRO_TIMEOUT", DEFAULT_SECONDS))
    memory = int(os.environ.get("URDFCLI_XACRO_MEMORY_MIB", DEFAULT_MEMORY_MIB))
    return seconds, memory


class Worker:
    """Runs functions of ``module`` in a bounded child process, one job at a time.

    The process is forked at the first job; the job (function name, arguments,
    the caller's environment and working folder) is pickled to it, and its answer
    pickled back. One that ran out of time is killed, one that died is reported;
    either is replaced at the next job. After answering, the process frees the
    job's cyclic garbage while the caller goes on; one that kept more than
    RETIRE_MIB of memory retires, so that every job has its whole allowance.
    Where ``os.fork`` is missing, jobs run in this process, unbounded.
    """

    def __init__(self, module: str) -> None:
        self.module = module
        self._process: _Process | None = None

    def run(self, function: str, *args):
        """``module.function(*args)`` under the bounds; its exception is raised here."""
        if not hasattr(os, "fork"):
            return getattr(importlib.import_module(self.module), function)(*args)
        seconds, memory_mib = limits_from_environment()
        job = _dumps_job(self.module, function, args)
        for _ in range(2):  # a process that retired or died since its last job is replaced once
            process = self._current(memory_mib)
            answer = process.ask(job, time.monotonic() + seconds)
            if answer is not _ENDED_BEFORE:
                break
            self.stop()
        if answer is None:
            self.stop()
            raise LimitExceeded(f"it took longer than {seconds:g} s")
        if not answer or answer is _ENDED_BEFORE:
            self.stop()
            raise LimitExceeded(f"its process ended without a result (more than {memory_mib} MiB of memory?)")
        ok, value = pickle.loads(answer)
        if ok:
            return value
        raise value

    def _current(self, memory_mib: int) -> _Process:
        process = self._process
        if process is not None and (process.interrupted or process.owner != os.getpid() or process.memory_mib != memory_mib):
            self.stop()  # interrupted (it may not have ended yet), inherited through a fork, or the limit changed
            process = None
        if process is None:
            process = self._process = _Process(memory_mib)
        return process

    def interrupt(self) -> None:
        """Kill the process now, from any thread: a job it runs ends in LimitExceeded
        (its process ended without a result), and the next job starts another."""
        process = self._process
        if process is not None and process.owner == os.getpid():
            process.interrupted = True  # the next job must not be given to it while it dies
            with contextlib.suppress(ProcessLookupError):
                os.kill(process.pid, signal.SIGKILL)

    def stop(self) -> None:
        """Stop the process (the next job starts another)."""
        process, self._process = self._process, None
        if process is not None:
            process.stop()


_ENDED_BEFORE = object()  # the process ended before it took the job


class _Process:
    """One forked worker process and the two pipes to it."""

    def __init__(self, memory_mib: int) -> None:
        jobs_read, self.jobs = os.pipe()
        self.answers, answers_write = os.pipe()
        self.memory_mib = memory_mib
        self.interrupted = False
        self.owner = os.getpid()
        self.pid = os.fork()
        if self.pid == 0:  # the worker: never returns
            os.close(self.jobs)
            os.close(self.answers)
            _serve(jobs_read, answers_write, memory_mib)
        os.close(jobs_read)
        os.close(answers_write)
        # stopped when the session lets go of it, or at the end of the program
        self._finalizer = weakref.finalize(self, _stop, self.owner, self.pid, self.jobs, self.answers)

    def ask(self, job: bytes, deadline: float):
        """The answer to ``job``: None when the time ran out, b"" when the process died
        during the job, _ENDED_BEFORE when it had ended before taking it."""
        if _readable(self.answers, 0):  # its notice of retiring, or its end, since the last answer
            return _ENDED_BEFORE
        try:
            _write_message(self.jobs, job)
        except OSError:  # BrokenPipeError: it ended before reading the job
            return _ENDED_BEFORE
        answer = _read_message(self.answers, deadline)
        return _ENDED_BEFORE if answer == _RETIRING else answer

    def stop(self) -> None:
        self._finalizer()


def _stop(owner: int, pid: int, *pipes: int) -> None:
    if owner != os.getpid():
        return  # a forked copy: the process is its parent's
    for fd in pipes:
        with contextlib.suppress(OSError):
            os.close(fd)
    with contextlib.suppress(ProcessLookupError):
        os.kill(pid, signal.SIGKILL)
    with contextlib.suppress(ChildProcessError):
        os.waitpid(pid, 0)


def _serve(jobs: int, answers: int, memory_mib: int) -> None:
    status = 0
    try:
        # A job's cyclic garbage is freed after it (below), not while it runs: collecting
        # during an expansion took a quarter of xacro's time on 1,500 macro calls, and
        # freed 2 MiB. A job that makes cycles without end still meets the memory limit.
        gc.disable()
        # What the worker inherited is the parent's, never its garbage: set aside, the
        # collection after a job walks only what jobs made (a full walk of a freshly
        # started command's objects took 7 ms, which the first expansion waited for).
        gc.freeze()
        _limit_memory(memory_mib)
        baseline = _memory_used(RESIDENT)
        while True:
            job = _read_message(jobs, None)
            if not job:
                break  # the parent is gone
            outcome = _outcome(job, memory_mib)
            job = None
            _write_message(answers, _dumps_outcome(outcome))
            outcome = None
            gc.collect()  # xacro's DOM is cyclic: freed while the parent goes on
            if _memory_used(RESIDENT) > baseline + RETIRE_MIB * 1024 * 1024:
                _write_message(answers, _RETIRING)
                break
    except BaseException:  # noqa: BLE001 - the parent reports an empty answer
        status = 1
    finally:
        os._exit(status)  # a forked child must not run its parent's exit handlers


def _outcome(job: bytes, memory_mib: int) -> tuple:
    try:
        module, function, args, environ, cwd = pickle.loads(job)
        os.environ.clear()
        os.environ.update(environ)
        if cwd is not None:
            with contextlib.suppress(OSError):
                os.chdir(cwd)
        return (True, getattr(importlib.import_module(module), function)(*args))
    except MemoryError:
        return (False, LimitExceeded(f"it needed more than {memory_mib} MiB of memory"))
    except BaseException as error:  # noqa: BLE001 - sent to the parent as it is
        return (False, error)


def _dumps_outcome(outcome: tuple) -> bytes:
    try:
        return pickle.dumps(outcome)
    except Exception as error:  # noqa: BLE001
        return pickle.dumps((False, RuntimeError(f"{type(error).__name__}: {error}")))


def _dumps_job(module: str, function: str, args: tuple) -> bytes:
    try:
        cwd = os.getcwd()
    except OSError:  # the working folder was removed
        cwd = None
    return pickle.dumps((module, function, args, dict(os.environ), cwd), pickle.HIGHEST_PROTOCOL)


def _write_message(fd: int, payload: bytes) -> None:
    data = memoryview(len(payload).to_bytes(8, "little") + payload)
    while data:
        data = data[os.write(fd, data):]


def _read_message(fd: int, deadline: float | None) -> bytes | None:
    """One message from ``fd``: None at the deadline, b"" when the writer is gone."""
    header = _read_exactly(fd, 8, deadline)
    if not header:
        return header
    return _read_exactly(fd, int.from_bytes(header, "little"), deadline)


def _read_exactly(fd: int, size: int, deadline: float | None) -> bytes | None:
    chunks, left = [], size
    while left:
        if deadline is not None:
            wait = deadline - time.monotonic()
            if wait <= 0 or not _readable(fd, wait):
                return None
        chunk = os.read(fd, min(left, 1 << 20))
        if not chunk:
            return b""
        chunks.append(chunk)
        left -= len(chunk)
    return b"".join(chunks)


def _readable(fd: int, seconds: float) -> bool:
    """Whether ``fd`` has something to read, or its writer is gone, within ``seconds``."""
    poll = select.poll()  # (select.select refuses descriptors above 1023)
    poll.register(fd, select.POLLIN)
    return bool(poll.poll(max(seconds, 0) * 1000))


MAPPED, RESIDENT = 0, 1  # the fields of /proc/self/statm: address space, and the pages in memory


def _memory_used(kind: int = MAPPED) -> int:
    """Bytes of this process's address space (what its limit counts), or of its pages in memory."""
    try:
        with open("/proc/self/statm") as statm:
            return int(statm.read().split()[kind]) * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError):
        return 0


def _limit_memory(memory_mib: int) -> None:
    """At most ``memory_mib`` more address space than the process has when forked.
    (Memory its parent had freed and kept for reuse comes on top: a worker is
    forked early, while its parent is small.)"""
    try:
        import resource

        used = _memory_used()
        if not used:
            return  # no /proc here: the time bound still holds
        limit = used + memory_mib * 1024 * 1024
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    except (ImportError, OSError, ValueError):
        pass  # no limits here: the time bound still holds
