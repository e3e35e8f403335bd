"""The one model ``tree`` and ``graph`` draw: loaded with its configuration and check's
rules, its errors printed as check prints them, and the link to draw from."""

from __future__ import annotations

from .. import api
from ..model.kinematics import roots
from ..model.result import Result, Unreadable
from ..report.console import Output, write
from ..report.lines import diagnostics_lines
from ..report.targets import joint_notes, link_notes
from ..rules import REGISTRY, Kind
from ..rules.suggestions import close_matches
from ..session import Session
from .common import fail, not_a_robot, refuse_library


def target_notes(builds) -> dict[str, str]:
    """What the targets make of each link and joint, each said by its target when there are several."""
    notes: dict[str, list[str]] = {}
    for built in builds:
        prefix = f"{built.profile.name}: " if len(builds) > 1 else ""
        for name, note in (link_notes(built) | joint_notes(built)).items():
            notes.setdefault(name, []).append(prefix + note)
    return {name: "; ".join(found) for name, found in notes.items()}


def load_model(path: str, session: Session) -> Result:
    """One input to draw, with its configuration and the rules `check` runs (its
    errors are the model's errors, as `check` reports them), with its arguments
    (:func:`urdfcli.api.model_arguments`)."""
    refuse_library(path, session)
    arguments = api.model_arguments(path, session)
    found = api.check_target(api.Target(path), session.using(session.options.but(arguments=tuple(arguments.items()))))
    if isinstance(found, Unreadable):
        raise fail(found.reason)
    if found.loaded is not None and found.loaded.semantic is not None:
        raise fail(not_a_robot(path))
    return found


def report_errors(result: Result, output: Output, session: Session) -> bool:
    """Print the model's errors on stderr as `check` prints them; whether there were any.
    A missing or unreadable mesh is no error of the tree: it is left to `check`."""
    errors = [d for d in result.errors if REGISTRY[d.code].kind is not Kind.FILES]
    write(output.err, diagnostics_lines(errors, session.files))
    loaded = result.loaded
    return bool(errors) or loaded is None or not loaded.modelled


def start_link(result: Result, from_link: str | None, output: Output) -> str | None:
    """The link to draw from: ``--from``, else the root. None (after saying
    why) when the model has no single root; an unknown ``--from`` exits 2."""
    loaded = result.loaded
    robot = result.robot
    if loaded is None or not loaded.modelled or not robot.links:
        return None
    if from_link is not None:
        if from_link not in robot.links:
            close = close_matches(from_link, robot.links, n=3)
            suggestion = f"; did you mean {' or '.join(repr(c) for c in close)}?" if close else ""
            raise fail(f"no link named {from_link!r} in robot {robot.name!r}{suggestion}")
        return from_link
    if loaded.root is None:
        found = roots(robot)
        if found:
            output.err.file.write(f"urdfcli: {len(found)} links have no parent; choose one with --from LINK\n")
        else:
            output.err.file.write("urdfcli: every link has a parent (a loop), so there is no root; choose one with --from LINK\n")
        return None
    return loaded.root
