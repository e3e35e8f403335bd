"""urdfcli as a library: check and lint models from Python, as the command line does.

::

    import urdfcli

    result = urdfcli.check("urdf/robot.urdf.xacro", "ur_type:=ur5e")
    assert not result.errors, urdfcli.text_report(result)
    results = urdfcli.lint(["urdf/a.urdf", "urdf/b.urdf.xacro"])

Nothing here prints or exits. A problem with the input itself (a missing file,
a ``-P`` that is no folder, a broken configuration) raises :class:`UsageError`;
every problem in a model is a diagnostic of its result.
"""

from __future__ import annotations

import contextlib
import os
from collections.abc import Callable, Iterable, Iterator
from dataclasses import replace
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, NamedTuple

from .diagnostics import Diagnostic, Fix
from .model import massprops
from .model.load import Loaded, load
from .model.meshes import mesh_files
from .model.result import Result, Unreadable
from .model.srdf import named_srdf
from .model.units import unit_verdict
from .project import drift as drift_
from .project import fixing, linter
from .project.compatibility import verdicts
from .project.config import Config, ConfigError
from .project.semantic import described, describing, unknown_names
from .project.workspace import LIBRARY_SUFFIXES, Aside, Entry, Models, Target, asked, assemble, fragment_includers, model_targets, models_below, plan, search_roots, unchecked_library, unread, xacro_sources
from .read.document import STDIN, Document, InputError, read_document
from .read.files import STDIN_NAME
from .read.xacro_scan import shown
from .read.edits import EditError
from .read.edits import apply as edit_text
from .read.packages import PackageError
from .options import AuditOptions, Options, UsageError, xacro_arguments
from .rules import REGISTRY, Kind, Remedy, RuleSet
from .session import Session

if TYPE_CHECKING:
    from .model.audit import Audit, LinkAudit
    from .report.diff import Difference


class Run(NamedTuple):
    """The results of one run, in the order the inputs were given, and each input that
    could not be read; ``models``: every model the run checked, those a library was
    checked through included (an editor follows them)."""

    results: list[Result]
    unreadable: list[Unreadable]
    models: tuple[Result, ...] = ()


Progress = Callable[[int, int, str], None]  # (done, total, the file being read)


def check(path: str | os.PathLike, *arguments: str, session: Session | None = None, **settings) -> Result:
    """Check one model (or xacro library) as ``urdfcli check`` does: every error, and
    the warnings of check's rules. ``arguments`` are xacro arguments ``NAME:=VALUE``;
    ``settings`` are those of :class:`~urdfcli.options.Options` (``package_paths``,
    ``config``...) when no session is given."""
    return _single(_run_api([os.fspath(path)], RuleSet.CHECK, arguments, session, settings))


def lint(paths: Iterable[str | os.PathLike], *arguments: str, session: Session | None = None, **settings) -> list[Result]:
    """Lint files and folders as ``urdfcli lint`` does: one result per model found
    (a model listed in ``[tool.urdfcli] models`` once per argument set)."""
    if isinstance(paths, (str, os.PathLike)):
        paths = [paths]
    return _run_api([os.fspath(p) for p in paths], RuleSet.LINT, arguments, session, settings).results


def _run_api(paths: list[str], rule_set: RuleSet, arguments: Iterable[str], session: Session | None, settings: dict) -> Run:
    given = xacro_arguments(arguments)
    own = session is None
    try:
        if own:
            session = Session(Options(**settings, rule_set=rule_set, arguments=given))
        else:
            session = session.using(session.options.but(rule_set=rule_set, arguments=tuple(given.items())))
    except (PackageError, ValueError) as error:
        raise UsageError(str(error)) from None
    try:
        found = run(find_models(paths, session), session)
    finally:
        if own:
            session.close()
    if found.unreadable:
        raise UsageError("; ".join(map(str, found.unreadable)))
    return found


def text_report(results: Result | Iterable[Result]) -> str:
    """What ``urdfcli lint`` prints of the results (the diagnostics, their source lines, a summary), as plain text."""
    from .report.text import plain_text

    return plain_text([results] if isinstance(results, Result) else list(results))


