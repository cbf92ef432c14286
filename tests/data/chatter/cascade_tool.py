#!/usr/bin/env python3
# The thesis's two-resonance tool (5-1), G = (1/K0) w1^2/(s^2 + 2 z1 w1 s + w1^2) * w2^2/(s^2 + 2 z2 w2 s + w2^2)
# (spec/chatter-stability-and-spindle-speed.md §1.6(b)), as a modal sum. Partial fractions of the undamped product:
#   w1^2 w2^2 / ((s^2 + w1^2)(s^2 + w2^2)) = w1^2 w2^2/(w2^2 - w1^2) * [1/(s^2 + w1^2) - 1/(s^2 + w2^2)],
# so mode 1 has modal mass m = K0 (w2^2 - w1^2)/(w1^2 w2^2) and mode 2 the NEGATIVE mass -m (a negative residue),
# each with its own damping ratio. The damped cascade differs from this sum by velocity terms of order zeta;
# the largest difference over 0..5 kHz is printed relative to the peak compliance. Pure Python (no numpy).
# Output: cascade_tool.txt (resources/samples/tool-two-mode.json, tests/core/avoidance/test_avoidance_cut.cpp).
import cmath
import math

K0, w1, w2, z1, z2 = 1e8, 9020.0, 12000.0, 0.01, 0.006
m = K0 * (w2**2 - w1**2) / (w1**2 * w2**2)
modes = [(m, 2 * z1 * w1 * m, m * w1**2), (-m, -2 * z2 * w2 * m, -m * w2**2)]


def cascade(f):
    s = 2j * math.pi * f
    return (1 / K0) * w1**2 / (s * s + 2 * z1 * w1 * s + w1**2) * w2**2 / (s * s + 2 * z2 * w2 * s + w2**2)


def modal(f, ms):
    s = 2j * math.pi * f
    return sum(1 / (mm * s * s + c * s + k) for mm, c, k in ms)


peak = max(abs(cascade(f / 10)) for f in range(0, 50000))
dev = max(abs(modal(f / 10, modes) - cascade(f / 10)) for f in range(0, 50000))
print("two-mode tool (5-1) as a modal sum with a negative-residue second mode")
for mm, c, k in modes:
    print(f"  mass_kg {mm:.10g} damping_Ns_per_m {c:.10g} stiffness_N_per_m {k:.10g}")
print(f"  peak compliance of (5-1) {peak:.6g} m/N; largest |modal - cascade| over 0..5 kHz {dev / peak:.4%} of it")
old = [(0.5348560351, 96.48802873, 43516100.96), (0.5348463066, 77.01786815, 77017868.15)]
for f in (1900.0, 1909.9):
    a, b = cascade(f), modal(f, old)
    print(f"  former all-positive sum at {f} Hz: phase off by {math.degrees(cmath.phase(b / a)):.1f} deg")
print(f"  static compliance: cascade {abs(cascade(0)):.4g}, this sum {abs(modal(0, modes)):.4g}, former sum "
      f"{abs(modal(0, old)):.4g} m/N")
