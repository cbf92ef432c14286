#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Reference receptance of the real impact record (shared/data/real/impact_test_raw_time.csv) for
tests/core/dsp/test_impacttest.cpp, computed independently of AxisTune with numpy:
the whole record (51 200 samples at 51.2 kHz, the rate stated by the data's README), no window (the force
in the file is zero after the pulse), H = FFT(accel)/FFT(force), receptance = -H/(2 pi f)^2, DC excluded.
The largest |receptance| between 200 Hz and 2.5 kHz is the reference peak. The data's author published
the same measurement as H11 of shared/data/real/tooltip_frf_H11_H15.csv; its value at the peak frequency
is written too, as a second, fully external reference.

Run: /usr/bin/python3 tests/data/impact/make_reference.py   (writes ref_peak.csv next to this script)
"""
import os

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
# shared/data/real beside the repository, as the tests find it; AXISTUNE_REAL_DATA_DIR overrides it.
REAL = os.environ.get("AXISTUNE_REAL_DATA_DIR") or os.path.normpath(
    os.path.join(HERE, "..", "..", "..", "..", "shared", "data", "real"))

d = np.loadtxt(os.path.join(REAL, "impact_test_raw_time.csv"), delimiter=",", comments="#", skiprows=4)
force, accel = d[:, 1], d[:, 2]
fs = 51200.0
F = np.fft.rfft(force)
A = np.fft.rfft(accel)
f = np.fft.rfftfreq(len(force), 1.0 / fs)
R = np.zeros(len(f), dtype=complex)
R[1:] = -(A[1:] / F[1:]) / (2 * np.pi * f[1:]) ** 2
band = (f >= 200.0) & (f <= 2500.0)
k = np.argmax(np.abs(R) * band)

h = np.loadtxt(os.path.join(REAL, "tooltip_frf_H11_H15.csv"), delimiter=",", comments="#", skiprows=5)
fh = h[:, 0]
H11 = h[:, 1] + 1j * h[:, 2]
kh = int(np.argmin(np.abs(fh - f[k])))

with open(os.path.join(HERE, "ref_peak.csv"), "w") as out:
    out.write("# generator=make_reference.py numpy %s\n" % np.__version__)
    out.write("peak_Hz,peak_m_per_N,h11_at_peak_m_per_N,bin_Hz\n")
    out.write("%r,%r,%r,%r\n" % (float(f[k]), float(abs(R[k])), float(abs(H11[kh])), float(f[1] - f[0])))
print(open(os.path.join(HERE, "ref_peak.csv")).read())
