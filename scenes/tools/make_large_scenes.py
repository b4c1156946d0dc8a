#!/usr/bin/env python3
"""Writes the two large scenes of the course as Wavefront OBJ/MTL (Kd = reflectance, Ke = emission in W/m^2):

- factory: a 60 x 30 m hall, 8 m to the eaves, under a sawtooth roof of ten teeth whose vertical glazing lets
  in the sky (the skylights emit); rows of machines, a line of racks, two rows of columns.
- museum: six 12 x 10 m galleries, 5 m high, joined by doorways in 0.3 m partition walls; a skylight in every
  gallery's ceiling, wall lights, plinths with works on them, and free-standing display walls.

Every surface is a rectangle (or a gable triangle) split into a regular grid of elements, with the cell size
chosen so that the scene has about ELEMENTS polygons in all. The programs keep one element per polygon for a
scene this size (a scene given without mesh options keeps its polygons when it has more than the default
mesh's count), so the file is the scene's default mesh: factory 30,000 and museum 50,000 by default, and any
size from about 1,000 to 1,000,000 on demand. Polygons are one-sided and counter-clockwise seen from the side
they face; solids stand on the floor without a bottom face (it could see nothing).

Usage: python3 scenes/tools/make_large_scenes.py factory|museum [ELEMENTS] [output.obj]
Default output: scenes/<scene>-<ELEMENTS/1000>k.obj and the .mtl beside it. Only the standard library is used.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_cornell_box import facing  # noqa: E402  (the same orientation rule as the Cornell box files)


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def add(a, b):
    return [x + y for x, y in zip(a, b)]


def scale(a, s):
    return [x * s for x in a]


def length(a):
    return math.sqrt(sum(x * x for x in a))


class Scene:
    """Rectangles and triangles by material and group; split into elements when written."""

    def __init__(self):
        self.shapes = []  # (group, material, corners, facing direction)

    def rect(self, group, material, origin, u, v, direction):
        self.shapes.append((group, material, [origin, add(origin, u), add(add(origin, u), v), add(origin, v)],
                            direction))

    def plane(self, group, material, origin, u, v, direction, holes=()):
        """The rectangle origin + a u/|u| + b v/|v| (0 <= a <= |u|, 0 <= b <= |v|) cut along the edges of `holes`,
        (a0, a1, b0, b1, fill): where something stands on the surface (fill None: the part under it is left
        out, it could see nothing) or is set into it (fill: (group, material) of a lamp or a skylight flush
        with it). No element straddles a hole's edge, so none is half lit and half hidden."""
        lu, lv = length(u), length(v)
        cuts_a = sorted({0.0, lu} | {min(max(x, 0.0), lu) for h in holes for x in h[:2]})
        cuts_b = sorted({0.0, lv} | {min(max(x, 0.0), lv) for h in holes for x in h[2:4]})
        eu, ev = scale(u, 1 / lu), scale(v, 1 / lv)
        for a0, a1 in zip(cuts_a, cuts_a[1:]):
            for b0, b1 in zip(cuts_b, cuts_b[1:]):
                if a1 - a0 < 1e-9 or b1 - b0 < 1e-9:
                    continue
                am, bm = (a0 + a1) / 2, (b0 + b1) / 2
                inside = [h for h in holes if h[0] < am < h[1] and h[2] < bm < h[3]]
                fill = inside[0][4] if inside else (group, material)
                if fill is None:
                    continue
                corner = add(origin, add(scale(eu, a0), scale(ev, b0)))
                self.rect(fill[0], fill[1], corner, scale(eu, a1 - a0), scale(ev, b1 - b0), direction)

    def triangle(self, group, material, a, b, c, direction):
        self.shapes.append((group, material, [a, b, c], direction))

    def box(self, group, material, x0, x1, y0, y1, z0, z1, bottom=False, top_holes=()):
        """An axis-aligned solid: its faces face outwards; no bottom when it stands on something. `top_holes`
        (x0, x1, z0, z1) are the footprints of what stands on it."""
        dx, dy, dz = [x1 - x0, 0, 0], [0, y1 - y0, 0], [0, 0, z1 - z0]
        self.plane(group, material, [x0, y1, z0], dx, dz, [0, 1, 0],
                   [(a0 - x0, a1 - x0, b0 - z0, b1 - z0, None) for a0, a1, b0, b1 in top_holes])
        if bottom:
            self.rect(group, material, [x0, y0, z0], dx, dz, [0, -1, 0])
        self.rect(group, material, [x0, y0, z0], dy, dz, [-1, 0, 0])
        self.rect(group, material, [x1, y0, z0], dy, dz, [1, 0, 0])
        self.rect(group, material, [x0, y0, z0], dx, dy, [0, 0, -1])
        self.rect(group, material, [x0, y0, z1], dx, dy, [0, 0, 1])

    def cells(self, shape, h):
        corners = shape[2]
        if len(corners) == 3:
            k = max(1, math.ceil(max(length(sub(corners[1], corners[0])), length(sub(corners[2], corners[0])),
                                     length(sub(corners[2], corners[1]))) / h))
            return k * k
        return max(1, math.ceil(length(sub(corners[1], corners[0])) / h)) * \
            max(1, math.ceil(length(sub(corners[3], corners[0])) / h))

    def count(self, h):
        return sum(self.cells(s, h) for s in self.shapes)

    def cell_size(self, elements):
        """The cell size whose polygon count is nearest to `elements` (bisection in log scale; the count jumps
        where many rectangles of one size gain a row at once)."""
        coarse, fine = 100.0, 0.001
        for _ in range(60):
            h = math.sqrt(coarse * fine)
            if self.count(h) >= elements:
                fine = h
            else:
                coarse = h
        return min((fine, coarse), key=lambda h: abs(self.count(h) - elements))

    def write(self, obj_path, elements, name, description, materials, camera):
        h = self.cell_size(elements)
        mtl_path = os.path.splitext(obj_path)[0] + ".mtl"
        lines = [f"# {description}",
                 "# Generated by scenes/tools/make_large_scenes.py; see scenes/README.md.",
                 "# unit: m",
                 f"# name: {name}",
                 "# camera: " + camera,
                 "mtllib " + os.path.basename(mtl_path)]
        count, polygons = 0, 0
        current = None
        for group, material, corners, direction in self.shapes:
            if (group, material) != current:
                lines += [f"g {group}", f"usemtl {material}"]
                current = (group, material)
            grid, faces = split(corners, h)
            lines += ["v " + " ".join(fmt(c) for c in p) for p in grid]
            for face in faces:
                ordered = facing([grid[i] for i in face], direction)
                index = {tuple(grid[i]): i for i in face}
                lines.append("f " + " ".join(str(count + index[tuple(p)] + 1) for p in ordered))
            count += len(grid)
            polygons += len(faces)
        with open(obj_path, "w") as f:
            f.write("\n".join(lines) + "\n")
        mtl = [f"# Materials of {os.path.basename(obj_path)}: Kd = reflectance, Ke = emission (W/m^2)."]
        for key, (kd, ke) in materials.items():
            mtl += ["", f"newmtl {key}", "Kd " + " ".join(fmt(c) for c in kd)]
            if ke:
                mtl.append("Ke " + " ".join(fmt(c) for c in ke))
        with open(mtl_path, "w") as f:
            f.write("\n".join(mtl) + "\n")
        return polygons, h


