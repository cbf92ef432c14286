// SPDX-License-Identifier: GPL-3.0-or-later
// Words for the ball-bar diagnostics' rule keys (core/tuning/BallBarReport.cpp; docs/ballbar.md "Rule keys").
#include "app/gui/BallBarText.h"
#include "app/gui/WidgetUtil.h"

#include <map>
#include <nlohmann/json.hpp>

namespace axistune {
namespace gui {
namespace {

/// Fills %1..%n; the English text when the number of arguments does not match the key's.
QString fill(const QString& pattern, const std::vector<std::string>& args, std::size_t expected, const std::string& english)
{
    if (args.size() != expected)
        return qs(english);
    QString out = pattern;
    for (const auto& a : args)
        out = out.arg(qs(a));
    return out;
}

} // namespace

QString BallBarText::findingName(const std::string& name)
{
    static const std::map<std::string, const char*> k{
        {"circularity", QT_TR_NOOP("Circularity")},
        {"center_x", QT_TR_NOOP("Centre offset X")},
        {"center_y", QT_TR_NOOP("Centre offset Y")},
        {"radius_deviation", QT_TR_NOOP("Radius deviation")},
        {"scale_mismatch", QT_TR_NOOP("Scale mismatch")},
        {"squareness", QT_TR_NOOP("Squareness")},
        {"servo_mismatch", QT_TR_NOOP("Servo mismatch")},
        {"backlash_x", QT_TR_NOOP("Backlash X")},
        {"backlash_y", QT_TR_NOOP("Backlash Y")},
        {"reversal_spike_x", QT_TR_NOOP("Reversal spike X")},
        {"reversal_spike_y", QT_TR_NOOP("Reversal spike Y")},
        {"cyclic_error_x", QT_TR_NOOP("Cyclic error X")},
        {"cyclic_error_y", QT_TR_NOOP("Cyclic error Y")},
    };
    auto it = k.find(name);
    return it == k.end() ? qs(name) : tr(it->second);
}

QString BallBarText::rule(const std::string& id, const std::vector<std::string>& a, const std::string& english)
{
    if (id == "squareness.both_directions")
        return fill(tr("sin2θ coefficient k of each run; k = γR/2 + σvΔτ/2 solved for γ over CW and CCW runs (the part "
                       "that keeps its sign with direction); positive = angle between +X and +Y below 90°"),
                    a, 0, english);
    if (id == "servo_mismatch.both_directions")
        return fill(tr("the sin2θ part that changes sign with travel direction, Δτ from k = γR/2 + σvΔτ/2; positive = X "
                       "lags Y"),
                    a, 0, english);
    if (id == "squareness.one_direction")
        return fill(tr("γ = 2k/R from the sin2θ coefficient k of runs in one direction only: includes any servo "
                       "mismatch (measure CW and CCW to separate them)"),
                    a, 0, english);
    if (id == "servo_mismatch.one_direction")
        return fill(tr("Servo mismatch: needs runs in both directions (CW and CCW); only %1 given"), a, 1, english);
    if (id == "cyclic_error.detected")
        return fill(tr("largest least-squares sinusoid of the %1 coordinate (pitch scanned from the sampling limit to "
                       "R/2, best pitch %2 mm) in the residual of the smooth fit, projected radially; detected against "
                       "a noise threshold of %3 µm (false alarm ≈ 1e-3)"),
                    a, 3, english);
    if (id == "cyclic_error.not_detected")
        return fill(tr("largest least-squares sinusoid of the %1 coordinate (pitch scanned from the sampling limit to "
                       "R/2, best pitch %2 mm) in the residual of the smooth fit, projected radially; not detected "
                       "against a noise threshold of %3 µm (false alarm ≈ 1e-3)"),
                    a, 3, english);
    if (id == "backlash" || id == "backlash.not_detected") {
        if (a.size() != 6)
            return qs(english);
        const QString verdict =
            id == "backlash" ? tr("a backlash: |step| above %1 µm (4× its standard error, at least 0.3 µm)")
                             : tr("no backlash: |step| not above %1 µm (4× its standard error, at least 0.3 µm)");
        std::vector<std::string> args(a.begin(), a.begin() + 5);
        args.push_back(verdict.arg(qs(a[5])).toStdString());
        return fill(tr("mean radial step across %1 %2 reversal(s) (%3): joint fit of a cubic plus a step over %4–%5° "
                       "each side of the reversal, where a spike has decayed; positive = outward step (lost motion), "
                       "negative = inward (over-compensation); %6"),
                    args, 6, english);
    }
    if (id == "backlash.not_covered")
        return fill(tr("Backlash: no %1 reversal is covered by the trace(s)"), a, 1, english);
    if (id == "reversal_spike")
        return fill(tr("transient at %1°, within ±%2° of a %3 reversal (width %4° at half height): the peak departure "
                       "from the step's own transition (the level before the reversal, then a monotonic move to the "
                       "level after it, which a backlash follows) that comes back to that level; reported when above "
                       "4× the fit-window noise and 0.3 µm"),
                    a, 4, english);
    if (id == "circularity")
        return fill(tr("max − min radial deviation after removing the least-squares circle (ISO 230-4), the largest "
                       "over the runs"),
                    a, 0, english);
    if (id == "center_x")
        return fill(tr("least-squares circle centre offset along X (mean of runs)"), a, 0, english);
    if (id == "center_y")
        return fill(tr("least-squares circle centre offset along Y (mean of runs)"), a, 0, english);
    if (id == "radius_deviation")
        return fill(tr("least-squares circle radius minus the nominal radius (includes mean scale error and ball-bar "
                       "length error)"),
                    a, 0, english);
    if (id == "scale_mismatch")
        return fill(tr("εx − εy = 2c/R from the cos2θ coefficient c of the joint fit (circle, 2nd harmonics, lost "
                       "motion) outside the reversal zones; positive = X travels further than Y"),
                    a, 0, english);
    if (id == "full_circle")
        return fill(tr("%1: centre, radius, circularity, scale mismatch, squareness, servo mismatch and cyclic error "
                       "not computed: they need a full 360° circle, but the trace is a partial arc covering %2° (from "
                       "%3° to %4° CCW; largest gap %5°, at most %6° allowed)"),
                    a, 6, english);
    return qs(english);
}

nlohmann::json BallBarText::findingJson(const tuning::Finding& f)
{
    return {{"name", f.name},     {"value", f.value},      {"unit", f.unit},
            {"rule", f.rule},     {"rule_id", f.ruleId},   {"rule_args", f.ruleArgs}};
}

nlohmann::json BallBarText::refusalJson(const tuning::RuleText& r)
{
    return {{"id", r.id}, {"args", r.args}, {"text", r.text}};
}

nlohmann::json BallBarText::translatedDiagnostics(const nlohmann::json& d)
{
    if (!d.is_object())
        return d;
    nlohmann::json out = d;
    if (auto f = out.find("findings"); f != out.end() && f->is_array()) {
        for (auto& e : *f) {
            if (!e.is_object() || !e.contains("rule_id") || !e["rule_id"].is_string())
                continue;
            std::vector<std::string> args;
            if (e.contains("rule_args") && e["rule_args"].is_array())
                for (const auto& a : e["rule_args"])
                    args.push_back(a.is_string() ? a.get<std::string>() : a.dump());
            const std::string english = e.value("rule", std::string());
            e["rule"] = rule(e["rule_id"].get<std::string>(), args, english).toStdString();
            if (e.contains("name") && e["name"].is_string())
                e["name"] = findingName(e["name"].get<std::string>()).toStdString();
            e.erase("rule_id");
            e.erase("rule_args");
        }
    }
    if (auto r = out.find("refused"); r != out.end() && r->is_array()) {
        nlohmann::json texts = nlohmann::json::array();
        for (const auto& e : *r) {
            if (!e.is_object()) {
                texts.push_back(e);
                continue;
            }
            std::vector<std::string> args;
            if (e.contains("args") && e["args"].is_array())
                for (const auto& a : e["args"])
                    args.push_back(a.is_string() ? a.get<std::string>() : a.dump());
            texts.push_back(rule(e.value("id", std::string()), args, e.value("text", std::string())).toStdString());
        }
        *r = texts;
    }
    return out;
}

} // namespace gui
} // namespace axistune
