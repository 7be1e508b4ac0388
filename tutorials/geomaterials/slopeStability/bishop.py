#!/usr/bin/env python3
"""Bishop's simplified method of slices for this slope (docs/theory/geotechnics.md (E2.2)).

An independent limit-equilibrium factor of safety: circular slip surfaces, interslice forces
horizontal, F = sum[(c b + W tan phi)/m_alpha] / sum W sin(alpha), m_alpha = cos(alpha) +
sin(alpha) tan(phi)/F, solved by fixed-point iteration; F_s is the least F over the circles
that stay above the rigid base (y >= 0) and in front of the back boundary (x >= 0). A grid of
centres and radii, then a pattern search. Writes the critical circle's arc to bishopCircle.dat
(x y) for plot.gp.

    python3 bishop.py            # prints F_s and the circle (about 3 s)
"""
import math

GAMMA = 2038.7 * 9.81      # unit weight [N/m^3]
COHESION = 10e3            # c' [Pa]
PHI = math.radians(20.0)   # phi'
# The ground surface: crest y = 10 to x = 12, the 2:1 face to the toe at (32, 0), then the base.
SURFACE = [((0.0, 10.0), (12.0, 10.0)), ((12.0, 10.0), (32.0, 0.0)), ((32.0, 0.0), (80.0, 0.0))]


def ground(x):
    return 10.0 if x <= 12.0 else 0.0 if x >= 32.0 else 10.0 - (x - 12.0) / 2.0


def crossings(xc, yc, r):
    """Where the circle's lower arc meets the ground surface."""
    found = []
    for (x1, y1), (x2, y2) in SURFACE:
        dx, dy = x2 - x1, y2 - y1
        fx, fy = x1 - xc, y1 - yc
        a, b, c = dx * dx + dy * dy, 2 * (fx * dx + fy * dy), fx * fx + fy * fy - r * r
        disc = b * b - 4 * a * c
        if disc < 0:
            continue
        for t in ((-b - math.sqrt(disc)) / (2 * a), (-b + math.sqrt(disc)) / (2 * a)):
            if 0.0 <= t <= 1.0 and y1 + t * dy < yc:
                found.append(x1 + t * dx)
    return found


def safety(xc, yc, r, slices):
    """Bishop's F of one circle, or None if it is not an admissible slip surface."""
    if yc - r < 0.0:
        return None  # through the rigid base
    xs = crossings(xc, yc, r)
    if len(xs) < 2:
        return None
    left, right = min(xs), max(xs)
    if left < 0.0 or right - left < 1.0:
        return None
    width = (right - left) / slices
    terms, driving = [], 0.0
    for i in range(slices):
        x = left + (i + 0.5) * width
        height = ground(x) - (yc - math.sqrt(max(r * r - (x - xc) ** 2, 0.0)))
        if height <= 0.0:
            continue
        weight = GAMMA * height * width
        # the base's inclination, positive where it descends towards the toe (+x)
        alpha = math.asin((xc - x) / r)
        terms.append((weight, alpha))
        driving += weight * math.sin(alpha)
    if driving <= 0.0:
        return None
    F = 1.5
    for _ in range(200):
        resisting = sum((COHESION * width + w * math.tan(PHI)) /
                        (math.cos(a) + math.sin(a) * math.tan(PHI) / F) for w, a in terms)
        F, previous = resisting / driving, F
        if abs(F - previous) < 1e-12:
            break
    return F, left, right


def main():
    best = None
    for xc in range(10, 41):
        for yc in range(10, 41):
            r = 1.0
            while r <= yc:
                s = safety(float(xc), float(yc), r, 40)
                if s and (best is None or s[0] < best[0]):
                    best = (s[0], float(xc), float(yc), r)
                r += 0.5
    step = 0.5
    while step > 1e-3:
        improved = False
        for dx in (-step, 0.0, step):
            for dy in (-step, 0.0, step):
                for dr in (-step, 0.0, step):
                    s = safety(best[1] + dx, best[2] + dy, best[3] + dr, 400)
                    if s and s[0] < best[0] - 1e-12:
                        best = (s[0], best[1] + dx, best[2] + dy, best[3] + dr)
                        improved = True
        if not improved:
            step /= 2
    F, left, right = safety(best[1], best[2], best[3], 2000)
    xc, yc, r = best[1:]
    print("Bishop's simplified method: F_s = %.3f, critical circle centre (%.2f, %.2f) m, "
          "radius %.2f m, from x = %.2f m on the crest to x = %.2f m on the face"
          % (F, xc, yc, r, left, right))
    with open("bishopCircle.dat", "w") as out:
        out.write("# x y: Bishop's critical circle (F_s = %.4f)\n" % F)
        for i in range(201):
            x = left + (right - left) * i / 200
            out.write("%.4f %.4f\n" % (x, yc - math.sqrt(max(r * r - (x - xc) ** 2, 0.0))))


if __name__ == "__main__":
    main()
