"""Bad input through Python: every fuzz regression (tests/fuzz/regressions) raises gfield.Error
with the one-line message the CLI prints for it, never a crash; paths of any bytes."""

import json
import os

import numpy as np
import pytest
from conftest import DATA_DIR, FUZZ_DIR, cli_error, run_cli

import gfield

REGRESSIONS = FUZZ_DIR / "regressions"


def files(*folders):
    return sorted(p for folder in folders for p in (REGRESSIONS / folder).iterdir())


MESHES = files("mesh_obj", "mesh_ply", "mesh_off", "mesh_stl", "mesh_gltf", "mesh_glb")


@pytest.mark.parametrize("path", MESHES, ids=lambda p: p.name)
def test_damaged_meshes_raise_the_cli_message(path):
    expected = cli_error("info", path)
    for read in (gfield.load_mesh, gfield.info):
        with pytest.raises(gfield.Error) as error:
            read(path)
        assert str(error.value) == expected


@pytest.mark.parametrize("path", files("gimage_obj"), ids=lambda p: p.name)
def test_damaged_parameterised_meshes_read_as_meshes_as_the_cli_reads_them(path):
    """These are damaged NAME.gimage.obj files; read as meshes, each fails with the CLI's
    message or loads as `gfield info` loads it (indices within the vertices)."""
    done = run_cli("info", path, "--json")
    if done.returncode == 0:
        mesh = gfield.load_mesh(path)
        assert len(mesh.faces) == int(json.loads(done.stdout)["faces"])
        assert mesh.faces.min() >= 0 and mesh.faces.max() < len(mesh.vertices)
    else:
        with pytest.raises(gfield.Error) as error:
            gfield.load_mesh(path)
        assert str(error.value) == cli_error("info", path)


@pytest.mark.parametrize("path", files("scene"), ids=lambda p: p.name)
def test_damaged_scenes_raise_the_cli_message(path, tmp_path):
    expected = cli_error("render", path, "-o", tmp_path / "x.png", "--size", "8x8", "--spp", 1)
    with pytest.raises(gfield.Error) as error:
        gfield.render(path, (8, 8), 1)
    assert str(error.value) == expected
    try:
        gfield.load_scene(path)  # some are refused only by the tracer (their reach)
    except gfield.Error as refused:
        assert str(refused) == expected


@pytest.mark.parametrize("path", files("gimage"), ids=lambda p: p.name)
def test_damaged_geometry_images_raise(path):
    with pytest.raises(gfield.Error) as error:
        gfield.GeometryImage.load(path)
    assert str(error.value).startswith(f"{path}: ") and "\n" not in str(error.value)


@pytest.mark.parametrize("path", files("gfield"), ids=lambda p: p.name)
def test_damaged_geometry_fields_raise(path):
    with pytest.raises(gfield.Error) as error:
        gfield.GeometryField.load(path)
    assert str(error.value).startswith(f"{path}: ") and "\n" not in str(error.value)


def test_missing_files_and_folders(tmp_path):
    missing = tmp_path / "missing.obj"
    with pytest.raises(gfield.Error) as error:
        gfield.load_mesh(missing)
    assert str(error.value) == cli_error("info", missing)
    with pytest.raises(gfield.Error) as error:
        gfield.info(tmp_path)
    assert str(error.value) == cli_error("info", tmp_path)
    with pytest.raises(gfield.Error, match="missing.gimage.exr"):
        gfield.GeometryImage.load(tmp_path / "missing.gimage.exr")
    with pytest.raises(gfield.Error, match="missing.json"):
        gfield.load_scene(tmp_path / "missing.json")


def test_file_names_of_any_bytes(tmp_path):
    """A name that is not UTF-8 (str with surrogate escapes, or bytes) reaches the file and comes
    back in the message as \\xNN, as the CLI prints it."""
    name = os.fsencode(tmp_path) + b"/bad-\xff.obj"
    with open(name, "w") as file:
        file.write("v 0 0 0\nf 1 2 3\n")
    for path in (os.fsdecode(name), name):
        with pytest.raises(gfield.Error) as error:
            gfield.load_mesh(path)
        assert str(error.value) == cli_error("info", os.fsdecode(name))
        assert "bad-\\xFF.obj" in str(error.value)
    with open(name, "w") as file:
        file.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    assert gfield.info(name)["file"].endswith("bad-\\xFF.obj")


def test_warnings_are_gfield_warnings(tmp_path):
    """A missing texture: mid-grey and a warning, as `gfield info` warns."""
    mesh = tmp_path / "m.obj"
    (tmp_path / "m.mtl").write_text("newmtl a\nKd 1 1 1\nmap_Kd missing.png\n")
    mesh.write_text("mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl a\nf 1/1 2/1 3/1\n")
    expected = run_cli("info", mesh).stderr.strip()
    assert expected.startswith("gfield: warning: ")
    with pytest.warns(gfield.GfieldWarning) as record:
        loaded = gfield.load_mesh(mesh)
    assert [str(w.message) for w in record] == [expected[len("gfield: warning: ") :]]
    assert loaded.warnings == [str(record[0].message)]
    assert loaded.uvs.shape == (1, 3, 2) and loaded.colors is None


def test_meshes_read_as_the_cli_reads_them():
    for name in ["spot.obj", "suzanne.obj", "teapot.obj"]:
        path = DATA_DIR / "meshes" / name
        mesh = gfield.load_mesh(path)
        report = gfield.info(path)
        assert report == json.loads(run_cli("info", path, "--json").stdout)
        assert mesh.vertices.shape == (report["vertices"], 3) and mesh.vertices.dtype == np.float64
        assert mesh.faces.shape == (report["faces"], 3) and mesh.faces.dtype == np.int32
        assert not mesh.vertices.flags.writeable


def test_mesh_parts_and_outside_paths(tmp_path):
    """mesh= is --mesh (one mesh of a glTF file); allow_outside_paths= is --allow-outside-paths."""
    glb = DATA_DIR / "scenes" / "textured-mirror.glb"
    whole, part = gfield.load_mesh(glb), gfield.load_mesh(glb, mesh="#1")
    assert len(part.faces) < len(whole.faces)
    cli_report = json.loads(run_cli("info", glb, "--mesh", "#1", "--json").stdout)
    assert gfield.info(glb, mesh="#1") == cli_report
    (tmp_path / "sub").mkdir()
    (tmp_path / "m.mtl").write_text("newmtl a\nKd 1 0 0\n")
    mesh = tmp_path / "sub" / "m.obj"
    mesh.write_text("mtllib ../m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n")
    with pytest.raises(gfield.Error) as error:
        gfield.load_mesh(mesh)
    assert str(error.value) == cli_error("info", mesh)
    assert gfield.info(mesh, allow_outside_paths=True)["appearance"]["materials"] == 1
