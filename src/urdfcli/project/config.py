"""Project configuration for every command that reads a model (check, lint, drift,
inertia, tree, graph, expand, diff).

Found by walking up from each input file: in every folder, ``urdfcli.toml``
or ``.urdfcli.toml`` (keys at the top level), else a ``pyproject.toml`` with a
``[tool.urdfcli]`` table; the first folder that has one wins. ``--config FILE``
names one explicitly. Every key, rule code and option value is validated: a
mistake is a :class:`ConfigError` (the command exits 2).

Keys::

    select = ["D", "J"]            # codes, prefixes or rule names ("ALL" for every rule)
    ignore = ["D002"]
    extend-select = ["S"]          # added to select (or to the defaults)
    package-paths = ["../vendor"]  # like -P: NAME=DIR or DIR, relative to the file
    [per-file-ignores]             # glob (relative to the config's folder) -> codes
    "legacy/*.urdf" = ["S"]
    [severity]                     # code or prefix -> error | warning | info
    I006 = "error"
    [options.link-name-suffix]     # rule code or name -> its options
    exempt = ["base_footprint", "*_frame"]
    [xacro-args]                   # glob -> xacro arguments for the files it matches
    "urdf/*.urdf.xacro" = { use_gpu = "false" }
    targets = ["mujoco"]           # consumers whose target rules run (--target), with variants: "pinocchio:mimic"
    fix = true                     # `lint` and `check` apply the safe fixes (as --fix)
    unsafe-fixes = true            # and the unsafe ones (as --unsafe-fixes)
    show-info = false              # show only warnings and errors (info still counted in the summary), like --no-info
    [models]                       # model -> the argument sets it is checked with
    "ur_description/urdf/ur.urdf.xacro" = [["ur_type:=ur5e", "name:=ur"]]

Paths and globs are relative to the folder of the file that holds them, whatever
the working directory; a glob without a ``/`` also matches a file's name alone.
"""

from __future__ import annotations

import os
import re
from fnmatch import fnmatchcase
from pathlib import Path
from typing import Any, NamedTuple

from ..diagnostics import Severity
from ..model.targets import Profile
from ..targets import profiles
from ..read.folders import nearest
from ..rules import REGISTRY, Rule, UnknownRule, lookup
from ..rules.suggestions import close_matches

CONFIG_NAMES = ("urdfcli.toml", ".urdfcli.toml")
KEYS = ("select", "ignore", "extend-select", "per-file-ignores", "severity", "options", "package-paths", "xacro-args", "models", "targets", "fix", "unsafe-fixes", "show-info")
ALL = "ALL"


class ConfigError(ValueError):
    """The configuration cannot be used; the message names the file and the key."""


