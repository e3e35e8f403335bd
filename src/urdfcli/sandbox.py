"""Bounded work: xacro's expansion runs in a child process limited in time and memory.

:func:`bounded` runs a job in the run's worker, a process forked once (see
:class:`_Worker`) and limited in time and memory, so that whatever gets past
the expression guard (:mod:`urdfcli.guard`: a long loop in
``python.sum(python.range(...))``, ``'a'.ljust(...)``) stops there. The worker
is forked as the run starts, before the rest of urdfcli is imported.
"""

from __future__ import annotations

import atexit
import contextlib
import gc
import importlib
import os
import pickle
import select
import time

TIMEOUT_SECONDS = float(os.environ.get("URDFCLI_XACRO_TIMEOUT", "30"))
MEMORY_MIB = int(os.environ.get("URDFCLI_XACRO_MEMORY_MIB", "2048"))


class LimitExceeded(Exception):
    """The expansion ran out of its time or memory."""


# -- the time and memory bound ------------------------------------------------------
def call(module: str, name: str, *args):
    """``module.name(*args)``, the module imported here: given to :func:`bounded`,
    only the process that runs the job imports it."""
    return getattr(importlib.import_module(module), name)(*args)


def start(*modules: str) -> None:
    """Fork the run's worker now (see :class:`_Worker`), and have it import ``modules``
    while this process goes on. Does nothing where fork is missing or a worker runs."""
    if hasattr(os, "fork"):
        with contextlib.suppress(OSError):  # no process to spare now: the first job forks it, or says why not
            _Worker.for_run(MEMORY_MIB, modules)


def bounded(function, *args):
    """``function(*args)`` in a forked process with at most TIMEOUT_SECONDS and MEMORY_MIB more memory.

    Returns its result or raises its exception; raises LimitExceeded when the
    process runs out of time or memory (or dies). A job that can be pickled goes
    to one worker forked for the whole run (see :class:`_Worker`); any other
    runs in a child forked for it. Where fork is missing, runs in-process.
    """
    if not hasattr(os, "fork"):
        return function(*args)
    try:
        sent = Sent(function, *args)
    except (pickle.PicklingError, TypeError, AttributeError, OSError):  # a lambda, a lost working folder...
        return _bounded_once(function, args)
    return sent.result()


class Sent:
    """A job given to the run's worker now, under the bounds of :func:`bounded`
    (its time counted from now); its answer is read when asked for, so that this
    process goes on meanwhile. Raises what pickling the job raises."""

    def __init__(self, function, *args):
        self.job = _dumps_job(function, args)
        self.seconds, self.memory_mib = TIMEOUT_SECONDS, MEMORY_MIB
        self.deadline = time.monotonic() + self.seconds
        self.worker = _Worker.for_run(self.memory_mib)
        self.taken = self.worker.send(self.job)

    def result(self):
        """The job's value, or its exception raised here (see :func:`bounded`)."""
        data = self.worker.receive(self.deadline) if self.taken else _RETIRED
        if data is _RETIRED:  # it ended before taking the job: a new one takes it
            worker = _Worker.for_run(self.memory_mib)
            data = worker.receive(time.monotonic() + self.seconds) if worker.send(self.job) else _RETIRED
        return _result(b"" if data is _RETIRED else data, self.seconds, self.memory_mib)

    def answered(self) -> bool:
        """Whether the answer is in: :meth:`result` would not wait."""
        return self.taken and self.worker.answered()

    def drop(self) -> None:
        """Give up the job: its answer is read and left when it is there already,
        else the worker is stopped (the next job starts another)."""
        if self.answered():
            self.worker.receive(self.deadline)
        else:
            self.worker.stop()


def _result(data: bytes | None, seconds: float, memory_mib: int):
    """The job's value from a child's answer, or its exception raised here."""
    if not data:
        _ended(data, seconds, memory_mib)
    ok, value = pickle.loads(data)
    if ok:
        return value
    raise value


