#!/usr/bin/env python3
"""The retaining wall's thrust against Rankine's active pressure, from a finished run.

    python3 thrust.py [CASE] [--from 2] [--to 5] [--threshold 1e-3] [--curve]

Reads CASE/postProcessing/walls/walls.dat (the wallForce table) and, from the case's own files,
the wall's velocity (constant/walls, `retainer`), the soil's density, friction angle and the
gravity (constant/bodies), the soil's height H (system/particlesDict, `soil`'s box) and the
command line of the run (postProcessing/summary.json), so that `-set` of these keys is
honoured. The thrust per unit width is retainer_Fx (the force the wall puts on the soil) and its
coefficient K = 2 Fx / (rho g H^2); Rankine's active value is K_a = (1 - sin phi)/(1 + sin phi).
Prints the mean of K over the rows whose wall displacement (velocity x time, in mm) lies in
[from, to] (the rows are equally spaced in time, so this is the time average over the window,
which averages the thrust's oscillation), its range there, and its error against K_a.

From the last particle snapshot (postProcessing/particles/, field plasticStrain) it prints the
failure wedge: the shear band's centre line, i.e. in each row of particles the x (within
x <= H) where the plastic strain peaks, provided it exceeds the threshold, and the angle from
the horizontal of the least-squares line x(y) through those points in the rows between 0.2 H
and 0.8 H (the rows by the floor and by the free surface are left out: the heel's corner and
the surface's cohesionless layer); Rankine's wedge is bounded by a plane at 45 + phi/2
degrees through the heel. --curve writes (displacement [mm], K) to CASE/postProcessing/walls/curve.dat
for plot.gp. Plain python3 (no numpy).
"""
import glob
import json
import math
import os
import re
import shlex
import sys


def block(text, name):
    """The body of the first dictionary `name { ... }` in an OpenFOAM-style text."""
    text = re.sub(r"//[^\n]*", "", text)
    m = re.search(r"\b" + name + r"\s*\{", text)
    if not m:
        sys.exit(f"thrust.py: no '{name}' entry")
    depth, i = 1, m.end()
    while depth and i < len(text):
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        i += 1
    return text[m.end():i - 1]


def vector(body, key):
    m = re.search(r"\b" + key + r"\s*\(([^)]*)\)", body)
    return [float(v) for v in m.group(1).split()] if m else None


def number(body, key):
    m = re.search(r"\b" + key + r"\s+([-+0-9.eE]+)\s*;", body)
    return float(m.group(1)) if m else None


def overrides(case):
    """The run's `-set key=value` pairs, from its summary.json (shlex: quoted values)."""
    try:
        with open(os.path.join(case, "postProcessing/summary.json")) as f:
            command = json.load(f).get("commandLine", "")
    except (OSError, ValueError):
        return {}
    words = shlex.split(command)
    return dict(w.split("=", 1) for a, w in zip(words, words[1:]) if a == "-set" and "=" in w)


def main():
    args = sys.argv[1:]
    case, lo, hi, threshold, curve = ".", 2.0, 5.0, 1e-3, False
    while args:
        a = args.pop(0)
        if a == "--from":
            lo = float(args.pop(0))
        elif a == "--to":
            hi = float(args.pop(0))
        elif a == "--threshold":
            threshold = float(args.pop(0))
        elif a == "--curve":
            curve = True
        else:
            case = a
    walls = open(os.path.join(case, "constant/walls")).read()
    bodies = open(os.path.join(case, "constant/bodies")).read()
    material = block(block(bodies, "soil"), "material")
    soil = block(open(os.path.join(case, "system/particlesDict")).read(), "soil")
    velocity = -vector(block(walls, "retainer"), "velocity")[0]
    rho = number(material, "rho")
    phi = number(material, "frictionAngle")
    gravity = abs(vector(bodies, "gravity")[1])
    height = vector(soil, "max")[1] - vector(soil, "min")[1]
    given = overrides(case)
    if "walls.retainer.velocity" in given:
        velocity = -float(given["walls.retainer.velocity"].strip("()").split()[0])
    if "bodies.soil.material.frictionAngle" in given:
        phi = float(given["bodies.soil.material.frictionAngle"])
    if velocity <= 0:
        sys.exit("thrust.py: the retainer does not move away from the soil (velocity x >= 0)")
    ka = (1 - math.sin(math.radians(phi))) / (1 + math.sin(math.radians(phi)))
    scale = 2.0 / (rho * gravity * height * height)

    table = os.path.join(case, "postProcessing/walls/walls.dat")
    header, rows = None, []
    for line in open(table):
        if line.startswith("#"):
            header = line[1:].split()
        elif line.strip():
            rows.append([float(v) for v in line.split()])
    column = header.index("retainer_Fx")
    points = [(1000.0 * velocity * r[0], scale * r[column]) for r in rows]
    window = [k for d, k in points if lo <= d <= hi]
    if not window:
        sys.exit(f"thrust.py: no rows with a wall displacement in [{lo}, {hi}] mm (the run is too short?)")
    mean = sum(window) / len(window)
    print(f"K over wall displacement {lo:g}-{hi:g} mm: mean {mean:.4f} (range {min(window):.4f}-{max(window):.4f}), "
          f"Rankine K_a = {ka:.4f}, error {100 * (mean - ka) / ka:+.1f} %")
    if curve:
        with open(os.path.join(case, "postProcessing/walls/curve.dat"), "w") as out:
            out.write("# wallDisplacement_mm K\n")
            for d, k in points:
                out.write(f"{d:.6g} {k:.6g}\n")

    snapshots = glob.glob(os.path.join(case, "postProcessing/particles/particles_*.dat"))
    if not snapshots:
        return
    last = max(snapshots, key=lambda f: float(re.search(r"particles_(.*)\.dat", f).group(1)))
    names = open(last).readline()[1:].split()
    ix, iy, ip = names.index("x"), names.index("y"), names.index("plasticStrain")
    with open(os.path.join(case, "postProcessing/summary.json")) as f:
        spacing = json.load(f)["spacing"]
    rowsOf = {}
    for line in open(last):
        if line.startswith("#") or not line.strip():
            continue
        v = [float(t) for t in line.split()]
        rowsOf.setdefault(round(v[iy] / spacing - 0.5), []).append((v[ix], v[iy], v[ip]))
    edge = []  # the band's centre: in each row, where the plastic strain peaks within x <= H
    for row in rowsOf.values():
        near = [(strain, x, y) for x, y, strain in row if x <= height]
        if not near:
            continue
        strain, x, y = max(near)
        if strain > threshold and 0.2 * height <= y <= 0.8 * height:
            edge.append((x, y))
    if len(edge) < 3:
        print(f"wedge: fewer than 3 rows between 0.2 H and 0.8 H with a plastic strain above {threshold:g}")
        return
    n = len(edge)
    my = sum(y for _, y in edge) / n
    mx = sum(x for x, _ in edge) / n
    slope = sum((y - my) * (x - mx) for x, y in edge) / sum((y - my) ** 2 for _, y in edge)  # dx/dy
    angle = math.degrees(math.atan2(1.0, slope))  # the band rises away from the wall: dx/dy > 0
    print(f"wedge (plastic strain > {threshold:g}, {n} rows, {os.path.basename(last)}): "
          f"{angle:.1f} degrees from the horizontal, Rankine {45 + phi / 2:.1f}")


if __name__ == "__main__":
    main()
