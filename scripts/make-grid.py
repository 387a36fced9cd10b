#!/usr/bin/python3
"""Writes OUTDIR/grid.json and OUTDIR/grid.obj: a dense caster for timing the
simplified levels of map option lodTexels (src/core/MeshLevels.cpp).

The caster is a rolling sheet (a height field, smooth vertex normals) of
--triangles triangles (default 10^6) floating over a ground plane, lit by one
directional light with a shadow map; its hills shadow its own valleys and the
ground. The same arguments write the same bytes (no randomness).

    /usr/bin/python3 scripts/make-grid.py OUTDIR [--triangles N]
    build/apps/shadowlab/shadowlab bench OUTDIR/grid.json --warmup 0 --frames 1 \\
        --vary 'lights[0].shadow.map.lodTexels=0,0.5'

Needs numpy (Debian's python3-numpy, scripts/install-deps.sh)."""
import argparse
import json
import math
import os
import sys

import numpy as np

SIZE = 6.0       # metres along the sheet's longer side
HEIGHT = 1.6     # the sheet's mean height over the ground
AMPLITUDE = 0.3  # of its hills, metres


def cells(triangles):
    """Columns and rows of quads (two triangles each) making exactly `triangles`,
    as near square as a divisor allows; else the nearest square grid."""
    if triangles < 2:
        sys.exit("make-grid.py: --triangles must be at least 2")
    quads = triangles // 2
    side = int(math.isqrt(quads))
    if triangles % 2 == 0:
        for rows in range(side, 0, -1):
            if quads % rows == 0 and quads // rows <= 2 * rows:
                return quads // rows, rows
    side = max(1, round(math.sqrt(quads)))
    return side, side


def height(x, z):
    """The sheet's height field and its two slopes (dh/dx, dh/dz), in metres."""
    k1, k2 = 2 * math.pi / 2.4, 2 * math.pi / 1.1
    h = AMPLITUDE * (np.sin(k1 * x) * np.cos(k1 * 0.8 * z) + 0.25 * np.sin(k2 * (x + 0.6 * z)))
    dx = AMPLITUDE * (k1 * np.cos(k1 * x) * np.cos(k1 * 0.8 * z) + 0.25 * k2 * np.cos(k2 * (x + 0.6 * z)))
    dz = AMPLITUDE * (-k1 * 0.8 * np.sin(k1 * x) * np.sin(k1 * 0.8 * z) + 0.25 * k2 * 0.6 * np.cos(k2 * (x + 0.6 * z)))
    return h, dx, dz


def write_obj(path, columns, rows):
    cell = SIZE / max(columns, rows)
    xs = (np.arange(columns + 1) - columns / 2) * cell
    zs = (np.arange(rows + 1) - rows / 2) * cell
    x, z = np.meshgrid(xs, zs)  # row-major: vertex (r, c) is r * (columns + 1) + c
    h, dx, dz = height(x, z)
    positions = np.stack([x, h, z], axis=-1).reshape(-1, 3)
    normals = np.stack([-dx, np.ones_like(h), -dz], axis=-1).reshape(-1, 3)
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    # Two triangles a quad, counter-clockwise seen from +Y; OBJ counts from 1.
    r, c = np.meshgrid(np.arange(rows), np.arange(columns), indexing="ij")
    i = (r * (columns + 1) + c).reshape(-1) + 1
    below = i + columns + 1
    faces = np.stack([i, below, i + 1, i + 1, below, below + 1], axis=-1).reshape(-1, 3)
    with open(path, "w", encoding="ascii", newline="\n") as f:
        f.write(f"# make-grid.py: {columns} x {rows} quads, {2 * columns * rows} triangles\no grid\n")
        np.savetxt(f, positions, fmt="v %.6f %.6f %.6f")
        np.savetxt(f, normals, fmt="vn %.6f %.6f %.6f")
        np.savetxt(f, np.repeat(faces, 2, axis=1), fmt="f %d//%d %d//%d %d//%d")


def scene(triangles):
    return {
        "name": f"grid-{triangles}",
        "camera": {"position": [4.5, 4.2, 6.5], "target": [0, 0.8, 0], "fovY": 45},
        "materials": {
            "ground": {"baseColor": [0.55, 0.55, 0.52]},
            "sheet": {"baseColor": [0.75, 0.68, 0.55], "specular": [0.1, 0.1, 0.1], "shininess": 16},
        },
        "lights": [{"name": "sun", "type": "directional", "direction": [-0.85, -0.3, 0.35],
                    "shadow": {"technique": "map"}}],
        "nodes": [
            {"name": "ground", "shape": {"type": "plane", "size": [20, 20]}, "material": "ground"},
            {"name": "grid", "mesh": "grid.obj", "material": "sheet", "translation": [0, HEIGHT, 0]},
        ],
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("outdir")
    parser.add_argument("--triangles", type=int, default=1_000_000, help="the caster's triangles (default 1000000)")
    args = parser.parse_args()
    columns, rows = cells(args.triangles)
    os.makedirs(args.outdir, exist_ok=True)
    write_obj(os.path.join(args.outdir, "grid.obj"), columns, rows)
    with open(os.path.join(args.outdir, "grid.json"), "w", encoding="ascii", newline="\n") as f:
        json.dump(scene(2 * columns * rows), f, indent=2)
        f.write("\n")
    print(f"{args.outdir}/grid.json: {columns} x {rows} quads, {2 * columns * rows} triangles")


if __name__ == "__main__":
    main()
