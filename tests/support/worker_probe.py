"""Functions for the tests of the bounded worker (tests/test_worker.py) to run in it."""

import os
import time

KEPT = []


def pid() -> int:
    return os.getpid()


def die(status: int) -> None:
    os._exit(status)


def keep(size: int) -> int:
    KEPT.append(bytearray(size))  # memory the job leaves behind in its process
    return os.getpid()


def sleep(seconds: float) -> None:
    time.sleep(seconds)


def allocate(size: int) -> int:
    return len(bytearray(size))


def variable(name: str) -> str | None:
    return os.environ.get(name)


def folder() -> str:
    return os.getcwd()
