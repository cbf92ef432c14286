// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// An independent frequency-domain model of the simulated velocity loop, built by the test from a
// preset's parameters: the continuous plant is discretized exactly over one current period, the
// current loop (PI with ratio α, dead time, torque filters) is written as a linear map per current
// tick, four (velDiv) ticks are composed into one velocity period, and the velocity PI with the
// backward-difference velocity measurement closes the loop. H(e^{jωT}) = C (zI − A)⁻¹ B gives the
// response from velocity command to measured velocity at the velocity-loop rate. It shares no code
// with core/sim except the filter design (tested on its own in tests/core/dsp).

#include "core/sim/MachineDefinition.h"

#include <Eigen/Dense>

#include <complex>
#include <numbers>

namespace axistune::simtest {

struct LiftedVelocityLoop {
    Eigen::MatrixXd a;
    Eigen::VectorXd b;
    Eigen::RowVectorXd c;
    double periodS = 0.0;

    std::complex<double> response(double fHz) const;
};

/// The per-current-tick map of the lifted model (plant, current PI, dead time, torque filters):
/// z' = mz·z + nzv·u with u the torque command into the filters; `encoder` reads the motor angle.
struct LiftedCurrentTick {
    Eigen::MatrixXd mz;
    Eigen::VectorXd nzv;
    Eigen::RowVectorXd encoder;  ///< over z
    int velDiv = 4;
    double currentPeriodS = 0.0;
};

/// The lifted model of one current tick of a preset's axis.
LiftedCurrentTick buildLiftedCurrentTick(const sim::AxisDefinition& axis);
/// The closed velocity loop from velocity command to measured velocity, at the velocity-loop rate.
LiftedVelocityLoop buildLiftedVelocityLoop(const sim::AxisDefinition& axis);

/// The velocity loop with velocity command 0 and a torque disturbance d added to the
/// velocity-controller output T_c before the torque filters, d sampled at every current tick
/// (the FRF test of core/device/FrfTest.h). State Z[k] at the velocity tick kT; over one velocity
/// period Z[k+1] = A Z[k] + Σ_i g_i d(kT + i h). Outputs at kT: T_c[k] and the measured velocity.
/// For d = e^{jωt}: Z = (zI − A)⁻¹ Σ_i g_i e^{jωih}, so the responses below are exact for a sine
/// injected at the current-loop rate and read at the velocity-loop rate.
struct LiftedInjectionLoop {
    Eigen::MatrixXd a;
    Eigen::MatrixXd g;            ///< one column per current tick of the velocity period
    Eigen::RowVectorXd torqueCmd; ///< T_c[k]
    Eigen::RowVectorXd velocity;  ///< ω_meas[k]
    double periodS = 0.0;
    double currentPeriodS = 0.0;

    Eigen::VectorXcd state(double fHz) const;
    /// T_c/d.
    std::complex<double> torqueResponse(double fHz) const
    {
        return (torqueCmd.cast<std::complex<double>>() * state(fHz))(0);
    }
    /// ω_meas/d.
    std::complex<double> velocityResponse(double fHz) const
    {
        return (velocity.cast<std::complex<double>>() * state(fHz))(0);
    }
    /// The closed loop measured by the FRF test, T = −T_c/d = PC/(1+PC) (spec §3.2 eq. 3.1).
    std::complex<double> closedLoop(double fHz) const { return -torqueResponse(fHz); }
    /// Slowest decay time constant 1/|ln|λ|/T| over the eigenvalues λ of A (λ = 0 excluded).
    double slowestTimeConstantS() const;
};

/// The velocity loop with a torque disturbance injected at the current-loop rate (the FRF test's loop).
LiftedInjectionLoop buildLiftedInjectionLoop(const sim::AxisDefinition& axis);

}  // namespace axistune::simtest
