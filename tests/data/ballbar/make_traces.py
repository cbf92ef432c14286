#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Reference ball-bar traces for the CLI end-to-end tests (tests/app/cli/test_ballbar.cpp) and the samples
in resources/samples/. Independent of the C++ code: exact geometry of an XY machine with injected errors.

Run from anywhere:  /usr/bin/python3 tests/data/ballbar/make_traces.py
Writes tests/data/ballbar/{ccw,cw,partial,lm_y_c200,lm_y_c400,lm_y_c600}.csv, injected.json and
resources/samples/ballbar-{ccw,cw}.csv.

Model (docs/ballbar.md): commanded angle phi; axis a follows its command delayed by tau_a; lost motion
L_a lags the axis against its motion (torque-synchronous transition after each reversal); scale
(1+eps_a) about the circle centre; squareness x += gamma*y; cyclic error on X; the bar measures
|p + offset| - R; a Gaussian spike after the Y reversal at 90 deg; seeded Gaussian noise.
"""
import json
import os

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))


def trace(ccw=True, R=0.1, feed_mm_min=1000.0, step_deg=0.25, start_deg=0.0, span_deg=360.0,
          offset=(0.0, 0.0), eps=(0.0, 0.0), gamma=0.0, tau=(0.0, 0.0), lost=(0.0, 0.0),
          lm_ab=None, lm_axis=1, dT=0.61, x0=0.0, centre=(0.0, 0.0), transition_deg=0.5,
          cyclic=(0.0, 0.012), spike=(0.0, 1.0, 1.5), noise=0.0, seed=1):
    sigma = 1.0 if ccw else -1.0
    v = feed_mm_min * 1e-3 / 60.0
    w = v / R
    n = int(round(span_deg / step_deg))
    phi = np.deg2rad(start_deg + sigma * step_deg * np.arange(n))
    ph = [phi - sigma * w * tau[0], phi - sigma * w * tau[1]]
    x = R * np.cos(ph[0])
    y = R * np.sin(ph[1])
    vel = [-sigma * np.sin(ph[0]), sigma * np.cos(ph[1])]
    pos = [x.copy(), y.copy()]
    for a in (0, 1):
        s = np.sign(vel[a])
        if lm_ab is not None and a == lm_axis:
            first = 0.0 if a == 0 else 0.5 * np.pi
            d = np.mod(sigma * (ph[a] - first), np.pi)
            torque = 0.5 * dT * s * (1.0 - 2.0 * np.exp(-d / np.deg2rad(transition_deg)))
            xs = x0 + centre[a] + (R * np.cos(ph[0]) if a == 0 else R * np.sin(ph[1]))
            pos[a] = pos[a] - (lm_ab[0] + lm_ab[1] * xs) * torque
        else:
            pos[a] = pos[a] - 0.5 * lost[a] * s
    x, y = pos
    x = x + cyclic[0] * np.sin(2 * np.pi * x / cyclic[1] + 0.3)
    x = x * (1 + eps[0])
    y = y * (1 + eps[1])
    x = x + gamma * y
    dr = np.hypot(x + offset[0], y + offset[1]) - R
    if spike[0] != 0.0:
        d = sigma * np.rad2deg(np.remainder(phi - 0.5 * np.pi + np.pi, 2 * np.pi) - np.pi) - spike[2]
        s = spike[1] / (2 * np.sqrt(2 * np.log(2)))
        dr = dr + spike[0] * np.exp(-0.5 * d * d / (s * s))
    rng = np.random.default_rng(seed)
    dr = dr + noise * rng.standard_normal(n)
    return np.rad2deg(phi), dr


def write(path, ang, dev, meta):
    with open(path, "w") as f:
        for k, val in meta.items():
            f.write(f"# {k}={val}\n")
        f.write("angle_deg,deviation_um\n")
        for a, d in zip(ang, dev):
            f.write(f"{a:.4f},{d * 1e6:.5f}\n")


def main():
    inj = dict(offset_um=[5.0, -3.0], scale_mismatch_ppm=60.0, radius_deviation_um=1.0,
               squareness_um_per_m=80.0, servo_mismatch_ms=0.5, backlash_x_um=3.0, backlash_y_um=-2.0,
               spike_y=dict(angle_deg_ccw=91.5, height_um=4.0, width_deg=1.2),
               cyclic_x=dict(amplitude_um=1.5, pitch_mm=12.0), noise_um=0.1)
    common = dict(offset=(5e-6, -3e-6), eps=(40e-6, -20e-6), gamma=80e-6, tau=(0.5e-3, 0.0),
                  lost=(3e-6, -2e-6), cyclic=(1.5e-6, 0.012), spike=(4e-6, 1.2, 1.5), noise=0.1e-6)
    meta = {"radius_mm": 100, "feed_mm_min": 1000, "plane": "XY", "center_x_mm": 0, "center_y_mm": 0}
    for name, ccw, start, seed in (("ccw", True, 0.0, 1), ("cw", False, 360.0, 2)):
        ang, dev = trace(ccw=ccw, start_deg=start, seed=seed, **common)
        m = dict(meta, direction="ccw" if ccw else "cw")
        write(os.path.join(HERE, f"{name}.csv"), ang, dev, m)
        write(os.path.join(ROOT, "resources", "samples", f"ballbar-{name}.csv"), ang, dev, m)
    ang, dev = trace(ccw=True, start_deg=-60.0, span_deg=220.0, lost=(2e-6, 0.0), noise=0.05e-6, seed=3)
    write(os.path.join(HERE, "partial.csv"), ang, dev, dict(meta, direction="ccw"))

    # Lost motion of Y at three table positions (thesis model, spec §1.7-1.8): A = 4.1 um/(N m),
    # B = 1.7e-5 1/(N m) (17 um/(N m m)), x0 = 0.05 m; circle centres y = 200, 400, 600 mm.
    lm = dict(A_m_per_Nm=4.1e-6, B_per_Nm=1.7e-5, x0_m=0.05, dT_Nm=[0.60, 0.61, 0.63], centres_mm=[200, 400, 600])
    for i, cy in enumerate(lm["centres_mm"]):
        ang, dev = trace(ccw=True, lm_ab=(4.1e-6, 1.7e-5), lm_axis=1, dT=lm["dT_Nm"][i], x0=0.05,
                         centre=(0.39, cy * 1e-3), lost=(1.1e-6, 0.0), noise=0.1e-6, seed=10 + i)
        m = dict(meta, direction="ccw", center_x_mm=390, center_y_mm=cy, dT_x_Nm=0.61, dT_y_Nm=lm["dT_Nm"][i])
        write(os.path.join(HERE, f"lm_y_c{cy}.csv"), ang, dev, m)
    inj["lost_motion_y"] = lm
    with open(os.path.join(HERE, "injected.json"), "w") as f:
        json.dump(inj, f, indent=2)
        f.write("\n")


if __name__ == "__main__":
    main()