def split(corners, h):
    """The shape's grid vertices and its cells (quads, or triangles for a triangle), as vertex indices."""
    if len(corners) == 3:
        a, b, c = corners
        k = max(1, math.ceil(max(length(sub(b, a)), length(sub(c, a)), length(sub(c, b))) / h))
        index, grid = {}, []
        for i in range(k + 1):
            for j in range(k + 1 - i):
                index[(i, j)] = len(grid)
                grid.append(add(a, add(scale(sub(b, a), i / k), scale(sub(c, a), j / k))))
        faces = []
        for i in range(k):
            for j in range(k - i):
                faces.append([index[(i, j)], index[(i + 1, j)], index[(i, j + 1)]])
                if j < k - i - 1:
                    faces.append([index[(i + 1, j)], index[(i + 1, j + 1)], index[(i, j + 1)]])
        return grid, faces
    o, u, v = corners[0], sub(corners[1], corners[0]), sub(corners[3], corners[0])
    nu, nv = max(1, math.ceil(length(u) / h)), max(1, math.ceil(length(v) / h))
    grid = [add(o, add(scale(u, i / nu), scale(v, j / nv))) for i in range(nu + 1) for j in range(nv + 1)]
    at = lambda i, j: i * (nv + 1) + j  # noqa: E731
    faces = [[at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)] for i in range(nu) for j in range(nv)]
    return grid, faces