def _single(found: Run) -> Result:
    if len(found.results) != 1:  # a model listed with several argument sets
        raise UsageError(f"{len(found.results)} results: use urdfcli.lint for a model checked with several argument sets")
    return found.results[0]


def find_models(paths: list[str], session: Session) -> Models:
    """Files as given; each folder replaced by the models below it (see
    :func:`urdfcli.project.workspace.models_below`), the files left out there
    in ``aside``. Raises UsageError for a folder that holds none."""
    files: list[str] = []
    aside: list = []
    for path in paths:
        if path != STDIN and Path(path).is_dir():
            found = models_below(Path(path), session.index)
            if not found:
                raise UsageError(f"{path}: no robot model in this folder (*.urdf, *.urdf.xacro, *.srdf, or a *.xacro file that makes a robot)")
            files.extend(shown(f) for f in found)  # relative to the working folder when below it, as includes are named
            aside.extend(found.aside)
        else:
            files.append(path)
    return Models(files, tuple(aside))


def library_models(path: str, session: Session) -> list[str] | None:
    """For a xacro library (macros and properties only: it makes no robot by itself), the
    models of its repository or workspace that include it; None for any other file."""
    if path == STDIN or not path.endswith(LIBRARY_SUFFIXES):
        return None
    try:
        [entry] = plan([path], configured(session), session.package_paths, session.packages, session.files)
    except PackageError as error:
        raise UsageError(str(error)) from None
    return list(dict.fromkeys(target.path for target in entry.targets)) if entry.library else None


def run(paths: list[str], session: Session, progress: Progress | None = None, aside: tuple[Aside, ...] | None = None) -> Run:
    """Check each input as the session's options ask (see :class:`~urdfcli.options.Options`).

    With ``libraries``, a xacro library is checked through the models that include
    it (see :mod:`urdfcli.project.workspace`), and so is each model that includes a file
    of the options' ``deleted``; a model listed in ``[tool.urdfcli]
    models`` is checked once per argument set. ``aside``: the files of a folder
    left out because a file there includes them (see :func:`find_models`): each
    that no model read is named in a note. Raises UsageError for a bad
    configuration or package path."""
    if aside is None:
        aside = paths.aside if isinstance(paths, Models) else ()
    config_for = configured(session)
    try:
        if session.options.libraries:
            entries = plan(paths, config_for, session.package_paths, session.packages, session.files, session.options.deleted)
        else:
            entries = [Entry(path, model_targets(path, config_for(path).argument_sets(path))) for path in paths]
        if session.options.srdfs:
            entries += _semantic_entries(entries, session, config_for)
    except PackageError as error:
        raise UsageError(str(error)) from None
    entries = [entry._replace(targets=asked(entry.targets, session.options.mappings)) for entry in entries]
    targets = list(dict.fromkeys(t for entry in entries for t in entry.targets))
    done = dict(zip(targets, _outcomes(targets, session, progress)))
    total = len(targets)

    def outcome(target: Target) -> Result | Unreadable:
        nonlocal total
        if target not in done:  # a library no model could check, expanded on its own; a fragment's models
            total += 1
            if progress is not None:
                progress(len(done), total, target.label)
            done[target] = check_target(target, session)
        return done[target]

    includers = fragment_includers(config_for, session.package_paths, session.packages, session.files) if session.options.libraries else (lambda path: ([], ()))
    results, unreadable = assemble(entries, outcome, includers, partial(_generated_from, session=session), session.packages.real_path)
    results += unread(aside, [r for r in done.values() if isinstance(r, Result)], results)
    results = [replace(result, show_info=config_for(result.path).show_info) for result in results]
    if session.options.load:
        results = [loaded_into_targets(result, session) for result in results]
    return Run(results, unreadable, tuple(r for r in done.values() if isinstance(r, Result) and r.loaded is not None))


def _semantic_entries(entries: list[Entry], session: Session, config_for) -> list[Entry]:
    """The SRDFs that describe the robots of the models to check and are not among them (``srdfs``)."""
    given = {Path(entry.path).resolve() for entry in entries if entry.path != STDIN}
    models = [(Path(t.path).resolve(), {**model_arguments(t.path, session), **dict(t.arguments)})
              for entry in entries for t in entry.targets if t.path != STDIN and not named_srdf(t.path) and not t.alone]
    found = [shown(file) for file in describing(models, session.index, lambda file: model_arguments(str(file), session)) if file not in given]
    return [Entry(path, model_targets(path, config_for(path).argument_sets(path))) for path in found]


