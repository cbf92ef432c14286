#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Builds resources/samples/vmc-profile.json from the simulator preset resources/machines/vmc.json:
the drive parameters of the preset (converted to SI), the lost-motion compensation set to the
preset's plant A/B (mode 2, proposed), and models from the preset's plant data. Filter and trace
settings, which the preset leaves at the simulator defaults, are sample values (documented in
docs/formats-profile.md). Run from the repository root, then make_expected.py:
    /usr/bin/python3 tests/data/nc/make_vmc_profile.py && /usr/bin/python3 tests/data/nc/make_expected.py
"""
import json
import os

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
TO_SI = {"1": 1.0, "A": 1.0, "V": 1.0, "Nm/A": 1.0, "ohm": 1.0, "mH": 1e-3, "V*s/rad": 1.0, "us": 1e-6,
         "ms": 1e-3, "s": 1.0, "V/A": 1.0, "V/(A*s)": 1.0, "Nm*s/rad": 1.0, "Nm/rad": 1.0, "kgm2": 1.0,
         "1/s": 1.0, "um/Nm": 1e-6, "um/(Nm*m)": 1e-6, "mm": 1e-3, "m": 1.0, "Nm": 1.0, "rad/s": 1.0,
         "Hz": 1.0}
# Sample settings the preset does not define (simulator defaults otherwise).
EXTRA = {"filter.notch1.center": 800.0, "filter.notch1.width": 200.0, "filter.notch1.depth": 0.1,
         "filter.notch2.center": 1500.0, "filter.notch2.width": 300.0, "filter.notch2.depth": 1.0,
         "filter.lowpass.cutoff": 2000.0, "lostmotion.mode": 2.0, "lostmotion.backlash": 0.0,
         "position.feedback": 0.0, "trace.divider": 1.0, "velocity.integral_divider": 4.0}


def si(p):
    if not isinstance(p, dict):
        return float(p)
    return float(p["value"]) * TO_SI[p["unit"]]


def main():
    preset = json.load(open(os.path.join(ROOT, "resources", "machines", "vmc.json")))
    common = preset["common"]["parameters"]
    axes = []
    for a in preset["axes"]:
        merged = dict(common)
        merged.update(a.get("parameters", {}))
        params = {k: si(v) for k, v in merged.items() if not k.startswith("plant.")}
        params.update(EXTRA)
        params["lostmotion.A"] = si(merged["plant.lost_motion_A"])
        params["lostmotion.B"] = si(merged["plant.lost_motion_B"])
        params["lostmotion.screw_offset"] = si(merged["plant.screw_offset"])
        models = {
            "motor": {"resistance_ohm": si(merged["plant.motor.resistance"]),
                      "inductance_q_H": si(merged["plant.motor.inductance_q"]),
                      "inductance_drop_at_max": si(merged["plant.motor.inductance_drop_at_max"]),
                      "back_emf_constant_V_s_per_rad": si(merged["plant.motor.back_emf_constant"]),
                      "torque_constant_Nm_per_A": si(merged["motor.torque_constant"]),
                      "max_current_A": si(merged["motor.max_current"]),
                      "rated_current_A": si(merged["motor.rated_current"])},
            "two_inertia": {"motor_inertia_kgm2": si(merged["plant.inertia_motor"]),
                            "load_inertia_kgm2": si(merged["plant.inertia_load"]),
                            "stiffness_Nm_per_rad": si(merged["plant.coupling_stiffness"]),
                            "damping_Nm_s_per_rad": si(merged["plant.coupling_damping"])},
            "lost_motion": {"A_m_per_Nm": params["lostmotion.A"], "B_per_Nm": params["lostmotion.B"],
                            "screw_offset_m": params["lostmotion.screw_offset"]},
        }
        axes.append({"name": a["name"], "parameters": params, "models": models})
    profile = {"format": "axistune-profile", "version": 1,
               "machine": {"name": preset["name"], "description": preset["description"]}, "axes": axes}
    path = os.path.join(ROOT, "resources", "samples", "vmc-profile.json")
    open(path, "w").write(json.dumps(profile, indent=2, sort_keys=True) + "\n")


if __name__ == "__main__":
    main()
