#!/usr/bin/env python3
"""A log-log line chart as SVG, from a CSV, with the Python standard library only: for the benchmark pages,
where a figure should come from the measured numbers and nothing else.

Usage: python3 scenes/tools/loglog_svg.py DATA.csv OUT.svg --x COLUMN --y COLUMN[,COLUMN...]
           [--labels TEXT[,TEXT...]] [--title TEXT] [--xlabel TEXT] [--ylabel TEXT] [--diagonal]

Each --y column is one series against the --x column (rows with an empty or non-positive value are left out).
--diagonal draws y = x, dashed: for "achieved error against requested tolerance".
"""
import argparse
import csv
import math
import sys

WIDTH, HEIGHT = 640, 420
LEFT, RIGHT, TOP, BOTTOM = 80, 170, 40, 60
COLOURS = ['#1f77b4', '#d62728', '#2ca02c', '#9467bd', '#ff7f0e']


def decades(lo, hi):
    return range(math.floor(math.log10(lo)), math.ceil(math.log10(hi)) + 1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('data')
    parser.add_argument('out')
    parser.add_argument('--x', required=True)
    parser.add_argument('--y', required=True)
    parser.add_argument('--labels', default=None, help='legend text per --y column (default: the names)')
    parser.add_argument('--title', default='')
    parser.add_argument('--xlabel', default=None)
    parser.add_argument('--ylabel', default='')
    parser.add_argument('--diagonal', action='store_true')
    args = parser.parse_args()

    with open(args.data, newline='') as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f'{args.data}: no rows')
    names = args.y.split(',')
    for name in [args.x] + names:
        if name not in rows[0]:
            sys.exit(f'{args.data}: no column "{name}" (columns: {", ".join(rows[0])})')

    def value(row, name):
        try:
            v = float(row[name])
        except ValueError:
            return None
        return v if v > 0 else None

    labels = args.labels.split(',') if args.labels else names
    if len(labels) != len(names):
        sys.exit(f'--labels: {len(labels)} labels for {len(names)} columns')
    series = []
    for name in names:
        points = [(value(r, args.x), value(r, name)) for r in rows]
        series.append((labels[len(series)], sorted(p for p in points if p[0] and p[1])))
    xs = [x for _, pts in series for x, _ in pts]
    ys = [y for _, pts in series for _, y in pts]
    if args.diagonal:
        ys += xs
    xd, yd = list(decades(min(xs), max(xs))), list(decades(min(ys), max(ys)))
    if len(yd) < 2:
        yd = [yd[0], yd[0] + 1]

    def px(x):
        t = (math.log10(x) - xd[0]) / (xd[-1] - xd[0])
        return LEFT + t * (WIDTH - LEFT - RIGHT)

    def py(y):
        t = (math.log10(y) - yd[0]) / (yd[-1] - yd[0])
        return HEIGHT - BOTTOM - t * (HEIGHT - TOP - BOTTOM)

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{HEIGHT}" '
           f'font-family="sans-serif" font-size="13">',
           f'<rect width="{WIDTH}" height="{HEIGHT}" fill="white"/>']
    for d in xd:
        x = px(10.0 ** d)
        out.append(f'<line x1="{x:.1f}" y1="{TOP}" x2="{x:.1f}" y2="{HEIGHT - BOTTOM}" stroke="#ddd"/>')
        out.append(f'<text x="{x:.1f}" y="{HEIGHT - BOTTOM + 18}" text-anchor="middle">1e{d}</text>')
    for d in yd:
        y = py(10.0 ** d)
        out.append(f'<line x1="{LEFT}" y1="{y:.1f}" x2="{WIDTH - RIGHT}" y2="{y:.1f}" stroke="#ddd"/>')
        out.append(f'<text x="{LEFT - 6}" y="{y + 4:.1f}" text-anchor="end">1e{d}</text>')
    out.append(f'<rect x="{LEFT}" y="{TOP}" width="{WIDTH - LEFT - RIGHT}" height="{HEIGHT - TOP - BOTTOM}" '
               'fill="none" stroke="black"/>')
    if args.diagonal:
        lo, hi = 10.0 ** max(xd[0], yd[0]), 10.0 ** min(xd[-1], yd[-1])
        out.append(f'<line x1="{px(lo):.1f}" y1="{py(lo):.1f}" x2="{px(hi):.1f}" y2="{py(hi):.1f}" '
                   'stroke="gray" stroke-dasharray="6,4"/>')
    for k, (name, pts) in enumerate(series):
        colour = COLOURS[k % len(COLOURS)]
        path = ' '.join(f'{px(x):.1f},{py(y):.1f}' for x, y in pts)
        out.append(f'<polyline points="{path}" fill="none" stroke="{colour}" stroke-width="2"/>')
        for x, y in pts:
            out.append(f'<circle cx="{px(x):.1f}" cy="{py(y):.1f}" r="3.5" fill="{colour}"/>')
        ly = TOP + 10 + 20 * k
        out.append(f'<line x1="{WIDTH - RIGHT + 12}" y1="{ly}" x2="{WIDTH - RIGHT + 32}" y2="{ly}" '
                   f'stroke="{colour}" stroke-width="2"/>')
        out.append(f'<text x="{WIDTH - RIGHT + 38}" y="{ly + 4}">{name}</text>')
    if args.diagonal:
        ly = TOP + 10 + 20 * len(series)
        out.append(f'<line x1="{WIDTH - RIGHT + 12}" y1="{ly}" x2="{WIDTH - RIGHT + 32}" y2="{ly}" '
                   'stroke="gray" stroke-dasharray="6,4"/>')
        out.append(f'<text x="{WIDTH - RIGHT + 38}" y="{ly + 4}">y = x</text>')
    out.append(f'<text x="{(LEFT + WIDTH - RIGHT) / 2}" y="{HEIGHT - 18}" text-anchor="middle">'
               f'{args.xlabel or args.x}</text>')
    out.append(f'<text x="18" y="{(TOP + HEIGHT - BOTTOM) / 2}" text-anchor="middle" '
               f'transform="rotate(-90 18 {(TOP + HEIGHT - BOTTOM) / 2})">{args.ylabel}</text>')
    out.append(f'<text x="{(LEFT + WIDTH - RIGHT) / 2}" y="24" text-anchor="middle" font-size="15">'
               f'{args.title}</text>')
    out.append('</svg>')
    with open(args.out, 'w') as f:
        f.write('\n'.join(out) + '\n')


if __name__ == '__main__':
    main()