class Config(NamedTuple):
    """Which rules run where, how severe they are, and how files are loaded."""

    source: str | None = None  # the file it was read from, for messages
    root: Path | None = None  # relative paths and globs start here (None: the current directory)
    select: tuple[str, ...] | None = None  # None: the rules that are on by default
    ignore: tuple[str, ...] = ()
    extend_select: tuple[str, ...] = ()
    per_file_ignores: tuple[tuple[str, tuple[str, ...]], ...] = ()
    severity: tuple[tuple[str, Severity], ...] = ()
    options: tuple[tuple[str, tuple[tuple[str, Any], ...]], ...] = ()  # code -> (name, value)...
    package_paths: tuple[str, ...] = ()
    xacro_args: tuple[tuple[str, tuple[tuple[str, str], ...]], ...] = ()
    models: tuple[tuple[Path, tuple[tuple[tuple[str, str], ...], ...]], ...] = ()  # absolute model -> argument sets
    targets: tuple[Profile, ...] = ()  # the consumers whose rules run (--target)
    show_info: bool = True  # the text formats show info diagnostics (they are counted either way)
    fix: bool = False  # apply the safe fixes without --fix
    unsafe_fixes: bool = False  # apply the unsafe fixes too

    @classmethod
    def everything(cls) -> "Config":
        """Every rule on, with default severities and options."""
        return cls(select=(ALL,))

    def overridden(
        self, select: tuple[str, ...] = (), ignore: tuple[str, ...] = (), extend_select: tuple[str, ...] = (), targets: tuple[Profile, ...] = (),
        show_info: bool | None = None,
    ) -> "Config":
        """The command line over the file: --select and --target replace, --ignore and --extend-select add;
        --no-info hides info."""
        where = "on the command line"
        changes: dict[str, Any] = {}
        if select:
            changes["select"] = _selectors(",".join(select), where)
        if ignore:
            changes["ignore"] = self.ignore + _selectors(",".join(ignore), where)
        if extend_select:
            changes["extend_select"] = self.extend_select + _selectors(",".join(extend_select), where)
        if targets:
            changes["targets"] = tuple(targets)
        if show_info is not None:
            changes["show_info"] = show_info
        return self._replace(**changes)

    # -- questions asked while linting -----------------------------------------
    def enabled(self, rule: Rule, *files: str) -> bool:
        """Is the rule on for diagnostics in these files? The most specific selector wins; ignore wins a tie."""
        best: tuple[int, bool] | None = None
        for selectors, on in ((self.select or ()) + self.extend_select, True), (self.ignore, False):
            for selector in selectors:
                if _matches(selector, rule.code):
                    candidate = (_specificity(selector), on)
                    if best is None or candidate[0] > best[0] or (candidate[0] == best[0] and not on):
                        best = candidate
        if best is None:
            on = self.select is None and rule.default
        else:
            on = best[1]
        return on and not any(
            _matches(selector, rule.code) for pattern, selectors in self.per_file_ignores if any(self._glob(pattern, f) for f in files) for selector in selectors
        )

    def severity_of(self, code: str, default: Severity) -> Severity:
        """The configured severity of a code, else ``default``."""
        found = [(_specificity(s), level) for s, level in self.severity if _matches(s, code)]
        return max(found, key=lambda pair: pair[0])[1] if found else default

    def rule_options(self) -> dict[str, dict[str, Any]]:
        return {code: dict(values) for code, values in self.options}

    def mappings_for(self, file: str) -> dict[str, str]:
        mappings: dict[str, str] = {}
        for pattern, values in self.xacro_args:
            if self._glob(pattern, file):
                mappings.update(values)
        return mappings

    def model_mappings(self, file: str, given: dict[str, str] | None = None) -> dict[str, str]:
        """The xacro arguments of a model read once (expanded, drawn, compared): those
        ``xacro-args`` gives it, and over them the first set ``models`` lists for it that
        agrees with ``given``, the command line's (see :func:`agreeing`)."""
        return {**self.mappings_for(file), **(agreeing(self.argument_sets(file) or [{}], given or {}) or [{}])[0]}

    def argument_sets(self, file: str) -> list[dict[str, str]] | None:
        """The argument sets ``models`` lists for a model, None when it is not listed."""
        if not self.models:
            return None
        try:
            resolved = Path(file).resolve()
        except OSError:
            return None
        for model, sets in self.models:
            if model == resolved:
                return [dict(arguments) for arguments in sets]
        return None

    def _glob(self, pattern: str, file: str) -> bool:
        """Whether a glob (relative to the config's folder) matches a file; one
        without a ``/`` also matches the file's name in any folder."""
        path = Path(file)
        if "/" not in pattern and fnmatchcase(path.name, pattern):
            return True
        try:
            relative = path.resolve().relative_to((self.root or Path.cwd()).resolve()).as_posix()
        except (ValueError, OSError):
            return False
        return fnmatchcase(relative, pattern)


def agreeing(sets: list[dict[str, str]], given: dict[str, str]) -> list[dict[str, str]]:
    """The argument sets of a model that give no argument another value than the command
    line does: ``check arm.urdf.xacro robot_model:=wx250s`` is asking for the wx250s arm
    of those ``models`` lists for Interbotix's one file of every arm, not for each arm."""
    return [s for s in sets if all(s.get(name, value) == value for name, value in given.items())]


