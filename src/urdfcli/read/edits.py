"""Edits of a source file: spans of its text replaced, every other byte kept.

An edit's offsets count characters of the text as :class:`~.positions.Source`
keeps it: decoded (byte-order mark, else declared encoding, else UTF-8) and
with its line ends read as ``\\n``. :func:`apply` maps them back onto the file's
own text, so that comments, indentation, attribute order, quotes, tabs, CR LF
line ends, the XML declaration and the encoding stay as they were, and writes
a new line in a replacement with the file's own line end. A file whose bytes
do not decode and encode back to themselves is not edited.

:func:`write` replaces a file atomically: a reader sees the old file or the new
one, never a part.
"""

from __future__ import annotations

import bisect
import os
from collections.abc import Iterable
from pathlib import Path

from .positions import bom_encoding, declared_encoding


class EditError(ValueError):
    """The edits cannot be applied to this file: what is wrong, in a sentence."""


def _codec(data: bytes) -> str:
    encoding = bom_encoding(data) or declared_encoding(data) or "utf-8"
    try:
        "".encode(encoding)
    except LookupError:
        return "utf-8"
    return encoding


def line_end(text: str) -> str:
    """The line end a text uses most: ``\\r\\n``, ``\\r`` or ``\\n``."""
    crlf = text.count("\r\n")
    cr = text.count("\r") - crlf
    lf = text.count("\n") - crlf
    return "\r\n" if crlf and crlf >= max(cr, lf) else "\r" if cr > lf else "\n"


def apply(data: bytes, edits: Iterable[tuple[int, int, str]]) -> bytes:
    """``data`` with each (start, end, text) edit made; the edits must not overlap
    (two insertions at one offset are made in the order given). Raises EditError."""
    edits = sorted(edits, key=lambda e: (e[0], e[1]))
    if not edits:
        return data
    codec = _codec(data)
    try:
        raw = data.decode(codec)
    except UnicodeDecodeError:
        raise EditError(f"not valid {codec}: left as it is") from None
    if raw.encode(codec) != data:
        raise EditError(f"its bytes do not read back the same as {codec}: left as it is")
    # a CR LF is one \n of the text: the CR of each is where the offsets shift by one
    # (a lone CR stands for the \n itself, one character for one)
    dropped = [i for i in range(len(raw) - 1) if raw[i] == "\r" and raw[i + 1] == "\n"] if "\r" in raw else []
    shifted = [position - k for k, position in enumerate(dropped)]  # where each is in the text
    newline = line_end(raw) if "\r" in raw else "\n"

    def raw_offset(offset: int) -> int:
        return offset + bisect.bisect_left(shifted, offset)

    pieces, at, previous_end = [], 0, -1
    for start, end, text in edits:
        if start < previous_end or start > end:
            raise EditError("two fixes change the same text")
        begin, finish = raw_offset(start), raw_offset(end)
        if finish > len(raw):
            raise EditError("a fix lies outside the file")
        pieces += [raw[at:begin], text.replace("\n", newline) if newline != "\n" else text]
        at, previous_end = finish, end
    pieces.append(raw[at:])
    try:
        return "".join(pieces).encode(codec)
    except UnicodeEncodeError:
        raise EditError(f"a fix writes a character {codec} cannot hold") from None


def write(path: str | os.PathLike, data: bytes) -> None:
    """Replace the file at ``path`` by ``data`` atomically, keeping its permissions; a
    symbolic link is kept, and the file it names replaced."""
    import tempfile  # (here: only a run that writes a fix needs it)

    target = Path(os.path.realpath(path))
    mode = target.stat().st_mode & 0o7777 if target.exists() else None
    handle, temporary = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".urdfcli", dir=target.parent)
    try:
        with os.fdopen(handle, "wb") as out:
            out.write(data)
            out.flush()
            os.fsync(out.fileno())
        if mode is not None:
            os.chmod(temporary, mode)
        os.replace(temporary, target)
    except BaseException:
        try:
            os.unlink(temporary)
        except OSError:
            pass
        raise


def diff_folder(names: Iterable[str]) -> str:
    """The folder a diff of these files is written relative to: the working folder
    (``.``) when each file is below it, else the nearest folder above it that holds them
    all (``..``, ``../..``): ``patch`` and ``git apply`` refuse a path with ``..`` in it,
    or an absolute one. Standard input and a file on another drive are left as named."""
    here = os.getcwd()
    files = [os.path.abspath(name) for name in names if _on_disk(name)]
    try:
        return os.path.relpath(os.path.commonpath([here, *files]), here)
    except ValueError:  # another drive
        return os.curdir


def unified_diff(name: str, old: bytes, new: bytes, folder: str = os.curdir) -> bytes:
    """The unified diff that makes ``new`` of ``old`` (``--- a/NAME`` ``+++ b/NAME``, NAME
    relative to ``folder`` when the file is below it), as ``patch -p1 -d FOLDER`` applies
    it: lines compared as bytes, so that line ends and the file's encoding are kept."""
    import difflib

    base = os.path.abspath(folder)
    full = os.path.abspath(name)
    shown = os.path.relpath(full, base) if _on_disk(name) and _below(full, base) else name
    lines = []
    for line in difflib.diff_bytes(
        difflib.unified_diff, old.splitlines(keepends=True), new.splitlines(keepends=True), os.fsencode(f"a/{shown}"), os.fsencode(f"b/{shown}")
    ):
        lines.append(line)
        if not line.endswith((b"\n", b"\r")):
            lines.append(b"\n\\ No newline at end of file\n")
    return b"".join(lines)


def _on_disk(name: str) -> bool:
    """Whether a file name is a path (not standard input, ``-`` or ``<stdin>``)."""
    return name != "-" and not name.startswith("<")


def _below(path: str, folder: str) -> bool:
    try:
        return os.path.commonpath([path, folder]) == folder
    except ValueError:  # another drive
        return False
