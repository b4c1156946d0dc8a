#!/usr/bin/env python3
"""Writes the prism room: a closed 1 m room lit by a 0.2 m square light 1 mm under its ceiling, with a closed
40-sided prism (radius 0.12 m, 0.3 m tall) standing on the floor and a floating 36-sided disc (radius 0.08 m,
0.4 m up) made of two coincident polygons back to back, as OBJ exporters write a two-sided plane. Occluders of
many corners, a body standing on the floor and a two-sided thin surface: the scene exercises what simpler rooms
do not. The geometry is that of `tests/core/occluder_room.h` (litRoom, addPrism, addDisc).

Usage: python3 scenes/tools/make_prism_room.py [output.json]
Default output: scenes/prism-room.json. Only the Python standard library is used.
"""
import json
import math
import os
import sys


def newell(p):
    n = [0.0, 0.0, 0.0]
    for k, a in enumerate(p):
        b = p[(k + 1) % len(p)]
        n[0] += (a[1] - b[1]) * (a[2] + b[2])
        n[1] += (a[2] - b[2]) * (a[0] + b[0])
        n[2] += (a[0] - b[0]) * (a[1] + b[1])
    return n


def facing(polygon, direction):
    """The polygon counter-clockwise seen from the side `direction` points to."""
    n = newell(polygon)
    return polygon if sum(a * b for a, b in zip(n, direction)) > 0 else polygon[::-1]


def r(p):
    return [round(c, 12) + 0.0 for c in p]


def ngon(n, cx, cy, radius, z):
    return [r([cx + radius * math.cos(2 * math.pi * k / n), cy + radius * math.sin(2 * math.pi * k / n), z])
            for k in range(n)]


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "prism-room.json")
    square = lambda axis, at: [[(at if k == axis else (u if k == [i for i in range(3) if i != axis][0] else v))
                                for k in range(3)] for u, v in ((0, 0), (1, 0), (1, 1), (0, 1))]
    walls = []
    for axis in range(3):
        for at in (0.0, 1.0):
            inward = [0.0, 0.0, 0.0]
            inward[axis] = 1.0 if at == 0.0 else -1.0
            walls.append(facing(square(axis, at), inward))
    floor = [w for w in walls if all(p[2] == 0.0 for p in w)]
    ceiling = [w for w in walls if all(p[2] == 1.0 for p in w)]
    sides = [w for w in walls if w not in floor and w not in ceiling]
    light = facing([[0.4, 0.4, 0.999], [0.6, 0.4, 0.999], [0.6, 0.6, 0.999], [0.4, 0.6, 0.999]], [0, 0, -1])
    n, cx, cy, radius, height = 40, 0.3, 0.3, 0.12, 0.3
    top, bottom = ngon(n, cx, cy, radius, height), ngon(n, cx, cy, radius, 0.0)
    prism = [facing(top, [0, 0, 1]), facing(bottom, [0, 0, -1])]
    for k in range(n):
        a, b = k, (k + 1) % n
        quad = [bottom[a], bottom[b], top[b], top[a]]
        mid = [(bottom[a][0] + bottom[b][0]) / 2 - cx, (bottom[a][1] + bottom[b][1]) / 2 - cy, 0.0]
        prism.append(facing(quad, mid))
    disc = ngon(36, 0.68, 0.68, 0.08, 0.4)
    scene = {
        "name": "Prism room",
        "description": "A closed 1 m room, a 0.2 m light under the ceiling, a 40-sided prism standing on the floor "
                       "and a floating 36-sided disc made of two coincident polygons back to back. Written by "
                       "scenes/tools/make_prism_room.py.",
        "unit": "m",
        "camera": {"position": [0.95, 0.05, 0.9], "target": [0.45, 0.5, 0.2], "up": [0, 0, 1], "fov_y_degrees": 60},
        "materials": [
            {"name": "light", "reflectance": [0, 0, 0], "emission": [1, 1, 1]},
            {"name": "white", "reflectance": [0.5, 0.5, 0.5]},
        ],
        "surfaces": [
            {"name": "floor", "material": "white", "polygons": floor},
            {"name": "ceiling", "material": "white", "polygons": ceiling},
            {"name": "walls", "material": "white", "polygons": sides},
            {"name": "light", "material": "light", "polygons": [light]},
            {"name": "prism", "material": "white", "polygons": prism},
            {"name": "disc_top", "material": "white", "polygons": [facing(disc, [0, 0, 1])]},
            {"name": "disc_bottom", "material": "white", "polygons": [facing(disc, [0, 0, -1])]},
        ],
    }
    with open(out, "w") as f:
        f.write(layout(scene))


def layout(scene):
    """One material, surface header or polygon a line, as the other scene files are written."""
    d = lambda x: json.dumps(x)
    lines = ["{"]
    for key in ("name", "description", "unit", "camera"):
        lines.append(f'  "{key}": {d(scene[key])},')
    lines.append('  "materials": [')
    lines.append(",\n".join("    " + d(m) for m in scene["materials"]))
    lines.append("  ],")
    lines.append('  "surfaces": [')
    surfaces = []
    for s in scene["surfaces"]:
        polygons = ",\n".join("        " + d(p) for p in s["polygons"])
        surfaces.append(f'    {{"name": {d(s["name"])}, "material": {d(s["material"])}, "polygons": [\n'
                        f"{polygons}\n      ]}}")
    lines.append(",\n".join(surfaces))
    lines.append("  ]")
    lines.append("}")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    main()
