"""gfield.build: the report, the same asset as `gfield build`, its options, its progress callback,
and Ctrl-C (from the callback and as SIGINT), which leaves the old asset whole."""

import json
import os
import signal
import threading
import time

import numpy as np
import pytest
from conftest import DATA_DIR, cli_error, run_cli

import gfield

SPOT = DATA_DIR / "meshes" / "spot.obj"
SMALL = {"size": 128, "samples": 8}


def builds_left(out):
    """The folders in OUT.builds besides `current` and the published build it names."""
    folder = out.parent / f"{out.name}.builds"
    current = os.readlink(folder / "current")
    return sorted(p.name for p in folder.iterdir() if p.name not in (".lock", "current", current))


def without_times(value):
    """A report without its timings (keys named seconds, at any depth)."""
    if isinstance(value, dict):
        return {k: without_times(v) for k, v in value.items() if k != "seconds"}
    if isinstance(value, list):
        return [without_times(v) for v in value]
    return value


def test_build_is_the_cli_build_and_returns_its_report(tmp_path):
    report = gfield.build(SPOT, tmp_path / "py" / "spot", verify_rays=2000, **SMALL)
    done = run_cli("build", SPOT, "-o", tmp_path / "cli" / "spot", "--size", 128, "--samples", 8,
                   "--verify-rays", 2000)
    assert done.returncode == 0, done.stderr
    with open(tmp_path / "py" / "spot.report.json") as file:
        assert report == json.load(file)
    with open(tmp_path / "cli" / "spot.report.json") as file:
        cli_report = json.load(file)
    assert report["build_id"] == cli_report["build_id"]
    same_paths = json.dumps(without_times(report["accuracy"])).replace(
        str(tmp_path / "py"), str(tmp_path / "cli"))
    assert same_paths == json.dumps(without_times(cli_report["accuracy"]))
    fields = [gfield.GeometryField.load(tmp_path / k / "spot.gfield.exr") for k in ("py", "cli")]
    assert np.array_equal(fields[0].nearest, fields[1].nearest)
    assert np.array_equal(fields[0].image.positions, fields[1].image.positions)


def test_options_are_the_cli_options(tmp_path):
    report = gfield.build(SPOT, tmp_path / "spot", size=64, samples=6, format=2, layers=2,
                          precision="float", method="square", components="largest",
                          verify_rays=0, threads=1)
    assert report["geometry_image"]["size"] == 64
    assert report["geometry_field"]["samples_per_side"] == 6
    assert report["geometry_field"]["layers"] == 2
    assert report["geometry_field"]["format_version"] == 2
    assert report["geometry_field"]["precision"] == "float"
    assert "accuracy" not in report
    options = report["inputs"]["options"]
    assert options["image"]["method"] == "square" and options["image"]["components"] == "largest"
    field = gfield.GeometryField.load(tmp_path / "spot.gfield.exr")
    assert (field.samples_per_side, field.layers) == (6, 2)


@pytest.mark.parametrize(
    "options, message",
    [
        ({"size": "12a"}, r"size: expected auto or texels per side in \[8, 8192\], got 12a"),
        ({"size": 4}, r"size: expected auto or texels per side in \[8, 8192\], got 4"),
        ({"max_image_error": 0.0}, "max_image_error: expected a positive percentage, got 0.0"),
        ({"layers": 5}, "layers: expected auto or 1 to 4, got 5"),
        ({"format": 4}, "format: expected 3 or 2, got 4"),
        ({"precision": "double"}, "precision: expected one of half, float, got double"),
        ({"method": "lscm"}, "method: expected one of auto, orbifold, square, got lscm"),
        ({"components": "some"}, "components: expected one of all, largest, got some"),
        ({"verify_rays": -1}, "verify_rays: expected 0 or more, got -1"),
        ({"proxy_above": -1}, r"proxy_above: expected 0 \(never\) or more, got -1"),
        ({"threads": -2}, r"threads: expected 0 \(all cores\) to 4096, got -2"),
    ],
)
def test_bad_options_raise_value_error(tmp_path, options, message):
    with pytest.raises(ValueError, match=message):
        gfield.build(SPOT, tmp_path / "spot", **options)
    assert not (tmp_path / "spot.report.json").exists()


