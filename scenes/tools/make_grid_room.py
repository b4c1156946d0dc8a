#!/usr/bin/env python3
"""Writes the form-factor benchmark room: a closed 556 x 548.8 x 559.2 mm box (the Cornell box's size, closed by a
front wall) whose six walls are each split into N x N separate quads, with the two Cornell blocks standing on the
floor as closed solids (top, four sides and a bottom). Every quad is its own polygon, so `--no-subdivide` gives one
element per quad: 6 N^2 wall elements (N = 20: 2,400; N = 40: 9,600) plus 12 block faces.

Usage: python3 scenes/tools/make_grid_room.py N [output.json]
Default output: scenes/grid-room-N.json. The ceiling quads whose centres lie inside the Cornell light's rectangle
(x 213..343, z 227..332 mm) emit, so that the room can be solved too; form factors need no light.
Only the Python standard library is used.
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_cornell_box import facing  # noqa: E402  (the same orientation rule as the Cornell box files)

SIZE = (556.0, 548.8, 559.2)  # x (width), y (height), z (depth), mm
LIGHT = (213.0, 343.0, 227.0, 332.0)  # x0, x1, z0, z1 on the ceiling
# The published block vertices (tests/data/refdata/cornell_box.json): top, then the four sides.
SHORT_TOP = [[130.0, 165.0, 65.0], [82.0, 165.0, 225.0], [240.0, 165.0, 272.0], [290.0, 165.0, 114.0]]
TALL_TOP = [[423.0, 330.0, 247.0], [265.0, 330.0, 296.0], [314.0, 330.0, 456.0], [472.0, 330.0, 406.0]]


def wall_quads(axis, at, inward, n):
    """N x N quads of the wall where coordinate `axis` equals `at`, facing `inward` (+1 or -1 along axis)."""
    u, v = [k for k in range(3) if k != axis]
    quads = []
    for i in range(n):
        for j in range(n):
            corners = []
            for du, dv in ((0, 0), (1, 0), (1, 1), (0, 1)):
                p = [0.0, 0.0, 0.0]
                p[axis] = at
                p[u] = round(SIZE[u] * (i + du) / n, 9)
                p[v] = round(SIZE[v] * (j + dv) / n, 9)
                corners.append(p)
            direction = [0.0, 0.0, 0.0]
            direction[axis] = inward
            quads.append(facing(corners, direction))
    return quads


def block(top):
    """Top, four sides and bottom of a block standing on the floor, each facing outwards."""
    middle = [sum(p[k] for p in top) / 4 for k in range(3)]
    middle[1] /= 2
    faces = [facing([list(p) for p in top], [0, 1, 0])]
    for a, b in zip(top, top[1:] + top[:1]):
        side = [[a[0], 0.0, a[2]], [b[0], 0.0, b[2]], list(b), list(a)]
        centre = [sum(p[k] for p in side) / 4 for k in range(3)]
        faces.append(facing(side, [c - m for c, m in zip(centre, middle)]))
    faces.append(facing([[p[0], 0.0, p[2]] for p in top], [0, -1, 0]))
    return faces


def build(n):
    walls = {
        "floor": (1, 0.0, 1, "white"),
        "ceiling": (1, SIZE[1], -1, "white"),
        "back_wall": (2, SIZE[2], -1, "white"),
        "front_wall": (2, 0.0, 1, "white"),
        "left_wall": (0, SIZE[0], -1, "red"),
        "right_wall": (0, 0.0, 1, "green"),
    }
    surfaces = []
    for name, (axis, at, inward, material) in walls.items():
        quads = wall_quads(axis, at, inward, n)
        if name == "ceiling":
            lit = [q for q in quads if LIGHT[0] < sum(p[0] for p in q) / 4 < LIGHT[1] and
                   LIGHT[2] < sum(p[2] for p in q) / 4 < LIGHT[3]]
            quads = [q for q in quads if q not in lit]
            if lit:
                surfaces.append({"name": "light", "material": "light", "polygons": lit})
        surfaces.append({"name": name, "material": material, "polygons": quads})
    surfaces.append({"name": "short_block", "material": "white", "polygons": block(SHORT_TOP)})
    surfaces.append({"name": "tall_block", "material": "white", "polygons": block(TALL_TOP)})
    return {
        "name": f"Grid room {n} x {n} per wall",
        "description": f"Closed Cornell-sized room, each wall split into {n} x {n} separate quads "
                       f"({6 * n * n} wall elements), with the two blocks as closed solids; made by "
                       "scenes/tools/make_grid_room.py for the form-factor benchmarks",
        "unit": "mm",
        "materials": [
            {"name": "white", "reflectance": [0.7378, 0.7361, 0.7371]},
            {"name": "red", "reflectance": [0.4718, 0.0468, 0.0489]},
            {"name": "green", "reflectance": [0.0877, 0.3986, 0.0843]},
            {"name": "light", "reflectance": [0.78, 0.78, 0.78], "emission": [142.3061, 94.9644, 25.307]},
        ],
        "surfaces": surfaces,
    }


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    n = int(sys.argv[1])
    out = sys.argv[2] if len(sys.argv) > 2 else f"scenes/grid-room-{n}.json"
    with open(out, "w") as f:
        json.dump(build(n), f, indent=None, separators=(",", ":"))
        f.write("\n")
    print(f"wrote {out}: {6 * n * n} wall quads and 12 block faces")


if __name__ == "__main__":
    main()
