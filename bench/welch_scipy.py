#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Peer timing for bench/bench_welch.cpp and `axistune-cli frf`: H1 + coherence with scipy.signal.

  /usr/bin/python3 bench/welch_scipy.py --write /tmp/welch_bench.csv      # make the capture (2^21 samples)
  /usr/bin/python3 bench/welch_scipy.py --csv /tmp/welch_bench.csv        # time scipy on it
  /usr/bin/python3 bench/welch_scipy.py --csv /tmp/welch_bench.csv --compare /tmp/frf.csv   # same numbers?

Settings are those of the benchmark: fs = 4000 Hz, nperseg = 4096, noverlap = 2048, periodic Hann,
detrend='constant'. Timings: the best of --repeat runs of the computation on arrays in memory
(csd + welch + welch, as scipy.signal.coherence does), and once the whole job including np.loadtxt.
"""
import argparse
import time

import numpy as np
import scipy.signal as sig

FS = 4000.0
NPERSEG = 4096
N = 1 << 21


def write(path):
    rng = np.random.default_rng(7)
    x = rng.standard_normal(N)
    b, a = sig.butter(2, [300.0, 500.0], btype="bandpass", fs=FS)
    y = sig.lfilter(b, a, x) + 0.1 * rng.standard_normal(N)
    with open(path, "w") as f:
        f.write("# fs_Hz=4000\n")
        f.write("torque_cmd_Nm,motor_vel_rad_s\n")
        for xi, yi in zip(x.tolist(), y.tolist()):
            f.write("%r,%r\n" % (xi, yi))


def h1_coherence(x, y):
    kw = dict(fs=FS, window="hann", nperseg=NPERSEG, noverlap=NPERSEG // 2, detrend="constant")
    f, pxy = sig.csd(x, y, **kw)
    _, pxx = sig.welch(x, **kw)
    _, pyy = sig.welch(y, **kw)
    return f, pxy / pxx, np.abs(pxy) ** 2 / pxx / pyy


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--write")
    ap.add_argument("--csv")
    ap.add_argument("--compare")
    ap.add_argument("--repeat", type=int, default=5)
    a = ap.parse_args()
    if a.write:
        write(a.write)
        print("wrote", a.write)
        return
    t0 = time.perf_counter()
    data = np.loadtxt(a.csv, delimiter=",", skiprows=2)
    x, y = data[:, 0].copy(), data[:, 1].copy()
    f, h1, coh = h1_coherence(x, y)
    whole = time.perf_counter() - t0
    best = min(timed(lambda: h1_coherence(x, y)) for _ in range(a.repeat))
    print("samples %d  scipy H1+coherence (arrays in memory, best of %d): %.1f ms" % (len(x), a.repeat, best * 1e3))
    print("scipy whole job incl. np.loadtxt: %.2f s" % whole)
    if a.compare:
        with open(a.compare) as fh:
            rows = [ln for ln in fh if not ln.startswith("#")][1:]  # drop metadata and the header
        got = np.array([[float(c) for c in ln.split(",")[:6]] for ln in rows])[:, [0, 1, 2, 5]]
        ref_h = h1[1:]
        h = got[:, 1] + 1j * got[:, 2]
        assert np.array_equal(got[:, 0], f[1:]), "frequency grids differ"
        print("max relative difference |H1 - H1_scipy|/|H1_scipy| = %.3g" % np.max(np.abs(h - ref_h) / np.abs(ref_h)))
        print("max relative difference coherence = %.3g" % np.max(np.abs(got[:, 3] - coh[1:]) / coh[1:]))


def timed(fn):
    t = time.perf_counter()
    fn()
    return time.perf_counter() - t


if __name__ == "__main__":
    main()
