"""GitHub Actions workflow annotations."""

from __future__ import annotations

from ..diagnostics import Diagnostic
from ..escape import escape
from . import call_phrase

LEVELS = {"error": "error", "warning": "warning", "info": "notice"}


def _escape_data(text: str) -> str:
    """Workflow-command escaping, after the control characters are made visible (the log is a terminal)."""
    return escape(text).replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")


def _escape_property(text: str) -> str:
    return _escape_data(text).replace(":", "%3A").replace(",", "%2C")


def line(diagnostic: Diagnostic) -> str:
    location = diagnostic.location
    props = [f"file={_escape_property(location.file)}"]
    if location.line:
        props.append(f"line={location.line}")
        if location.column:
            props.append(f"col={location.column}")
    props.append(f"title={_escape_property(diagnostic.code)}")
    calls = [call_phrase(call) for call in location.trace]
    return f"::{LEVELS[diagnostic.severity.value]} {','.join(props)}::" + "%0A".join(map(_escape_data, [diagnostic.message, *calls]))