def _generated_from(path: str, session: Session) -> Path | None:
    """The xacro file a URDF says it was generated from, beside it or in its package, or
    that sits beside it under its name (see :func:`urdfcli.project.drift.find_source`): the
    source X110 compares it with (unitree's urdf/go2_description.urdf, from xacro/robot.xacro)."""
    if path == STDIN or path.endswith(".xacro"):
        return None
    found = drift_.generated_from(Path(path), session)
    return found.file.resolve() if found is not None else None


def configured(session: Session):
    """The configuration of each input; a broken configuration raises UsageError."""

    def config_for(path: str):
        try:
            return session.configs.for_input(path)
        except ConfigError as error:
            raise UsageError(str(error)) from None

    return config_for


def _outcomes(targets: list[Target], session: Session, progress: Progress | None):
    """Each target's result, in order: here, or in the options' ``jobs`` processes."""
    jobs = session.options.jobs
    parallel = jobs != 1 and len(targets) > 1 and not any(t.path == STDIN for t in targets)
    if not parallel:
        for done, target in enumerate(targets):
            if progress is not None:
                progress(done, len(targets), target.label)
            yield check_target(target, session)
        return
    from concurrent.futures import ProcessPoolExecutor

    with ProcessPoolExecutor(max_workers=jobs or None, initializer=_start_process, initargs=(session.options,)) as pool:
        for done, found in enumerate(pool.map(_check_in_process, targets), 1):
            yield found
            if progress is not None and done < len(targets):
                progress(done, len(targets), targets[done].label)


class _ProcessSession:
    """The session of a process that checks models for another (``-j``)."""

    current: Session | None = None


def _start_process(options: Options) -> None:
    _ProcessSession.current = Session(options)


def _check_in_process(target: Target) -> Result | Unreadable:
    found = check_target(target, _ProcessSession.current)
    return found if isinstance(found, Unreadable) else found.detached()


def check_target(target: Target, session: Session) -> Result | Unreadable:
    """One model with one argument set (or a library on its own): its result, or why
    it cannot be read. Raises UsageError (configuration, package path)."""
    path = target.path
    options = session.options
    rule_set = options.rule_set
    config = configured(session)(path)
    arguments = {**config.mappings_for(path), **options.mappings, **dict(target.arguments)}

    def sources(document):
        return xacro_sources(document, session.index, session.expander.global_names)

    try:
        resolver = session.resolver(config.package_paths, None if path == STDIN else Path(path))
        if target.fragment:  # it cannot be read on its own: only why its models did not check it
            document = Document(path, b"", Path(path), is_xacro=True, files=session.files)
            loaded = Loaded(document, diagnostics=[unchecked_library(path, target.unchecked, fragment=True, example=target.example, stopped=target.stopped)], resolver=resolver)
            return Result(path, tuple(linter.lint(loaded, config, rule_set)), None, target.arguments)
        if target.alone:  # a library: its own xacro, and what the source rules find in it
            document, found = read_document(path, session.inputs, resolver, arguments)
            if target.unchecked:
                found.append(unchecked_library(path, target.unchecked, example=target.example, environment=target.environment, stopped=target.stopped))
            loaded = Loaded(document, diagnostics=found, resolver=resolver, meshes=session.meshes, sources=sources(document))
            diagnostics = linter.lint(loaded, config, rule_set)
            return Result(path, tuple(diagnostics), None, target.arguments, includes=tuple(document.includes))
        loaded = load(
            path, session.inputs, resolver, arguments, vocabulary=rule_set is RuleSet.LINT, meshes=session.meshes,
            reads_meshes=rule_set is not RuleSet.CHECK, sources=sources, configured_as=None if path == STDIN else partial(_configured_as, path, config, session),
        )
    except InputError as error:
        return Unreadable(path, str(error))
    except PackageError as error:
        raise UsageError(str(error)) from None
    document = loaded.document
    extra = [] if loaded.semantic is None else [d for d in [_described(loaded, session, dict(target.arguments))] if d is not None]
    if rule_set is not RuleSet.TREE and drift_.enabled(config, path):
        extra += drift_.drift(loaded, config, session)
    diagnostics = linter.lint(loaded, config, rule_set, extra)
    meshes = tuple(mesh_files(loaded, partial(unit_verdict, loaded))) if rule_set is RuleSet.LINT and loaded.modelled else ()
    audited = _audit(loaded, config, options.audit, session) if options.audit is not None else None
    return Result(
        path, tuple(diagnostics), loaded, target.arguments, includes=tuple(document.includes), needs_argument=document.missing_argument,
        called=tuple(sorted({call[3] for call in document.origins.calls})) if document.origins is not None else None,
        meshes=meshes, audit=audited, compatibility=verdicts(diagnostics, config.targets),
    )


