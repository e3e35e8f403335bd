"""The ``urdfcli`` program (``python -m urdfcli`` too): a Ctrl-C while it starts
ends it as one pressed later does, with exit code 130 and no traceback."""

import sys


def main() -> None:
    try:
        from urdfcli.cli import run
    except KeyboardInterrupt:
        sys.stderr.write("urdfcli: interrupted\n")
        raise SystemExit(130) from None
    run()


if __name__ == "__main__":
    main()
