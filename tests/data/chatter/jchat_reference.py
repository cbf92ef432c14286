#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Independent reference numbers for the chatter-avoidance unit tests (tests/core/machining/test_ChatterAvoidance.cpp):
#  - J_chat(rho) = sum_j w_j (r_j - round(r_j))^2, r_j = rho f_j / f_1 (spec eqs. (5-3), (5-4)), round half up;
#  - the search (5-6) over [rho_new - n_below, rho_new + n_above], tie -> least (rho - rho_new)^2;
#  - the ESC design (6-24) and the roots of s^3 + (h+k) s^2 + w^2 s + w^2 h (6-22);
#  - the modal-sum equivalent of the two-mode tool (5-1): k = 1/(2 zeta peak), m = k/wn^2, c = 2 zeta sqrt(k m).
# Run: /usr/bin/python3 tests/data/chatter/jchat_reference.py > tests/data/chatter/jchat_reference.txt
import math
import numpy as np

def rnd(x):
    return math.floor(x + 0.5)

def jchat(rho, f, w):
    # r_1 = rho exactly (the j = 1 term is zero by definition; computing rho*f1/f1 could leave one ulp)
    return sum(wj * (rho * fj / f[0] - rnd(rho * fj / f[0])) ** 2 for fj, wj in zip(f[1:], w[1:]))

def search(f, w, rpm, teeth, below, above):
    ftpe = teeth * rpm / 60.0
    rho_new = rnd(f[0] / ftpe)
    cands = [(r, jchat(r, f, w)) for r in range(max(1, rho_new - below), rho_new + above + 1)]
    best = min(cands, key=lambda c: (c[1], (c[0] - rho_new) ** 2, c[0]))
    return rho_new, best[0], best[1], 60.0 * f[0] / (best[0] * teeth), cands

print("case A: f = [1435.6, 1909.9], w = [1, 0.5]")
f, w = [1435.6, 1909.9], [1.0, 0.5]
for rho in (6, 7, 8, 9):
    print(f"  J({rho}) = {jchat(rho, f, w):.10g}")
rn, rp, j, rpm, c = search(f, w, 2800.0, 4, 1, 1)
print(f"  search at 2800 rpm, 4 teeth, widths 1/1: rho_new {rn}, rho_prop {rp}, J {j:.10g}, rpm {rpm:.10g}")
rn, rp, j, rpm, c = search(f, w, 2800.0, 4, 2, 1)
print(f"  search at 2800 rpm, 4 teeth, widths 2/1: rho_new {rn}, rho_prop {rp}, J {j:.10g}, rpm {rpm:.10g}")
print("case B (ties): f = [1000, 1500], w = [1, 1]; J even rho = 0, odd = 0.25")
f, w = [1000.0, 1500.0], [1.0, 1.0]
# rho_new = 4 at f_TPE = 250 Hz (3750 rpm, 4 teeth), widths 2/2 -> candidates 2..6, J(2)=J(4)=J(6)=0 -> 4
rn, rp, j, rpm, c = search(f, w, 3750.0, 4, 2, 2)
print(f"  at 3750 rpm widths 2/2: rho_new {rn}, rho_prop {rp}, J {j}, rpm {rpm:.10g}")
# rho_new = 3 at f_TPE = 333.33 Hz (5000 rpm), widths 1/1 -> J(2)=J(4)=0, equal distance -> lower rho (2)
rn, rp, j, rpm, c = search(f, w, 5000.0, 4, 1, 1)
print(f"  at 5000 rpm widths 1/1: rho_new {rn}, rho_prop {rp}, J {j}, rpm {rpm:.10g}")
print("case C: one frequency 1394.8 Hz at 2800 rpm -> J = 0, rho_prop = rho_new")
rn, rp, j, rpm, c = search([1394.8], [1.0], 2800.0, 4, 1, 1)
print(f"  rho_new {rn}, rho_prop {rp}, J {j}, rpm {rpm:.10g}")
print("ESC design (6-24), p_c = 8*2*pi")
pc = 8 * 2 * math.pi
h, k, wp = pc / 3, 8 * pc / 3, math.sqrt(3) * pc
print(f"  h_c {h:.10g} rad/s = {h / 2 / math.pi:.10g} Hz, k_c {k:.10g} 1/s, w_p {wp:.10g} rad/s = {wp / 2 / math.pi:.10g} Hz")
print("  roots of (6-22) denominator:", np.roots([1, h + k, wp ** 2, wp ** 2 * h]))
# Superseded: this all-positive sum puts the second mode 176 deg out of phase with the cascade (5-1); the sample
# tool and the tests now use the exact partial-fraction sum of cascade_tool.py (negative-residue second mode).
print("two-mode tool (5-1) as a modal sum with the same peaks, frequencies and damping")
for wn, z, pk in ((9020.0, 0.01, 1.149e-6), (12000.0, 0.006, 1.082e-6)):
    kk = 1 / (2 * z * pk)
    m = kk / wn ** 2
    print(f"  mass_kg {m:.10g} damping_Ns_per_m {2 * z * math.sqrt(kk * m):.10g} stiffness_N_per_m {kk:.10g}")
