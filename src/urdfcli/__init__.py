"""urdfcli: check, expand, draw and lint URDF and xacro robot descriptions.

The command line is ``urdfcli``; from Python::

    import urdfcli

    result = urdfcli.check("urdf/robot.urdf.xacro", "ur_type:=ur5e")
    assert not result.errors, result.report()
"""

from .api import UsageError, check, lint
from .diagnostics import Call, Diagnostic, Location, Severity
from .report.result import Result
from .session import Session
from .version import __version__

__all__ = ["Call", "Diagnostic", "Location", "Result", "Session", "Severity", "UsageError", "__version__", "check", "lint"]
