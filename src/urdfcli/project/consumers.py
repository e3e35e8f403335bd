"""The real consumers, by name (``LOADERS``): ``check --target NAME --load`` and the differential tests.

Each consumer's ``load`` module (:mod:`urdfcli.targets`) says how it is run. A Python
consumer runs in a child process (:func:`child`, started with ``python -c``): PyBullet
segfaults on some models and Drake turns some inputs into ``SystemExit``, neither of
which may take urdfcli down. The child prints one JSON object per file: whether the
consumer accepted it, its error, what it printed, and what it built. Nothing here is
imported by a prediction, and only the child imports a consumer.
"""

from __future__ import annotations

import contextlib
import json
import os
import subprocess
import sys
import tempfile
from collections.abc import Iterator, Sequence

from ..targets.drake.load import LOADER as DRAKE
from ..targets.gazebo.load import LOADER as GAZEBO
from ..targets.isaac.load import LOADER as ISAAC
from ..targets.kdl.load import LOADER as KDL
from ..targets.mujoco.load import LOADER as MUJOCO
from ..targets.pinocchio.load import LOADER as PINOCCHIO
from ..targets.pybullet.load import LOADER as PYBULLET
from ..read.packages import uri_package
from .loading import Loader, Outcome, Packages

LOADERS: dict[str, Loader] = {loader.name: loader for loader in (MUJOCO, DRAKE, PINOCCHIO, PYBULLET, GAZEBO, KDL, ISAAC)}
TIMEOUT = 120.0  # seconds a consumer may take to load one model
CHILD = "import sys; from urdfcli.project.consumers import child; sys.exit(child(sys.argv[1:]))"


def load(target: str, paths: Sequence[str], variants: frozenset[str] = frozenset(), packages: Packages | None = None) -> list[Outcome]:
    """Load each of ``paths`` (plain URDF files) into ``target``: one :class:`Outcome` per
    path, in order. ``packages`` are those urdfcli resolved, given to the consumers that
    take a package map."""
    loader = LOADERS[target]
    packages = dict(packages or {})
    if loader.load is not None:
        return loader.load(paths, variants, packages)
    return _in_child(target, list(paths), variants, packages)


def _in_child(target: str, paths: list[str], variants: frozenset[str], packages: dict[str, str]) -> list[Outcome]:
    """The files loaded one after the other in one child process; when the consumer kills
    it, that file is said to have crashed it and the rest go to a new child."""
    if not paths:
        return []
    command = [sys.executable, "-c", CHILD, target, ",".join(sorted(variants)), json.dumps(packages), *map(os.path.abspath, paths)]
    try:
        # Its working folder (where MuJoCo writes MUJOCO_LOG.TXT) is its temporary folder too:
        # removed here, it takes with it what a consumer leaves there (urdf-usd-converter
        # leaves its stage when it fails; a crash leaves PyBullet's package folder).
        with tempfile.TemporaryDirectory(prefix="urdfcli-load-") as folder:
            done = subprocess.run(command, capture_output=True, text=True, timeout=TIMEOUT * len(paths), errors="replace", cwd=folder,
                                  env={**os.environ, "TMPDIR": folder})
    except subprocess.TimeoutExpired:
        return [Outcome(False, f"{target} did not finish loading in {TIMEOUT:.0f} s")] * len(paths)
    answers = [json.loads(line) for line in done.stdout.splitlines() if line.startswith("{")]
    found = [Outcome(a["accepted"], a.get("error", ""), a.get("printed", ""), a.get("built", {})) for a in answers]
    if len(found) < len(paths):  # the child died on the next one
        signal = -done.returncode if done.returncode < 0 else None
        why = f"{target} crashed (signal {signal})" if signal else f"{target} exited with status {done.returncode}"
        found.append(Outcome(False, why, done.stderr[-2000:], crashed=signal))
        found += _in_child(target, paths[len(found):], variants, packages)
    return found


# -- in the child process ----------------------------------------------------------------


def child(argv: list[str]) -> int:
    """Load each file named after the target, its variants and packages; one JSON line per file."""
    target, variants, packages = argv[0], frozenset(v for v in argv[1].split(",") if v), json.loads(argv[2])
    built = LOADERS[target].built
    for path in argv[3:]:
        answer: dict = {"accepted": True}
        with captured() as printed:
            try:
                answer["built"] = built(path, variants, packages)
            except BaseException as error:  # noqa: BLE001 -- Drake's asserts raise SystemExit
                answer = {"accepted": False, "error": f"{type(error).__name__}: {error}".strip()}
        answer["printed"] = printed[0] if printed else ""
        print(json.dumps(answer), flush=True)
    return 0


