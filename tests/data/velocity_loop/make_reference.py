#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Independent reference for core/tuning/VelocityLoopDesign (issue 18 item 1) and `axistune-cli velocity-loop`.

Python standard library only (cmath, bisection); nothing from AxisTune. Writes
  reference.json         the expected PI gains and margins
  plant_rigid.csv        torque -> motor velocity P = e^{-s tau_m}/(J s), measurement=plant
  complementary.csv      T = C_d P/(1 + C_d P) of the running discrete PI, measurement=complementary
                         (injection_hold_corrected=true, as the drives write it)

Case "inertia": chapter 5 rule (spec/lost-motion-and-two-inertia.md 2.8, corrected 5.13)
  K_P = k sqrt2 w_l J,  K_I = k w_l^2 J, rigid model P = e^{-s 1.5 T_v}/(J s),
  margins of L = (K_P + K_I/s) P found on the continuous function (bisection), before (running PI) and after.
Case "margins": PI with |C P| = 1 and arg(C P) = -180 + PM at f_c on the plant above (TI-5 4.12):
  arg C = -180 + PM - arg P,  K_I/(K_P w) = tan(-arg C),  |C| = 1/|P|.
"""
import cmath
import json
import math

TWO_PI = 2.0 * math.pi
TV = 250e-6          # velocity period [s]
TC = 62.5e-6         # current period [s]
RUNNING = (0.8, 75.0)  # running PI (sim:vmc X's velocity.kp, velocity.ki)


def pi_c(kp, ki, f):
    return kp + ki / complex(0.0, TWO_PI * f)


def pi_discrete(kp, ki, f):
    zinv = cmath.exp(complex(0.0, -TWO_PI * f * TV))
    return kp + ki * TV / (1.0 - zinv)


def rigid(j, tau, f):
    s = complex(0.0, TWO_PI * f)
    return cmath.exp(-s * tau) / (j * s)


def phase_deg_L(kp, ki, tau, f):
    # arg L = -90 (integrator) - w tau + arg C, continuous (no wrapping)
    w = TWO_PI * f
    return -90.0 - math.degrees(w * tau) - math.degrees(math.atan2(ki / w, kp))


def bisect(fun, a, b):
    fa = fun(a)
    for _ in range(200):
        m = math.sqrt(a * b)
        fm = fun(m)
        if (fm > 0) == (fa > 0):
            a, fa = m, fm
        else:
            b = m
    return math.sqrt(a * b)


def margins(kp, ki, j, tau):
    L = lambda f: pi_c(kp, ki, f) * rigid(j, tau, f)
    fc = bisect(lambda f: abs(L(f)) - 1.0, 1.0, 2000.0)
    pm = 180.0 + phase_deg_L(kp, ki, tau, fc)
    fp = bisect(lambda f: phase_deg_L(kp, ki, tau, f) + 180.0, 1.0, 2000.0)
    gm = -20.0 * math.log10(abs(L(fp)))
    return {"crossover_Hz": fc, "phase_margin_deg": pm, "phase_crossover_Hz": fp, "gain_margin_dB": gm}


def main():
    ref = {}
    # Inertia rule.
    j, wl, k = 1e-3, TWO_PI * 24.0, 10.0
    tau = 1.5 * TV
    kp, ki = k * math.sqrt(2.0) * wl * j, k * wl * wl * j
    ref["inertia"] = {"Jm_kgm2": j, "bandwidth_Hz": 24.0, "k": k, "kp": kp, "ki": ki,
                      "margins_before": margins(*RUNNING, j, tau), "margins_after": margins(kp, ki, j, tau)}
    # Margins rule on a measured rigid plant.
    jp, taum, fc, pm = 2e-3, 250e-6, 60.0, 50.0
    p = rigid(jp, taum, fc)
    argc = -180.0 + pm - math.degrees(cmath.phase(p))  # cmath.phase in (-180, 180]: P is near -90 - 5.4 deg
    ratio = math.tan(math.radians(-argc))               # K_I/(K_P w)
    mag_c = 1.0 / abs(p)
    kp2 = mag_c / math.sqrt(1.0 + ratio * ratio)
    ki2 = kp2 * ratio * TWO_PI * fc
    ref["margins"] = {"Jm_plant_kgm2": jp, "tau_plant_s": taum, "crossover_Hz": fc, "phase_margin_deg": pm,
                      "kp": kp2, "ki": ki2}
    freqs = [5.0 * i for i in range(1, 201)]  # 5 .. 1000 Hz, f_c = 60 Hz is a line
    with open("plant_rigid.csv", "w") as fh:
        fh.write("# measurement=plant\n# source=tests/data/velocity_loop/make_reference.py\n")
        fh.write("f_Hz,re,im,mag_dB,phase_deg,coherence,valid\n")
        for f in freqs:
            h = rigid(jp, taum, f)
            fh.write("%r,%r,%r,%r,%r,,1\n" % (f, h.real, h.imag, 20 * math.log10(abs(h)), math.degrees(cmath.phase(h))))
    with open("complementary.csv", "w") as fh:
        fh.write("# measurement=complementary\n# injection_hold_corrected=true\n"
                 "# source=tests/data/velocity_loop/make_reference.py\n")
        fh.write("f_Hz,re,im,mag_dB,phase_deg,coherence,valid\n")
        for f in freqs:
            l = pi_discrete(*RUNNING, f) * rigid(jp, taum, f)
            t = l / (1.0 + l)
            fh.write("%r,%r,%r,%r,%r,,1\n" % (f, t.real, t.imag, 20 * math.log10(abs(t)), math.degrees(cmath.phase(t))))
    ref["running"] = {"kp": RUNNING[0], "ki": RUNNING[1], "velocity_period_s": TV, "current_period_s": TC}
    # Back-EMF constant of a torque constant (amplitude-invariant dq, k_t = 1.5 k_e), line-to-line rms per krpm.
    kt = 0.9
    ke = kt / 1.5
    ref["back_emf"] = {"kt_Nm_per_A": kt, "ke_V_s_per_rad": ke,
                       "V_per_krpm": ke * math.sqrt(1.5) * 1000.0 * TWO_PI / 60.0}
    with open("reference.json", "w") as fh:
        json.dump(ref, fh, indent=2, sort_keys=True)
        fh.write("\n")


if __name__ == "__main__":
    main()
