#!/usr/bin/env python3
"""Writes the bundled textured mesh: data/meshes/spot-painted.obj (spot.obj with a material),
spot-painted.mtl (Kd 1, map_Kd spot-painted.png) and spot-painted.png, a 1024 x 1024 texture
painted in spot's own texture coordinates: every texel inside a triangle of spot's uv layout gets
the colour of its point on the surface, a cream coat with dark patches (soft-edged blobs placed
by a fixed seed), a pink muzzle and darker hooves; texels outside every triangle take the colour
of the nearest painted texel, so bilinear lookups at chart borders stay on the coat. Deterministic
(no dependencies beyond Python 3). Usage: python3 scripts/paint_spot_texture.py [MESH_DIR]"""
import math
import os
import random
import struct
import sys
import zlib

SIZE = 1024
COAT = (0.86, 0.82, 0.74)     # linear RGB
PATCH = (0.035, 0.028, 0.024)
MUZZLE = (0.80, 0.42, 0.42)
HOOF = (0.10, 0.08, 0.07)


def read_obj(path):
    positions, uvs, faces = [], [], []
    with open(path) as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] == "v":
                positions.append(tuple(float(x) for x in w[1:4]))
            elif w[0] == "vt":
                uvs.append(tuple(float(x) for x in w[1:3]))
            elif w[0] == "f":
                corners = [tuple(int(i) - 1 for i in c.split("/")[:2]) for c in w[1:]]
                for k in range(1, len(corners) - 1):
                    faces.append((corners[0], corners[k], corners[k + 1]))
    return positions, uvs, faces


def smoothstep(a, b, x):
    t = min(1.0, max(0.0, (x - a) / (b - a)))
    return t * t * (3.0 - 2.0 * t)


def blobs():
    rng = random.Random(17)
    out = []
    for _ in range(140):
        centre = (rng.uniform(-0.5, 0.5), rng.uniform(-0.4, 0.9), rng.uniform(-0.7, 0.8))
        out.append((centre, rng.uniform(0.07, 0.13)))
    return out


def paint(p, patches):
    x, y, z = p
    field = sum(math.exp(-((x - c[0]) ** 2 + (y - c[1]) ** 2 + (z - c[2]) ** 2) / (r * r))
                for c, r in patches)
    amount = smoothstep(0.42, 0.62, field)
    color = [COAT[k] + (PATCH[k] - COAT[k]) * amount for k in range(3)]
    muzzle = smoothstep(0.94, 1.0, z) * smoothstep(0.45, 0.25, y)  # the snout's front
    hoof = smoothstep(-0.64, -0.69, y)
    for k in range(3):
        color[k] += (MUZZLE[k] - color[k]) * muzzle
        color[k] += (HOOF[k] - color[k]) * hoof
    return color


def rasterize(positions, uvs, faces, patches):
    """Texel colours (row 0 at the top, v = 1) and which texels a triangle painted."""
    image = [None] * (SIZE * SIZE)
    for face in faces:
        q = [(uvs[t][0] * SIZE - 0.5, (1.0 - uvs[t][1]) * SIZE - 0.5) for _, t in face]
        p = [positions[v] for v, _ in face]
        area = (q[1][0] - q[0][0]) * (q[2][1] - q[0][1]) - (q[1][1] - q[0][1]) * (q[2][0] - q[0][0])
        if area == 0.0:
            continue
        x0 = max(0, math.ceil(min(a[0] for a in q)))
        x1 = min(SIZE - 1, math.floor(max(a[0] for a in q)))
        y0 = max(0, math.ceil(min(a[1] for a in q)))
        y1 = min(SIZE - 1, math.floor(max(a[1] for a in q)))
        for y in range(y0, y1 + 1):
            for x in range(x0, x1 + 1):
                w = []
                for k in range(3):
                    a, b = q[(k + 1) % 3], q[(k + 2) % 3]
                    w.append(((a[0] - x) * (b[1] - y) - (a[1] - y) * (b[0] - x)) / area)
                if min(w) < -1e-9:
                    continue
                point = tuple(sum(w[k] * p[k][c] for k in range(3)) for c in range(3))
                image[y * SIZE + x] = paint(point, patches)
    return image


def dilate(image):
    """Unpainted texels take the colour of the nearest painted one (breadth-first)."""
    frontier = [i for i, c in enumerate(image) if c is not None]
    while frontier:
        following = []
        for i in frontier:
            x, y = i % SIZE, i // SIZE
            for nx, ny in ((x - 1, y), (x + 1, y), (x, y - 1), (x, y + 1)):
                if 0 <= nx < SIZE and 0 <= ny < SIZE and image[ny * SIZE + nx] is None:
                    image[ny * SIZE + nx] = image[i]
                    following.append(ny * SIZE + nx)
        frontier = following
    return image


def srgb(v):
    v = min(1.0, max(0.0, v))
    s = v * 12.92 if v <= 0.0031308 else 1.055 * v ** (1.0 / 2.4) - 0.055
    return int(round(s * 255.0))


def write_png(path, image):
    rows = b"".join(b"\x00" + bytes(srgb(c) for texel in image[y * SIZE:(y + 1) * SIZE]
                                    for c in texel) for y in range(SIZE))

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))
    header = struct.pack(">IIBBBBB", SIZE, SIZE, 8, 2, 0, 0, 0)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
                chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else "data/meshes"
    positions, uvs, faces = read_obj(os.path.join(folder, "spot.obj"))
    write_png(os.path.join(folder, "spot-painted.png"),
              dilate(rasterize(positions, uvs, faces, blobs())))
    with open(os.path.join(folder, "spot-painted.mtl"), "w") as f:
        f.write("# spot's painted coat (scripts/paint_spot_texture.py)\n"
                "newmtl painted\nKd 1 1 1\nmap_Kd spot-painted.png\n")
    with open(os.path.join(folder, "spot.obj")) as src:
        body = src.read()
    with open(os.path.join(folder, "spot-painted.obj"), "w") as f:
        f.write("# spot.obj with the texture of scripts/paint_spot_texture.py\n"
                "mtllib spot-painted.mtl\nusemtl painted\n" + body)


if __name__ == "__main__":
    main()
