"""Writing output files: atomically, never over an input."""

from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path


class OutputError(Exception):
    pass


def refuse_inputs(out: Path, inputs: Iterable[str | Path]) -> None:
    for candidate in inputs:
        if str(candidate) == "-":
            continue
        try:
            if Path(candidate).resolve() == out.resolve() or (out.exists() and os.path.samefile(out, candidate)):
                raise OutputError(f"{out}: refusing to overwrite the input file")
        except OSError:
            continue


def write_atomic(out: Path, data: bytes | str, inputs: Iterable[str | Path] = ()) -> None:
    """Write to a temporary file beside ``out`` and rename it into place."""
    refuse_inputs(out, inputs)
    if out.is_dir():
        raise OutputError(f"{out}: is a directory")
    payload = data.encode("utf-8") if isinstance(data, str) else data
    folder = out.parent if str(out.parent) else Path(".")
    import tempfile  # (with shutil and random) only when a file is written: most runs write none

    try:
        handle, temporary = tempfile.mkstemp(prefix=f".{out.name}.", suffix=".tmp", dir=folder)
    except OSError as error:
        raise OutputError(f"{out}: cannot write: {error.strerror}") from None
    try:
        with os.fdopen(handle, "wb") as stream:
            stream.write(payload)
        os.chmod(temporary, 0o644)
        os.replace(temporary, out)
    except BaseException as error:
        Path(temporary).unlink(missing_ok=True)
        if isinstance(error, OSError):
            raise OutputError(f"{out}: cannot write: {error.strerror}") from None
        raise
