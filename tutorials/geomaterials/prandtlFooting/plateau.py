#!/usr/bin/env python3
"""The footing's bearing pressure against Prandtl's limit (2 + pi) c_u, from a finished run.

    python3 plateau.py [CASE] [--from 0.05] [--to 0.10] [--curve]

Reads CASE/postProcessing/walls/walls.dat (the wallForce table) and, from the case's own files,
the footing's velocity and start gap (constant/walls), its width B (the box's x extent) and c_u
= yieldStress / sqrt(3) (constant/bodies), and the command line of the run
(postProcessing/summary.json) so that `-set walls.footing.velocity=...` is honoured. The model
is the half problem (x = 0 a symmetry plane): the load on the whole footing per unit thickness
is -2 footing_Fy, the pressure q = -2 footing_Fy / B. Penetration = footing travel - start gap.
Prints the plateau: the mean of q / c_u over the rows whose penetration lies in [from, to] B
(the table's rows are equally spaced in time, so this is the time average over the window and
it averages the load's oscillation), its range in the window, and the error against 2 + pi.
--curve writes the curve (penetration/B, q/c_u) to CASE/postProcessing/walls/curve.dat for
plot.gp. Plain python3 (no numpy).
"""
import json
import math
import os
import re
import sys

PRANDTL = 2.0 + math.pi


def block(text, name):
    """The body of the first dictionary `name { ... }` in an OpenFOAM-style text."""
    text = re.sub(r"//[^\n]*", "", text)
    m = re.search(r"\b" + name + r"\s*\{", text)
    if not m:
        sys.exit(f"plateau.py: no '{name}' entry")
    depth, i = 1, m.end()
    while depth and i < len(text):
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        i += 1
    return text[m.end():i - 1]


def vector(body, key):
    m = re.search(r"\b" + key + r"\s*\(([^)]*)\)", body)
    return [float(v) for v in m.group(1).split()] if m else None


def main():
    args = sys.argv[1:]
    case, lo, hi, curve = ".", 0.05, 0.10, False
    while args:
        a = args.pop(0)
        if a == "--from":
            lo = float(args.pop(0))
        elif a == "--to":
            hi = float(args.pop(0))
        elif a == "--curve":
            curve = True
        else:
            case = a
    footing = block(open(os.path.join(case, "constant/walls")).read(), "footing")
    lower, upper = vector(footing, "min"), vector(footing, "max")
    velocity = vector(footing, "velocity")[1]
    soil = open(os.path.join(case, "constant/bodies")).read()
    yield_stress = float(re.search(r"\byieldStress\s+([-+0-9.eE]+)", soil).group(1))
    summary = os.path.join(case, "postProcessing/summary.json")
    if os.path.exists(summary):  # a -set of the footing's velocity (the rate sweep)
        command = json.load(open(summary)).get("commandLine", "")
        m = re.search(r"walls\.footing\.velocity=['\"]?\(\s*\S+\s+(\S+)\s*\)", command)
        if m:
            velocity = float(m.group(1))
    B = upper[0] - lower[0]
    gap = lower[1]  # the soil's surface is y = 0
    cu = yield_stress / math.sqrt(3.0)
    lines = open(os.path.join(case, "postProcessing/walls/walls.dat")).read().splitlines()
    header = [l for l in lines if l.startswith("#")][-1].split()[1:]
    fy = header.index("footing_Fy")
    rows = [[float(v) for v in l.split()] for l in lines if l.strip() and not l.startswith("#")]
    points = [((-velocity * r[0] - gap) / B, -2.0 * r[fy] / B / cu) for r in rows]
    if curve:
        with open(os.path.join(case, "postProcessing/walls/curve.dat"), "w") as out:
            out.write("# penetration/B q/c_u (q = -2 footing_Fy / B; Prandtl 2 + pi = %.4f)\n" % PRANDTL)
            for p, q in points:
                out.write(f"{p:.6g} {q:.6g}\n")
    window = [q for p, q in points if lo <= p <= hi]
    if not window:
        sys.exit(f"plateau.py: no row with penetration in [{lo}, {hi}] B (the run reached "
                 f"{points[-1][0]:.4f} B)")
    mean = sum(window) / len(window)
    print(f"velocity {-velocity:g} m/s, B {B:g} m, c_u {cu:g} Pa; {len(window)} rows with "
          f"penetration {lo:g}-{hi:g} B")
    print(f"plateau q/c_u = {mean:.4f} (range {min(window):.4f} to {max(window):.4f}); "
          f"Prandtl 2 + pi = {PRANDTL:.4f}; error {100.0 * (mean / PRANDTL - 1.0):+.2f} %")


main()
