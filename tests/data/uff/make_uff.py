#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""An ASCII universal file with dataset 58 records, written from the dataset-58 specification
independently of AxisTune's reader (tests/core/io/test_uff58.cpp reads it back).

Run: /usr/bin/python3 tests/data/uff/make_uff.py
Writes frf.unv (records: FRF complex double even in mm/s^2 per N with units labels, FRF complex single
uneven without labels, a time response real double even, and a coherence record) and expected.csv: one
line per point "record,x,re,im" with the very decimal strings written into frf.unv, so that the C++ test
can compare the parsed doubles exactly.
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def e13(v):
    return "%13.5E" % v


def e20(v):
    return "%20.12E" % v


def header(lines, fun_type, resp_node, resp_dir, ref_node, ref_dir, ord_type, n, even, xmin, dx, axes):
    out = ["    -1", "    58"]
    out += [l[:80] for l in lines]
    out.append("%5d%10d%5d%10d %-10s%10d%4d %-10s%10d%4d" % (fun_type, 1, 1, 0, "NONE", resp_node, resp_dir, "NONE", ref_node, ref_dir))
    out.append("%10d%10d%10d%s%s%s" % (ord_type, n, 1 if even else 0, e13(xmin), e13(dx), e13(0.0)))
    for (dtype, lexp, fexp, label, units) in axes:
        out.append("%10d%5d%5d%5d %-20s %-20s" % (dtype, lexp, fexp, 0, label, units))
    return out


def rows(values, per_line):
    return ["".join(values[i:i + per_line]) for i in range(0, len(values), per_line)]


records = []
lines = []

# 1. FRF, complex double, even spacing, accelerance in mm/s^2 per N (labels), 0.5 Hz from 10 Hz
n = 7
xmin, dx = 10.0, 0.5
vals, exp = [], []
for i in range(n):
    f = xmin + i * dx
    h = 1.0 / complex(2.0e7 - 0.3 * (2 * math.pi * f) ** 2, 60.0 * 2 * math.pi * f) * -(2 * math.pi * f) ** 2 * 1000.0
    re, im = e20(h.real), e20(h.imag)
    vals += [re, im]
    exp.append((1, repr(float(e13(xmin)) + i * float(e13(dx))), re.strip(), im.strip()))
lines += header(["accelerance tip", "run 1", "25-Nov-26 18:00:00", "", ""], 4, 1, 1, 1, 1, 6, n, True, xmin, dx,
                [(18, 0, 0, "Frequency", "Hz"), (12, 1, 0, "Acceleration", "mm/s^2"), (13, 0, 1, "Force", "N"), (0, 0, 0, "NONE", "NONE")])
lines += rows(vals, 4)
lines.append("    -1")

# 2. FRF, complex single, uneven spacing, receptance, no units labels (SI by data type)
xs = [100.0, 150.5, 233.25, 400.0, 1000.0]
vals = []
for x in xs:
    h = 1.0 / complex(3.0e7 - 0.4 * (2 * math.pi * x) ** 2, 80.0 * 2 * math.pi * x)
    xv, re, im = e13(x), e13(h.real), e13(h.imag)
    vals += [xv, re, im]
    exp.append((2, xv.strip(), re.strip(), im.strip()))
lines += header(["receptance", "", "", "", ""], 4, 1, 2, 1, 2, 5, len(xs), False, 0.0, 0.0,
                [(18, 0, 0, "Frequency", ""), (8, 1, 0, "Displacement", ""), (13, 0, 1, "Force", ""), (0, 0, 0, "", "")])
lines += rows(vals, 6)
lines.append("    -1")

# 3. time response, real double, even, acceleration in g? no: m/s^2, 1/2048 s step
n = 9
vals = []
for i in range(n):
    v = e20(math.sin(0.7 * i) * 3.25 - 0.5)
    vals.append(v)
    # the abscissa is what the file states: minimum + i * increment, both as written with E13.5
    exp.append((3, repr(float(e13(0.0)) + i * float(e13(1.0 / 2048.0))), v.strip(), "0"))
lines += header(["accel", "", "", "", ""], 1, 5, 3, 0, 0, 4, n, True, 0.0, 1.0 / 2048.0,
                [(17, 0, 0, "Time", "s"), (12, 1, 0, "Acceleration", "m/s^2"), (0, 0, 0, "NONE", "NONE"), (0, 0, 0, "NONE", "NONE")])
lines += rows(vals, 4)
lines.append("    -1")

# a dataset the reader skips
lines += ["    -1", "   151", "model", "description", "    -1"]

with open(os.path.join(HERE, "frf.unv"), "w") as f:
    f.write("\n".join(lines) + "\n")
with open(os.path.join(HERE, "expected.csv"), "w") as f:
    f.write("record,x,re,im\n")
    for r in exp:
        f.write("%d,%s,%s,%s\n" % r)
