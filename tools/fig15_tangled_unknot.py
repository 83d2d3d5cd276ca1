#!/usr/bin/env python3
"""Writes scenes/fig15-tangled-unknot.curve: the exercise of the paper's Fig. 15.

The curve is the closure of a two-strand braid with seven crossings drawn round a circle, as the
torus knot T(2,7) is, but with crossings 1, 4 and 6 (counting from 0) turned over: the braid is
s^1 s^-1 s^1 s^1 s^-1 s^1 s^-1 = s^1, whose closure is the unknot, though its picture is a
seven-crossing star like the knot 7_1. Wherever a turned crossing follows an ordinary one, one
strand lies over the other at both: a Reidemeister II move, done by dragging that strand's arc
off the other, removes both; the last crossing goes by a Reidemeister I move.

Run: python3 tools/fig15_tangled_unknot.py > scenes/fig15-tangled-unknot.curve
"""
import math

Q = 7                                       # crossings
STANDARD = [True, False, True, True, False, True, False]  # False: the crossing is turned over
N = 280                                     # points
R, r, H = 2.0, 0.6, 0.35                    # circle radius, braid half-width, depth at crossings


def main():
    sigma = [0.0] * (2 * Q)
    for c in range(Q):
        sigma[c] = (1 if STANDARD[c] else -1) * (1 if c % 2 == 0 else -1)
        sigma[c + Q] = -sigma[c]
    print("# The exercise of the paper's Fig. 15: a tangled curve that is the unknot.")
    print("# Made by tools/fig15_tangled_unknot.py (the closure of the braid s s^-1 s s s^-1 s s^-1).")
    for i in range(N):
        u = 2.0 * i / N
        phi, theta = 2 * math.pi * u, Q * math.pi * u
        k_real = u * Q - 0.5
        k = math.floor(k_real)
        frac = k_real - k
        s0, s1 = sigma[k % (2 * Q)], sigma[(k + 1) % (2 * Q)]
        s = s0 + (s1 - s0) * 0.5 * (1 - math.cos(math.pi * frac))
        rho = R + r * math.cos(theta)
        print(f"{rho * math.cos(phi):.6f} {rho * math.sin(phi):.6f} {H * s:.6f}")


if __name__ == "__main__":
    main()
