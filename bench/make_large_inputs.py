#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Writes the large valid inputs of docs/robustness.md "Speed" into DIR (default .):
#   frf-100k.csv      100,000-point velocity-loop FRF (T = L/(1+L)) of the two-inertia open loop of
#                     bench/bench_notch.cpp, 1 Hz .. 2 kHz, ±0.2 dB deterministic ripple, for `notch`;
#   ballbar-1e6.csv   1,000,000-row CCW ball-bar trace of bench/bench_ballbar_large.cpp (R 100 mm,
#                     4 µm reversal steps, 2 µm cyclic error of 20 mm pitch), for `ballbar`.
# Usage: python3 bench/make_large_inputs.py /tmp/big
import cmath
import math
import sys

out = sys.argv[1] if len(sys.argv) > 1 else "."

n = 100_000
wr, wa = 2 * math.pi * 400.0, 2 * math.pi * 250.0
with open(f"{out}/frf-100k.csv", "w") as f:
    f.write("# units=1\n# measurement=complementary\nf_Hz,re,im,mag_dB,phase_deg,coherence,valid\n")
    for i in range(n):
        hz = 1.0 + 1999.0 * i / (n - 1)
        s = complex(0.0, 2 * math.pi * hz)
        L = 2.0e5 * (s * s + 2 * 0.05 * wa * s + wa * wa) / (s * s * (s * s + 2 * 0.03 * wr * s + wr * wr)) * (wr * wr / (wa * wa))
        L *= 10 ** (0.01 * math.sin(0.7 * i))
        T = L / (1 + L)
        f.write(f"{hz!r},{T.real!r},{T.imag!r},,,0.99,1\n")

rows = 1_000_000
with open(f"{out}/ballbar-1e6.csv", "w") as f:
    f.write("# radius_mm=100\n# feed_mm_min=1000\n# direction=ccw\nangle_deg,deviation_um\n")
    for i in range(rows):
        deg = 360.0 * i / rows
        th = math.radians(deg)
        x = 100.0 * math.cos(th)
        dev = 2.0 * math.sin(x / 20.0 * 2 * math.pi) * math.cos(th)
        dev += (2.0 if math.sin(th) > 0 else -2.0) * abs(math.cos(th)) + (2.0 if math.cos(th) > 0 else -2.0) * abs(math.sin(th))
        dev += 0.1 * math.sin(0.37 * i)
        f.write(f"{deg!r},{dev!r}\n")
