"""``urdfcli lsp``: urdfcli in an editor, over the Language Server Protocol.

An application over the library, as the command line is: :mod:`.engine` does the
work with one session for the server's lifetime (checks, navigation, quick
fixes), :mod:`.server` speaks the protocol (pygls, the optional extra
``urdfcli[lsp]``); :mod:`.outline`, :mod:`.navigation`, :mod:`.actions` and
:mod:`.places` read sources and cursors without expanding anything.
"""
