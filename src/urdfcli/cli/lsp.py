"""`urdfcli lsp`: the editor server, over standard input and output."""

from __future__ import annotations

from typing import Annotated

import typer

from .common import PackagePathOption, fail

NEEDED = ("pygls", "lsprotocol")


def lsp(
    package_path: PackagePathOption = None,
    stdio: Annotated[bool, typer.Option("--stdio", help="Accepted for the clients that pass it: standard input and output are the only transport.")] = False,
) -> None:
    """Run the language server for editors: diagnostics of URDF and xacro files as you type, hover, go to definition, completion and quick fixes.

    It speaks the Language Server Protocol on standard input and output; the README shows how to set up VS Code, Neovim and Helix. Needs the extra: pip install 'urdfcli\\[lsp]'.
    """
    from ..read.packages import PackageError

    try:
        from ..lsp import server
    except ModuleNotFoundError as error:
        if (error.name or "").partition(".")[0] not in NEEDED:
            raise
        raise fail("urdfcli lsp needs pygls and lsprotocol: pip install 'urdfcli[lsp]'") from None
    try:
        code = server.serve(tuple(package_path or ()))
    except PackageError as error:
        raise fail(str(error)) from None
    raise typer.Exit(code)
