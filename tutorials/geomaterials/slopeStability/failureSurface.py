#!/usr/bin/env python3
"""The failure surface of a failing run (docs/theory/geotechnics.md §E2): how far each particle
moved by the end of the run (its last snapshot), and where the sliding mass ends.

Writes, in the run's folder:
  failureSurface.dat  X Y u: each particle's initial position and its displacement at the end
                      [m] (plot.gp colours the particles by it);
  failureLine.dat     X Y: in each column of particles (initial x), the deepest particle that
                      moved at least half the sliding mass's displacement (taken as the 95th
                      percentile of all: the largest is a few particles running out at the
                      toe): the base of the sliding mass.
Prints the line's distance to Bishop's critical circle (bishopCircle.dat, from bishop.py) when
that file is in the current folder.

    python3 failureSurface.py [run folder]      # default: this case
"""
import glob
import math
import os
import re
import sys


def snapshots(folder):
    files = glob.glob(os.path.join(folder, "postProcessing", "particles", "particles_*.dat"))
    return sorted(files, key=lambda f: int(re.findall(r"_(\d+)\.dat$", f)[0]))


def read(path):
    with open(path) as f:
        header = f.readline().split()[1:]
        rows = [list(map(float, line.split())) for line in f if line.strip()]
    col = {name: i for i, name in enumerate(header)}
    return [(r[col["x"]], r[col["y"]], r[col["displacement_x"]], r[col["displacement_y"]])
            for r in rows]


def main(argv):
    folder = argv[0] if argv else "."
    files = snapshots(folder)
    if not files:
        sys.exit(folder + ": needs the snapshots of the particles function object")
    particles = [(x - ux, y - uy, math.hypot(ux, uy)) for x, y, ux, uy in read(files[-1])]
    ranked = sorted(du for _, _, du in particles)
    largest = ranked[-1]
    sliding = ranked[int(0.95 * (len(ranked) - 1))]
    with open(os.path.join(folder, "failureSurface.dat"), "w") as out:
        out.write("# X Y u: initial position [m], displacement at the end [m]\n")
        for X, Y, du in particles:
            out.write("%.4f %.4f %.6e\n" % (X, Y, du))
    columns = {}
    for X, Y, du in particles:
        if du >= 0.5 * sliding:
            key = round(X, 6)
            columns[key] = min(columns.get(key, Y), Y)
    line = sorted(columns.items())
    with open(os.path.join(folder, "failureLine.dat"), "w") as out:
        out.write("# X Y: the deepest particle of each column that moved at least half the "
                  "95th percentile of the displacements (%.4g m)\n" % sliding)
        for X, Y in line:
            out.write("%.4f %.4f\n" % (X, Y))
    print("Failure surface: the sliding mass (moved %.3g m, 95th percentile; largest %.3g m) "
          "spans x = %.2f to %.2f m and reaches y = %.2f m"
          % (sliding, largest, line[0][0], line[-1][0], min(Y for _, Y in line)))
    if os.path.exists("bishopCircle.dat"):
        with open("bishopCircle.dat") as f:
            circle = [tuple(map(float, l.split())) for l in f if not l.startswith("#")]
        distances = [min(math.hypot(X - cx, Y - cy) for cx, cy in circle) for X, Y in line]
        print("Distance of that line to Bishop's critical circle: mean %.2f m, largest %.2f m"
              % (sum(distances) / len(distances), max(distances)))


if __name__ == "__main__":
    main(sys.argv[1:])
