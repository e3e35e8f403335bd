"""A session: one run of urdfcli, and everything it reads and learns.

The source texts, the package look-ups, the configuration files, the mesh
summaries and the xacro worker belong to a session, never to a module: a
program that checks models for hours (an editor server, a test suite) makes a
session, or one per batch, and gets it all back when the session ends. Files
that change on disk are read again within a session.
"""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path

from .model.meshes import MeshSummaries
from .project.config import Config, Configurations
from .project.workspace import Index
from .read.document import Inputs
from .read.packages import PackageIndex, PackageResolver
from .read.positions import Sources
from .read.xacro import Expander
from .read.xacro_scan import Scans


class Session:
    """What a run shares: give it the command line's settings, use it for any
    number of inputs, and close it (or use it in a ``with`` block).

    ``package_paths`` are ``-P`` options (``NAME=DIR`` or a folder to scan);
    ``config`` names a configuration file to use instead of the nearest one above
    each input (or is a :class:`~urdfcli.project.config.Config`), ``isolated`` reads none; ``select``, ``ignore`` and ``extend_select``
    are the command line's rule selections over the configuration's; ``targets``
    (``["mujoco", "pinocchio:mimic"]``) replaces the configuration's targets.
    """

    def __init__(
        self,
        package_paths: Iterable[str] = (),
        config: str | Path | Config | None = None,
        isolated: bool = False,
        select: list[str] | None = None,
        ignore: list[str] | None = None,
        extend_select: list[str] | None = None,
        targets: list[str] | None = None,
    ) -> None:
        self.package_paths = tuple(package_paths)
        self.settings = dict(package_paths=self.package_paths, config=config, isolated=isolated, select=select, ignore=ignore, extend_select=extend_select, targets=targets)
        self.sources = Sources()
        self.packages = PackageIndex()
        self.expander = Expander()
        self.meshes = MeshSummaries()
        self._forget_sources()
        overrides = {"select": select, "ignore": ignore, "extend_select": extend_select, "targets": targets}
        self.configs = Configurations(Path(config) if isinstance(config, (str, Path)) else config, isolated, overrides)
        PackageResolver(self.package_paths)  # a -P that is not NAME=DIR or a folder: said now (PackageError)

    @property
    def inputs(self) -> Inputs:
        return Inputs(self.sources, self.packages, self.expander)

    def _forget_sources(self) -> None:
        """The xacro files read statically (each once, for the workspace search and the
        source rules), and the includes and folders found between them."""
        self.scans = Scans(lambda name: self.sources.data(name), lambda: self.sources.given())
        self.index = Index(self.package_paths, self.packages, self.scans)

    def resolver(self, extra: Iterable[str], input_file: Path | None) -> PackageResolver:
        """The package look-up for one input: its configuration's package paths, then the session's."""
        return self.packages.resolver((*extra, *self.package_paths), input_file)

    def forget(self) -> None:
        """Forget what was learnt of the folders on disk (which configuration file and
        which package is nearest, which packages a folder holds): after a change on
        disk such as a ``git checkout``. Files are read again when they change anyway."""
        self.configs.forget()
        self.packages.forget()

    def close(self) -> None:
        """Stop the xacro worker and let go of what the session learnt."""
        self.expander.close()
        self.sources = Sources()
        self.packages = PackageIndex()
        self.meshes = MeshSummaries()
        self._forget_sources()

    def __enter__(self) -> Session:
        return self

    def __exit__(self, *exc) -> None:
        self.close()