def test_bad_input_raises_the_cli_message(tmp_path):
    with pytest.raises(gfield.Error) as error:
        gfield.build(SPOT, tmp_path / "spot", samples=99)
    assert str(error.value) == cli_error("build", SPOT, "-o", tmp_path / "x", "--samples", 99)
    missing = tmp_path / "missing.obj"
    with pytest.raises(gfield.Error) as error:
        gfield.build(missing, tmp_path / "spot")
    assert str(error.value) == cli_error("build", missing, "-o", tmp_path / "x")
    assert not list(tmp_path.glob("spot*"))


def test_progress_reaches_the_callback_on_this_thread(tmp_path):
    calls = []
    caller = threading.get_ident()

    def progress(stage, done):
        assert threading.get_ident() == caller
        calls.append((stage, done))

    gfield.build(SPOT, tmp_path / "spot", verify_rays=1000, progress=progress, **SMALL)
    stages = [stage for stage, _ in calls]
    order = ["mesh", "image", "field", "write", "verify"]
    assert set(stages) <= set(order) and stages == sorted(stages, key=order.index)
    assert stages[-1] == "verify" and calls[-1][1] == 1.0
    for stage in set(stages):
        done = [d for s, d in calls if s == stage]
        assert all(0.0 <= d <= 1.0 for d in done) and done == sorted(done), stage


def test_print_progress_draws_bars(capsys):
    for stage, done in [("image", 0.0), ("image", 1.0), ("field", 0.5), ("write", 0.0)]:
        gfield.print_progress(stage, done)
    err = capsys.readouterr().err
    assert "\rfield   [###############               ]  50%\n" in err
    assert err.count("\n") == 2 and err.endswith("  0%")


@pytest.fixture
def old_asset(tmp_path):
    """An asset built first (N = 8) that an interrupted build (N = 24) must leave whole."""
    out = tmp_path / "spot"
    report = gfield.build(SPOT, out, verify_rays=0, **SMALL)
    return out, report["build_id"]


def check_left_whole(out, build_id, field_seen):
    assert 0.0 < max(field_seen) < 1.0  # stopped during the field's casts
    with open(f"{out}.report.json") as file:
        assert json.load(file)["build_id"] == build_id
    field = gfield.GeometryField.load(f"{out}.gfield.exr")
    assert field.build_id == build_id and field.samples_per_side == 8
    assert builds_left(out) == []


def test_an_exception_in_the_callback_stops_the_build(old_asset):
    out, build_id = old_asset
    field_seen = []

    def progress(stage, done):
        if stage == "field":
            field_seen.append(done)
            if done > 0.05:
                raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        gfield.build(SPOT, out, size=128, samples=24, verify_rays=0, progress=progress)
    check_left_whole(out, build_id, field_seen)


def test_sigint_stops_the_build(old_asset):
    """A Ctrl-C while the build runs: Python's handler raises KeyboardInterrupt in build's wait,
    and the build has stopped and cleaned up within a second of the signal."""
    out, build_id = old_asset
    field_seen = []
    sent = []

    def interrupt():
        sent.append(time.monotonic())
        os.kill(os.getpid(), signal.SIGINT)

    def progress(stage, done):
        if stage == "field":
            if not field_seen:
                threading.Timer(0.2, interrupt).start()
            field_seen.append(done)

    with pytest.raises(KeyboardInterrupt):
        gfield.build(SPOT, out, size=128, samples=24, verify_rays=0, progress=progress)
    assert time.monotonic() - sent[0] < 1.0
    check_left_whole(out, build_id, field_seen)
