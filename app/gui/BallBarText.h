// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The ball-bar diagnostics' finding names and rules in the user's language. core/tuning gives every
// finding and refusal a stable rule key with its arguments (tuning::RuleText, docs/ballbar.md "Rule
// keys"); this table words them through tr(). Unknown keys fall back to core's English text.

#include "core/tuning/BallBarDiagnostics.h"

#include <QCoreApplication>
#include <QString>
#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace axistune {
namespace gui {

class BallBarText {
    Q_DECLARE_TR_FUNCTIONS(BallBarText)

public:
    /// "circularity", "backlash_x", … in words; unknown names are returned as they are.
    static QString findingName(const std::string& name);
    /// The rule of `id` with `args` filled in; `english` when the id is unknown or the arguments do not fit.
    static QString rule(const std::string& id, const std::vector<std::string>& args, const std::string& english);
    static QString rule(const tuning::Finding& f) { return rule(f.ruleId, f.ruleArgs, f.rule); }
    static QString rule(const tuning::RuleText& r) { return rule(r.id, r.args, r.text); }

    /// JSON of a stored finding: {name, value, unit, rule, rule_id, rule_args}.
    static nlohmann::json findingJson(const tuning::Finding& f);
    /// JSON of a stored refusal: {id, args, text}.
    static nlohmann::json refusalJson(const tuning::RuleText& r);
    /// A stored "diagnostics" result with the names and rules worded in the user's language (for reports);
    /// findings without a rule_id and refusals stored as plain strings are kept as they are.
    static nlohmann::json translatedDiagnostics(const nlohmann::json& diagnostics);
};

} // namespace gui
} // namespace axistune