# -- selectors -------------------------------------------------------------------
def _matches(selector: str, code: str) -> bool:
    return selector == ALL or code.startswith(selector)


matches = _matches


def selector(value: str) -> str | None:
    """``ALL``, a code or code prefix (upper-cased), or the code of a rule named
    ``value`` (``visual-without-collision``); None when it selects no rule."""
    key = value.strip()
    if key.upper() == ALL:
        return ALL
    if any(code.startswith(key.upper()) for code in REGISTRY) and key:
        return key.upper()
    return next((rule.code for rule in REGISTRY.values() if rule.name == key.lower()), None)


def _specificity(selector: str) -> int:
    return 0 if selector == ALL else len(selector)


def _selectors(values: Any, where: str) -> tuple[str, ...]:
    """Validated codes or prefixes (upper-cased); unknown ones are an error."""
    if isinstance(values, str):
        values = [v for v in values.replace(",", " ").split() if v]
    if not isinstance(values, list) or not all(isinstance(v, str) for v in values):
        raise ConfigError(f"{where}: expected a list of rule codes or prefixes, not {values!r}")
    codes = list(REGISTRY)
    out = []
    for value in values:
        found = selector(value)
        if found is None:
            close = close_matches(value.strip().upper(), codes)
            raise ConfigError(f"{where}: unknown rule code or prefix '{value}'" + (f" (did you mean '{close[0]}'?)" if close else "") + "; `urdfcli rules` lists them")
        out.append(found)
    return tuple(out)


def _profiles(values: Any, where: str) -> tuple[Profile, ...]:
    """Validated target profiles (``mujoco``, ``pybullet:inertia-from-file``), each once."""
    if not isinstance(values, list) or not all(isinstance(v, str) for v in values):
        raise ConfigError(f"{where}: expected a list of targets such as [\"mujoco\", \"pinocchio:mimic\"], not {values!r}")
    try:
        return tuple(dict.fromkeys(chosen for text in values for v in text.split(",") if v.strip() for chosen in profiles(v)))
    except ValueError as error:
        raise ConfigError(f"{where}: {error}") from None


# -- reading ---------------------------------------------------------------------
def parse(table: dict[str, Any], source: str, root: Path) -> Config:
    """A Config from the urdfcli table of a TOML file; every mistake is a ConfigError."""
    for key in table:
        if key not in KEYS:
            close = close_matches(key, KEYS)
            raise ConfigError(f"{source}: unknown key '{key}'" + (f" (did you mean '{close[0]}'?)" if close else "") + f"; the keys are {', '.join(KEYS)}")

    def where(key: str) -> str:
        return f"{source}: {key}"

    def mapping(key: str) -> dict[str, Any]:
        value = table.get(key, {})
        if not isinstance(value, dict):
            raise ConfigError(f"{where(key)}: expected a table, not {value!r}")
        return value

    select = _selectors(table["select"], where("select")) if "select" in table else None
    per_file = tuple((pattern, _selectors(codes, where(f"per-file-ignores.{pattern!r}"))) for pattern, codes in mapping("per-file-ignores").items())
    severity = []
    for selector, level in mapping("severity").items():
        (code,) = _selectors([selector], where("severity"))
        try:
            severity.append((code, Severity(level)))
        except ValueError:
            raise ConfigError(f"{where(f'severity.{selector}')}: {level!r} is not error, warning or info") from None
    options = []
    for name, values in mapping("options").items():
        try:
            rule = lookup(name)
        except UnknownRule as error:
            raise ConfigError(f"{where('options')}: {error}") from None
        if not isinstance(values, dict):
            raise ConfigError(f"{where(f'options.{name}')}: expected a table of option values, not {values!r}")
        checked = []
        for option, value in values.items():
            try:
                checked.append((option, rule.option(option).validate(value)))
            except (KeyError, ValueError) as error:
                raise ConfigError(f"{where(f'options.{name}')}: {error.args[0]}") from None
        options.append((rule.code, tuple(checked)))
    paths = table.get("package-paths", [])
    if not isinstance(paths, list) or not all(isinstance(p, str) for p in paths):
        raise ConfigError(f"{where('package-paths')}: expected a list of NAME=DIR or DIR strings")
    xacro_args = []
    for pattern, values in mapping("xacro-args").items():
        if not isinstance(values, dict) or not all(isinstance(v, (str, int, float, bool)) for v in values.values()):
            raise ConfigError(f"{where(f'xacro-args.{pattern!r}')}: expected a table of argument values")
        xacro_args.append((pattern, tuple((k, _xacro_value(v)) for k, v in values.items())))
    models = []
    for model, sets in mapping("models").items():
        models.append(((root / model).resolve(), _argument_sets(sets, where(f"models.{model!r}"))))
    return Config(
        source=source,
        root=root,
        select=select,
        ignore=_selectors(table.get("ignore", []), where("ignore")),
        extend_select=_selectors(table.get("extend-select", []), where("extend-select")),
        per_file_ignores=per_file,
        severity=tuple(severity),
        options=tuple(options),
        package_paths=tuple(_absolute_package_path(p, root) for p in paths),
        xacro_args=tuple(xacro_args),
        models=tuple(models),
        targets=_profiles(table.get("targets", []), where("targets")),
        fix=_boolean(table, "fix", where("fix")),
        unsafe_fixes=_boolean(table, "unsafe-fixes", where("unsafe-fixes")),
        show_info=_boolean(table, "show-info", where("show-info"), default=True),
    )


