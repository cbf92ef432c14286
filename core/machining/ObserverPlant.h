// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Nominal plant of the cutting force observer, seed 003 (spec/cutting-force-observer-and-chatter-detection.md
// §1.2, Table 1): the two-inertia bench from the drive current i_M to the motor velocity ω_M,
//   P_n(s) = K_t (J_L s² + B_L s + K) / (J_M J_L s³ + (J_M B_L + J_L B_M) s² + (K (J_M + J_L) + B_M B_L) s
//                                          + K (B_M + B_L))
// (no torsional damping, as Table 1 has none). Rotary units: N·m/A, kg·m², N·m·s/rad, N·m/rad.

#include <complex>

namespace axistune::machining {

struct ObserverPlant {
    double torqueConstantNmPerA = 0.0; ///< K_t
    double motorInertia = 0.0;         ///< J_M
    double loadInertia = 0.0;          ///< J_L
    double motorViscous = 0.0;         ///< B_M
    double loadViscous = 0.0;          ///< B_L
    double stiffnessNmPerRad = 0.0;    ///< K

    /// Table 1 of the spec, with K read as 24 000 N·m/rad (spec §1.2 [OCR] note).
    static ObserverPlant table1();
    /// P_n(jω) in (rad/s)/A at the frequency fHz.
    std::complex<double> response(double fHz) const;
};

} // namespace axistune::machining
