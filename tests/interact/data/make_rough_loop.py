#!/usr/bin/env python3
"""Writes rough_loop_stroke.txt: a quick hand-drawn loop, as the ribbon sketch receives it.

No person drew it: it is made by a model of a hand on a mouse, written down here so that it can be
read and made again (python3 make_rough_loop.py > rough_loop_stroke.txt gives the same file).

- Four strokes between the corners of a rough quadrilateral about 1 across (the size of a sphere
  of radius 0.5 in the window's view), each a minimum-jerk reach (Flash and Hogan 1985: the speed
  profile of a quick point-to-point hand movement) of 0.4 to 0.5 s, bowed sideways by up to 0.02.
- A short stop (40 to 60 ms) at each corner; at the third the hand overshoots by 0.035 and comes
  back (a hook, as quick corners often have).
- Physiological tremor (two sines near 9 and 11 Hz, 0.0025 and 0.0015) and sensor noise (0.001),
  the cursor read on a grid of 0.004 (a pixel of the window's view at 1280x800).
- Sampled at 120 Hz (a mouse's report rate; the CLI's default --dt); the loop ends 0.07 short of
  and beside its start, as a hand closing a loop does.
"""
import math
import random

rng = random.Random(34)
RATE = 120.0
PIXEL = 0.004
corners = [(-0.45, -0.40), (0.50, -0.46), (0.44, 0.48), (-0.48, 0.42)]
end = (corners[0][0] + 0.03, corners[0][1] + 0.06)

samples = []  # (x, y) of the hand, one per 1/120 s


def hold(p, seconds):
    for _ in range(int(round(seconds * RATE))):
        samples.append(p)


def reach(a, b, seconds, bow):
    n = int(round(seconds * RATE))
    dx, dy = b[0] - a[0], b[1] - a[1]
    length = math.hypot(dx, dy)
    nx, ny = -dy / length, dx / length
    for k in range(1, n + 1):
        t = k / n
        s = 10 * t**3 - 15 * t**4 + 6 * t**5
        side = bow * math.sin(math.pi * s)
        samples.append((a[0] + s * dx + side * nx, a[1] + s * dy + side * ny))


hold(corners[0], 0.05)
path = corners[1:] + [end]
at = corners[0]
for i, target in enumerate(path):
    reach(at, target, rng.uniform(0.4, 0.5), rng.uniform(-0.02, 0.02))
    at = target
    if i == 1:  # the hook: past the corner along the way in, and back
        dx, dy = target[0] - corners[1][0], target[1] - corners[1][1]
        length = math.hypot(dx, dy)
        past = (target[0] + 0.035 * dx / length, target[1] + 0.035 * dy / length)
        reach(target, past, 0.06, 0.0)
        reach(past, target, 0.08, 0.0)
    hold(target, rng.uniform(0.04, 0.06))

phases = [rng.uniform(0, 2 * math.pi) for _ in range(4)]
print("# A rough hand-drawn loop with four corners (one with a hook) and tremor, in the plane z = 0")
print("# facing the eye on +z: x y z u at 120 Hz, no modifier. Made by make_rough_loop.py (a model of")
print("# a hand, not a recording; see there). Its ribbon 0.1 wide folds at the corners as drawn.")
for k, (x, y) in enumerate(samples):
    t = k / RATE
    x += 0.0025 * math.sin(2 * math.pi * 8.7 * t + phases[0]) + 0.0015 * math.sin(2 * math.pi * 11.3 * t + phases[1])
    y += 0.0025 * math.sin(2 * math.pi * 9.1 * t + phases[2]) + 0.0015 * math.sin(2 * math.pi * 10.9 * t + phases[3])
    x += rng.gauss(0, 0.001)
    y += rng.gauss(0, 0.001)
    x = round(x / PIXEL) * PIXEL
    y = round(y / PIXEL) * PIXEL
    print(f"{x:.3f} {y:.3f} 0 0")