def _boolean(table: dict[str, Any], key: str, where: str, default: bool = False) -> bool:
    value = table.get(key, default)
    if not isinstance(value, bool):
        raise ConfigError(f"{where}: expected true or false, not {value!r}")
    return value


def _argument_sets(value: Any, where: str) -> tuple[tuple[tuple[str, str], ...], ...]:
    """``[["name:=ur", "ur_type:=ur5e"], ...]``: each inner list is one run of the model."""
    if not isinstance(value, list) or not value or not all(isinstance(s, list) for s in value):
        raise ConfigError(f'{where}: expected a list of argument lists, such as [["ur_type:=ur5e", "name:=ur"]]')
    sets = []
    for arguments in value:
        pairs = []
        for argument in arguments:
            name, separator, text = argument.partition(":=") if isinstance(argument, str) else ("", "", "")
            if not separator or not name:
                raise ConfigError(f"{where}: expected NAME:=VALUE, not {argument!r}")
            pairs.append((name, text))
        sets.append(tuple(pairs))
    return tuple(sets)


def _xacro_value(value: str | int | float | bool) -> str:
    return str(value).lower() if isinstance(value, bool) else str(value)


def _absolute_package_path(entry: str, root: Path) -> str:
    name, equals, folder = entry.rpartition("=") if "=" in entry else ("", "", entry)
    absolute = str((root / Path(folder).expanduser()).resolve())
    return f"{name}={absolute}" if equals else absolute


def _read_toml(path: Path, data: bytes) -> dict[str, Any]:
    import tomllib  # only where there is a file to read

    try:
        return tomllib.loads(data.decode())
    except tomllib.TOMLDecodeError as error:
        raise ConfigError(f"{path}: not valid TOML: {error}") from None


# Where TOML can open tool.urdfcli: a header or dotted key tool.urdfcli (spaces and quotes
# allowed), or a [tool] table or tool = {...} that may hold it. (Compiled by re when a
# pyproject.toml is first met, not at every start.)
_MAY_HOLD_TABLE = rb"""(?m)tool['"]?\s*\.\s*['"]?urdfcli|^\s*\[\s*['"]?tool['"]?\s*\]|^\s*['"]?tool['"]?\s*="""


