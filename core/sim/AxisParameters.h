// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The parameter catalogue of a simulated feed axis. Drive parameters (controllers, filters,
// compensation, trace) are what a drive exposes and lets a tool write; plant parameters ("plant.*")
// describe the physical machine and are fixed by the preset (read-only through the Drive).

#include "core/model/Parameter.h"

#include <string>
#include <vector>

namespace axistune::sim {

enum class AxisKind { Linear, Rotary };

/// Number of torque-command notch filters the simulated drive offers (filter.notch1 .. notchN).
constexpr int kNotchCount = 4;

/// Metadata of every parameter of an axis of this kind (drive and plant), with limits in SI.
/// Position-related units are m for linear axes and rad for rotary axes.
const std::vector<model::ParameterMeta>& axisParameterMetas(AxisKind kind);

/// Default values (SI) of every parameter of axisParameterMetas(kind).
model::ParameterValues defaultAxisParameters(AxisKind kind);

/// True for keys that describe the plant ("plant.*"), not the drive.
bool isPlantParameter(const std::string& key);

}  // namespace axistune::sim
