"""urdfcli: check, expand, draw and lint URDF and xacro robot descriptions.

The command line is ``urdfcli``; from Python::

    import urdfcli

    result = urdfcli.check("urdf/robot.urdf.xacro", "ur_type:=ur5e")
    assert not result.errors, urdfcli.text_report(result)
"""

from importlib import import_module

from .version import __version__

_EXPORTS = {
    "UsageError": "api", "check": "api", "diff": "api", "drift": "api", "lint": "api", "text_report": "api",
    "Call": "diagnostics", "Diagnostic": "diagnostics", "Location": "diagnostics", "Severity": "diagnostics",
    "Options": "options", "Result": "model.result", "RuleSet": "options", "Session": "session",
}


def __getattr__(name: str):
    """The library's names, imported when first used: ``urdfcli`` itself, which the
    program's entry point imports first, imports nothing else (see __main__)."""
    if name not in _EXPORTS:
        raise AttributeError(f"module 'urdfcli' has no attribute {name!r}")
    return getattr(import_module(f".{_EXPORTS[name]}", __name__), name)


__all__ = [
    "Call", "Diagnostic", "Location", "Options", "Result", "RuleSet", "Session", "Severity", "UsageError", "__version__", "check", "diff", "drift",
    "lint", "text_report",
]
