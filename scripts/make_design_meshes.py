#!/usr/bin/env python3
# Copyright (c) 2026 The CGAL Surface Design authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes the generated meshes of data/ (standard library only, deterministic):

- egg_1k.off: an icosphere (icosahedron, 4-1 subdivided 3 times: 642 vertices, 1280 faces)
  stretched along z by 1.35, its sections widened by (1 + 0.18 z): an egg, blunt end up.
- pebble_1k.off: the same icosphere as an ellipsoid of half-axes 1.2, 0.8, 0.5 twisted about
  its long (x) axis by 0.9 rad per unit length: a twisted pebble.
- pebble_320.off: the same pebble from the icosphere one level coarser (162 vertices, 320 faces),
  the lighter input of the developability example under the sanitizers.
- torus_1k.off, noisy_sheet.off: a noisy torus and a noisy half cylinder (below).
- saddle_l.off: an L-shaped saddle (corners for the field-aligned quads).
- holed_plate.off, noisy_pipe.off: a bent plate with two holes and an open tube (several
  boundary loops for the field-aligned quads).
- creased_slab.off: a box with a rectangular hole through it (genus 1, creases of 90 degrees:
  fields that follow creases).

Usage: python3 scripts/make_design_meshes.py [OUTPUT_FOLDER]   (default: data/)
"""
import math
import os
import random
import sys


def icosphere(levels):
    g = (1.0 + math.sqrt(5.0)) / 2.0
    points = [(-1, g, 0), (1, g, 0), (-1, -g, 0), (1, -g, 0), (0, -1, g), (0, 1, g),
              (0, -1, -g), (0, 1, -g), (g, 0, -1), (g, 0, 1), (-g, 0, -1), (-g, 0, 1)]
    points = [tuple(c / math.sqrt(sum(x * x for x in p)) for c in p) for p in points]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(levels):
        midpoint = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in midpoint:
                p = [(x + y) / 2.0 for x, y in zip(points[a], points[b])]
                n = math.sqrt(sum(x * x for x in p))
                points.append(tuple(x / n for x in p))
                midpoint[key] = len(points) - 1
            return midpoint[key]

        refined = []
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            refined += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = refined
    return points, faces


def egg(p):
    x, y, z = p
    w = 1.0 + 0.18 * z
    return (w * x, w * y, 1.35 * z)


def pebble(p):
    x, y, z = 1.2 * p[0], 0.8 * p[1], 0.5 * p[2]
    a = 0.9 * x
    return (x, math.cos(a) * y - math.sin(a) * z, math.sin(a) * y + math.cos(a) * z)


def noisy_torus(major, minor, R, r, noise, seed):
    """A torus of major x minor quads split along one diagonal, every vertex moved by up to `noise`
    per coordinate at random (the regular torus is a stationary point of the energies)."""
    rng = random.Random(seed)
    points = []
    for i in range(major):
        u = 2.0 * math.pi * i / major
        for j in range(minor):
            v = 2.0 * math.pi * j / minor
            p = ((R + r * math.cos(v)) * math.cos(u), (R + r * math.cos(v)) * math.sin(u), r * math.sin(v))
            points.append(tuple(c + rng.uniform(-noise, noise) for c in p))
    faces = []
    for i in range(major):
        for j in range(minor):
            a, b = i * minor + j, ((i + 1) % major) * minor + j
            c, d = ((i + 1) % major) * minor + (j + 1) % minor, i * minor + (j + 1) % minor
            faces += [(a, b, c), (a, c, d)]
    return points, faces


def noisy_sheet(around, along, noise, seed):
    """Half a cylinder (radius 1, length 2): a developable sheet, its interior vertices moved off
    it by up to `noise` radially and noise / 2.5 along the axis (the paper's Fig. 7 input)."""
    rng = random.Random(seed)
    points = []
    for j in range(along + 1):
        for i in range(around + 1):
            a = math.pi * i / around
            x, y, z = math.cos(a), math.sin(a), 2.0 * j / along
            if 0 < i < around and 0 < j < along:
                k = 1.0 + rng.uniform(-noise, noise)
                x, y = k * x, k * y
                z += rng.uniform(-noise / 2.5, noise / 2.5)
            points.append((x, y, z))
    faces = []
    for j in range(along):
        for i in range(around):
            a, b = j * (around + 1) + i, j * (around + 1) + i + 1
            c, d = (j + 1) * (around + 1) + i + 1, (j + 1) * (around + 1) + i
            faces += [(a, b, c), (a, c, d)] if (i + j) % 2 == 0 else [(a, b, d), (b, c, d)]
    return points, faces


def grid_cells(n, keep, jitter, seed, lift):
    """The cells (i, j) of the n x n grid of [0, 1]^2 with keep(i, j), two triangles each, the
    vertices inside the kept region moved by up to `jitter` cells in the plane at random, lifted to
    the height lift(x, y)."""
    rng = random.Random(seed)
    cells = [(i, j) for j in range(n) for i in range(n) if keep(i, j)]
    kept = set(cells)
    index, points = {}, []
    for j in range(n + 1):
        for i in range(n + 1):
            around = sum(1 for c in [(i - 1, j - 1), (i, j - 1), (i - 1, j), (i, j)] if c in kept)
            if around == 0:
                continue
            x, y = i / n, j / n
            if around == 4:
                x += rng.uniform(-jitter, jitter) / n
                y += rng.uniform(-jitter, jitter) / n
            index[(i, j)] = len(points)
            points.append((x, y, lift(x, y)))
    faces = []
    for i, j in cells:
        a, b, c, d = index[(i, j)], index[(i + 1, j)], index[(i, j + 1)], index[(i + 1, j + 1)]
        faces += [(a, b, d), (a, d, c)] if (i + j) % 2 == 0 else [(a, b, c), (b, d, c)]
    return points, faces


def saddle_l(n, jitter, seed):
    """The n x n grid of [0, 1]^2 without its cells i, j >= n / 2: an L (five convex corners, one
    concave), the vertices inside it moved by up to `jitter` cells in the plane at random, lifted
    to the saddle z = 0.4 ((x - 0.5)^2 - (y - 0.5)^2) (the field-aligned quads with corners)."""
    return grid_cells(n, lambda i, j: not (i >= n // 2 and j >= n // 2), jitter, seed,
                      lambda x, y: 0.4 * ((x - 0.5) ** 2 - (y - 0.5) ** 2))


def holed_plate(n, jitter, seed):
    """The n x n grid of [0, 1]^2 without two rectangular blocks of cells (three boundary loops:
    four convex corners, eight concave ones), the vertices inside it moved by up to `jitter` cells
    at random, bent onto z = 0.3 (x - 0.5)^2 (field-aligned quads: several loops, no cone)."""
    def hole(i, j):
        return (n * 3 // 16 <= i < n * 6 // 16 and n * 3 // 16 <= j < n * 7 // 16) or \
            (n * 9 // 16 <= i < n * 13 // 16 and n * 10 // 16 <= j < n * 12 // 16)
    return grid_cells(n, lambda i, j: not hole(i, j), jitter, seed, lambda x, y: 0.3 * (x - 0.5) ** 2)


def noisy_pipe(around, along, noise, seed):
    """An open cylinder (radius 0.5, length 2, two boundary loops), its rings staggered by half a
    step and its interior vertices moved off it by up to `noise` radially and along the axis."""
    rng = random.Random(seed)
    points = []
    for j in range(along + 1):
        for i in range(around):
            a = 2.0 * math.pi * (i + 0.5 * (j % 2)) / around
            r, z = 0.5, 2.0 * j / along
            if 0 < j < along:
                r *= 1.0 + rng.uniform(-noise, noise)
                z += rng.uniform(-noise, noise)
            points.append((r * math.cos(a), r * math.sin(a), z))
    faces = []
    for j in range(along):
        for i in range(around):
            a, b = j * around + i, j * around + (i + 1) % around
            c, d = (j + 1) * around + i, (j + 1) * around + (i + 1) % around
            faces += [(a, b, c), (b, d, c)] if j % 2 == 0 else [(a, d, c), (a, b, d)]
    return points, faces


def creased_slab(nx, ny, hole, rows, cell, thickness):
    """A closed box of nx x ny cells (side `cell`) and `thickness`, with the block of cells `hole`
    = (i0, i1, j0, j1) cut through it: the top and bottom grids, and walls of `rows` rows of quads
    along the outer and the inner loop, every quad split in two triangles. Every edge of the box
    is a crease of 90 degrees; the hole's vertical edges are concave (saddle-like corners)."""
    i0, i1, j0, j1 = hole

    def kept(i, j):
        return 0 <= i < nx and 0 <= j < ny and not (i0 <= i < i1 and j0 <= j < j1)

    index, points, faces = {}, [], []

    def vertex(i, j, r):  # r = 0: top, rows: bottom, between: the walls' rows
        key = (i, j, r)
        if key not in index:
            index[key] = len(points)
            points.append((i * cell, j * cell, thickness * (1.0 - r / rows)))
        return index[key]

    def quad(a, b, c, d):
        faces.extend([(a, b, c), (a, c, d)])

    for j in range(ny):
        for i in range(nx):
            if not kept(i, j):
                continue
            quad(vertex(i, j, 0), vertex(i + 1, j, 0), vertex(i + 1, j + 1, 0), vertex(i, j + 1, 0))
            quad(vertex(i, j + 1, rows), vertex(i + 1, j + 1, rows), vertex(i + 1, j, rows), vertex(i, j, rows))
            # the cell's edges on the loops, with the cell on their left (seen from the top)
            for (a, b), out in ((((i, j), (i + 1, j)), (i, j - 1)), (((i + 1, j), (i + 1, j + 1)), (i + 1, j)),
                                (((i + 1, j + 1), (i, j + 1)), (i, j + 1)), (((i, j + 1), (i, j)), (i - 1, j))):
                if kept(*out):
                    continue
                for r in range(rows):
                    quad(vertex(b[0], b[1], r), vertex(a[0], a[1], r), vertex(a[0], a[1], r + 1),
                         vertex(b[0], b[1], r + 1))
    return points, faces


def write_off(path, points, faces, comment):
    with open(path, "w") as f:
        f.write("OFF\n# %s\n%d %d 0\n" % (comment, len(points), len(faces)))
        for p in points:
            f.write("%.9f %.9f %.9f\n" % p)
        for t in faces:
            f.write("3 %d %d %d\n" % t)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "data")
    points, faces = icosphere(3)
    write_off(os.path.join(out, "egg_1k.off"), [egg(p) for p in points], faces,
              "egg: icosphere (3 levels) stretched 1.35 along z, sections widened by 1 + 0.18 z")
    write_off(os.path.join(out, "pebble_1k.off"), [pebble(p) for p in points], faces,
              "twisted pebble: icosphere (3 levels), ellipsoid 1.2 x 0.8 x 0.5 twisted 0.9 rad per unit about x")
    points, faces = icosphere(2)
    write_off(os.path.join(out, "pebble_320.off"), [pebble(p) for p in points], faces,
              "twisted pebble: icosphere (2 levels), ellipsoid 1.2 x 0.8 x 0.5 twisted 0.9 rad per unit about x")
    points, faces = noisy_torus(32, 16, 1.0, 0.45, 0.01, 2026)
    write_off(os.path.join(out, "torus_1k.off"), points, faces,
              "torus 32 x 16, R = 1, r = 0.45, every coordinate moved by up to 0.01 at random (seed 2026)")
    points, faces = noisy_sheet(28, 20, 0.025, 7)
    write_off(os.path.join(out, "noisy_sheet.off"), points, faces,
              "half cylinder 28 x 20, interior vertices moved by up to 0.025 radially at random (seed 7)")
    points, faces = saddle_l(24, 0.2, 11)
    write_off(os.path.join(out, "saddle_l.off"), points, faces,
              "L of the 24 x 24 grid of the unit square, inner vertices moved by up to 0.2 cells (seed 11), "
              "on z = 0.4 ((x - 0.5)^2 - (y - 0.5)^2)")
    points, faces = holed_plate(32, 0.2, 13)
    write_off(os.path.join(out, "holed_plate.off"), points, faces,
              "32 x 32 grid of the unit square without two blocks of cells, inner vertices moved by up to 0.2 "
              "cells (seed 13), on z = 0.3 (x - 0.5)^2")
    points, faces = noisy_pipe(40, 24, 0.02, 17)
    write_off(os.path.join(out, "noisy_pipe.off"), points, faces,
              "open cylinder 40 x 24 (radius 0.5, length 2), staggered rings, interior vertices moved by up to "
              "0.02 (seed 17)")
    points, faces = creased_slab(24, 16, (9, 15, 6, 10), 3, 1.0 / 16, 3.0 / 16)
    write_off(os.path.join(out, "creased_slab.off"), points, faces,
              "box of 24 x 16 cells of side 1/16 and thickness 3/16, the block of cells [9, 15) x [6, 10) cut "
              "through it; walls of 3 rows")


if __name__ == "__main__":
    main()
