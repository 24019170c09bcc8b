"""examples/python/field_error.py (docs/python.md's worked example) runs with matplotlib's
non-interactive backend, on a small asset of spot (128^2 image, N = 8; the docs run it on the
default one), and reports what the lookup modes are: refined lookups agree with Embree's exact
hits far better than the nearest sample's, and the histogram is written."""

import os
import re
import subprocess
import sys

from conftest import SOURCE_DIR


def test_field_error_example(tmp_path):
    done = subprocess.run(
        [sys.executable, SOURCE_DIR / "examples" / "python" / "field_error.py", "--out", tmp_path,
         "--size", "128", "--samples", "8", "--rays", "20000"],
        capture_output=True, text=True, check=False, env={**os.environ, "MPLBACKEND": "Agg"},
    )
    assert done.returncode == 0, done.stderr
    figures = {
        mode: (float(agreement), float(median))
        for mode, agreement, median in re.findall(
            r"^(\w+) +20000 rays: hit/miss agreement ([0-9.]+)%, position error median ([0-9.]+)%",
            done.stdout, re.MULTILINE)
    }
    assert set(figures) == {"nearest", "linear", "refined"}, done.stdout
    # this small asset: refined 98.95% and 0.014% of the diagonal, nearest 93.6% and 2.2%
    assert figures["refined"][0] >= 98.5 and figures["refined"][1] <= 0.05, figures
    assert figures["refined"][0] > figures["linear"][0] > figures["nearest"][0], figures
    assert figures["refined"][1] < figures["linear"][1] < figures["nearest"][1], figures
    png = tmp_path / "field-error.png"
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and png.stat().st_size > 10000