def _ended(data: bytes | None, seconds: float, memory_mib: int):
    if data is None:
        raise LimitExceeded(f"it took longer than {seconds:g} s")
    raise LimitExceeded(f"its process ended without a result (more than {memory_mib} MiB of memory?)")


def _bounded_once(function, args):
    """``bounded`` for a job that cannot be pickled: a child forked for it alone."""
    seconds, memory_mib = TIMEOUT_SECONDS, MEMORY_MIB
    read_end, write_end = os.pipe()
    pid = os.fork()
    if pid == 0:  # the child: never returns
        os.close(read_end)
        _run_child(write_end, memory_mib, function, args)
    os.close(write_end)
    try:
        data = _read_until(read_end, time.monotonic() + seconds)
    finally:
        os.close(read_end)
        _reap(pid)
    return _result(data, seconds, memory_mib)


def _run_child(write_end: int, memory_mib: int, function, args) -> None:
    status = 0
    try:
        _limit_memory(memory_mib)
        payload = _dumps_outcome(_outcome(function, args, memory_mib))
        with os.fdopen(write_end, "wb") as stream:
            stream.write(payload)
    except BaseException:  # noqa: BLE001 - the parent reports an empty answer
        status = 1
    finally:
        os._exit(status)


def _outcome(function, args, memory_mib: int) -> tuple:
    try:
        return (True, function(*args))
    except MemoryError:
        return (False, LimitExceeded(f"it needed more than {memory_mib} MiB of memory"))
    except BaseException as error:  # noqa: BLE001 - sent to the parent as it is
        return (False, error)


def _dumps_outcome(outcome: tuple) -> bytes:
    try:
        return pickle.dumps(outcome)
    except Exception as error:  # noqa: BLE001
        return pickle.dumps((False, RuntimeError(f"{type(error).__name__}: {error}")))


# -- one worker for the run ------------------------------------------------------------
RETIRE_MIB = 64  # a worker that kept this much more memory after a job is replaced
_RETIRING = b"retiring"  # the worker's last message (never a pickle: those start with 0x80)
_RETIRED = object()


class _Worker:
    """A process forked once per run that takes jobs, each under the same bounds.

    Forking a child per xacro file costs tens of milliseconds, and more the larger
    the parent has grown (its whole memory is mapped into the child and torn down
    after). The worker is forked at the first job, while the parent is small, or
    earlier by :func:`start`, which has it import what the jobs will need. A job
    is ``(function, args)`` pickled, with the parent's environment and working
    folder; the answer is pickled back. The worker has the same memory limit as a
    child per job had; one that ran out of time is killed, one that died is
    reported, and either is replaced at the next job. After answering, the worker
    frees the job's cyclic garbage while the parent goes on; one that kept more
    than RETIRE_MIB of memory retires (says so and ends), so that every job has its
    whole allowance.
    """

    _current: _Worker | None = None

    def __init__(self, memory_mib: int, modules: tuple[str, ...] = ()):
        jobs_read, self.jobs = os.pipe()
        self.answers, answers_write = os.pipe()
        self.memory_mib = memory_mib
        self.owner = os.getpid()
        self.pid = os.fork()
        if self.pid == 0:  # the worker: never returns
            os.close(self.jobs)
            os.close(self.answers)
            _serve(jobs_read, answers_write, memory_mib, modules)
        os.close(jobs_read)
        os.close(answers_write)

    @classmethod
    def for_run(cls, memory_mib: int, modules: tuple[str, ...] = ()) -> _Worker:
        current = cls._current
        if current is not None and current.owner != os.getpid():
            current = cls._current = None  # inherited by a forked process: its parent's, not ours
        if current is not None and current.memory_mib != memory_mib:
            current.stop()
            current = None
        if current is None:
            current = cls._current = cls(memory_mib, modules)
            atexit.register(current.stop)
        return current

    def send(self, job: bytes) -> bool:
        """Give it a job; False when it has ended (retired, or died) since its last answer."""
        if self.answered():  # its notice of retiring, or its end, since the last answer
            self.stop()
            return False
        try:
            _write_message(self.jobs, job)
        except OSError:  # BrokenPipeError: it ended before reading the job
            self.stop()
            return False
        return True

    def receive(self, deadline: float):
        """The answer to the job it took: None when the time ran out, b"" when it died
        during the job, _RETIRED when it ended without taking the job. The worker
        is stopped unless it answered."""
        answer = _read_message(self.answers, deadline)
        if answer == _RETIRING:  # it retired after its last answer, before reading this job
            answer = _RETIRED
        if answer is None or answer is _RETIRED or not answer:
            self.stop()
        return answer

    def answered(self) -> bool:
        """Whether it has written something not read yet (or ended)."""
        return _readable(self.answers, 0)

    def stop(self) -> None:
        if self.owner != os.getpid() or self.pid is None:
            return
        for fd in (self.jobs, self.answers):
            with contextlib.suppress(OSError):
                os.close(fd)
        _reap(self.pid)
        self.pid = None
        if _Worker._current is self:
            _Worker._current = None