def _configured_as(path: str, config: Config, session: Session) -> str:
    """How [tool.urdfcli.xacro-args] names a model: by its file name, or, when another file
    of its repository or workspace has that name (unitree_ros: a robot.xacro per robot), by
    its path from the configuration's folder (the repository's when there is no configuration)."""
    file = Path(path).resolve()
    roots, _ = search_roots(file, session.packages)
    if sum(found.name == file.name for found in session.index.scan(roots)) <= 1:
        return file.name
    folder = config.root if config.source is not None and config.root is not None else roots[0]
    return Path(os.path.relpath(file, folder.resolve())).as_posix()


def _described(loaded: Loaded, session: Session, given: dict[str, str]) -> Diagnostic | None:
    """An SRDF checked against the URDF of its robot: that URDF set on ``loaded``, or why there is none.
    ``given``: the SRDF's argument set of ``[tool.urdfcli] models``, the URDF's too (a 6-dof arm's SRDF: dof:=6);
    under the URDF's own configuration, the defaults of the SRDF's own arguments (see :func:`_own_defaults`)."""
    own = _own_defaults(loaded, session)
    found = described(loaded, session.index, session.options.urdf, lambda file: {**own, **model_arguments(str(file), session), **given}, partial(_load_urdf, session))
    urdf = loaded.described
    if urdf is not None and urdf.modelled and unknown_names(loaded.semantic, urdf):
        loaded.described_source = _generating(urdf, session)
    return found


def _generating(urdf: Loaded, session: Session) -> Loaded | None:
    """The expansion of the xacro file that generated ``urdf`` (a URDF whose header says xacro
    wrote it, or with a xacro file of its name beside it), or None."""
    file = urdf.document.file
    source = drift_.generated_from(file, session) if file is not None and not urdf.document.is_xacro else None
    if source is None:
        return None
    found = drift_.expand_source(source.file, configured(session)(urdf.path), session)
    return None if isinstance(found, str) else found


def _own_defaults(loaded: Loaded, session: Session) -> dict[str, str]:
    """The literal defaults of a xacro SRDF's arguments: a launch file passes one value to the
    URDF and the SRDF alike (franka_ros2's hand:=true), so the SRDF's default is the URDF's
    argument of that name when nothing else gives it (the SRDF of the arm with its hand, whose
    URDF leaves the hand out by default). A default computed from something else is left out."""
    document = loaded.document
    defaults: dict[str, str] = {}
    for file in (document.shown, *document.includes):
        found = session.files.get(file)
        for name, value in found.scan.arguments if found is not None and found.scan is not None else ():
            if "$(" not in value and "${" not in value:
                defaults.setdefault(name, value)
    return defaults


def model_arguments(path: str, session: Session) -> dict[str, str]:
    """The xacro arguments of a model read once (drawn, expanded, compared, or the URDF
    of an SRDF): those ``[tool.urdfcli.xacro-args]`` gives it, the first set ``[tool.urdfcli]
    models`` lists for it, and those of the command line over both (``check panda.srdf
    --urdf panda_arm.urdf.xacro hand:=true``). Raises UsageError for a broken configuration."""
    config = configured(session)(path)
    return {**config.model_mappings(path, session.options.mappings), **session.options.mappings}