def fmt(x):
    text = f"{x:.6f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def factory():
    s = Scene()
    L, W, H, T, P = 60.0, 30.0, 8.0, 2.5, 6.0  # length (x), width (z), eaves, tooth rise, tooth period
    machines = [(5.0 + 8.5 * k, 5.0 + 8.5 * k + 4.0, z, z + 2.5, row) for row, z in enumerate((6.0, 13.0))
                for k in range(6)]
    racks = [(4.0 + 11.0 * k, 12.0 + 11.0 * k, 24.0, 25.2) for k in range(5)]
    columns = [(k * P - 0.2, k * P + 0.2, z - 0.2, z + 0.2) for z in (10.0, 20.0) for k in range(1, int(L / P))]
    footprints = [m[:4] for m in machines] + racks + columns
    s.plane("floor", "concrete", [0, 0, 0], [L, 0, 0], [0, 0, W], [0, 1, 0],
            [(x0, x1, z0, z1, None) for x0, x1, z0, z1 in footprints])
    s.rect("walls", "wall", [0, 0, 0], [0, H, 0], [0, 0, W], [1, 0, 0])
    s.rect("walls", "wall", [L, 0, 0], [0, H, 0], [0, 0, W], [-1, 0, 0])
    s.rect("walls", "wall", [0, 0, 0], [L, 0, 0], [0, H, 0], [0, 0, 1])
    s.rect("walls", "wall", [0, 0, W], [L, 0, 0], [0, H, 0], [0, 0, -1])
    for k in range(int(L / P)):
        x0, x1 = k * P, (k + 1) * P
        # The opaque slope rises towards +x; the vertical glazing closes the tooth and faces back into it.
        s.rect("roof", "roof", [x0, H, 0], [P, T, 0], [0, 0, W], [T, -P, 0])
        s.rect("skylights", "sky", [x1, H, 0], [0, T, 0], [0, 0, W], [-1, 0, 0])
        s.triangle("gables", "wall", [x0, H, 0], [x1, H, 0], [x1, H + T, 0], [0, 0, 1])
        s.triangle("gables", "wall", [x0, H, W], [x1, H, W], [x1, H + T, W], [0, 0, -1])
    for x0, x1, z0, z1, row in machines:
        hood = (x0 + 1.0, x0 + 2.5, z0 + 0.5, z0 + 2.0)
        s.box("machines", "machine-blue" if row == 0 else "machine-yellow", x0, x1, 0, 2.2, z0, z1,
              top_holes=[hood])
        s.box("machines", "steel", hood[0], hood[1], 2.2, 3.0, hood[2], hood[3])
    for x0, x1, z0, z1 in racks:
        s.box("racks", "rack", x0, x1, 0, 4.5, z0, z1)
    for x0, x1, z0, z1 in columns:
        s.box("columns", "steel", x0, x1, 0, H - 0.4, z0, z1)  # clear of the roof's seams
    materials = {"concrete": ([0.42, 0.41, 0.39], None), "wall": ([0.62, 0.6, 0.56], None),
                 "roof": ([0.7, 0.7, 0.7], None), "sky": ([0.05, 0.05, 0.05], [40.0, 45.0, 52.0]),
                 "machine-blue": ([0.12, 0.22, 0.45], None), "machine-yellow": ([0.6, 0.5, 0.08], None),
                 "steel": ([0.45, 0.46, 0.48], None), "rack": ([0.62, 0.3, 0.08], None)}
    camera = "position 2 6 2 target 40 2 20 up 0 1 0 fov_y_degrees 60"
    return s, "Factory hall", ("Factory hall, 60 x 30 m under a sawtooth roof with skylights: machines, racks "
                               "and columns"), materials, camera


