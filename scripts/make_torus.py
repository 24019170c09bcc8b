#!/usr/bin/env python3
"""Writes data/meshes/torus.obj: a closed genus-1 torus about the Y axis (major radius 1, minor
radius 0.4, 96 x 48 quads split into triangles, outward winding), the mirror torus of the
example scenes. Usage: python3 scripts/make_torus.py [OUT.obj]"""
import math
import sys

MAJOR, MINOR, NU, NV = 1.0, 0.4, 96, 48


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "data/meshes/torus.obj"
    lines = ["# torus: major radius 1, minor radius 0.4, axis Y (scripts/make_torus.py)"]
    for i in range(NU):
        u = 2.0 * math.pi * i / NU
        for j in range(NV):
            v = 2.0 * math.pi * j / NV
            r = MAJOR + MINOR * math.cos(v)
            lines.append("v %.6f %.6f %.6f" % (r * math.cos(u), MINOR * math.sin(v), r * math.sin(u)))
    for i in range(NU):
        for j in range(NV):
            a = i * NV + j + 1
            b = ((i + 1) % NU) * NV + j + 1
            c = ((i + 1) % NU) * NV + (j + 1) % NV + 1
            d = i * NV + (j + 1) % NV + 1
            lines.append("f %d %d %d" % (a, d, c))
            lines.append("f %d %d %d" % (a, c, b))
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