def _load_urdf(session: Session, path: str, arguments: dict[str, str]) -> Loaded | str:
    """A URDF an SRDF is checked against, loaded once per session (no mesh is read)."""
    key = (path, tuple(sorted(arguments.items())))
    stamp, known = session.index.described.get(key, (None, None))
    if known is None or stamp != _stamps([path, *(known.document.includes if not isinstance(known, str) else ())]):
        config = configured(session)(path)
        try:
            resolver = session.resolver(config.package_paths, Path(path))
            known = load(path, session.inputs, resolver, arguments, meshes=session.meshes, reads_meshes=False)
        except InputError as error:
            known = str(error)
        except PackageError as error:
            raise UsageError(str(error)) from None
        session.index.described[key] = (_stamps([path, *(known.document.includes if not isinstance(known, str) else ())]), known)
    return known


def _stamps(files: list[str]) -> tuple:
    """When each file last changed: a URDF loaded for an SRDF is loaded again when one did."""
    found = []
    for file in files:
        try:
            found.append(os.stat(file).st_mtime_ns)
        except OSError:
            found.append(None)
    return tuple(found)


class Fixed(NamedTuple):
    """A run with its fixes applied: ``run`` is what remains (the last check, made
    with the fixed texts), ``fixed`` the fixes applied, ``changed`` each file they
    changed (before, after), ``failed`` the files a fix could not be written in, and why."""

    run: Run
    fixed: list[Fix]
    changed: dict[str, tuple[bytes, bytes]]
    failed: list[str]


def fix(paths: list[str], session: Session, progress: Progress | None = None) -> Fixed:
    """Check the inputs as :func:`run` does and apply the fixes found, round after round
    (a fix may let another be found) until none is left. Nothing is written: the fixed
    texts are given to the session, and :attr:`Fixed.changed` says what to write. The
    options' ``fix`` and ``unsafe_fixes`` (None: each input's configuration, ``fix`` and
    ``unsafe-fixes``) say which fixes apply. Raises UsageError as :func:`run` does."""
    options = session.options
    config_for = configured(session)
    before: dict[str, bytes] = {}
    applied: list[Fix] = []
    failed: list[str] = []

    def chosen(result: Result) -> tuple[bool, bool]:
        config = config_for(result.path)
        return (config.fix if options.fix is None else options.fix), (config.unsafe_fixes if options.unsafe_fixes is None else options.unsafe_fixes)

    serial = session.using(options.but(jobs=1))  # the fixed texts are this process's: checked here
    fixes_at: dict[tuple, int] = {(): 0}  # the texts fixed so far, as they stood after each round -> the fixes applied by then
    ours = _writable(paths, session)

    def texts() -> tuple:
        return tuple(sorted((file, session.files.read(file).data) for file in before))

    for round_ in range(fixing.MAX_ROUNDS + 1):
        found = run(paths, serial if before else session, progress if round_ == 0 else None)
        pairs = [(d, settings[1]) for result in found.results if (settings := chosen(result))[0] for d in result.diagnostics]
        selection = fixing.select(_not_called_elsewhere(pairs, found, session, ours, failed))
        if not selection.edits or round_ == fixing.MAX_ROUNDS:
            break
        written = False
        for file, edits in selection.edits.items():
            if not ours(file):
                failed.append(f"{file}: not written: it is outside the repository or workspace of what was checked (a package found with -P, or installed)")
                continue
            try:
                data = session.files.read(file).data
                new = edit_text(data, [(e.start, e.end, e.text) for e in edits])
            except (OSError, EditError) as error:
                failed.append(f"{file}: {error}")
                continue
            before.setdefault(file, data)
            session.files.give(file, new)
            written = True
        if not written:
            break
        applied += selection.fixes
        now = tuple((file, data) for file, data in texts() if data != before[file])
        if now in fixes_at:  # a fix undid another's edit (two models wanting one value each its own way): back where it was
            del applied[fixes_at[now]:]
            found = run(paths, serial, None)  # what remains of the texts as they are
            break
        fixes_at[now] = len(applied)
    changed = {file: (data, session.files.read(file).data) for file, data in before.items()}
    return Fixed(found, applied, {file: pair for file, pair in changed.items() if pair[0] != pair[1]}, list(dict.fromkeys(failed)))


