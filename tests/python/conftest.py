"""Shared fixtures of the Python module's tests (CTest runs each test_*.py file with pytest and
the interpreter the module was built for: tests/CMakeLists.txt sets the environment below)."""

import os
import pathlib
import subprocess

import numpy as np
import pytest

import gfield

DATA_DIR = pathlib.Path(os.environ["GFIELD_DATA_DIR"])
FUZZ_DIR = pathlib.Path(os.environ["GFIELD_FUZZ_DIR"])
SOURCE_DIR = pathlib.Path(os.environ["GFIELD_SOURCE_DIR"])
CLI = os.environ["GFIELD_CLI"]
LOOKUP_RAYS = os.environ["GFIELD_LOOKUP_RAYS"]


def run_cli(*args):
    """Runs `gfield ARGS...`; the completed process (text output)."""
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, check=False)


def cli_error(*args):
    """The message `gfield ARGS...` prints after 'gfield: error: ' (it must fail with exit 2)."""
    done = run_cli(*args)
    assert done.returncode == 2, (args, done.returncode, done.stdout, done.stderr)
    line = done.stderr.strip().splitlines()[-1]
    assert line.startswith("gfield: error: "), line
    return line[len("gfield: error: ") :]


@pytest.fixture(scope="session")
def spot_asset(tmp_path_factory):
    """Spot's asset, small (128^2 image, N = 8, K chosen): the path DIR/spot."""
    out = tmp_path_factory.mktemp("assets") / "spot"
    gfield.build(DATA_DIR / "meshes" / "spot.obj", out, size=128, samples=8, verify_rays=0)
    return out


@pytest.fixture(scope="session")
def spot_mesh():
    return gfield.load_mesh(DATA_DIR / "meshes" / "spot.obj")


@pytest.fixture(scope="session")
def spot_field(spot_asset):
    return gfield.GeometryField.load(f"{spot_asset}.gfield.exr")


def box_rays(box, count, rng):
    """`count` rays from random points outside the box through random points inside it."""
    lo, hi = box[0].astype(np.float64), box[1].astype(np.float64)
    centre, extent = (lo + hi) / 2, hi - lo
    inside = lo + rng.random((count, 3)) * extent
    outward = rng.normal(size=(count, 3))
    outward /= np.linalg.norm(outward, axis=1, keepdims=True)
    origins = centre + outward * np.linalg.norm(extent)
    return origins.astype(np.float32), (inside - origins).astype(np.float32)
