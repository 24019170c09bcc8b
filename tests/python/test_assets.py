"""GeometryImage and GeometryField: arrays, their layout against docs/formats.md, and their values
against Embree's exact casts of the meshes they were built from."""

import shutil
import threading

import numpy as np
import pytest
from conftest import DATA_DIR, run_cli

import gfield


def bilinear(image_array, uv):
    """Bilinear lookup between texel centres, clamped to the edge, at uvs (R, 2): texel (i, j)
    is image_array[j, i] with its centre at ((i + 0.5) / n, (j + 0.5) / n) (docs/formats.md)."""
    n = image_array.shape[0]
    x = np.clip(uv * n - 0.5, 0, n - 1)
    i0 = np.minimum(np.floor(x).astype(int), n - 2)
    f = x - i0
    def at(di, dj):
        return image_array[i0[:, 1] + dj, i0[:, 0] + di]

    a = at(0, 0) * (1 - f[:, :1]) + at(1, 0) * f[:, :1]
    b = at(0, 1) * (1 - f[:, :1]) + at(1, 1) * f[:, :1]
    return a * (1 - f[:, 1:]) + b * f[:, 1:]


def sample_points(box, n):
    """The 6 N^2 box samples in mesh coordinates, by sample index face * N^2 + b * N + a."""
    a, b = np.meshgrid(np.arange(n), np.arange(n))
    s, t = ((a.ravel() + 0.5) / n), ((b.ravel() + 0.5) / n)
    faces = []
    for face in range(6):
        axis, side = face // 2, face % 2
        others = [k for k in range(3) if k != axis]
        unit = np.zeros((n * n, 3))
        unit[:, axis] = side
        unit[:, others[0]], unit[:, others[1]] = s, t
        faces.append(unit)
    unit = np.concatenate(faces)
    return box[0] + unit * (box[1] - box[0])


def test_geometry_image_arrays(spot_asset):
    image = gfield.GeometryImage.load(f"{spot_asset}.gimage.exr")
    n = image.size
    assert n == 128 and image.source == "spot.obj" and len(image.build_id) == 32
    assert image.box.shape == (2, 3) and np.all(image.box[0] < image.box[1])
    for name, shape in [("positions", (n, n, 3)), ("normals", (n, n, 3)), ("coverage", (n, n))]:
        array = getattr(image, name)
        assert array.shape == shape and array.dtype == np.float32, name
        assert not array.flags.writeable, name
    assert image.albedo is None  # spot.obj carries no base colour
    with pytest.raises(ValueError):
        image.positions[0, 0, 0] = 1.0
    covered = image.coverage > 0
    assert 0.3 < covered.mean() < 1.0
    assert np.allclose(np.linalg.norm(image.normals[covered], axis=1), 1.0, atol=1e-3)


def test_geometry_image_lies_on_the_mesh(spot_asset):
    """A ray from each covered texel's position, moved 1% of the diagonal out along its normal,
    back along the normal hits the mesh (Embree) about 1% of the diagonal away."""
    image = gfield.GeometryImage.load(f"{spot_asset}.gimage.exr")
    diagonal = np.linalg.norm(image.box[1] - image.box[0])
    covered = image.coverage > 0
    p, normal = image.positions[covered], image.normals[covered]
    mesh = gfield.load_mesh(DATA_DIR / "meshes" / "spot.obj")
    exact = mesh.intersect(p + 0.01 * diagonal * normal, -normal)
    off = np.abs(exact["t"][exact["hit"]] - 0.01 * diagonal) / diagonal
    assert exact["hit"].mean() > 0.99
    assert np.percentile(off, 95) < 0.002  # within 0.2% of the diagonal (texel: 0.5%)