def _not_called_elsewhere(
    pairs: list[tuple[Diagnostic, bool]], found: Run, session: Session, ours: Callable[[str], bool], failed: list[str]
) -> list[tuple[Diagnostic, bool]]:
    """The (diagnostic, unsafe) pairs but those whose unsafe fix edits the body of a macro
    that a model this run does not fix expands too (see :func:`fixing.called_elsewhere`):
    each of those is said in ``failed``. A file the run may not write is said so after."""
    own: set[Path] | None = None  # the files the models being fixed read: asked only when a fix edits a macro's body
    kept = []
    for diagnostic, unsafe in pairs:
        fix = diagnostic.fix
        if fixing.applies(fix, unsafe) and not fix.safe and all(ours(edit.file) for edit in fix.edits):
            if own is None:
                read = (file for result in found.results for file in (result.path, *result.includes, *(result.library.read if result.library else ())))
                own = {session.packages.real_path(Path(file)) for file in read if file not in (STDIN, STDIN_NAME)}
            why = fixing.called_elsewhere(diagnostic, own, session.index)
            if why is not None:
                failed.append(why)
                continue
        kept.append((diagnostic, unsafe))
    return kept


def _writable(paths: list[str], session: Session) -> Callable[[str], bool]:
    """Whether a fix may write a file: one of the repositories or workspaces of the inputs
    (their search roots), never a package found elsewhere (-P, an installed share)."""
    roots = set()
    for path in paths:
        if path == STDIN:
            continue
        given = Path(path).resolve()
        roots.update(search_roots(given / "x" if given.is_dir() else given, session.packages)[0])  # (a folder: as for a file in it)
        if given.is_dir():
            roots.add(given)
    return lambda file: file in (STDIN, STDIN_NAME) or any(Path(file).resolve().is_relative_to(root) for root in roots)


def audit(loaded: Loaded, config: Config, tolerance: float = massprops.TOLERANCE, density: float | None = None) -> Audit | None:
    """The mass-property audit of a model (None when there is no robot): every
    mass-property rule run with this tolerance and density, what the configuration
    and suppressions leave of them, and the per-link table."""
    from .model import audit as audits  # (only `inertia` and the editor's fixes audit)

    if not loaded.modelled:
        return None
    chosen = {"tolerance": tolerance, "density": density or 0.0}
    found = [
        diagnostic
        for rule in REGISTRY.values() if rule.kind is Kind.MASS
        for diagnostic in rule.run(loaded, rule.given({k: v for k, v in chosen.items() if k in rule.defaults}))
    ]
    problems = [d for d in linter.configure(loaded, found, config, RuleSet.LINT) if REGISTRY[d.code].kind is not Kind.SUPPRESSIONS]
    return audits.build(loaded, problems, tolerance, density)


def flagged(audit: Audit) -> list[LinkAudit]:
    """The links with a problem that a new <inertial> fixes: those a uniform body is suggested for."""
    return [entry for entry in audit.links if any(REGISTRY[d.code].remedy is Remedy.INERTIAL for d in entry.problems)]


def _audit(loaded: Loaded, config: Config, asked: AuditOptions, session: Session) -> Audit | None:
    """The audit ``urdfcli inertia`` prints: with the suggested <inertial> elements, and
    what each consumer of the targets builds, when asked for."""
    from .model import fixes
    from .targets import build

    found = audit(loaded, config, asked.tolerance, asked.density)
    if found is None:
        return None
    if asked.suggest or asked.xacro:
        found = found._replace(suggestions=fixes.suggestions(found, flagged(found), session.expander, asked.density, asked.xacro))
    return found._replace(targets=tuple(build(loaded, chosen) for chosen in session.options.targets))


def loaded_into_targets(result: Result, session: Session) -> Result:
    """``check --load``: the result with what the consumers of its targets said of the
    model when it was loaded into them (C001-C004). Raises UsageError when no target is
    asked for."""
    from .project import consumers

    loaded = result.loaded
    if loaded is None or not loaded.modelled:
        return result
    config = configured(session)(result.path)
    if not config.targets:
        raise UsageError("--load loads the model into the --target consumers: name one, such as --target mujoco")
    if loaded.document.file is None and not loaded.document.is_xacro:
        raise UsageError("--load needs the model in a file, not standard input")
    found = [d for chosen in config.targets for d in consumers.verify(loaded, list(result.diagnostics), chosen)]
    return result.but(diagnostics=tuple(sorted([*result.diagnostics, *(linter.with_severity(d, config) for d in found)], key=Diagnostic.sort_key)))


