#!/usr/bin/env python3
"""Error of a form-factor matrix against a reference on the grid room's floor elements that lie wholly outside
the blocks' footprints (where every method worth comparing sees the same geometry), as the form-factor
benchmark reports it: the largest |dF| and the RMS over those rows and all columns.

Usage: python3 scenes/tools/floor_error.py SCENE.json REFERENCE.npy F.npy
Both matrices as `radiosity formfactors SCENE --no-subdivide --output F.npy` writes them (float64). Only the
Python standard library is used.
"""
import array
import ast
import json
import math
import struct
import sys

from make_grid_room import SHORT_TOP, TALL_TOP


def load_npy(path):
    with open(path, 'rb') as f:
        data = f.read()
    if data[:6] != b'\x93NUMPY':
        sys.exit(f'{path}: not a .npy file')
    if data[6] == 1:
        length, offset = struct.unpack('<H', data[8:10])[0], 10
    else:
        length, offset = struct.unpack('<I', data[8:12])[0], 12
    header = ast.literal_eval(data[offset:offset + length].decode())
    values = array.array('d')
    values.frombytes(data[offset + length:])
    n, m = header['shape']
    if header.get('fortran_order'):
        return [[values[j * n + i] for j in range(m)] for i in range(n)]
    return [values[i * m:(i + 1) * m] for i in range(n)]


def inside(point, corners):
    """Point (x, z) inside the convex footprint (x, z) corners, boundary included."""
    sign = 0
    for a, b in zip(corners, corners[1:] + corners[:1]):
        c = (b[0] - a[0]) * (point[1] - a[1]) - (b[1] - a[1]) * (point[0] - a[0])
        if abs(c) < 1e-9:
            continue
        if sign == 0:
            sign = 1 if c > 0 else -1
        elif (c > 0) != (sign > 0):
            return False
    return True


def outside_footprints(polygon, footprints, samples=10):
    """No point of an 11 x 11 grid over the element's box lies in a footprint."""
    xs, zs = [p[0] for p in polygon], [p[2] for p in polygon]
    for i in range(samples + 1):
        for j in range(samples + 1):
            point = (min(xs) + (max(xs) - min(xs)) * i / samples, min(zs) + (max(zs) - min(zs)) * j / samples)
            if any(inside(point, f) for f in footprints):
                return False
    return True


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    scene = json.load(open(sys.argv[1]))
    footprints = [[(p[0], p[2]) for p in top] for top in (SHORT_TOP, TALL_TOP)]
    rows, index = [], 0
    for surface in scene['surfaces']:
        for polygon in surface['polygons']:
            if surface['name'] == 'floor' and outside_footprints(polygon, footprints):
                rows.append(index)
            index += 1
    reference, F = load_npy(sys.argv[2]), load_npy(sys.argv[3])
    worst, squares, count = 0.0, 0.0, 0
    for i in rows:
        for r, f in zip(reference[i], F[i]):
            e = abs(f - r)
            worst = max(worst, e)
            squares += e * e
            count += 1
    print(f'{len(rows)} floor rows outside the footprints: max |dF| {worst:.3g}, RMS {math.sqrt(squares / count):.3g}')


if __name__ == '__main__':
    main()