def wall_with_door(s, group, material, origin, along, height, direction, door_at, door_width, door_height):
    """A wall face of length |along| with a doorway starting `door_at` along it: three rectangles."""
    s.plane(group, material, origin, along, [0, height, 0], direction,
            [(door_at, door_at + door_width, 0, door_height, None)])


def museum():
    s = Scene()
    NX, NZ, GX, GZ, H, T = 3, 2, 12.4, 9.8, 5.2, 0.3  # galleries, their size, height, partition thickness
    DW, DH = 2.0, 3.0  # doorway
    LX, LZ = NX * GX, NZ * GZ
    doors_x = [j * GZ + GZ / 2 - DW / 2 for j in range(NZ)]  # along z, in the partitions x = i GX
    doors_z = [i * GX + GX / 2 - DW / 2 for i in range(NX)]  # along x, in the partition z = GZ
    # The partitions' footprints: strips x = i GX +- T/2 and z = GZ +- T/2, with and without their doorways.
    strips_x = [(i * GX - T / 2, i * GX + T / 2) for i in range(1, NX)]
    strip_z = (GZ - T / 2, GZ + T / 2)

    def between(cuts, total):
        edges = [0.0] + [c for d in cuts for c in (d, d + DW)] + [total]
        return list(zip(edges[0::2], edges[1::2]))

    under_partitions = [(a0, a1, b0, b1) for a0, a1 in strips_x for b0, b1 in between(doors_x, LZ)]
    under_partitions += [(a0, a1) + strip_z for a0, a1 in between(doors_z, LX)]
    above_partitions = [(a0, a1, 0, LZ) for a0, a1 in strips_x] + [(0, LX) + strip_z]
    plinths, works, displays, skylights = [], [], [], []
    for i in range(NX):
        for j in range(NZ):
            x0, z0 = i * GX, j * GZ
            skylights.append((x0 + 4.0, x0 + 8.0, z0 + 3.5, z0 + 6.5))
            for px, pz in ((x0 + 3.0, z0 + 2.5), (x0 + 8.0, z0 + 7.0)):
                plinths.append((px, px + 1.0, pz, pz + 1.0))
                works.append((px + 0.3, px + 0.7, pz + 0.3, pz + 0.7))
            displays.append((x0 + 5.5, x0 + 7.5, z0 + 8.0, z0 + 8.2))
    s.plane("floor", "floor", [0, 0, 0], [LX, 0, 0], [0, 0, LZ], [0, 1, 0],
            [f + (None,) for f in under_partitions + plinths + displays])
    s.plane("ceilings", "ceiling", [0, H, 0], [LX, 0, 0], [0, 0, LZ], [0, -1, 0],
            [f + (None,) for f in above_partitions] + [f + (("skylights", "sky"),) for f in skylights])
    # Outer walls; wall lights set into the long walls at 3 m; no wall where a partition meets it.
    lamps = [(xc - 0.2, xc + 0.2, 2.85, 3.15, ("wall-lights", "lamp")) for i in range(NX)
             for xc in (i * GX + 3.0, i * GX + 9.0)]
    meets_long = [(a0, a1, 0, H, None) for a0, a1 in strips_x]
    s.plane("walls", "plaster", [0, 0, 0], [LX, 0, 0], [0, H, 0], [0, 0, 1], meets_long + lamps)
    s.plane("walls", "plaster", [0, 0, LZ], [LX, 0, 0], [0, H, 0], [0, 0, -1], meets_long + lamps)
    meets_short = [strip_z + (0, H, None)]
    s.plane("walls", "plaster", [0, 0, 0], [0, 0, LZ], [0, H, 0], [1, 0, 0], meets_short)
    s.plane("walls", "plaster", [LX, 0, 0], [0, 0, LZ], [0, H, 0], [-1, 0, 0], meets_short)
    # Partition faces, each with its doorway, and the doorways' jambs and lintels.
    for a0, a1 in strips_x:
        for side, sign in ((a0, -1), (a1, 1)):
            for j in range(NZ):
                z_start = j * GZ + (0 if j == 0 else T / 2)
                z_end = (j + 1) * GZ - (0 if j == NZ - 1 else T / 2)
                wall_with_door(s, "partitions", "plaster", [side, 0, z_start], [0, 0, z_end - z_start], H,
                               [sign, 0, 0], doors_x[j] - z_start, DW, DH)
        for zd in doors_x:
            s.rect("partitions", "plaster", [a0, 0, zd], [T, 0, 0], [0, DH, 0], [0, 0, 1])
            s.rect("partitions", "plaster", [a0, 0, zd + DW], [T, 0, 0], [0, DH, 0], [0, 0, -1])
            s.rect("partitions", "plaster", [a0, DH, zd], [T, 0, 0], [0, 0, DW], [0, -1, 0])
    for i in range(NX):
        x0 = i * GX + (0 if i == 0 else T / 2)
        x1 = (i + 1) * GX - (0 if i == NX - 1 else T / 2)
        for side, sign in ((strip_z[0], -1), (strip_z[1], 1)):
            wall_with_door(s, "partitions", "plaster", [x0, 0, side], [x1 - x0, 0, 0], H, [0, 0, sign],
                           doors_z[i] - x0, DW, DH)
        xd = doors_z[i]
        s.rect("partitions", "plaster", [xd, 0, strip_z[0]], [0, DH, 0], [0, 0, T], [1, 0, 0])
        s.rect("partitions", "plaster", [xd + DW, 0, strip_z[0]], [0, DH, 0], [0, 0, T], [-1, 0, 0])
        s.rect("partitions", "plaster", [xd, DH, strip_z[0]], [DW, 0, 0], [0, 0, T], [0, -1, 0])
    for plinth, work in zip(plinths, works):
        s.box("plinths", "plinth", plinth[0], plinth[1], 0, 1.0, plinth[2], plinth[3], top_holes=[work])
        s.box("works", "bronze", work[0], work[1], 1.0, 1.8, work[2], work[3])
    for x0, x1, z0, z1 in displays:
        s.box("display-walls", "plaster", x0, x1, 0, 3.0, z0, z1)
    materials = {"floor": ([0.35, 0.28, 0.2], None), "plaster": ([0.78, 0.77, 0.74], None),
                 "ceiling": ([0.8, 0.8, 0.8], None), "sky": ([0.05, 0.05, 0.05], [60.0, 64.0, 70.0]),
                 "lamp": ([0.1, 0.1, 0.1], [900.0, 800.0, 600.0]), "plinth": ([0.7, 0.7, 0.68], None),
                 "bronze": ([0.35, 0.22, 0.1], None)}
    camera = "position 1 1.7 1 target 18 1.5 10 up 0 1 0 fov_y_degrees 65"
    return s, "Museum", ("Museum: six galleries joined by doorways, partition walls, plinths, skylights and "
                         "wall lights"), materials, camera


def main():
    if len(sys.argv) < 2 or sys.argv[1] not in ("factory", "museum"):
        sys.exit(__doc__)
    kind = sys.argv[1]
    elements = int(sys.argv[2]) if len(sys.argv) > 2 else (30000 if kind == "factory" else 50000)
    here = os.path.dirname(os.path.abspath(__file__))
    default = os.path.join(os.path.dirname(here), f"{kind}-{round(elements / 1000)}k.obj")
    out = sys.argv[3] if len(sys.argv) > 3 else default
    scene, name, description, materials, camera = factory() if kind == "factory" else museum()
    polygons, h = scene.write(out, elements, name, description, materials, camera)
    print(f"wrote {out}: {polygons} polygons (cells of {h:.3g} m) and its .mtl")


if __name__ == "__main__":
    main()