def expand(path: str, session: Session) -> tuple[str | None, list[str], list[Diagnostic]]:
    """The xacro expansion of one file with its arguments (:func:`model_arguments`), as the
    ``xacro`` tool prints it (None when it fails), the files it read, and what xacro said
    (each with its severity). Raises UsageError when the file cannot be read."""
    config = configured(session)(path)
    try:
        resolver = session.resolver(config.package_paths, None if path == STDIN else Path(path))
        document, found = read_document(path, session.inputs, resolver, model_arguments(path, session), force_xacro=True)
    except (InputError, PackageError) as error:
        raise UsageError(str(error)) from None
    diagnostics = [linter.with_severity(d, Config()) for d in found]
    return document.expanded_text, list(document.includes), diagnostics


def diff(old: str | os.PathLike, new: str | os.PathLike, *arguments: str, session: Session | None = None, tolerance: float | None = None, **settings) -> Difference:
    """What changed from the robot ``old`` to ``new`` (``urdfcli diff``): each a file, ``-``
    for standard input, or ``REV:PATH`` for a file at a git revision. ``arguments`` are
    xacro arguments for both (over the session's); ``tolerance``, the relative tolerance
    of numbers (see :data:`urdfcli.model.compare.TOLERANCE`); ``settings`` those of
    :class:`~urdfcli.options.Options` when no session is given. Raises UsageError when
    either cannot be read as a robot."""
    return diff_with_revisions(os.fspath(old), os.fspath(new), xacro_arguments(arguments), session, tolerance, settings)[0]


def diff_with_revisions(old: str, new: str, mappings: dict[str, str], session: Session | None, tolerance: float | None, settings: dict) -> tuple[Difference, tuple[str, ...]]:
    """:func:`diff`, and the git revisions its inputs name. Each is read with its arguments
    (:func:`model_arguments`), ``mappings`` over them."""
    from .project.versions import NotComparable, compare_versions  # (git and archives: only diff reads them)

    with _session(session, settings) as session:
        try:
            return compare_versions(old, new, lambda file: {**model_arguments(file, session), **mappings}, session.inputs, session.resolver, tolerance)
        except (NotComparable, PackageError) as error:
            raise UsageError(str(error)) from None


def drift(paths: Iterable[str | os.PathLike], session: Session | None = None, **settings) -> list[Result]:
    """The generated URDFs that ``paths`` concern (each given, each below a folder given,
    each generated from a given xacro file or one including it), each with what rule
    X110 finds: whether it still matches the xacro file it was generated from.
    ``settings`` are those of :class:`~urdfcli.options.Options` when no session is given."""
    with _session(session, settings) as session:
        return [_drift_of(path, session) for path in drift_.generated_urdfs([os.fspath(p) for p in paths], session)]


@contextlib.contextmanager
def _session(session: Session | None, settings: dict) -> Iterator[Session]:
    """``session``, or one made of ``settings`` (Options) for the call and closed after it."""
    if session is not None:
        yield session
        return
    try:
        session = Session(Options(**settings))
    except (PackageError, ValueError) as error:
        raise UsageError(str(error)) from None
    try:
        yield session
    finally:
        session.close()


def _drift_of(path: str, session: Session) -> Result:
    config = configured(session)(path)
    try:
        loaded = load(path, session.inputs, session.resolver(config.package_paths, Path(path)), reads_meshes=False)
    except (InputError, PackageError) as error:
        raise UsageError(str(error)) from None
    found = drift_.drift(loaded, config, session, asked=True) if drift_.enabled(config, path) else []
    kept = [d for d in linter.configure(loaded, found, config) if d.code == "X110"]
    return Result(path, tuple(kept), loaded)


__all__ = [
    "Difference", "Fixed", "Options", "Result", "Run", "RuleSet", "Session", "Unreadable", "UsageError", "audit", "check", "check_target", "diff",
    "drift", "expand", "find_models", "fix", "library_models", "lint", "model_arguments", "run", "text_report", "xacro_arguments",
]