def test_albedo_of_a_textured_mesh(tmp_path):
    out = tmp_path / "painted"
    gfield.build(DATA_DIR / "meshes" / "spot-painted.obj", out, size=64, samples=4, verify_rays=0)
    image = gfield.GeometryImage.load(f"{out}.gimage.exr")
    assert image.albedo.shape == (64, 64, 3) and image.albedo.dtype == np.float32
    covered = image.coverage > 0
    assert image.albedo[covered].std(axis=0).min() > 0.01  # a painted texture, not a constant


def test_field_tables_against_exact_casts(spot_asset, spot_field):
    """nearest[entry, column] and line_hits as docs/formats.md lays them out: the nearest hits
    are those of Embree's casts from sample to sample of the parameterised mesh, and every line
    reads the same hits from both ends; table(K) is the layered table of format 2."""
    n, k = spot_field.samples_per_side, spot_field.layers
    side = 6 * n * n
    nearest = spot_field.nearest
    assert nearest.shape == (side, 5 * n * n, 2) and nearest.dtype == np.float32
    assert not nearest.flags.writeable and 4 <= k <= 8
    hit = nearest[..., 0] >= 0
    assert np.all(nearest[hit] <= 1.0) and np.all(nearest[~hit] == -1.0)
    face = np.arange(side) // (n * n)
    rng = np.random.default_rng(11)
    entry, exit = rng.integers(0, side, (2, 20000))
    keep = face[entry] != face[exit]
    entry, exit = entry[keep], exit[keep]
    # The column of the exit sample in the entry's row: the five other faces in order.
    column = (face[exit] - (face[exit] > face[entry])) * n * n + exit % (n * n)
    points = sample_points(spot_field.box.astype(np.float64), n)
    built = gfield.load_mesh(f"{spot_asset}.gimage.obj")
    exact = built.intersect(points[entry], points[exit] - points[entry])
    stored = nearest[entry, column]
    stored_hit = stored[:, 0] >= 0
    assert np.mean(stored_hit == exact["hit"]) > 0.999
    both = stored_hit & exact["hit"]
    image = spot_field.image
    error = bilinear(image.positions, stored[both]) - exact["position"][both]
    error = np.linalg.norm(error, axis=1)
    diagonal = np.linalg.norm(spot_field.box[1] - spot_field.box[0])
    assert np.median(error) / diagonal < 0.002
    for a, b, first in zip(entry[:500], exit[:500], stored[:500]):
        hits = spot_field.line_hits(a, b)
        assert np.array_equal(hits, spot_field.line_hits(b, a)[::-1])
        assert np.array_equal(hits[0], first) if len(hits) else first[0] == -1.0
    assert spot_field.line_hits(0, 1).shape == (0, 2)  # one face: no line
    table = spot_field.table(2)
    assert table.shape == (2, side, side, 2)
    same_face = face[:, None] == face[None, :]
    assert np.all(table[:, same_face] == -2.0) and not np.any(table[:, ~same_face] == -2.0)
    assert np.array_equal(table[0, entry, exit], stored)
    with pytest.raises(ValueError, match="layers: expected 1 to 8, got 9"):
        spot_field.table(9)


def test_field_properties_and_its_image(spot_asset, spot_field, tmp_path):
    assert spot_field.samples_per_side == 8 and spot_field.source == "spot.obj"
    assert spot_field.build_id == spot_field.image.build_id
    assert np.array_equal(spot_field.box, spot_field.image.box)
    image = gfield.GeometryImage.load(f"{spot_asset}.gimage.exr")
    given = gfield.GeometryField.load(f"{spot_asset}.gfield.exr", image=image)
    assert given.image is image
    by_path = gfield.GeometryField.load(f"{spot_asset}.gfield.exr", f"{spot_asset}.gimage.exr")
    assert by_path.image.size == 128
    alone = tmp_path / "alone.gfield.exr"
    shutil.copy(f"{spot_asset}.gfield.exr", alone)
    field = gfield.GeometryField.load(alone)
    assert field.image is None and field.nearest.shape == (384, 320, 2)
    with pytest.raises(gfield.Error, match="no geometry image to look up with"):
        field.lookup(np.zeros((1, 3)), np.ones((1, 3)))
    with pytest.raises(TypeError, match="image: expected None, a GeometryImage or a path, not int"):
        gfield.GeometryField.load(f"{spot_asset}.gfield.exr", image=5)


