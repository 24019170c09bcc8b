"""gfield: geometry images and geometry fields of triangle meshes on numpy arrays.

Meshes become geometry images and geometry fields (build); a field answers "where does this ray
first hit the object?" by table lookups (GeometryField.lookup), and the Embree reference tracer
renders scenes (render) and casts exact rays (Mesh.intersect) to measure it against. Bad input
raises gfield.Error with the one-line message the gfield command line prints. docs/python.md.
"""

import sys as _sys

from ._gfield import (
    Error,
    GeometryField,
    GeometryImage,
    GfieldWarning,
    Mesh,
    __version__,
    build,
    compare,
    info,
    load_mesh,
    load_scene,
    render,
)

__all__ = [
    "Error",
    "GeometryField",
    "GeometryImage",
    "GfieldWarning",
    "Mesh",
    "build",
    "compare",
    "info",
    "load_mesh",
    "load_scene",
    "print_progress",
    "render",
]

_shown_stage = None


def print_progress(stage: str, done: float) -> None:
    """A progress callback for build and render: a bar per stage on stderr, tqdm style.

    Each call rewrites the stage's line ("field   [############            ]  40%"); a new stage,
    or done reaching 1, ends the line.
    """
    global _shown_stage
    if _shown_stage is not None and _shown_stage != stage:
        _sys.stderr.write("\n")
    width = 30
    filled = min(width, max(0, int(done * width)))
    _sys.stderr.write(f"\r{stage:<7} [{'#' * filled}{' ' * (width - filled)}] {100 * done:3.0f}%")
    if done >= 1.0:
        _sys.stderr.write("\n")
        _shown_stage = None
    else:
        _shown_stage = stage
    _sys.stderr.flush()
