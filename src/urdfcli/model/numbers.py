"""Numbers as urdfdom reads them, so that urdfcli accepts and rejects the same text.

urdfdom reads a scalar with a C++ stream: leading white space is skipped, the
whole rest must be a decimal number (no ``nan``, ``inf``, hex or trailing
space), and a value that overflows is refused. A vector is split on single
spaces only (tabs and newlines are not separators), empty pieces skipped.
"""

from __future__ import annotations

import math
import re

_DECIMAL = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
_DECIMAL_CHARACTERS = "0123456789.eE+-"
_VECTOR_CHARACTERS = _DECIMAL_CHARACTERS + " "
_NON_FINITE = re.compile(r"[+-]?(?:nan|inf|infinity)", re.IGNORECASE)


class NumberError(ValueError):
    """``code`` is V001 (not a number) or V002 (not finite)."""

    def __init__(self, code: str, reason: str):
        super().__init__(reason)
        self.code = code
        self.reason = reason


def shown(text: str, limit: int = 60) -> str:
    """``text`` quoted for a message, shortened when it is long."""
    if len(text) <= limit:
        return f"'{text}'"
    return f"'{text[:limit]}...' ({len(text)} characters)"


def parse_double(text: str) -> float:
    if text and not text.strip(_DECIMAL_CHARACTERS):
        # Only digits, signs, points and exponents: here float() accepts exactly
        # what _DECIMAL matches, and is much faster (models hold millions of numbers).
        try:
            value = float(text)
        except ValueError:
            pass
        else:
            if not math.isinf(value):
                return value
    body = text.lstrip(" \t\n\r\f\v")
    if _DECIMAL.fullmatch(body):
        value = float(body)
        if math.isinf(value):
            raise NumberError("V002", f"{shown(text)} overflows a double")
        return value
    if _NON_FINITE.fullmatch(body.strip()):
        raise NumberError("V002", f"{shown(text)} is not a finite number")
    if _DECIMAL.fullmatch(body.rstrip()):
        raise NumberError("V001", f"{shown(text)} is not a number: it ends in white space")
    return _malformed(text)


def parse_doubles(texts: tuple[str | None, ...]) -> tuple[float, ...] | None:
    """The values of several attributes at once when each is a plain finite number
    (an inertia tensor's six): as in parse_double, float() then accepts exactly
    urdfdom's numbers. None when one is missing or not such a number: parse_double
    on each then says which and why."""
    if None in texts:
        return None
    joined = "".join(texts)  # type: ignore[arg-type]
    if joined.strip(_DECIMAL_CHARACTERS):
        return None
    try:
        values = tuple(map(float, texts))  # type: ignore[arg-type]
    except ValueError:  # an empty text, or a sign or point alone
        return None
    return values if all(map(math.isfinite, values)) else None


def _malformed(text: str):
    raise NumberError("V001", f"{shown(text)} is not a number")


def parse_vector(text: str, length: int = 3) -> tuple[float, ...]:
    """Raises NumberError, or VectorLengthError for a wrong count of components."""
    if not text.strip(_VECTOR_CHARACTERS):
        # The common case, whole: as in parse_double, float() then accepts exactly urdfdom's numbers.
        try:
            values = tuple(map(float, text.split()))
        except ValueError:
            pass
        else:
            if len(values) == length and all(map(math.isfinite, values)):
                return values
    values = tuple([parse_double(piece) for piece in text.split(" ") if piece])
    if len(values) != length:
        raise VectorLengthError(len(values), length, text)
    return values


class VectorLengthError(ValueError):
    def __init__(self, found: int, expected: int, text: str):
        super().__init__(f"{shown(text)} has {found} components, {expected} expected")
        self.found = found
        self.expected = expected
        self.reason = str(self)


def format_number(value: float) -> str:
    """Shortest text that reads back as the same double (Python's repr, no '.0')."""
    text = repr(float(value))
    return text[:-2] if text.endswith(".0") else text
