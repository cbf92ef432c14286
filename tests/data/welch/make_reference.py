#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Reference values for the Welch H1/H2/coherence tests (tests/core/dsp/test_welch.cpp).

Run with Debian's python3-scipy:  /usr/bin/python3 tests/data/welch/make_reference.py
Writes input.csv (x, y) and one ref_<case>.csv per case with scipy.signal.csd / welch / coherence
results; the C++ tests read these files and need no Python.
"""
import os

import numpy as np
import scipy
import scipy.signal as sig

HERE = os.path.dirname(os.path.abspath(__file__))
FS = 4000.0
N = 6000

rng = np.random.default_rng(20240601)
x = rng.standard_normal(N) + 0.3
# a lightly damped second-order system plus independent measurement noise and an offset
b, a = sig.butter(2, [300.0, 500.0], btype="bandpass", fs=FS)
y = 2.0 * sig.lfilter(b, a, x) + 0.05 * np.cumsum(rng.standard_normal(N)) / 50 + 0.1 * rng.standard_normal(N) - 1.5

with open(os.path.join(HERE, "input.csv"), "w") as f:
    f.write("# fs_Hz=%r\n# generator=make_reference.py scipy %s numpy %s\n" % (FS, scipy.__version__, np.__version__))
    f.write("x,y\n")
    for xi, yi in zip(x, y):
        f.write("%r,%r\n" % (float(xi), float(yi)))

# name, nperseg, noverlap (None = scipy default), window
CASES = [
    ("hann256", 256, None, "hann"),
    ("hann500_ov100", 500, 100, "hann"),
    ("hann255_odd", 255, None, "hann"),
    ("boxcar128_ov0", 128, 0, "boxcar"),
]

for name, nperseg, noverlap, window in CASES:
    kw = dict(fs=FS, window=window, nperseg=nperseg, noverlap=noverlap, detrend="constant")
    f, pxy = sig.csd(x, y, **kw)
    _, pxx = sig.welch(x, **kw)
    _, pyy = sig.welch(y, **kw)
    _, coh = sig.coherence(x, y, **kw)
    h1 = pxy / pxx
    h2 = pyy / np.conj(pxy)
    with open(os.path.join(HERE, "ref_%s.csv" % name), "w") as out:
        out.write("# nperseg=%d\n# noverlap=%s\n# window=%s\n" % (nperseg, "default" if noverlap is None else noverlap, window))
        out.write("f_Hz,pxx,pyy,pxy_re,pxy_im,h1_re,h1_im,h2_re,h2_im,coherence\n")
        for row in zip(f, pxx, pyy, pxy.real, pxy.imag, h1.real, h1.imag, h2.real, h2.imag, coh):
            out.write(",".join("%r" % float(v) for v in row) + "\n")
print("wrote", len(CASES), "reference files")
