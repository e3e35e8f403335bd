"""The rules on a loaded model, and what configuration and suppressions leave of them.

:func:`lint` runs the rules of a rule set, with the options the configuration
gives; keeps what the configuration selects for each file; drops what
suppression comments silence (reporting the comments that silence nothing); and
gives each diagnostic its severity: the configured one, else the one its rule
chose, else its rule's default. ``check``, ``lint``, ``inertia``, ``tree`` and
``graph`` all go through it, so that configuration and ``noqa`` comments mean
the same everywhere.
"""

from __future__ import annotations

from ..diagnostics import Diagnostic
from ..model.inertia import inertial_fix
from ..model.load import Loaded
from ..model.written import place_fixes
from ..read.document import SUPPRESSION_MARK
from ..read.files import SourceFiles
from ..read.positions import may_contain
from ..rules import REGISTRY, Kind, Remedy, RuleSet, checks
from ..rules.base import names
from . import suppressions
from .config import Config


def ran(code: str, rule_set: RuleSet) -> bool:
    """Whether the diagnostics of ``code`` can be there (a rule said while reading always can;
    a check, when the rule set runs it; a target rule, for the targets asked for)."""
    rule = REGISTRY.get(code)
    return rule is None or rule.function is None or rule_set.holds(rule.rule_set)


def run_rules(loaded: Loaded, config: Config, rule_set: RuleSet) -> list[Diagnostic]:
    """What the rules find, each with the options the configuration gives it. A rule
    the configuration turns off everywhere does not run. The rules on the xacro
    sources run when the caller gave them (``loaded.xacro_sources``), whether or not a
    robot could be read; the others need a robot."""
    options = config.rule_options()
    found: list[Diagnostic] = []
    for rule in checks(rule_set):
        ready = loaded.xacro_sources is not None if rule.kind is Kind.SOURCES else loaded.semantic is not None if rule.kind is Kind.SEMANTIC else loaded.modelled
        if not ready or not (rule.kind is Kind.TREE or config.enabled(rule)):
            continue
        if rule.kind is not Kind.TARGET:
            found.extend(rule.run(loaded, rule.given(options.get(rule.code))))
            continue
        consumer = rule.consumer
        for profile in config.targets:
            if profile.target == consumer:
                found.extend(rule.run(loaded, rule.given(profile=profile)))
    return found


def lint(loaded: Loaded, config: Config, rule_set: RuleSet = RuleSet.LINT, found: list[Diagnostic] | None = None) -> list[Diagnostic]:
    """Every diagnostic of a loaded model that its configuration and suppressions leave,
    each with its fix placed in the sources (see :func:`with_fixes`); ``found``: what was
    found of it beside reading and the rules (a generated URDF's drift)."""
    kept = configure(loaded, [*loaded.diagnostics, *(found or ()), *run_rules(loaded, config, rule_set)], config, rule_set)
    return with_fixes(loaded, written_once(kept))


def written_once(diagnostics: list[Diagnostic]) -> list[Diagnostic]:
    """One diagnostic for a mistake a macro's calls copied: those of one rule at one place of
    the sources that say the same thing but for the name of their link or joint become one
    naming them all (its ``subjects``), at the first; its fix is theirs together, which
    :func:`with_fixes` places as one edit of the macro body. The rest stay as they are."""
    groups: dict[object, list[Diagnostic]] = {}
    for number, diagnostic in enumerate(diagnostics):
        groups.setdefault(_copy_key(diagnostic) or number, []).append(diagnostic)
    return [group[0] if len(group) == 1 else _together(group) for group in groups.values()]


def _copy_key(diagnostic: Diagnostic) -> tuple | None:
    """What copies of one written mistake share: the rule, the place, what is said but the name."""
    if len(diagnostic.subjects) != 1 or diagnostic.line is None:
        return None
    quoted = f"'{diagnostic.subjects[0]}'"
    if diagnostic.message.count(quoted) != 1:
        return None
    fix = diagnostic.fix
    said = (fix.applicability, fix.reason, fix.title.replace(quoted, "")) if fix is not None else None
    place = diagnostic.location
    return (diagnostic.code, place.file, place.line, place.column, diagnostic.severity, diagnostic.model, diagnostic.hint, diagnostic.message.replace(quoted, ""), said)


def _together(copies: list[Diagnostic]) -> Diagnostic:
    first = copies[0]
    subjects = tuple(dict.fromkeys(d.subjects[0] for d in copies))
    fix = first.fix
    if fix is not None:
        fix = fix._replace(
            title=_naming_all(fix.title, subjects), edits=tuple(dict.fromkeys(e for d in copies for e in d.fix.edits)),
            changes=tuple(dict.fromkeys(c for d in copies for c in d.fix.changes)),
        )
    return first._replace(message=_naming_all(first.message, subjects), subjects=subjects, fix=fix)


def _naming_all(text: str, subjects: tuple[str, ...]) -> str:
    """``text`` naming ``subjects`` where it named the first: ``inertia of links 'a', 'b' and 'c': ...``
    when the name qualifies a noun of its own (the verb stays right), else ``link 'a' (and 'b' alike) has ...``."""
    quoted = f"'{subjects[0]}'"
    head, found, tail = text.partition(quoted)
    if not found:
        return text
    if head.endswith(("of link ", "of joint ")):
        return f"{head[:-1]}s {names(subjects)}{tail}"
    return f"{head}{quoted} (and {names(subjects[1:])} alike){tail}"


