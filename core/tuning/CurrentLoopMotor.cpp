// SPDX-License-Identifier: GPL-3.0-or-later
// Motor data for the current-loop design (motor JSON, docs/tuning.md) and its checks, including the
// back-EMF check of spec/current-loop-and-multisweep-frf.md §2.1 / §4.1 step 2 (C-A1).
#include "core/model/InputLimits.h"
#include "core/tuning/CurrentLoop.h"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace axistune::tuning {

namespace {

Error bad(const std::string& source, const std::string& what) { return makeError(ErrorCode::BadInput, source + ": " + what); }

Result<double> number(const nlohmann::json& j, const std::string& key, const std::string& source, bool required,
                      double fallback)
{
    if (!j.contains(key)) {
        if (required) {
            return bad(source, "missing key '" + key + "'");
        }
        return fallback;
    }
    const auto& v = j.at(key);
    if (!v.is_number()) {
        return bad(source, "key '" + key + "': not a number (" + v.dump() + ")");
    }
    const double x = v.get<double>();
    if (!std::isfinite(x)) {
        return bad(source, "key '" + key + "': not finite");
    }
    return x;
}

}  // namespace

Status validateMotor(const MotorData& m, const std::string& source)
{
    auto fail = [&](const std::string& what) { return Status(makeError(ErrorCode::OutOfRange, source + ": " + what)); };
    if (!(m.resistanceOhm >= 0.0) || !std::isfinite(m.resistanceOhm)) {
        return fail("'resistance_ohm' must be ≥ 0, got " + std::to_string(m.resistanceOhm));
    }
    if (!(m.inductanceQH > 0.0) || !std::isfinite(m.inductanceQH)) {
        return fail("'inductance_q_H' must be > 0, got " + std::to_string(m.inductanceQH));
    }
    if (!(m.maxCurrentA > 0.0) || !std::isfinite(m.maxCurrentA)) {
        return fail("'max_current_A' must be > 0, got " + std::to_string(m.maxCurrentA));
    }
    if (!(m.maxVoltageV > 0.0) || !std::isfinite(m.maxVoltageV)) {
        return fail("'max_voltage_V' must be > 0, got " + std::to_string(m.maxVoltageV));
    }
    if (!(m.inductanceDropAtMax >= 0.0) || !(m.inductanceDropAtMax < 1.0)) {
        return fail("'inductance_drop_at_max' must be in [0, 1), got " + std::to_string(m.inductanceDropAtMax));
    }
    if (m.ratedCurrentA < 0.0 || m.ratedCurrentA > m.maxCurrentA) {
        return fail("'rated_current_A' must be in [0, max_current_A], got " + std::to_string(m.ratedCurrentA));
    }
    if (m.polePairs < 0) {
        return fail("'pole_pairs' must be ≥ 1, got " + std::to_string(m.polePairs));
    }
    if (m.backEmfVPerKrpm < 0.0 || m.contouringSpeedRpm < 0.0) {
        return fail("'back_emf_V_per_krpm' and 'contouring_speed_rpm' must be ≥ 0");
    }
    if (m.backEmfVPerKrpm > 0.0) {
        const double e = backEmfV(m.backEmfVPerKrpm, m.contouringSpeedRpm);
        if (e >= m.maxVoltageV) {
            return fail("back-EMF at the contouring speed (" + std::to_string(e) + " V at " +
                        std::to_string(m.contouringSpeedRpm) + " min^-1) is not below 'max_voltage_V' (" +
                        std::to_string(m.maxVoltageV) + " V); the design assumes back-EMF << V_max");
        }
    }
    return Status::success();
}

Result<MotorData> parseMotorJson(const std::string& text, const std::string& source)
{
    auto parsed = model::parseJsonText(text, source);
    if (!parsed)
        return parsed.error();
    const nlohmann::json& j = *parsed;
    if (!j.is_object()) {
        return bad(source, "expected a JSON object");
    }
    MotorData m;
    struct Field {
        const char* key;
        double* target;
        bool required;
    };
    double polePairs = 0.0;
    const Field fields[] = {
        {"resistance_ohm", &m.resistanceOhm, true},
        {"inductance_q_H", &m.inductanceQH, true},
        {"max_current_A", &m.maxCurrentA, true},
        {"max_voltage_V", &m.maxVoltageV, true},
        {"inductance_drop_at_max", &m.inductanceDropAtMax, true},
        {"rated_current_A", &m.ratedCurrentA, false},
        {"pole_pairs", &polePairs, false},
        {"back_emf_V_per_krpm", &m.backEmfVPerKrpm, false},
        {"contouring_speed_rpm", &m.contouringSpeedRpm, false},
    };
    for (const auto& f : fields) {
        auto v = number(j, f.key, source, f.required, *f.target);
        if (!v) {
            return v.error();
        }
        *f.target = *v;
    }
    if (polePairs != std::floor(polePairs) || polePairs < 0.0 || polePairs > 1000.0) {
        return bad(source, "key 'pole_pairs': must be a whole number ≥ 1");
    }
    m.polePairs = static_cast<int>(polePairs);
    if (j.contains("pole_pairs") && m.polePairs < 1) {
        return bad(source, "key 'pole_pairs': must be a whole number ≥ 1");
    }
    if (auto st = validateMotor(m, source); !st) {
        return st.error();
    }
    return m;
}

Result<MotorData> readMotorJsonFile(const std::string& path)
{
    auto text = model::readInputFile(path);
    if (!text)
        return text.error();
    return parseMotorJson(*text, path);
}

}  // namespace axistune::tuning
