#!/usr/bin/env python3
"""How far are a geometry field's lookups from the exact hits?

Builds the asset of a mesh (spot by default) with gfield.build, looks 100,000 random rays through
its box up in the field in each lookup mode (GeometryField.lookup), casts the same rays exactly
against the mesh with Embree (Mesh.intersect, the ground truth of `gfield verify` and of the
reference tracer), prints the hit/miss agreement and the position error of each mode, and plots
the error histograms with matplotlib into OUT/field-error.png (docs/python.md).

Usage: PYTHONPATH=build/python /usr/bin/python3 examples/python/field_error.py
           [--mesh data/meshes/spot.obj] [--out out/python] [--rays 100000] [--seed 1]
           [--size auto] [--samples 24]   (gfield build's --size and --samples)
"""

import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")  # draws into the PNG file: no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import gfield  # noqa: E402

CHECKOUT = pathlib.Path(__file__).resolve().parents[2]


def box_face_points(box, faces, rng):
    """A random point on each given face of the box (faces -X, +X, -Y, +Y, -Z, +Z = 0..5)."""
    unit = rng.random((len(faces), 3))
    unit[np.arange(len(faces)), faces // 2] = faces % 2
    return box[0] + unit * (box[1] - box[0])


def box_rays(box, count, rng):
    """Rays from a random point on one face of the box to a random point on another: the box
    rays of `gfield verify`. Origins and directions, (count, 3) each."""
    entry_faces = rng.integers(0, 6, count)
    exit_faces = (entry_faces + rng.integers(1, 6, count)) % 6
    entry = box_face_points(box, entry_faces, rng)
    exit = box_face_points(box, exit_faces, rng)
    return entry, exit - entry


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--mesh", type=pathlib.Path, default=CHECKOUT / "data/meshes/spot.obj")
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("out/python"))
    parser.add_argument("--rays", type=int, default=100000)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--size", default="auto", help="texels per side, or auto")
    parser.add_argument("--samples", type=int, default=24, help="N, samples per box side")
    args = parser.parse_args()

    name = args.out / args.mesh.stem
    report = gfield.build(args.mesh, name, size=args.size, samples=args.samples, verify_rays=0,
                          progress=gfield.print_progress)
    print(f"built {name}: {report['geometry_image']['size']}^2 image, "
          f"N = {report['geometry_field']['samples_per_side']}, "
          f"K = {report['geometry_field']['layers']} in {report['seconds']:.1f} s")

    field = gfield.GeometryField.load(f"{name}.gfield.exr")
    box = field.box.astype(np.float64)
    diagonal = np.linalg.norm(box[1] - box[0])
    origins, directions = box_rays(box, args.rays, np.random.default_rng(args.seed))
    exact = gfield.load_mesh(args.mesh).intersect(origins, directions)

    figure, axes = plt.subplots(figsize=(7, 4))
    bins = np.logspace(-6, 2, 81)
    for mode in ["nearest", "linear", "refined"]:
        found = field.lookup(origins, directions, mode=mode)
        agreement = 100 * np.mean(found["hit"] == exact["hit"])
        both = found["hit"] & exact["hit"]
        error = np.linalg.norm(found["position"][both] - exact["position"][both], axis=1)
        error = 100 * error / diagonal  # percent of the box diagonal
        print(f"{mode:8} {args.rays} rays: hit/miss agreement {agreement:.2f}%, position error "
              f"median {np.median(error):.4f}% p95 {np.percentile(error, 95):.4f}% of the diagonal")
        axes.hist(np.maximum(error, bins[0]), bins=bins, histtype="step", linewidth=1.5,
                  label=f"{mode}: hit/miss {agreement:.2f}%")
    axes.set_xscale("log")
    axes.set_xlabel("position error, % of the box diagonal")
    axes.set_ylabel("rays (both hit)")
    axes.set_title(f"{args.mesh.name}: field lookups vs exact hits, {args.rays} box rays")
    axes.legend(loc="upper left")
    figure.tight_layout()
    png = args.out / "field-error.png"
    figure.savefig(png, dpi=100)
    print(f"wrote {png}")


if __name__ == "__main__":
    main()
