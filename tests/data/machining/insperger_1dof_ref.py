#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Independent reference for the classic one-direction milling benchmark (Insperger & Stépán 2004,
# "Updated semi-discretization method for periodic delay-differential equations with discrete delay",
# IJNME 61:117-141; the same parameters are used by the full-discretization papers that followed):
# a tool flexible in x (the feed direction) only, m = 0.03993 kg, f_n = 922 Hz, zeta = 0.011, 2 teeth,
# K_t = 6e8 N/m^2, K_n = 2e8 N/m^2, slotting (a/D = 1) down milling; their chart spans 5000-10000 rpm and
# 0-4 mm. Written here from the equations, not from any published code, as a scalar 1-DOF delay
# equation  x'' + 2 zeta w0 x' + w0^2 x = -(w h(t)/m) (x(t) - x(t - tau)),
#   h(t) = sum_j g_j sin(phi_j) (K_t cos(phi_j) + K_n sin(phi_j))   (spec eq. (1-6), element 11),
# discretized by the first-order semi-discretization (x(t - tau) linear between the two delayed samples on
# each step; h averaged over each step by 200-point midpoint quadrature), monodromy matrix built
# explicitly, limit depth by bisection on its spectral radius = 1.
# Run: /usr/bin/python3 tests/data/machining/insperger_1dof_ref.py > tests/data/machining/insperger_1dof_ref.out
import numpy as np
from scipy.linalg import expm

m_t, fn, zeta = 0.03993, 922.0, 0.011
w0 = 2 * np.pi * fn
N, Kt, Kn = 2, 6e8, 2e8
phi_st, phi_ex = 0.0, np.pi  # slotting: down milling arccos(2*1-1) = 0 .. pi
STEPS = 120


def h_mean(t0, t1, omega_sp):
    s = np.linspace(t0, t1, 201)
    s = 0.5 * (s[1:] + s[:-1])
    tot = np.zeros_like(s)
    for j in range(N):
        phi = np.mod(omega_sp * s + 2 * np.pi * j / N, 2 * np.pi)
        g = (phi > phi_st) & (phi < phi_ex)
        tot += g * np.sin(phi) * (Kt * np.cos(phi) + Kn * np.sin(phi))
    return tot.mean()


def setup(rpm):
    tau = 60.0 / (N * rpm)
    dt = tau / STEPS
    omega_sp = rpm * 2 * np.pi / 60.0
    hs = [h_mean(i * dt, (i + 1) * dt, omega_sp) for i in range(STEPS)]
    return dt, hs


def rho(rpm, w, pre=None):
    dt, hs = pre if pre else setup(rpm)
    n = STEPS + 2  # [x_i, v_i, x_{i-1}, ..., x_{i-m}]
    Phi = np.eye(n)
    for h in hs:
        A = np.array([[0.0, 1.0], [-(w0 ** 2) - w * h / m_t, -2 * zeta * w0]])
        Bd = np.array([[0.0], [w * h / m_t]])  # input: x(t - tau)
        P = expm(A * dt)
        Ai = np.linalg.inv(A)
        F1 = Ai @ (P - np.eye(2))            # int_0^dt e^{A(dt-s)} ds
        F2 = dt * F1 - Ai @ (dt * P - F1)    # int_0^dt e^{A(dt-s)} s ds
        Rm = (F1 - F2 / dt) @ Bd             # weight of x_{i-m}
        Rm1 = (F2 / dt) @ Bd                 # weight of x_{i-m+1}
        D = np.zeros((n, n))
        D[0:2, 0:2] = P
        D[0:2, n - 1:n] += Rm
        D[0:2, n - 2:n - 1] += Rm1
        D[2, 0] = 1.0
        for k in range(3, n):
            D[k, k - 1] = 1.0
        Phi = D @ Phi
    return max(abs(np.linalg.eigvals(Phi)))


def limit_depth(rpm, hi=0.02):
    pre = setup(rpm)
    lo = 0.0
    if rho(rpm, hi, pre) < 1.0:
        return float("inf")
    for _ in range(40):
        mid = 0.5 * (lo + hi)
        if rho(rpm, mid, pre) < 1.0:
            lo = mid
        else:
            hi = mid
        if hi - lo < 1e-4 * hi:
            break
    return 0.5 * (lo + hi)


if __name__ == "__main__":
    print("# Insperger-Stepan 1-DOF slotting benchmark, first-order SDM, %d steps per tooth period" % STEPS)
    print("# rpm,limit_depth_m")
    for rpm in range(5000, 10001, 250):
        print("%d,%.6e" % (rpm, limit_depth(float(rpm))))
