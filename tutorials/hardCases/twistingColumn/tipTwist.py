#!/usr/bin/env python3
"""The top corner's twist about the column's axis, from the tip probe.

Usage: ./tipTwist.py [postProcessing/tip/tip.dat] [every]   (every: print interval [s], 0.025)
Prints time, the twist angle [deg] (unwrapped: one turn is 360), the corner's displacement,
and the largest and smallest twist.
"""
import math
import sys

path = sys.argv[1] if len(sys.argv) > 1 else "postProcessing/tip/tip.dat"
every = float(sys.argv[2]) if len(sys.argv) > 2 else 0.025
header = None
rows = []
for line in open(path):
    if line.startswith("#"):
        header = line[1:].split()
    elif line.strip():
        rows.append([float(v) for v in line.split()])
col = {name: i for i, name in enumerate(header)}
x, y = col["position_x"], col["position_y"]
first = math.atan2(rows[0][y], rows[0][x])
previous, turns, next_time = first, 0.0, 0.0
largest, smallest = (-math.inf, 0.0), (math.inf, 0.0)
print("# time [s]  twist [deg]  displacement x y z [m]")
for r in rows:
    angle = math.atan2(r[y], r[x])
    if angle - previous > math.pi:
        turns -= 2 * math.pi
    elif angle - previous < -math.pi:
        turns += 2 * math.pi
    previous = angle
    twist = math.degrees(angle + turns - first)
    largest = max(largest, (twist, r[0]))
    smallest = min(smallest, (twist, r[0]))
    if r[0] >= next_time - 1e-9:
        print(f"{r[0]:.3f}  {twist:+7.1f}  {r[col['displacement_x']]:+.3f} "
              f"{r[col['displacement_y']]:+.3f} {r[col['displacement_z']]:+.3f}")
        next_time += every
print(f"# largest twist {largest[0]:+.1f} deg at t = {largest[1]:.3f} s, "
      f"smallest {smallest[0]:+.1f} deg at t = {smallest[1]:.3f} s")