def test_a_field_and_a_foreign_image_are_refused(spot_asset, tmp_path):
    out = tmp_path / "torus"
    gfield.build(DATA_DIR / "meshes" / "torus.obj", out, size=64, samples=4, verify_rays=0)
    refused = r"spot.gfield.exr: does not match .*torus.gimage.exr \("
    with pytest.raises(gfield.Error, match=refused):
        gfield.GeometryField.load(f"{spot_asset}.gfield.exr", image=f"{out}.gimage.exr")


def test_an_asset_is_checked_against_the_mesh_it_names(spot_asset, tmp_path):
    spot = DATA_DIR / "meshes" / "spot.obj"
    field = gfield.GeometryField.load(f"{spot_asset}.gfield.exr", mesh=spot)
    assert field.source == "spot.obj"
    refused = rf"spot.report.json: built from spot.obj \(sha256 .*\), not from .*torus.obj"
    with pytest.raises(gfield.Error, match=r"spot.report.json: built from spot.obj \(330624 bytes\), "
                       r"not from .*torus.obj as it is now"):
        gfield.GeometryField.load(f"{spot_asset}.gfield.exr", mesh=DATA_DIR / "meshes" / "torus.obj")
    edited = tmp_path / "spot.obj"
    edited.write_bytes(spot.read_bytes().replace(b"v ", b"v  ", 1)[:-1])  # same size, new bytes
    assert edited.stat().st_size == spot.stat().st_size
    with pytest.raises(gfield.Error, match=refused.replace("torus", "spot")):
        gfield.GeometryField.load(f"{spot_asset}.gfield.exr", mesh=edited)
    with pytest.raises(TypeError, match="mesh: expected None or a path, not int"):
        gfield.GeometryField.load(f"{spot_asset}.gfield.exr", mesh=5)


def test_a_load_while_the_asset_is_republished_reads_one_build(tmp_path):
    """The asset republished with two sizes in turn while loads run: each load is one build."""
    spot = DATA_DIR / "meshes" / "spot.obj"
    name = tmp_path / "spot"

    def publish(round_):
        return run_cli("build", spot, "-o", name, "--samples", "4", "--verify-rays", "0",
                       "--size", "64" if round_ % 2 else "96")

    assert publish(0).returncode == 0
    done = threading.Event()

    def publisher():
        for round_ in range(1, 7):
            publish(round_)
        done.set()

    thread = threading.Thread(target=publisher)
    thread.start()
    try:
        sizes = set()
        loads = 0
        while not done.is_set():
            field = gfield.GeometryField.load(f"{name}.gfield.exr")
            assert field.build_id == field.image.build_id
            sizes.add(field.image.size)
            loads += 1
    finally:
        done.set()
        thread.join()
    assert sizes == {64, 96} and loads > 100, (sizes, loads)  # the loads saw both builds


def test_nearest_lookups_read_the_image_at_their_uv(spot_field):
    """A nearest-mode hit is the geometry image at its uv (bilinear, texel (i, j) at [j, i])."""
    rng = np.random.default_rng(2)
    box = spot_field.box
    origins = box[0] - 0.5 * (box[1] - box[0]) * rng.random((5000, 3))
    directions = box[0] + rng.random((5000, 3)) * (box[1] - box[0]) - origins
    found = spot_field.lookup(origins, directions, mode="nearest")
    hit = found["hit"]
    assert hit.mean() > 0.3
    at_uv = bilinear(spot_field.image.positions, found["uv"][hit])
    assert np.allclose(at_uv, found["position"][hit], atol=1e-5 * np.linalg.norm(box[1] - box[0]))
