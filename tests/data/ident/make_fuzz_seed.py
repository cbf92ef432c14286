#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Writes fuzz-seed-motion.csv, the seed of the identify_capture fuzz target (tests/fuzz/targets/):
# 1000 samples at 1 kHz of a rigid axis (m = 2 kg, viscous 30 N*s/m, Coulomb 5 N, offset 1 N) driven
# back and forth, columns t_s, x_m, f_N in the capture CSV format (docs/formats.md). Small enough for
# libFuzzer's 64 KiB input limit; only a plausible starting point for mutation, not a reference.
import math

fs = 1000.0
n = 1000
m, b, fc, off = 2.0, 30.0, 5.0, 1.0
rows = []
for k in range(n):
    t = k / fs
    w = 2 * math.pi * 5.0
    x = 0.01 * math.sin(w * t)
    v = 0.01 * w * math.cos(w * t)
    a = -0.01 * w * w * math.sin(w * t)
    f = m * a + b * v + fc * (1 if v > 0 else -1 if v < 0 else 0) + off
    rows.append(f"{t:.6f},{x:.9g},{f:.9g}")
with open("fuzz-seed-motion.csv", "w") as out:
    out.write("t_s,x_m,f_N\n")
    out.write("\n".join(rows) + "\n")
