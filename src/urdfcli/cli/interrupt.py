"""Ctrl-C while a command runs: what every command does with it, installed before any is built."""

from __future__ import annotations

import signal
import threading


class CtrlC:
    """The SIGINT handler of a command: raise KeyboardInterrupt, and remember it. A
    library may swallow the exception (trimesh catches BaseException while it imports
    scipy): the command still stops at the next model (:meth:`stop_if_pressed`), or
    ends with exit code 130."""

    def __init__(self) -> None:
        self.pressed = False
        self.previous = None

    @classmethod
    def install(cls) -> CtrlC:
        handler = cls()
        if threading.current_thread() is threading.main_thread():  # signals reach the main thread only
            handler.previous = signal.signal(signal.SIGINT, handler)
        return handler

    def uninstall(self) -> None:
        if self.previous is not None:
            signal.signal(signal.SIGINT, self.previous)

    def __call__(self, signum, frame) -> None:
        self.pressed = True
        raise KeyboardInterrupt

    @staticmethod
    def stop_if_pressed(*_) -> None:
        """Raise KeyboardInterrupt when Ctrl-C was pressed (a progress callback)."""
        handler = signal.getsignal(signal.SIGINT)
        if isinstance(handler, CtrlC) and handler.pressed:
            raise KeyboardInterrupt
