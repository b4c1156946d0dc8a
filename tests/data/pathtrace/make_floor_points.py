#!/usr/bin/env python3
"""Writes the benchmark's query points: a grid on the floor of scenes/cornell-box-closed.json, leaving out the
two blocks' footprints (and 2 mm around them, where the floor meets a block). The blocks' shadows cross the
grid, so shadow edges are among the points. Usage: make_floor_points.py N > points.csv (N x N grid)."""
import sys

SHORT = [(130, 65), (82, 225), (240, 272), (290, 114)]
TALL = [(423, 247), (265, 296), (314, 456), (472, 406)]


def inside(polygon, x, z, margin):
    # Convex polygon, either winding: inside when on the same side of every edge, by at least the margin.
    sign = 0
    for k in range(len(polygon)):
        (ax, az), (bx, bz) = polygon[k], polygon[(k + 1) % len(polygon)]
        length = ((bx - ax) ** 2 + (bz - az) ** 2) ** 0.5
        side = ((bx - ax) * (z - az) - (bz - az) * (x - ax)) / length
        if abs(side) < margin:
            return True  # on the footprint's edge: too close to count as free floor
        s = 1 if side > 0 else -1
        if sign == 0:
            sign = s
        elif s != sign:
            return False
    return True


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 24
    points = []
    for i in range(n):
        for j in range(n):
            x = 10 + (530 * i) / (n - 1)
            z = 10 + (539 * j) / (n - 1)
            if inside(SHORT, x, z, 2) or inside(TALL, x, z, 2):
                continue
            points.append(f"{x:.4f},0,{z:.4f},0,1,0")
    if len(sys.argv) > 2:
        m = int(sys.argv[2])
        points = [points[(i * len(points)) // m] for i in range(m)]
    print("x,y,z,nx,ny,nz")
    for point in points:
        print(point)


main()
