"""GeometryField.lookup: shapes and dtypes, bit-for-bit equality with the C++ CPU lookup
(gfield_lookup_rays, the C++ lookup as a C++ program calls it) on 100,000 rays, accuracy against
Embree's exact casts, the GIL released while it runs."""

import os
import signal
import subprocess
import threading
import time

import numpy as np
import pytest
from conftest import DATA_DIR, LOOKUP_RAYS, box_rays

import gfield

ANSWER_COLUMNS = ["hit", "t", "distance", "position", "normal", "uv"]


def surface_points(mesh, count, rng):
    """Random points on the mesh's triangles (uniform per triangle) and their triangles' normals."""
    v, f = mesh.vertices, mesh.faces
    faces = rng.integers(0, len(f), count)
    a, b, c = v[f[faces, 0]], v[f[faces, 1]], v[f[faces, 2]]
    r1, r2 = rng.random((2, count, 1))
    s = np.sqrt(r1)
    points = (1 - s) * a + s * (1 - r2) * b + s * r2 * c
    normals = np.cross(b - a, c - a)
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    return points, normals


def equality_rays(field, mesh, rng):
    """100,000 rays: box rays, rays leaving the surface, rays from inside the box, odd rays."""
    box = field.box.astype(np.float64)
    diagonal = np.linalg.norm(box[1] - box[0])
    o1, d1 = box_rays(field.box, 40000, rng)
    points, normals = surface_points(mesh, 30000, rng)
    d2 = rng.normal(size=(30000, 3))
    d2 *= np.sign(np.sum(d2 * normals, axis=1, keepdims=True))  # leaving on the normals' side
    o2 = points + 1e-4 * diagonal * normals
    o3 = box[0] + rng.random((20000, 3)) * (box[1] - box[0])
    d3 = rng.normal(size=(20000, 3))
    o4, d4 = box_rays(field.box, 10000, rng)
    o4[0::5] *= 1e30  # far away
    d4[1::5] *= 1e-30  # tiny directions
    d4[2::5] *= 1e17  # long directions
    origins = np.concatenate([o1, o2, o3, o4]).astype(np.float32)
    directions = np.concatenate([d1, d2, d3, d4]).astype(np.float32)
    t_min = np.concatenate(
        [np.zeros(40000), np.zeros(30000), rng.random(20000) * 0.5, rng.random(10000)]
    ).astype(np.float32)
    t_min[-1] = 1e30  # beyond every hit
    return origins, directions, t_min


def answers_of(hits):
    """The lookup's answers as gfield_lookup_rays writes them: (R, 11) float32."""
    columns = [hits["hit"].astype(np.float32)[:, None], hits["t"][:, None]]
    columns += [hits["distance"][:, None], hits["position"], hits["normal"], hits["uv"]]
    return np.concatenate(columns, axis=1)


@pytest.mark.parametrize("mode", ["nearest", "linear", "refined"])
def test_lookup_equals_the_cpp_cpu_lookup_bit_for_bit(spot_asset, spot_field, tmp_path, mode):
    rng = np.random.default_rng(7)
    mesh = gfield.load_mesh(DATA_DIR / "meshes" / "spot.obj")
    origins, directions, t_min = equality_rays(spot_field, mesh, rng)
    rays = tmp_path / "rays.f32"
    np.concatenate([origins, directions, t_min[:, None]], axis=1).astype(np.float32).tofile(rays)
    expected_file = tmp_path / "answers.f32"
    subprocess.run(
        [LOOKUP_RAYS, f"{spot_asset}.gfield.exr", f"{spot_asset}.gimage.exr", rays, mode,
         expected_file],
        check=True, capture_output=True,
    )
    expected = np.fromfile(expected_file, dtype=np.float32).reshape(-1, 11)
    got = answers_of(spot_field.lookup(origins, directions, t_min, mode=mode))
    assert got.shape == expected.shape == (100000, 11)
    differ = np.any(got.view(np.uint32) != expected.view(np.uint32), axis=1)
    assert not differ.any(), f"{differ.sum()} rays differ, the first {np.flatnonzero(differ)[:5]}"
    hits = expected[:, 0] == 1
    assert 0.2 < hits.mean() < 0.9  # the rays test both hits and misses
    assert not hits[90000::5].any() and not hits[90001::5].any()  # NaN origins, zero directions


def test_lookup_shapes_dtypes_and_arguments(spot_field):
    origins = [[0.0, 0.0, 5.0], [0.0, 0.0, -5.0]]  # lists of float64 are taken
    directions = np.array([[0, 0, -1], [0, 0, 1]], dtype=np.float64)
    hits = spot_field.lookup(origins, directions)
    assert sorted(hits) == sorted(ANSWER_COLUMNS)
    shapes = {"hit": (2,), "t": (2,), "distance": (2,), "position": (2, 3), "normal": (2, 3),
              "uv": (2, 2)}
    for name, shape in shapes.items():
        assert hits[name].shape == shape, name
        assert hits[name].dtype == (np.bool_ if name == "hit" else np.float32), name
    per_ray = spot_field.lookup(origins, directions, t_min=np.zeros(2), mode="nearest")
    assert per_ray["hit"].shape == (2,)
    assert spot_field.lookup(np.zeros((0, 3)), np.zeros((0, 3)))["hit"].shape == (0,)
    with pytest.raises(ValueError, match=r"origins: expected an array of shape \(R, 3\)"):
        spot_field.lookup(np.zeros((2, 2)), directions)
    with pytest.raises(ValueError, match="directions: 3 rows for 2 origins"):
        spot_field.lookup(origins, np.zeros((3, 3)))
    with pytest.raises(ValueError, match=r"t_min: expected a number or an array of shape \(2,\)"):
        spot_field.lookup(origins, directions, t_min=np.zeros(3))
    with pytest.raises(ValueError, match="mode: expected nearest, linear or refined, got exact"):
        spot_field.lookup(origins, directions, mode="exact")


