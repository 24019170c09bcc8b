"""gfield.render, gfield.compare and gfield.load_scene against `gfield render`, `gfield compare`
and the scene files themselves."""

import json

import numpy as np
import pytest
from conftest import DATA_DIR, cli_error, run_cli

import gfield

SPHERES = DATA_DIR / "scenes" / "two-mirror-spheres.json"


def test_render_is_the_cli_render(tmp_path):
    picture = gfield.render(SPHERES, size=(40, 30), spp=2, depth=3, seed=5)
    assert picture.shape == (30, 40, 3) and picture.dtype == np.float32
    assert np.all(np.isfinite(picture)) and picture.max() > 0.1
    exr = tmp_path / "spheres.exr"
    done = run_cli("render", SPHERES, "-o", exr, "--size", "40x30", "--spp", 2, "--depth", 3,
                   "--seed", 5, "-q")
    assert done.returncode == 0, done.stderr
    same = gfield.compare(picture, exr)
    assert same["max_abs_error"] == 0.0 and same["psnr_db"] == float("inf")
    centres = gfield.render(SPHERES, (40, 30), 2, 3, strata_centres=True)
    assert not np.array_equal(centres, picture)  # other sample positions


def test_render_progress_and_interrupt():
    seen = []
    gfield.render(SPHERES, (32, 16), 1, 1, progress=lambda stage, done: seen.append((stage, done)))
    assert seen and {stage for stage, _ in seen} == {"render"} and seen[-1][1] == 1.0

    def stop(stage, done):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        gfield.render(SPHERES, (256, 256), 16, 10, progress=stop)


def test_render_arguments_and_bad_scenes(tmp_path):
    with pytest.raises(ValueError, match="spp: expected 1 or more, got 0"):
        gfield.render(SPHERES, (8, 8), spp=0)
    with pytest.raises(ValueError, match="dielectric: expected full, refract-only or tir-only"):
        gfield.render(SPHERES, (8, 8), dielectric="glass")
    with pytest.raises(ValueError, match=r"size: expected \(width, height\), both positive"):
        gfield.render(SPHERES, (0, 8))
    with pytest.raises(gfield.Error) as error:
        gfield.render(SPHERES, (100000, 100000), spp=1)
    assert str(error.value) == cli_error("render", SPHERES, "-o", tmp_path / "x.png", "--size",
                                         "100000x100000", "--spp", 1)
    with pytest.raises(ValueError) as error:
        gfield.render(SPHERES, (8, 8), camera="1,2")
    cli = cli_error("render", SPHERES, "-o", tmp_path / "x.png", "--camera", "1,2")
    assert "--" + str(error.value) == cli  # the argument named as Python names it


def test_compare_against_known_errors():
    a = np.zeros((8, 8, 3), dtype=np.float32)
    same = gfield.compare(a, a)
    assert same["psnr_db"] == float("inf") and same["ssim"] == 1.0 and same["pixels"] == 64
    off = gfield.compare(a, a + 0.1)
    assert off["mse"] == pytest.approx(0.01, rel=1e-6)
    assert off["psnr_db"] == pytest.approx(20.0, abs=1e-5)
    assert off["max_abs_error"] == pytest.approx(0.1, rel=1e-6)
    half = np.zeros((8, 8), dtype=bool)
    half[:, :4] = True
    b = a.copy()
    b[:, 4:] = 1.0  # differs only outside the mask
    masked = gfield.compare(a, b, mask=half)
    assert masked["pixels"] == 32 and masked["mse"] == 0.0
    with pytest.raises(gfield.Error, match="mask: the mask selects no pixel"):
        gfield.compare(a, b, mask=np.zeros((8, 8), dtype=bool))
    with pytest.raises(gfield.Error, match=r"b: size 4x8 differs from a \(8x8\)"):
        gfield.compare(a, np.zeros((8, 4, 3)))
    with pytest.raises(ValueError, match=r"a: expected an array of shape \(height, width, 3\)"):
        gfield.compare(np.zeros((8, 8)), a)


def test_compare_files_is_the_cli_compare(tmp_path):
    first, second = tmp_path / "a.exr", tmp_path / "b.png"
    for path, spp in [(first, 1), (second, 4)]:
        done = run_cli("render", SPHERES, "-o", path, "--size", "24x24", "--spp", spp, "-q")
        assert done.returncode == 0, done.stderr
    result = gfield.compare(first, second)
    done = run_cli("compare", first, second, "--json")
    expected = json.loads(done.stdout)
    for key in ["pixels", "psnr_db", "ssim", "mse", "max_abs_error", "mean_abs_error", "scale"]:
        assert result[key] == expected[key], key
    assert result["scale"] == "display (sRGB 8-bit)"
    linear = gfield.compare(first, second, linear=True)
    assert linear["scale"] == "linear light" and linear["psnr_db"] != result["psnr_db"]


def test_compare_of_pngs_is_on_their_stored_values(tmp_path):
    """PSNR as ImageMagick and scikit-image compute it for PNGs: on the stored 8-bit values."""
    import matplotlib.image

    first, second = tmp_path / "a.png", tmp_path / "b.png"
    for path, spp in [(first, 1), (second, 4)]:
        done = run_cli("render", SPHERES, "-o", path, "--size", "32x24", "--spp", spp, "-q")
        assert done.returncode == 0, done.stderr
    stored = [matplotlib.image.imread(str(p))[..., :3].astype(np.float64) for p in (first, second)]
    mse = np.mean((stored[0] - stored[1]) ** 2)
    assert mse > 0.0
    result = gfield.compare(first, second)
    assert result["psnr_db"] == pytest.approx(10.0 * np.log10(1.0 / mse), abs=1e-3)
    missing = tmp_path / "missing.png"
    with pytest.raises(gfield.Error) as error:
        gfield.compare(first, missing)
    assert str(error.value) == cli_error("compare", first, missing)


def test_load_scene_reads_the_file():
    for name in ["two-mirror-spheres.json", "mirror-torus-instances.json", "textured-mirror.json"]:
        path = DATA_DIR / "scenes" / name
        scene = gfield.load_scene(path)
        with open(path) as file:
            text = json.load(file)
        assert scene["purpose"] == text["purpose"]
        assert scene["camera"]["position"] == pytest.approx(text["camera"]["position"])
        assert scene["camera"]["fov_degrees"] == pytest.approx(text["camera"].get("fov", 45))
        assert [o["name"] for o in scene["objects"]] == [o["name"] for o in text["objects"]]
        for obj, given in zip(scene["objects"], text["objects"]):
            assert obj["shape"]["type"] == given["shape"]
            assert obj["material"]["type"] == given["material"]["type"]
        meshes = {o["shape"]["mesh"] for o in scene["objects"] if o["shape"]["type"] == "mesh"}
        assert meshes == set(range(len(scene["meshes"])))
    spheres = gfield.load_scene(SPHERES)
    assert (spheres["width"], spheres["height"]) == (512, 512)
    assert spheres["environment"]["type"] == "studio"
    assert spheres["lights"][0]["type"] == "directional"
