#!/usr/bin/env python3
"""check_quad_bound.py -- whether the quadratic time's table bound holds.

Reads bench/quad_bound's lines (P0 P1 P2, the distance s, the answer t and
its bound) on stdin and measures each answer's true miss |s(t) - s| with
mpmath at 50 digits: s(t) = (H(u0 + t|b|^2) - H(u0))/|b|^3 with H(u) =
u sqrt(u^2 + k^2) + k^2 asinh(u/k), on the legs as the C core has them (the
differences of the points rounded to doubles: the curve it measures).
Prints the count and the ratios miss / bound (median, 99th percentile,
largest); exits 1 where a ratio exceeds 1 or no answer was read.
Run: sh tools/check-quad-bound.sh (CI runs it).
"""
import sys

from mpmath import asinh, mp, mpf, sqrt

mp.dps = 50


def H(u, k):
    r = u * sqrt(u * u + k * k)
    return r + k * k * asinh(u / k) if k != 0 else r


def main():
    ratios = []
    for line in sys.stdin:
        f = [float(x) for x in line.split()]
        x0, y0, x1, y1, x2, y2, s, t, bound = f
        ax, ay = mpf(x1 - x0), mpf(y1 - y0)    # as doubles: the core's legs
        cx, cy = mpf(x2 - x1), mpf(y2 - y1)
        bx, by = cx - ax, cy - ay
        B = bx * bx + by * by
        k = abs(ax * cy - ay * cx)
        u0 = ax * bx + ay * by
        st = (H(u0 + mpf(t) * B, k) - H(u0, k)) / (B * sqrt(B))
        ratios.append(float(abs(st - mpf(s)) / mpf(bound)))
    if not ratios:
        print("check_quad_bound: no answers read")
        return 1
    ratios.sort()
    n = len(ratios)
    print("%d answers: miss / bound median %.3g, 99th percentile %.3g, largest %.3g"
          % (n, ratios[n // 2], ratios[int(0.99 * n)], ratios[-1]))
    return 0 if ratios[-1] <= 1 else 1


if __name__ == "__main__":
    sys.exit(main())