@contextlib.contextmanager
def captured() -> Iterator[list[str]]:
    """What C and Python code write to file descriptors 1 and 2 while the block runs."""
    found: list[str] = []
    sys.stdout.flush()
    sys.stderr.flush()
    saved = os.dup(1), os.dup(2)
    with tempfile.TemporaryFile() as sink:
        os.dup2(sink.fileno(), 1)
        os.dup2(sink.fileno(), 2)
        try:
            yield found
        finally:
            sys.stdout.flush()
            sys.stderr.flush()
            os.dup2(saved[0], 1)
            os.dup2(saved[1], 2)
            os.close(saved[0])
            os.close(saved[1])
            sink.seek(0)
            found.append(sink.read().decode(errors="replace"))


def missing(target: str) -> str | None:
    """Why ``target`` cannot be run here, in one line (None: it can)."""
    return LOADERS[target].missing()


def packages_of(loaded) -> dict[str, str]:
    """The packages a model's ``package://`` URIs name, as urdfcli resolved them (a model.load.Loaded)."""
    found = {}
    for _, _, uri in loaded.robot.resources:
        name = uri_package(uri)
        if name and name not in found:
            folder = loaded.resolver.find(name)
            if folder is not None:
                found[name] = str(folder)
    return found


# -- --load: the real load beside the prediction -------------------------------------------------


def verify(loaded, diagnostics: list, chosen) -> list:
    """Load a model (a model.load.Loaded) into ``chosen``'s consumer and say what it did:
    each of its errors (C001) and warnings (C003) whole, at the line or element it names;
    C002 when its verdict is not urdfcli's; C004 when it cannot run here."""
    from .compatibility import verdict

    robot = loaded.robot
    why = missing(chosen.target)
    if why is not None:
        return [loaded.diagnostic("C004", f"{chosen.name} cannot be loaded here: {why}", robot.at)]
    with model_file(loaded) as path:
        [outcome] = load(chosen.target, [path], chosen.variants, packages_of(loaded))
        messages = [m._replace(text=_in_words_of(m.text, path, loaded.document.shown)) for m in LOADERS[chosen.target].said(outcome, path)]
    found = []
    for message in messages:
        if message.severity == "error":
            found.append(_placed(loaded, "C001", f"{chosen.name} refuses the model: {message.text}", message))
        else:
            found.append(_placed(loaded, "C003", f"{chosen.name} warns: {message.text}", message))
    predicted = verdict(diagnostics, chosen).refuses
    if predicted == outcome.accepted:
        said = "refuses" if predicted else "loads"
        did = "loaded it" if outcome.accepted else "refused it"
        found.append(loaded.diagnostic("C002", f"urdfcli predicted that {chosen.name} {said} the model, but it {did}", robot.at))
    return found


def _in_words_of(text: str, path: str, shown: str) -> str:
    """A consumer's message about the file it was given, as the user knows it: the file's
    ``PATH:LINE:`` prefix left out (the diagnostic is placed there), its other mentions made
    the input's name."""
    import re

    for given in dict.fromkeys((os.path.abspath(path), path)):
        text = re.sub(re.escape(given) + r":\d+: ", "", text).replace(given, shown)
    return text


def _placed(loaded, code: str, message: str, said):
    """A diagnostic at the line the consumer named, else at the first link or joint it names, else at <robot>."""
    robot = loaded.robot
    at = loaded.document.element_on_line(said.line) if said.line is not None else None
    subjects = tuple(name for name in said.names if name in robot.links or name in robot.joints)
    if at is None and subjects:
        element = robot.links.get(subjects[0]) or robot.joints.get(subjects[0])
        at = element.at
    return loaded.diagnostic(code, message, at if at is not None else robot.at, subjects=subjects)


@contextlib.contextmanager
def model_file(loaded) -> Iterator[str]:
    """The model as a file the consumer can read: the input itself, or a xacro input's
    expansion written to the system's temporary folder (its relative mesh paths made
    absolute, each on its own line), removed after."""
    document = loaded.document
    if not document.is_xacro and document.file is not None:
        yield str(document.file)
        return
    folder = document.file.parent if document.file is not None else None
    text = _absolute_paths(document.expanded_text or "", folder) if folder is not None else document.expanded_text or ""
    handle, path = tempfile.mkstemp(prefix="urdfcli-load-", suffix=".urdf")
    try:
        with os.fdopen(handle, "w", encoding="utf-8") as out:
            out.write(text)
        yield path
    finally:
        os.unlink(path)


def _absolute_paths(text: str, folder) -> str:
    """``filename="meshes/a.stl"`` made ``filename="/FOLDER/meshes/a.stl"`` (the lines stay where they are)."""
    import re

    def absolute(match: re.Match) -> str:
        value = match.group(2)
        if "://" in value or os.path.isabs(value) or not value:
            return match.group(0)
        return f"{match.group(1)}{os.path.join(folder, value)}{match.group(3)}"

    return re.sub(r"""(\bfilename\s*=\s*["'])([^"']*)(["'])""", absolute, text)
