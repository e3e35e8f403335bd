"""Text from an input, made safe to show on a terminal or in a text output.

A name, message or source line from an untrusted file must not drive the
terminal (ESC and OSC sequences, C1 controls such as CSI), hide or reorder
what is shown (bidirectional overrides and isolates, direction marks), or
break the output's lines. Every character that is not printable (Unicode
categories Cc, Cf, Zl, Zp, Zs other than the space, Co, Cn, Cs) is shown as a
visible escape, ``\\x1b``, ``\\u202e``, ``\\n``; everything printable, any
script included, is left alone.
"""

from __future__ import annotations

NAMED = {"\n": "\\n", "\r": "\\r", "\t": "\\t"}


def escaped(character: str) -> str:
    """One character as a visible escape."""
    if character in NAMED:
        return NAMED[character]
    code = ord(character)
    if code < 0x100:
        return f"\\x{code:02x}"
    return f"\\u{code:04x}" if code < 0x10000 else f"\\U{code:08x}"


def escape(text: str) -> str:
    """``text`` with every non-printable character shown as an escape."""
    if text.isprintable():  # the usual case, and fast
        return text
    return "".join(c if c.isprintable() else escaped(c) for c in text)


def json_escape(text: str) -> str:
    """JSON text (``ensure_ascii=False``) with the same characters escaped as JSON
    ``\\uXXXX`` escapes: the data is unchanged, the terminal is safe."""
    if text.isprintable():
        return text
    return "".join(c if c.isprintable() or c == "\n" else _json_escaped(c) for c in text)


def _json_escaped(character: str) -> str:
    code = ord(character)
    if code < 0x10000:
        return f"\\u{code:04x}"
    code -= 0x10000
    return f"\\u{0xD800 + (code >> 10):04x}\\u{0xDC00 + (code & 0x3FF):04x}"
