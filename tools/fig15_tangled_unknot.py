#!/usr/bin/env python3
"""Writes scenes/fig15-tangled-unknot.curve: the exercise of the paper's Fig. 15.

The curve is a two-strand band wound round most of a circle, its strands twisting about each other
through eight crossings, closed by a cap at each end (the plat closure of a two-strand braid). The
crossings are chosen so that the braid is s s^-1 s^-1 s s s^-1 s^-1 s, whose exponents add up to 0:
at crossings 0-1, 2-3, 4-5 and 6-7 one strand lies over the other at both, a Reidemeister II pair.
Dragging that strand's arc off the other (laterally, in the picture) removes both crossings, and
after four such drags the picture has none: it is the unknot, though it looks like a tangle.

Run: python3 tools/fig15_tangled_unknot.py > scenes/fig15-tangled-unknot.curve
"""
import math

EXPONENTS = [1, -1, -1, 1, 1, -1, -1, 1]  # the braid's, crossing by crossing along the band
R, r, H = 2.0, 0.6, 0.35                  # circle radius, band half-width, depth at crossings
SPAN = math.radians(300)                  # how far round the circle the band goes
STEP = 0.1                                # spacing of the points, scene units


def strand_one_depth(theta):
    """Strand 1's depth sign at twist angle theta (strand 2's is its negative)."""
    q = len(EXPONENTS)
    # Strand 1 goes from outside in at even crossings, from inside out at odd ones; the strand
    # going from outside in is over for a positive exponent.
    over = [e if k % 2 == 0 else -e for k, e in enumerate(EXPONENTS)]
    x = theta / math.pi - 0.5  # crossing k at x = k
    if x <= 0:
        return over[0]
    if x >= q - 1:
        return over[-1]
    k = math.floor(x)
    f = x - k
    return over[k] + (over[k + 1] - over[k]) * 0.5 * (1 - math.cos(math.pi * f))


def point(phi, radial, z):
    return ((R + radial) * math.cos(phi), (R + radial) * math.sin(phi), z)


def main():
    q = len(EXPONENTS)
    n_strand = int(round(R * SPAN * 1.12 / STEP))
    n_cap = int(round(math.pi * r / STEP))
    pts = []
    for sign, forward in ((1, True), (-1, False)):  # strand 1 out, strand 2 back
        for i in range(n_strand):
            u = i / n_strand if forward else 1 - i / n_strand
            theta = q * math.pi * u
            pts.append(point(SPAN * u, sign * r * math.cos(theta), sign * H * strand_one_depth(theta)))
        # The cap at the end just reached: a half circle beyond it, its depth going over to the
        # other strand's.
        end = 1.0 if forward else 0.0
        theta = q * math.pi * end
        z0 = sign * H * strand_one_depth(theta)
        c = math.cos(theta) * sign  # the radial side this strand ends on, ±1
        for j in range(n_cap):
            a = math.pi * j / n_cap
            bulge = (1 if forward else -1) * r * math.sin(a) / R
            pts.append(point(SPAN * end + bulge, c * r * math.cos(a), z0 * math.cos(a)))
    print("# The exercise of the paper's Fig. 15: a tangled curve that is the unknot.")
    print("# Made by tools/fig15_tangled_unknot.py (the plat closure of s s^-1 s^-1 s s s^-1 s^-1 s).")
    for x, y, z in pts:
        print(f"{x:.6f} {y:.6f} {z:.6f}")


if __name__ == "__main__":
    main()
