#!/usr/bin/env python3
"""Writes docs/results.md: gfield's measured figures, each section the verbatim output of the
benchmark or test that measures it, with the date, the commit and the machine it ran on.

Usage: scripts/results.py [--list] [SECTION ...]
  Runs the named sections (default: all; --list names them) from the checkout's root with the
  tools of build/ (scripts/build.sh builds them, the demo's out/assets is built when missing) and
  rewrites their part of docs/results.md; the other sections stay as they were, with their own
  dates. A section whose command fails keeps its old text and the script exits 1.

The figures docs/ quote come from here; scripts/check-docs.sh measures the marked ones again.
"""
import datetime
import os
import pathlib
import platform
import re
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
RESULTS = ROOT / "docs" / "results.md"
DEMO = "scripts/demo.sh --no-build > /dev/null"

# id, title, what the figures mean, commands (the last one's output is shown; "!" runs one
# silently first), check-docs markers as (regular expression with one group, tolerance): the
# first figure of the output that the expression matches is measured again in CI.
SECTIONS = [
    ("demo", "The demo picture against the reference tracer",
     "`scripts/demo.sh`: mirror-torus-instances at 512², 8 spp, depth 10, rendered by gfield-view "
     "through the geometry fields and by the Embree reference tracer at the same sample "
     "positions; `gfield compare` of the two PNGs, on their stored values (ImageMagick's scale).",
     ["!" + DEMO, "build/preprocess/gfield compare out/mirror-torus.png "
      "out/mirror-torus-reference.png"],
     [(r"PSNR +([0-9.]+) dB", 0.5), (r"SSIM +([0-9.]+)", 0.002)]),
    ("geometry-image", "Geometry images: build time per stage",
     "`bench_geometry_image`: mesh file to 512² geometry image, the median of 3 runs per stage, "
     "against the time to read the mesh file in the same run.",
     ["build/bench/bench_geometry_image"], []),
    ("geometry-image-error", "Geometry images: reconstruction error",
     "`gfield image` at 512² on spot: the error of the image's surface against the mesh, in % of "
     "the bounding box's diagonal.",
     ["build/preprocess/gfield image data/meshes/spot.obj -o out/spot-512.gimage.exr --size 512"],
     [(r"mesh -> image [^:]*: mean ([0-9.]+)", 0.0002)]),
    ("field-build", "Geometry fields: build time and memory",
     "`bench_field_build 24 3`: per bundled mesh, the field build against the bare Embree cast of "
     "the same rays, and the compact field's GPU bytes against the layered one's.",
     ["build/bench/bench_field_build 24 3"], []),
    ("asset-build", "Whole assets: `gfield build` against its floor",
     "`bench_asset_build`: each build's stages and peak memory against its floor (its "
     "parameterisation plus the bare first-hit cast of the field's rays).",
     ["build/bench/bench_asset_build"], []),
    ("proxy-families", "Large meshes through a proxy, across mesh families",
     "`bench_proxy_families --largest`: flat-faced (midpoint-subdivided), smooth (PN-split) and "
     "bundled meshes built with the defaults, beside the same mesh without a proxy and the "
     "original it was refined from.",
     ["build/bench/bench_proxy_families --largest"], []),
    ("lookup-work", "CPU lookups: work and agreement with exact casts",
     "`bench_lookup_work 20000`: per ray family and mode, texel fetches and Newton steps per ray "
     "beside the hit/miss agreement with Embree's casts of the same rays.",
     ["build/bench/bench_lookup_work 20000"], []),
    ("field-lookup", "CPU lookups against Embree",
     "`bench_field_lookup`: lookups per second per mode against rtcIntersect1 on the same rays, "
     "one thread each.",
     ["build/bench/bench_field_lookup"], []),
    ("reference-tracer", "The reference tracer",
     "`bench_reference_tracer`: every example scene at 512², 8 spp, depth 10, against the raw "
     "first-hit casts of the same camera rays.",
     ["build/bench/bench_reference_tracer"], []),
    ("render-tests", "Runtime pictures against the reference tracer",
     "`RenderTest.ExampleScenesMatchReferenceTracer`: every example scene at 256², depth 4, 4 spp "
     "at the strata centres, PSNR in linear light clamped to [0, 1] per lookup mode.",
     ["build/tests/gfield_runtime_tests --gtest_filter=RenderTest.ExampleScenesMatchReferenceTracer"],
     []),
    ("runtime", "Runtime on this machine's GL: field against BVH",
     "`bench_runtime_field --frames 5 --depths 4 256`: per example scene, ms per frame of the field method "
     "(refined, nearest, linear) and of exact BVH tracing, in the compute and in the fragment "
     "pass, each against the reference tracer's time for the same picture in the same run, with "
     "PSNR, GPU bytes and work per lookup.",
     ["build/bench/bench_runtime_field --frames 5 --depths 4 256"], []),
    ("runtime-complexity", "Runtime cost against the mesh's size",
     "`bench_runtime_complexity`: one mesh at 5.9K to 1.1M faces as glass and as a mirror, field "
     "against BVH against `--intersect auto`.",
     ["build/bench/bench_runtime_complexity"], []),
    ("image-space", "Image-space refraction (Davis & Wyman 2007, Table 1)",
     "`bench_image_space_refraction`: frame times of the image-space methods beside the geometry "
     "field and the reference tracer, with PSNR against it.",
     ["build/bench/bench_image_space_refraction"], []),
    ("glass", "Glass by vertex displacement (Mukai et al. 2013, Tables 1-3)",
     "`bench_glass --quick --vertices 100000,200000 --azimuths 1`: frame time against the "
     "vertices behind the glass and against the resolution, beside the reference tracer (two "
     "timed frames a row after the warm-up ones).",
     ["build/bench/bench_glass --quick --vertices 100000,200000 --azimuths 1"], []),
]


