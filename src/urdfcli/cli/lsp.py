"""`urdfcli lsp`: the editor server, over standard input and output."""

from __future__ import annotations

from typing import Annotated

import typer

from .common import PackagePathOption, fail

NEEDED = ("pygls", "lsprotocol")


def lsp(
    package_path: PackagePathOption = None,
    stdio: Annotated[bool, typer.Option("--stdio", help="Accepted for the clients that pass it: standard input and output are the only transport.")] = False,
    in_process: Annotated[bool, typer.Option("--in-process", hidden=True, help="Serve in this process: what the supervisor runs.")] = False,
) -> None:
    """Run the language server for editors: diagnostics of URDF and xacro files as you type, hover, go to definition, completion and quick fixes.

    It speaks the Language Server Protocol on standard input and output; the README shows how to set up VS Code, Neovim and Helix. Needs the extra: pip install 'urdfcli\\[lsp]'.
    """
    from ..read.packages import PackageError

    try:
        if not in_process:  # a small process that passes messages to the server and replaces it to give memory back
            import lsprotocol  # noqa: F401 - said missing here, not by the server it would start
            import pygls  # noqa: F401

            from ..lsp import supervisor

            raise typer.Exit(supervisor.supervise(tuple(package_path or ())))
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
