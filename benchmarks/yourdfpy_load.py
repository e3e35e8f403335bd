"""Load each model once with yourdfpy, meshes included, in one process: what a Python user
would write to read these models. benchmarks/run.py compares `urdfcli lint` with it.

    python benchmarks/yourdfpy_load.py PACKAGE_DIR MODEL.urdf...

``package://example-robot-data/`` URIs are resolved in PACKAGE_DIR, as ``-P`` does for urdfcli.
"""

import logging
import sys

import yourdfpy

PREFIX = "package://example-robot-data/"


def main() -> None:
    logging.disable(logging.CRITICAL)
    package, models = sys.argv[1], sys.argv[2:]

    def resolve(fname: str) -> str:
        return f"{package}/{fname[len(PREFIX):]}" if fname.startswith(PREFIX) else fname

    for model in models:
        try:
            yourdfpy.URDF.load(model, load_meshes=True, filename_handler=resolve)
        except KeyError:  # ur3.urdf is an empty robot: yourdfpy raises KeyError('name'); any other error fails the run
            pass


if __name__ == "__main__":
    main()
