// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/Units.h"

#include "core/model/Constants.h"

#include <array>
#include <numbers>

namespace axistune::model {
namespace {

// One row per unit. The SI unit of each quantity has toSi = 1.
constexpr std::array kUnits{
    UnitInfo{"1", "", "1", 1.0},
    UnitInfo{"%", "%", "1", 0.01},
    UnitInfo{"m", "m", "m", 1.0},
    UnitInfo{"mm", "mm", "m", 1e-3},
    UnitInfo{"um", "µm", "m", 1e-6},
    UnitInfo{"nm", "nm", "m", 1e-9},
    UnitInfo{"rad", "rad", "rad", 1.0},
    UnitInfo{"deg", "deg", "rad", kRadPerDeg},
    UnitInfo{"rev", "rev", "rad", kTwoPi},
    UnitInfo{"m/s", "m/s", "m/s", 1.0},
    UnitInfo{"mm/min", "mm/min", "m/s", 1e-3 / 60.0},
    UnitInfo{"rad/s", "rad/s", "rad/s", 1.0},
    UnitInfo{"min^-1", "min⁻¹", "rad/s", kRadPerSPerRpm},
    UnitInfo{"deg/s", "deg/s", "rad/s", kRadPerDeg},
    UnitInfo{"s", "s", "s", 1.0},
    UnitInfo{"ms", "ms", "s", 1e-3},
    UnitInfo{"us", "µs", "s", 1e-6},
    UnitInfo{"Hz", "Hz", "Hz", 1.0},
    UnitInfo{"kHz", "kHz", "Hz", 1e3},
    UnitInfo{"1/s", "s⁻¹", "1/s", 1.0},
    UnitInfo{"Nm", "N·m", "Nm", 1.0},
    UnitInfo{"N", "N", "N", 1.0},
    UnitInfo{"kg", "kg", "kg", 1.0},
    UnitInfo{"kgm2", "kg·m²", "kgm2", 1.0},
    UnitInfo{"A", "A", "A", 1.0},
    UnitInfo{"V", "V", "V", 1.0},
    UnitInfo{"ohm", "Ω", "ohm", 1.0},
    UnitInfo{"H", "H", "H", 1.0},
    UnitInfo{"mH", "mH", "H", 1e-3},
    UnitInfo{"Wb", "Wb", "Wb", 1.0},
    UnitInfo{"V/A", "V/A", "V/A", 1.0},
    UnitInfo{"V/(A*s)", "V/(A·s)", "V/(A*s)", 1.0},
    UnitInfo{"Nm/A", "N·m/A", "Nm/A", 1.0},
    UnitInfo{"V*s/rad", "V·s/rad", "V*s/rad", 1.0},
    UnitInfo{"V/kmin^-1", "V/(1000 min⁻¹)", "V*s/rad", 1.0 / (1000.0 * kRadPerSPerRpm)},
    UnitInfo{"Nm*s/rad", "N·m·s/rad", "Nm*s/rad", 1.0},
    UnitInfo{"Nm/rad", "N·m/rad", "Nm/rad", 1.0},
    UnitInfo{"N/m", "N/m", "N/m", 1.0},
    UnitInfo{"N*s/m", "N·s/m", "N*s/m", 1.0},
    UnitInfo{"m/rad", "m/rad", "m/rad", 1.0},
    UnitInfo{"mm/rev", "mm/rev", "m/rad", 1e-3 / kTwoPi},
    UnitInfo{"m/Nm", "m/(N·m)", "m/Nm", 1.0},
    UnitInfo{"um/Nm", "µm/(N·m)", "m/Nm", 1e-6},
    UnitInfo{"1/Nm", "1/(N·m)", "1/Nm", 1.0},
    UnitInfo{"um/(Nm*m)", "µm/(N·m·m)", "1/Nm", 1e-6},
    UnitInfo{"counts/rev", "counts/rev", "counts/rev", 1.0},
    // Measurement channels of imported records (impact tests, foreign loggers) and FRF units (docs/formats.md).
    UnitInfo{"mm/s", "mm/s", "m/s", 1e-3},
    UnitInfo{"m/s2", "m/s²", "m/s2", 1.0},
    UnitInfo{"mm/s2", "mm/s²", "m/s2", 1e-3},
    UnitInfo{"g", "g", "m/s2", 9.80665},
    UnitInfo{"kN", "kN", "N", 1e3},
    UnitInfo{"mN", "mN", "N", 1e-3},
    UnitInfo{"mV", "mV", "V", 1e-3},
    UnitInfo{"m/N", "m/N", "m/N", 1.0},
    UnitInfo{"mm/N", "mm/N", "m/N", 1e-3},
    UnitInfo{"um/N", "µm/N", "m/N", 1e-6},
    UnitInfo{"nm/N", "nm/N", "m/N", 1e-9},
    UnitInfo{"m/s/N", "m/(s·N)", "m/s/N", 1.0},
    UnitInfo{"mm/s/N", "mm/(s·N)", "m/s/N", 1e-3},
    UnitInfo{"m/s2/N", "m/(s²·N)", "m/s2/N", 1.0},
    UnitInfo{"mm/s2/N", "mm/(s²·N)", "m/s2/N", 1e-3},
    UnitInfo{"g/N", "g/N", "m/s2/N", 9.80665},
};

} // namespace

Result<UnitInfo> findUnit(std::string_view token)
{
    for (const auto& u : kUnits) {
        if (u.token == token)
            return u;
    }
    return makeError(ErrorCode::NotFound, "unknown unit '" + std::string(token) + "'");
}

Result<double> convertUnit(double value, std::string_view from, std::string_view to)
{
    auto f = findUnit(from);
    if (!f)
        return f.error();
    auto t = findUnit(to);
    if (!t)
        return t.error();
    if (f->si != t->si) {
        return makeError(ErrorCode::BadInput, "cannot convert '" + std::string(from) + "' to '" + std::string(to) +
                                                  "': different quantities");
    }
    return value * f->toSi / t->toSi;
}

Result<double> toSi(double value, std::string_view from)
{
    auto f = findUnit(from);
    if (!f)
        return f.error();
    return value * f->toSi;
}

std::string unitLabel(std::string_view token)
{
    auto f = findUnit(token);
    return f ? std::string(f->label) : std::string(token);
}

std::vector<UnitInfo> allUnits()
{
    return {kUnits.begin(), kUnits.end()};
}

} // namespace axistune::model
