#!/usr/bin/env python3
"""Area-weighted relative RMS difference of two radiosity files written by `radiosity solve --output`:

    sqrt(sum_i A_i |B_i - R_i|^2) / sqrt(sum_i A_i |R_i|^2)   (|.| over the three channels)

Usage: python3 scenes/tools/radiosity_error.py B.csv REFERENCE.csv [REFERENCE_RAY_RATIO]
With REFERENCE_RAY_RATIO k, the reference is an independent run of the same stochastic solver with k times the rays:
its own noise is then 1/sqrt(k) of the run's, and the run's error is the difference divided by sqrt(1 + 1/k).
Only the Python standard library is used.
"""
import csv
import math
import sys


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return [(float(r["area"]), (float(r["B_r"]), float(r["B_g"]), float(r["B_b"]))) for r in rows]


def main():
    run, reference = read(sys.argv[1]), read(sys.argv[2])
    if len(run) != len(reference):
        sys.exit("the two files have different element counts")
    ratio = float(sys.argv[3]) if len(sys.argv) > 3 else math.inf
    difference = sum(a * sum((b - r) ** 2 for b, r in zip(bs, rs)) for (a, bs), (_, rs) in zip(run, reference))
    norm = sum(a * sum(r * r for r in rs) for a, rs in reference)
    error = math.sqrt(difference / norm) / math.sqrt(1.0 + 1.0 / ratio)
    print(f"{error:.4e}")


if __name__ == "__main__":
    main()
