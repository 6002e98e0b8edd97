#!/usr/bin/env python3
"""Writes data/reference/precision_points.csv: precision-point problems with a known answer.

Independent of the solver: each problem is a train (n, a2, a3, phase) drawn at random and three
points on its curve computed here from the report's rotation chain (Eq. 4,
P = Rz(t) Rx(a2) Rz(n t + phase) Rx(a3) z) with NumPy. The solver must list that train (a2, a3 to
1e-9, the phase modulo 2 pi / q) among its solutions. Families (column `kind`): `random` (carrier
angles uniform over a period), `z_extreme` (the first point where theta3 = 0 or pi: the top or
bottom of the curve, where an arccos of z would fold), `close` (the second and third points
0.02 rad of carrier angle apart).

Usage: /usr/bin/python3 scripts/make_precision_points_reference.py [OUT] (seeded, reproducible)
"""
import math
import sys
from fractions import Fraction

import numpy as np


def rz(t):
    c, s = math.cos(t), math.sin(t)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def rx(t):
    c, s = math.cos(t), math.sin(t)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def point(n, a2, a3, phase, t):
    return rz(t) @ rx(a2) @ rz(float(n) * t + phase) @ rx(a3) @ np.array([0.0, 0.0, 1.0])


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "data/reference/precision_points.csv"
    rng = np.random.default_rng(19)
    rows = []
    for k in range(60):
        kind = ["random", "z_extreme", "close"][k % 3]
        n = Fraction(int(rng.integers(1, 6)) * (1 if rng.random() < 0.5 else -1), int(rng.integers(1, 6)))
        a2, a3 = 0.15 + rng.random() * (math.pi - 0.3), 0.15 + rng.random() * (math.pi - 0.3)
        phase = 2 * math.pi * rng.random()
        period = 2 * math.pi * n.denominator
        t = list(rng.random(3) * period)
        if kind == "z_extreme":  # theta3 = n t + phase = 0 or pi (mod 2 pi)
            t[0] = (math.pi * int(rng.integers(0, 2)) + 2 * math.pi * int(rng.integers(0, 3)) - phase) / float(n)
        if kind == "close":
            t[2] = t[1] + 0.02
        pts = [point(n, a2, a3, phase, ti) for ti in t]
        ratio = f"{n.numerator}/{n.denominator}" if n.denominator != 1 else f"{n.numerator}"
        rows.append([k, kind, ratio, a2, a3, phase, *t, *[c for p in pts for c in p]])
    header = "id,kind,n,a2,a3,phase,t1,t2,t3,x1,y1,z1,x2,y2,z2,x3,y3,z3"
    with open(out, "w") as f:
        f.write("# Precision-point problems with a known train (scripts/make_precision_points_reference.py;\n")
        f.write("# points from Eq. 4 in NumPy, not from the solver). Angles in radians.\n")
        f.write(header + "\n")
        for r in rows:
            f.write(",".join(str(v) if isinstance(v, (int, str)) else repr(float(v)) for v in r) + "\n")


if __name__ == "__main__":
    main()
