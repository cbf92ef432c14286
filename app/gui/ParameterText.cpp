// SPDX-License-Identifier: GPL-3.0-or-later
// Generated list of the drive-parameter labels of core/sim/AxisParameters.cpp and of LinuxCNC's pid pins
// (core/device/hal/HalDrive.cpp), so lupdate sees them.
// tests/gui/tst_parametertext.cpp fails when a label is missing here.
#include "app/gui/ParameterText.h"

#include <QCoreApplication>

namespace axistune {
namespace gui {

namespace {
// clang-format off
const char* const kLabels[] = {
    QT_TRANSLATE_NOOP("Parameter", "Maximum current (peak)"),
    QT_TRANSLATE_NOOP("Parameter", "Rated current (peak)"),
    QT_TRANSLATE_NOOP("Parameter", "Torque constant"),
    QT_TRANSLATE_NOOP("Parameter", "Maximum voltage"),
    QT_TRANSLATE_NOOP("Parameter", "Current-loop period"),
    QT_TRANSLATE_NOOP("Parameter", "Current proportional gain k_p"),
    QT_TRANSLATE_NOOP("Parameter", "Current integral gain k_i"),
    QT_TRANSLATE_NOOP("Parameter", "PI ratio α"),
    QT_TRANSLATE_NOOP("Parameter", "Dead time"),
    QT_TRANSLATE_NOOP("Parameter", "Velocity-loop period"),
    QT_TRANSLATE_NOOP("Parameter", "Velocity proportional gain"),
    QT_TRANSLATE_NOOP("Parameter", "Velocity integral gain"),
    QT_TRANSLATE_NOOP("Parameter", "Velocity integral divider"),
    QT_TRANSLATE_NOOP("Parameter", "Inertia for torque feedforward"),
    QT_TRANSLATE_NOOP("Parameter", "Position-loop period"),
    QT_TRANSLATE_NOOP("Parameter", "Position gain"),
    QT_TRANSLATE_NOOP("Parameter", "Velocity feedforward"),
    QT_TRANSLATE_NOOP("Parameter", "Torque feedforward"),
    QT_TRANSLATE_NOOP("Parameter", "Feedback (0 semi-closed, 1 full-closed)"),
    QT_TRANSLATE_NOOP("Parameter", "Notch 1 centre"),
    QT_TRANSLATE_NOOP("Parameter", "Notch 1 width"),
    QT_TRANSLATE_NOOP("Parameter", "Notch 1 depth"),
    QT_TRANSLATE_NOOP("Parameter", "Notch 2 centre"),
    QT_TRANSLATE_NOOP("Parameter", "Notch 2 width"),
    QT_TRANSLATE_NOOP("Parameter", "Notch 2 depth"),
    QT_TRANSLATE_NOOP("Parameter", "Notch 3 centre"),
    QT_TRANSLATE_NOOP("Parameter", "Notch 3 width"),
    QT_TRANSLATE_NOOP("Parameter", "Notch 3 depth"),
    QT_TRANSLATE_NOOP("Parameter", "Notch 4 centre"),
    QT_TRANSLATE_NOOP("Parameter", "Notch 4 width"),
    QT_TRANSLATE_NOOP("Parameter", "Notch 4 depth"),
    QT_TRANSLATE_NOOP("Parameter", "Torque low-pass cutoff (0 = off)"),
    QT_TRANSLATE_NOOP("Parameter", "Lost-motion compensation (0 off, 1 conventional, 2 proposed)"),
    QT_TRANSLATE_NOOP("Parameter", "Conventional backlash amount"),
    QT_TRANSLATE_NOOP("Parameter", "Lost-motion coefficient A"),
    QT_TRANSLATE_NOOP("Parameter", "Lost-motion coefficient B"),
    QT_TRANSLATE_NOOP("Parameter", "Ball-screw length offset x0"),
    QT_TRANSLATE_NOOP("Parameter", "Trace divider (of the velocity period)"),
    QT_TRANSLATE_NOOP("Parameter", "Vibration-suppression filter (0 off, 1 semi-closed F_m, 2 full-closed F_L)"),
    QT_TRANSLATE_NOOP("Parameter", "Suppression filter frequency f0"),
    QT_TRANSLATE_NOOP("Parameter", "Suppression filter damping zeta"),
    QT_TRANSLATE_NOOP("Parameter", "F_L time constant tau"),
    QT_TRANSLATE_NOOP("Parameter", "Reversal compensation pulse amplitude (velocity command)"),
    QT_TRANSLATE_NOOP("Parameter", "Reversal compensation pulse time constant"),
    // LinuxCNC pid pins (core/device/hal/HalDrive.cpp kPidPins)
    QT_TRANSLATE_NOOP("Parameter", "Proportional gain P"),
    QT_TRANSLATE_NOOP("Parameter", "Integral gain I"),
    QT_TRANSLATE_NOOP("Parameter", "Derivative gain D"),
    QT_TRANSLATE_NOOP("Parameter", "Feedforward FF0"),
    QT_TRANSLATE_NOOP("Parameter", "Velocity feedforward FF1"),
    QT_TRANSLATE_NOOP("Parameter", "Acceleration feedforward FF2"),
    QT_TRANSLATE_NOOP("Parameter", "Jerk feedforward FF3"),
    QT_TRANSLATE_NOOP("Parameter", "Output bias"),
    QT_TRANSLATE_NOOP("Parameter", "Deadband"),
    QT_TRANSLATE_NOOP("Parameter", "Error limit"),
    QT_TRANSLATE_NOOP("Parameter", "Integrator limit"),
    QT_TRANSLATE_NOOP("Parameter", "Error-rate limit"),
    QT_TRANSLATE_NOOP("Parameter", "Output limit"),
};
// clang-format on
}  // namespace

QString parameterLabel(const std::string& label)
{
    return QCoreApplication::translate("Parameter", label.c_str());
}

bool hasParameterLabel(const std::string& label)
{
    for (const char* l : kLabels) {
        if (label == l)
            return true;
    }
    return false;
}

}  // namespace gui
}  // namespace axistune
