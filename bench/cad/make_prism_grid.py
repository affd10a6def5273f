#!/usr/bin/env python3
"""Writes an exact tessellation of N x N rounded-square prisms (4 planes, 4
rounds of 9 facets, fan caps: about 160 facets each) as OBJ with 17 digits,
for timing the exact-facet path on large inputs.
usage: make_prism_grid.py N OUT.obj"""
import math, sys

n, out = int(sys.argv[1]), sys.argv[2]
side, radius, steps, length = 7.5, 2.54, 9, 20.0
inner = side / 2 - radius
profile = [(-inner, -side / 2)]
centres = [(inner, -inner), (inner, inner), (-inner, inner), (-inner, -inner)]
for k in range(4):
    for j in range(steps + 1):
        if k == 3 and j == steps:
            break
        a = (k - 1 + j / steps) * math.pi / 2
        profile.append((centres[k][0] + radius * math.cos(a), centres[k][1] + radius * math.sin(a)))
m = len(profile)
with open(out, 'w') as f:
    base = 1
    for i in range(n):
        for j in range(n):
            ox, oy = 12.0 * i, 12.0 * j
            for x in (0.0, length):
                for (y, z) in profile:
                    f.write('v %.17g %.17g %.17g\n' % (x, ox + y, oy + z))
            f.write('v %.17g %.17g %.17g\n' % (0.0, ox, oy))
            f.write('v %.17g %.17g %.17g\n' % (length, ox, oy))
            c0, c1 = base + 2 * m, base + 2 * m + 1
            for a in range(m):
                b = (a + 1) % m
                f.write('f %d %d %d\n' % (base + a, base + b, base + m + b))
                f.write('f %d %d %d\n' % (base + a, base + m + b, base + m + a))
                f.write('f %d %d %d\n' % (c0, base + b, base + a))
                f.write('f %d %d %d\n' % (c1, base + m + a, base + m + b))
            base += 2 * m + 2