def machine():
    cpu = platform.processor() or platform.machine()
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return f"{os.cpu_count()} hardware threads, {cpu}, {platform.system()} {platform.release()}"


def commit():
    done = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, capture_output=True,
                          text=True)
    dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no"], cwd=ROOT,
                           capture_output=True, text=True).stdout.strip()
    return (done.stdout.strip() or "unknown") + (" with local changes" if dirty else "")


def run_section(section):
    ident, title, about, commands, markers = section
    start = time.time()
    output = ""
    for command in commands:
        quiet = command.startswith("!")
        command = command.lstrip("!")
        done = subprocess.run(command, shell=True, cwd=ROOT, capture_output=True, text=True)
        if done.returncode != 0:
            print(f"results: {ident}: `{command}` failed ({done.returncode}):\n{done.stderr}",
                  file=sys.stderr)
            return None
        if not quiet:
            output = done.stdout
    shown = commands[-1].lstrip("!")
    lines = [f"<!-- results: {ident} -->", f"## {title}", "", about, "",
             f"Measured {datetime.date.today().isoformat()} at {commit()} in "
             f"{time.time() - start:.0f} s on {machine()}.", "", "```", f"$ {shown}",
             output.rstrip(), "```"]
    for pattern, tolerance in markers:
        found = re.search(pattern, output)
        if not found:
            print(f"results: {ident}: no figure matches {pattern!r}", file=sys.stderr)
            return None
        lines.append(f'<!-- check-docs: figure {found.group(1)} ±{tolerance} "{pattern}" '
                     f"{shown} -->")
    return "\n".join(lines) + "\n"


HEADER = """# Measured figures

Written by `scripts/results.py` (do not edit by hand): each section is the verbatim output of the
benchmark or test that measures it, with the date, the commit and the machine. Run
`scripts/results.py SECTION` after a change that moves its figures; the marked figures are
measured again by CI (`scripts/check-docs.sh`). Timings vary with the machine's load; the
benchmarks print each figure beside a reference measured in the same run, and those ratios are
what to compare between machines.
"""


def parse(text):
    """The sections of docs/results.md by id: each starts at its marker line (the outputs they
    quote may hold markdown headings of their own)."""
    sections = {}
    for part in re.split(r"(?m)^(?=<!-- results: )", text):
        found = re.match(r"<!-- results: ([a-z-]+) -->", part)
        if found:
            sections[found.group(1)] = part.rstrip() + "\n"
    return sections


def main(argv):
    ids = [s[0] for s in SECTIONS]
    if "--list" in argv:
        print("\n".join(ids))
        return 0
    unknown = [a for a in argv if a not in ids]
    if unknown:
        print(f"results: unknown section {unknown[0]} (scripts/results.py --list)", file=sys.stderr)
        return 2
    wanted = argv or ids
    sections = parse(RESULTS.read_text(encoding="utf-8")) if RESULTS.exists() else {}
    failed = False
    for section in SECTIONS:
        if section[0] not in wanted:
            continue
        print(f"results: {section[0]} ...", flush=True)
        text = run_section(section)
        if text is None:
            failed = True
            continue
        sections[section[0]] = text
        write(sections, ids)  # each section as it is done: a long run stopped keeps the others
    return 1 if failed else 0


def write(sections, ids):
    body = [sections[i] for i in ids if i in sections]
    temporary = RESULTS.with_suffix(".md.tmp")
    temporary.write_text(HEADER + "\n" + "\n".join(body), encoding="utf-8")
    temporary.replace(RESULTS)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