@pytest.mark.parametrize("cast", ["lookup", "intersect"])
def test_rays_no_lookup_or_cast_may_take_raise_naming_the_argument(spot_field, spot_mesh, cast):
    """Checked before the lookup or Embree sees them (a negative t_min aborted Embree; a huge
    direction's squared length overflowed to a hit at t = 0)."""
    answer = spot_field.lookup if cast == "lookup" else spot_mesh.intersect
    origins = np.array([[0.0, 0.0, 5.0], [0.0, 0.0, -5.0]])
    directions = np.array([[0.0, 0.0, -1.0], [0.0, 0.0, 1.0]])
    bad = [
        ("origins", 1, np.nan, r"origins\[1\]: .* is not finite"),
        ("directions", 1, 0.0, r"directions\[1\]: .* is zero"),
        ("directions", 0, 1e20, r"directions\[0\]: .* is not finite or beyond 1e18"),
        ("directions", 0, np.inf, r"directions\[0\]: .* is not finite or beyond 1e18"),
    ]
    for name, row, value, message in bad:
        o, d = origins.copy(), directions.copy()
        (o if name == "origins" else d)[row] = value
        with pytest.raises(ValueError, match=message):
            answer(o, d)
    with pytest.raises(ValueError, match=r"t_min: -100.000000 is negative"):
        answer(origins, directions, t_min=-100)
    with pytest.raises(ValueError, match=r"t_min\[1\]: nan is not a number"):
        answer(origins, directions, t_min=[0.0, np.nan])
    with pytest.raises(TypeError, match="t_min: expected a number or an array of numbers, not NoneType"):
        answer(origins, directions, t_min=None)


def test_refined_lookup_agrees_with_exact_casts(spot_field):
    """Against Embree's cast of the original mesh (docs/geometry-field.md measures 99.8% for
    spot's default asset; this one is small: 128^2, N = 8)."""
    rng = np.random.default_rng(3)
    origins, directions = box_rays(spot_field.box, 20000, rng)
    mesh = gfield.load_mesh(DATA_DIR / "meshes" / "spot.obj")
    exact = mesh.intersect(origins, directions)
    diagonal = np.linalg.norm(spot_field.box[1] - spot_field.box[0])
    agreement, median = {}, {}
    for mode in ["nearest", "refined"]:
        found = spot_field.lookup(origins, directions, mode=mode)
        agreement[mode] = np.mean(found["hit"] == exact["hit"])
        both = found["hit"] & exact["hit"]
        error = np.linalg.norm(found["position"][both] - exact["position"][both], axis=1)
        median[mode] = 100 * np.median(error) / diagonal
        print(f"{mode}: hit/miss {100 * agreement[mode]:.2f}%, median error "
              f"{median[mode]:.4f}% of the diagonal")
    assert agreement["refined"] >= 0.99
    assert agreement["refined"] > agreement["nearest"]
    # refined: on the image's surface, within its error at 128^2; nearest: a sample's hit
    assert median["refined"] < 0.05 < 1.0 < median["nearest"]


def test_lookup_releases_the_gil(spot_field):
    """While a long lookup runs on another thread, this thread runs Python code."""
    rng = np.random.default_rng(5)
    origins, directions = box_rays(spot_field.box, 300000, rng)
    worker = threading.Thread(target=spot_field.lookup, args=(origins, directions, 0, "nearest"))
    steps = 0
    worker.start()
    while worker.is_alive():
        steps += 1
    worker.join()
    assert steps > 10000, f"only {steps} steps while the lookup ran"


def test_ctrl_c_stops_a_long_lookup_within_a_second(spot_field):
    """A SIGINT 0.2 s into a batch of refined lookups that takes seconds raises
    KeyboardInterrupt soon after (Mesh.intersect runs its batches the same way)."""
    rng = np.random.default_rng(6)
    origins, directions = box_rays(spot_field.box, 4_000_000, rng)
    sent, finished = [], []

    def interrupt():
        sent.append(time.monotonic())
        os.kill(os.getpid(), signal.SIGINT)

    threading.Timer(0.2, interrupt).start()
    with pytest.raises(KeyboardInterrupt):
        spot_field.lookup(origins, directions)
        finished.append(True)
        time.sleep(5)  # the signal lands here when the batch was faster than the timer
    stopped = time.monotonic()
    assert not finished, "the batch finished before the signal: make it longer"
    assert stopped - sent[0] < 1.0, f"stopped {stopped - sent[0]:.2f} s after the signal"