def unnamed(diagnostic: Diagnostic) -> str:
    """Its message without the names of its links or joints (as :func:`_naming_all` wrote
    them): what one mistake of a macro says in each model that calls it, whichever and
    however many of its copies a model makes (one hand, or two)."""
    text, subjects = diagnostic.message, diagnostic.subjects
    if len(subjects) == 1:
        return text.replace(f"'{subjects[0]}'", "'…'", 1)
    if len(subjects) > 1:
        for named in (f"s {names(subjects)}", f"'{subjects[0]}' (and {names(subjects[1:])} alike)"):
            head, found, tail = text.partition(named)
            if found:
                return f"{head}{' ' if named.startswith('s ') else ''}'…'{tail}"
    return text


def with_fixes(loaded: Loaded, diagnostics: list[Diagnostic]) -> list[Diagnostic]:
    """The diagnostics with their fixes where the sources were written: a rule that a new
    ``<inertial>`` fixes gets the geometry's (unless it gave a fix of its own), then
    every change to the model is placed as edits, or as the reason it cannot be."""
    if loaded.modelled:
        diagnostics = [_inertial(loaded, d) if d.fix is None and REGISTRY[d.code].remedy is Remedy.INERTIAL else d for d in diagnostics]
    return place_fixes(loaded, diagnostics)


def _inertial(loaded: Loaded, diagnostic: Diagnostic) -> Diagnostic:
    links = [loaded.robot.links[name] for name in diagnostic.subjects if name in loaded.robot.links]
    fixes = [inertial_fix(loaded, link) for link in links]
    if not fixes:
        return diagnostic
    blocked = next((f for f in fixes if f.reason is not None), None)
    if len(fixes) == 1 or blocked is not None:
        return diagnostic.with_fix(blocked or fixes[0])
    title = f"write the tensors and centres of mass of uniform bodies filling the geometry of links {', '.join(repr(link.name) for link in links)}"
    return diagnostic.with_fix(fixes[0]._replace(title=title, changes=tuple(c for f in fixes for c in f.changes)))


def configure(loaded: Loaded, diagnostics: list[Diagnostic], config: Config, rule_set: RuleSet = RuleSet.LINT) -> list[Diagnostic]:
    """``diagnostics`` found on ``loaded``, after configuration and suppression comments,
    each with its severity, in file order. A suppression naming a rule that did not
    run in ``rule_set`` is not reported as unused."""
    path = loaded.path
    document = loaded.document

    def enabled(code: str, file: str) -> bool:
        return config.enabled(REGISTRY[code], path, file)

    # Why nothing was checked (an unreadable model) is never selected away, nor silenced;
    # what the source rules found in its files is configured as anywhere.
    unreadable = not document.readable
    always = [d for d in diagnostics if unreadable and not _is(d, Kind.SOURCES)]
    selected = [d for d in diagnostics if not (unreadable and not _is(d, Kind.SOURCES)) and enabled(d.code, d.path)]
    if unreadable and not selected:
        found = []
    else:
        # each file once, named as the diagnostics name it (the includes are named absolutely)
        named: dict[str, str] = {}
        for file in [place.file for d in selected for place in (d.location, *d.location.trace)] + [document.shown, *document.includes]:
            named.setdefault(suppressions.file_key(file), file)
        if document.may_suppress is False:  # told while its bytes were read
            named.pop(suppressions.file_key(document.shown), None)
        texts = ((file, _text_holding(document.files, file, SUPPRESSION_MARK)) for file in sorted(named.values()))
        found = [s for file, text in texts if text is not None for s in suppressions.parse(file, text)]
    written = document.origins.written() if found and document.origins is not None else None
    kept = suppressions.apply(selected, found, lambda code: ran(code, rule_set) and enabled(code, path), written)
    if unreadable:  # whether a comment silences anything is known only when every rule ran
        kept = [d for d in kept if not _is(d, Kind.SUPPRESSIONS)] + always
    kept = [d for d in kept if not _is(d, Kind.SUPPRESSIONS) or enabled(d.code, d.path)]
    kept = [with_severity(d, config) for d in kept]
    kept.sort(key=Diagnostic.sort_key)
    return kept


def _text_holding(files: SourceFiles, name: str, mark: str) -> str | None:
    """The text of a file, when its bytes may hold ``mark`` (ASCII): most files need
    no decoding then. None when unreadable."""
    found = files.get(name)
    return found.text if found is not None and may_contain(found.data, mark) else None


def _is(diagnostic: Diagnostic, kind: Kind) -> bool:
    """Whether a diagnostic's rule is of this kind."""
    rule = REGISTRY.get(diagnostic.code)
    return rule is not None and rule.kind is kind


def with_severity(diagnostic: Diagnostic, config: Config) -> Diagnostic:
    """The diagnostic with its severity: configured, else chosen by its rule, else the rule's default."""
    default = diagnostic.severity or REGISTRY[diagnostic.code].severity
    return diagnostic._replace(severity=config.severity_of(diagnostic.code, default))
