#!/usr/bin/env python3
"""The 3D slab's mid-plane surface against the 2D plane-strain run's, from two finished runs.

    python3 compare2D.py [CASE3D] CASE2D [--time 1]

Reads the surface profiles (surfaceProfile tables, postProcessing/surface/surface_<time>.dat:
x height, one row per column of width one spacing) of both runs at the given time (default:
the latest both have) and prints:
- the largest vertical difference between them column by column, and where; the mean of the
  differences' magnitudes; and the largest difference between the two profiles each averaged
  over three neighbouring columns (a running mean: a coarse deposit's surface is jagged by a
  particle from column to column, and a particle that ends one column over makes a column
  difference of a particle's height where the surfaces agree);
- the largest distance from a surface point of either profile to the other profile (the
  symmetric Hausdorff distance between the two polylines through the columns' tops, in the
  (x, height) plane), which does not count a step of the jagged surface of a coarse deposit
  shifted by one column as a difference of the step's height.
Columns with no particle (height 0, ahead of a deposit that has broken up) are left out of the
polylines. Plain python3 (no numpy).
"""
import glob
import math
import os
import re
import sys


def profile(case, time):
    path = os.path.join(case, "postProcessing/surface", f"surface_{time}.dat")
    points = []
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        x, h = (float(v) for v in line.split()[:2])
        points.append((x, h))
    return points


def times(case):
    found = glob.glob(os.path.join(case, "postProcessing/surface/surface_*.dat"))
    return {re.search(r"surface_(.*)\.dat$", f).group(1) for f in found}


def segmentDistance(p, a, b):
    ax, ay = a
    bx, by = b
    dx, dy = bx - ax, by - ay
    length2 = dx * dx + dy * dy
    t = 0.0 if length2 == 0 else max(0.0, min(1.0, ((p[0] - ax) * dx + (p[1] - ay) * dy) / length2))
    return math.hypot(p[0] - ax - t * dx, p[1] - ay - t * dy)


def toPolyline(p, line):
    if len(line) == 1:
        return math.hypot(p[0] - line[0][0], p[1] - line[0][1])
    return min(segmentDistance(p, a, b) for a, b in zip(line, line[1:]))


def main():
    args = sys.argv[1:]
    time = None
    if "--time" in args:
        i = args.index("--time")
        time = args[i + 1]
        del args[i:i + 2]
    if len(args) == 1:
        args.insert(0, ".")
    if len(args) != 2:
        sys.exit(__doc__)
    case3d, case2d = args
    if time is None:
        common = times(case3d) & times(case2d)
        if not common:
            sys.exit("compare2D.py: the two runs have no surface profile at a common time")
        time = max(common, key=float)
    p3, p2 = profile(case3d, time), profile(case2d, time)
    vertical, at = 0.0, 0.0
    for (x, h3), (_, h2) in zip(p3, p2):
        if abs(h3 - h2) > vertical:
            vertical, at = abs(h3 - h2), x
    longer = p3 if len(p3) > len(p2) else p2
    for x, h in longer[min(len(p3), len(p2)):]:
        if h > vertical:
            vertical, at = h, x
    count = max(len(p3), len(p2))
    h3 = [h for _, h in p3] + [0.0] * (count - len(p3))
    h2 = [h for _, h in p2] + [0.0] * (count - len(p2))
    x = [p[0] for p in (p3 if len(p3) == count else p2)]
    mean = sum(abs(a - b) for a, b in zip(h3, h2)) / count

    def smooth(h):
        return [sum(h[max(0, i - 1):i + 2]) / len(h[max(0, i - 1):i + 2]) for i in range(len(h))]

    smoothed, smoothedAt = 0.0, 0.0
    for xi, a, b in zip(x, smooth(h3), smooth(h2)):
        if abs(a - b) > smoothed:
            smoothed, smoothedAt = abs(a - b), xi
    s3 = [p for p in p3 if p[1] > 0]
    s2 = [p for p in p2 if p[1] > 0]
    hausdorff, where = 0.0, None
    for points, other in ((s3, s2), (s2, s3)):
        for p in points:
            d = toPolyline(p, other)
            if d > hausdorff:
                hausdorff, where = d, p
    print(f"t = {time} s, {count} columns: largest vertical difference {vertical:.4f} m at x = {at:.3f} m, "
          f"mean {mean:.4f} m; over three columns {smoothed:.4f} m at x = {smoothedAt:.3f} m; "
          f"largest distance between the profiles {hausdorff:.4f} m at ({where[0]:.3f}, {where[1]:.4f})")


if __name__ == "__main__":
    main()