def _serve(jobs: int, answers: int, memory_mib: int, modules: tuple[str, ...]) -> None:
    status = 0
    try:
        for module in modules:  # what its jobs will need, imported before the first one comes
            with contextlib.suppress(Exception):  # a job that needs it raises the error itself
                importlib.import_module(module)
        gc.freeze()  # what the parent had: never scanned here, so never copied
        # A job's cyclic garbage is freed after it (below), not while it runs: collecting
        # during an expansion took a quarter of xacro's time on 1,500 macro calls, and
        # freed 2 MiB. A job that makes cycles without end still meets the memory limit.
        gc.disable()
        _limit_memory(memory_mib)
        baseline = _memory_used()
        while True:
            job = _read_message(jobs, None)
            if not job:
                break  # the parent is gone
            try:
                function, args, environ, cwd = pickle.loads(job)
                os.environ.clear()
                os.environ.update(environ)
                with contextlib.suppress(OSError):
                    os.chdir(cwd)
            except BaseException as error:  # noqa: BLE001 - told to the parent
                outcome = (False, error)
            else:
                outcome = _outcome(function, args, memory_mib)
            job = function = args = None
            _write_message(answers, _dumps_outcome(outcome))
            outcome = None
            gc.collect()  # xacro's DOM is cyclic: freed while the parent goes on
            if _memory_used() > baseline + RETIRE_MIB * 1024 * 1024:
                _write_message(answers, _RETIRING)
                break
    except BaseException:  # noqa: BLE001 - the parent reports an empty answer
        status = 1
    finally:
        os._exit(status)


def _dumps_job(function, args) -> bytes:
    return pickle.dumps((function, args, dict(os.environ), os.getcwd()), pickle.HIGHEST_PROTOCOL)


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


def _memory_used() -> int:
    try:
        with open("/proc/self/statm") as statm:
            return int(statm.read().split()[0]) * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError):
        return 0


def _limit_memory(memory_mib: int) -> None:
    try:
        import resource

        used = _memory_used()
        if not used:
            return  # no /proc here: the time bound still holds
        limit = used + memory_mib * 1024 * 1024
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    except (ImportError, OSError, ValueError):
        pass  # no /proc or no limits here: the time bound still holds


def _read_until(fd: int, deadline: float) -> bytes | None:
    """Everything written to ``fd`` until it closes, or None at the deadline."""
    chunks = []
    while True:
        left = deadline - time.monotonic()
        if left <= 0 or not _readable(fd, left):
            return None
        chunk = os.read(fd, 1 << 20)
        if not chunk:
            return b"".join(chunks)
        chunks.append(chunk)


def _reap(pid: int) -> None:
    """Stop the child if it still runs, and collect it."""
    import signal  # (here: at the end of a run, not on the way to its first answer)

    try:
        os.kill(pid, signal.SIGKILL)
    except ProcessLookupError:
        pass
    os.waitpid(pid, 0)
