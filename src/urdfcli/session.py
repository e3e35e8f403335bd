"""A session: one run of urdfcli, and everything it reads and learns.

The source files, the package look-ups, the configuration files, the mesh
summaries and the xacro worker belong to a session, never to a module: a
program that checks models for hours (an editor server, a test suite) makes a
session, or one per batch, and gets it all back when the session ends. Files
that change on disk are read again within a session.
"""

from __future__ import annotations

import copy
from collections.abc import Iterable
from pathlib import Path

from .model.mesh_summaries import MeshSummaries
from .options import Options
from .project.config import Configurations
from .project.workspace import Index
from .read.document import Inputs
from .read.packages import PackageIndex, PackageResolver
from .read.files import SourceFiles
from .read.xacro import Expander


class Session:
    """What the runs of one set of :class:`~urdfcli.options.Options` share: make one,
    use it for any number of inputs, and close it (or use it in a ``with`` block)."""

    def __init__(self, options: Options | None = None, files: SourceFiles | None = None) -> None:
        """``files``: another session's source files, to share (an editor's two threads read the same buffers)."""
        self.options = options if options is not None else Options()
        self.files = files if files is not None else SourceFiles()
        self.packages = PackageIndex(self._given)
        self.expander = Expander()
        self.meshes = MeshSummaries()
        self.index = Index(self.package_paths, self.packages, self.files)
        self.configs = self._configurations()
        PackageResolver(self.package_paths)  # a -P that is not NAME=DIR or a folder: said now (PackageError)

    def _given(self) -> dict[str, bytes]:
        return self.files.given()

    @property
    def package_paths(self) -> tuple[str, ...]:
        return self.options.package_paths

    def _configurations(self) -> Configurations:
        return Configurations(self.options.config, self.options.isolated, self.options.overrides)

    def using(self, options: Options) -> Session:
        """A session for other options that shares this one's texts, look-ups, summaries
        and xacro worker (closing either closes both)."""
        other = copy.copy(self)
        other.options = options
        same = self.options
        if (options.config, options.isolated, options.overrides) != (same.config, same.isolated, same.overrides):
            other.configs = other._configurations()
        if options.package_paths != same.package_paths:
            PackageResolver(options.package_paths)
            other.index = Index(options.package_paths, other.packages, other.files)
        return other

    @property
    def inputs(self) -> Inputs:
        return Inputs(self.files, self.packages, self.expander)

    def resolver(self, extra: Iterable[str], input_file: Path | None, fallback: PackageResolver | None = None) -> PackageResolver:
        """The package look-up for one input: its configuration's package paths, then the
        session's; ``fallback`` for what none of them holds."""
        return self.packages.resolver((*extra, *self.package_paths), input_file, fallback)

    def forget(self) -> None:
        """Forget what was learnt of the folders on disk (which configuration file and
        which package is nearest, which packages a folder holds): after a change on
        disk such as a ``git checkout``. Files are read again when they change anyway."""
        self.configs.forget()
        self.packages.forget()

    def close(self) -> None:
        """Stop the xacro worker and let go of what the session learnt."""
        self.expander.close()
        self.files = SourceFiles()
        self.packages = PackageIndex(self._given)
        self.meshes = MeshSummaries()
        self.index = Index(self.package_paths, self.packages, self.files)

    def __enter__(self) -> Session:
        return self

    def __exit__(self, *exc) -> None:
        self.close()
