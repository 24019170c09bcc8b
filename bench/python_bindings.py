#!/usr/bin/env python3
"""The Python module against the C++ it wraps, measured in one run (docs/python.md, "Benchmark"):

- GeometryField.lookup of random box rays (1,000,000; numpy arrays in, numpy arrays out) against
  the C++ CPU lookup of the same rays in a C++ program (gfield_lookup_rays: lookup_first_hit in a
  TBB parallel_for over every core, as a program linking gfield::core calls it), per mode, on
  spot's default asset. Target: at least 0.90 of the C++ throughput (ratio = C++ time / Python
  time).
- gfield.build of spot (default options) against `gfield build` of it. Target: within 5% of the
  CLI's time (ratio = Python time / CLI time).

The two sides alternate, so that the load of whatever else runs on the machine reaches both
alike; the best of the runs is compared (for builds, the median printed beside it; for lookups,
the CPU seconds of all threads beside the wall-clock time, which on a loaded machine counts the
waits for a core too).
Usage: PYTHONPATH=build/python /usr/bin/python3 bench/python_bindings.py [--build build]
       [--rays 1000000] [--reps 5] [--builds 3]   (--builds 0: the lookups alone)
"""

import argparse
import pathlib
import re
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import gfield

CHECKOUT = pathlib.Path(__file__).resolve().parents[1]
SPOT = CHECKOUT / "data" / "meshes" / "spot.obj"


def box_rays(box, count, rng):
    """Rays between random points on two different faces of the box (`gfield verify`'s)."""
    faces = rng.integers(0, 6, (2, count))
    faces[1] = (faces[0] + rng.integers(1, 6, count)) % 6
    points = []
    for face in faces:
        unit = rng.random((count, 3))
        unit[np.arange(count), face // 2] = face % 2
        points.append(box[0] + unit * (box[1] - box[0]))
    return points[0].astype(np.float32), (points[1] - points[0]).astype(np.float32)


def cpp_lookup_seconds(tool, asset, rays_file, mode, reps):
    """The best of `reps` runs of the C++ lookup as gfield_lookup_rays prints it: (wall seconds,
    CPU seconds of all its threads)."""
    done = subprocess.run([tool, f"{asset}.gfield.exr", f"{asset}.gimage.exr", rays_file, mode,
                           "-", str(reps)], capture_output=True, text=True, check=True)
    found = re.search(r"best of \d+: ([0-9.]+) s, .* cpu ([0-9.]+) s", done.stdout)
    return float(found.group(1)), float(found.group(2))


def python_lookup_seconds(field, origins, directions, mode, reps):
    """The best of `reps` calls of field.lookup: (wall seconds, CPU seconds of the process)."""
    best, best_cpu = float("inf"), float("inf")
    for _ in range(reps):
        start, cpu_start = time.perf_counter(), time.process_time()
        field.lookup(origins, directions, mode=mode)
        best = min(best, time.perf_counter() - start)
        best_cpu = min(best_cpu, time.process_time() - cpu_start)
    return best, best_cpu


def bench_lookup(args, work):
    asset = work / "lookup" / "spot"
    gfield.build(SPOT, asset, verify_rays=0)
    field = gfield.GeometryField.load(f"{asset}.gfield.exr")
    origins, directions = box_rays(field.box.astype(np.float64), args.rays,
                                   np.random.default_rng(1))
    rays_file = work / "rays.f32"
    np.concatenate([origins, directions, np.zeros((args.rays, 1), np.float32)], axis=1).tofile(
        rays_file)
    tool = args.build / "python" / "gfield_lookup_rays"
    print(f"lookup of {args.rays} box rays on spot's default asset (N = "
          f"{field.samples_per_side}, K = {field.layers}), best of 2 x {args.reps} runs each")
    print(f"{'mode':8} {'C++ Mrays/s':>12} {'Python Mrays/s':>15} {'ratio':>7} "
          f"{'C++ cpu s':>10} {'Python cpu s':>13} {'cpu ratio':>10}")
    for mode in ["nearest", "linear", "refined"]:
        cpp, python = [], []
        for _ in range(2):  # alternating
            cpp.append(cpp_lookup_seconds(tool, asset, rays_file, mode, args.reps))
            python.append(python_lookup_seconds(field, origins, directions, mode, args.reps))
        wall = [min(s[0] for s in side) for side in (cpp, python)]
        cpu = [min(s[1] for s in side) for side in (cpp, python)]
        print(f"{mode:8} {args.rays / wall[0] / 1e6:12.2f} {args.rays / wall[1] / 1e6:15.2f} "
              f"{wall[0] / wall[1]:7.3f} {cpu[0]:10.3f} {cpu[1]:13.3f} {cpu[0] / cpu[1]:10.3f}")
    print("ratio: C++ seconds / Python seconds (target for the default mode, refined: >= 0.90);")
    print("cpu: CPU seconds of all threads (what the lookups cost, less their waits for a core)")


def bench_build(args, work):
    cli = args.build / "preprocess" / "gfield"
    times = {"cli": [], "python": []}
    for run in range(args.builds):
        start = time.perf_counter()
        subprocess.run([cli, "build", SPOT, "-o", work / "cli" / "spot"], check=True,
                       capture_output=True)
        times["cli"].append(time.perf_counter() - start)
        start = time.perf_counter()
        gfield.build(SPOT, work / "python" / "spot")
        times["python"].append(time.perf_counter() - start)
        print(f"build {run + 1}: gfield build {times['cli'][-1]:.2f} s, gfield.build "
              f"{times['python'][-1]:.2f} s")
    best = {k: min(v) for k, v in times.items()}
    median = {k: statistics.median(v) for k, v in times.items()}
    print(f"build of spot (default options), {args.builds} alternating runs: best CLI "
          f"{best['cli']:.2f} s, Python {best['python']:.2f} s, ratio "
          f"{best['python'] / best['cli']:.3f}; median {median['cli']:.2f} s, "
          f"{median['python']:.2f} s, ratio {median['python'] / median['cli']:.3f}")
    print("ratio: Python seconds / CLI seconds (target: <= 1.05)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", type=pathlib.Path, default=CHECKOUT / "build")
    parser.add_argument("--rays", type=int, default=1000000)
    parser.add_argument("--reps", type=int, default=5)
    parser.add_argument("--builds", type=int, default=3)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="gfield-bench-python.") as folder:
        work = pathlib.Path(folder)
        bench_lookup(args, work)
        if args.builds > 0:
            bench_build(args, work)
    return 0


if __name__ == "__main__":
    sys.exit(main())