class Configurations:
    """The configuration files of a session, each read once (again when it changes),
    and the nearest one above each folder, looked for once. ``explicit`` is a file
    to use for every input, or a :class:`Config` itself."""

    def __init__(self, explicit: Path | Config | None = None, isolated: bool = False, overrides: dict | None = None) -> None:
        self.fixed = explicit if isinstance(explicit, Config) else None
        explicit = None if isinstance(explicit, Config) else explicit
        self.explicit = explicit
        self.isolated = isolated
        self.overrides = overrides or {}
        self._tables: dict[tuple[Path, int, int], dict[str, Any] | None] = {}
        self._nearest: dict[Path, Path | None] = {}
        self._configs: dict[tuple[Path | None, int, int], Config] = {}
        self._folders: dict[str, Path | None] = {}  # an input's folder, as given -> its configuration file

    def forget(self) -> None:
        """Look for the nearest configuration file again (each file is read again anyway when it changes)."""
        self._nearest.clear()
        self._folders.clear()

    def for_input(self, file: str) -> Config:
        """The configuration of one input: none when isolated, the explicit file when
        given, else the nearest one above the input; with the command line's
        selections over it. Raises ConfigError."""
        if self.fixed is not None:
            key = (None, -1, -1)  # the configuration given, whatever the input
            if key not in self._configs:
                self._configs[key] = self.fixed.overridden(**self.overrides)
            return self._configs[key]
        if self.isolated:
            found = None
        elif self.explicit is not None:
            if not self.explicit.is_file():
                raise ConfigError(f"{self.explicit}: no such configuration file")
            found = self.explicit
        else:
            folder = os.getcwd() if file == "-" else os.path.dirname(os.path.abspath(file))
            if folder not in self._folders:  # the inputs of a folder share its configuration
                self._folders[folder] = self.find(Path(folder).resolve())
            found = self._folders[folder]
        stamp = _stamp(found) if found is not None else (0, 0)
        key = (found, *stamp)
        if key not in self._configs:
            self._configs[key] = (self.read(found) if found is not None else Config()).overridden(**self.overrides)
        return self._configs[key]

    def read(self, path: Path) -> Config:
        """The configuration in one file (urdfcli.toml, .urdfcli.toml or pyproject.toml)."""
        if not path.is_file():
            raise ConfigError(f"{path}: no such configuration file")
        table = self._table(path)
        source = f"{path} [tool.urdfcli]" if path.name == "pyproject.toml" else str(path)
        return parse(table or {}, source, path.resolve().parent)

    def find(self, start: Path) -> Path | None:
        """The nearest configuration file at or above a folder."""
        return nearest(start, self._own, self._nearest)

    def _own(self, folder: Path) -> Path | None:
        for name in CONFIG_NAMES:
            if (folder / name).is_file():
                return folder / name
        pyproject = folder / "pyproject.toml"
        if pyproject.is_file() and self._table(pyproject) is not None:
            return pyproject
        return None

    def _table(self, path: Path) -> dict[str, Any] | None:
        """The urdfcli table of a config file; None when a pyproject.toml has none."""
        key = (path.resolve(), *_stamp(path))
        if key not in self._tables:
            self._tables[key] = _table(path)
        return self._tables[key]


def _stamp(path: Path) -> tuple[int, int]:
    try:
        status = path.stat()
    except OSError:
        return (0, 0)
    return (status.st_mtime_ns, status.st_size)


def _table(path: Path) -> dict[str, Any] | None:
    """The urdfcli table of a config file; None when a pyproject.toml has none."""
    try:
        data = path.read_bytes()
    except OSError as error:
        raise ConfigError(f"{path}: cannot read: {error.strerror}") from None
    if path.name != "pyproject.toml":
        table = _read_toml(path, data)
    elif re.search(_MAY_HOLD_TABLE, data) is None:
        table = None  # most pyproject.toml files are not ours: not parsed
    else:
        table = _read_toml(path, data).get("tool", {}).get("urdfcli")
    if table is not None and not isinstance(table, dict):
        raise ConfigError(f"{path}: [tool.urdfcli] must be a table")
    return table
