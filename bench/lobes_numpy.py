#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Peer of bench/bench_lobes.cpp: the same SDM lobe computation in NumPy/SciPy (200 speeds 2000-5980 rpm,
Table 1 tool, a_e/D = 7/12 down milling, 4 teeth, 40 steps per period), written the straightforward way:
dense lifted step matrices D_i multiplied into the monodromy, scipy.linalg.expm, numpy.linalg.eigvals, bisection
to the same relative tolerance (1e-4). Run: /usr/bin/python3 bench/lobes_numpy.py [n_speeds]"""
import sys, time
import numpy as np
from scipy.linalg import expm

M, C, K = 0.40, 83.0, 30.1e6
NT, KT, KR = 4, 0.98e9, 0.294e9
IMM = 7.0 / 12.0
PHI_ST, PHI_EN = np.arccos(2 * IMM - 1), np.pi
KSTEPS, INTK = 40, 20

def kf_avg(theta0, dtheta):
    s = np.zeros((2, 2))
    for h in range(INTK):
        th = theta0 + dtheta * (h + 0.5) / INTK
        for j in range(NT):
            p = np.mod(th + 2 * np.pi * j / NT, 2 * np.pi)
            if PHI_ST < p < PHI_EN:
                sn, cs = np.sin(p), np.cos(p)
                s += np.array([[(KT * cs + KR * sn) * sn, (KT * cs + KR * sn) * cs],
                               [(-KT * sn + KR * cs) * sn, (-KT * sn + KR * cs) * cs]])
    return s / INTK

A = np.block([[np.zeros((2, 2)), np.eye(2)], [-K / M * np.eye(2), -C / M * np.eye(2)]])
B = np.vstack([np.zeros((2, 2)), np.eye(2) / M])
Cq = np.hstack([np.eye(2), np.zeros((2, 2))])

def rho(kfs, dt, ap):
    k = KSTEPS
    n = 4 + 2 * k
    F = np.eye(n)
    for i in range(k):
        bc = ap * B @ kfs[i]
        a1 = A - bc @ Cq
        aug = np.zeros((6, 6)); aug[:4, :4] = a1 * dt; aug[:4, 4:] = bc * dt
        e = expm(aug)
        D = np.zeros((n, n))
        D[:4, :4] = e[:4, :4]
        D[:4, n - 4:n - 2] = 0.5 * e[:4, 4:]
        D[:4, n - 2:n] = 0.5 * e[:4, 4:]
        D[4:6, :4] = Cq
        D[6:, 4:n - 2] = np.eye(2 * k - 2)
        F = D @ F
    return np.max(np.abs(np.linalg.eigvals(F)))

def limit(rpm):
    tau = 60.0 / (rpm * NT); dt = tau / KSTEPS; dth = 2 * np.pi / (NT * KSTEPS)
    kfs = [kf_avg(i * dth, dth) for i in range(KSTEPS)]
    lo, hi = 0.0, 1e-3
    while rho(kfs, dt, hi) < 1.0:
        lo, hi = hi, 2 * hi
    while (hi - lo) > 1e-4 * hi:
        mid = 0.5 * (lo + hi)
        if rho(kfs, dt, mid) < 1.0:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)

if __name__ == '__main__':
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 200
    rpms = [2000.0 + 20.0 * i * 200 / n for i in range(n)]
    t0 = time.perf_counter()
    res = [limit(r) for r in rpms]
    t1 = time.perf_counter()
    print(f"{n} speeds: {t1 - t0:.2f} s (per speed {1e3 * (t1 - t0) / n:.1f} ms); 2800 rpm check: {limit(2800.0) * 1e3:.4f} mm")
