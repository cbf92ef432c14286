// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/autotune/AutoTuneRun.h"

#include <algorithm>
#include <cmath>

namespace axistune::autotune::detail {

Run::Run(device::Drive& drive, const Options& o) : m_drive(drive), m_o(o), m_t(styleTargets(o.style))
{
    if (o.minBandwidthHz > 0.0)
        m_t.minBandwidthHz = o.minBandwidthHz;
}

AutoTuneResult Run::refuse(const std::string& reason, ErrorCode code)
{
    m_r.outcome = Outcome::Refused;
    m_r.reason = reason;
    m_r.reasonCode = code;
    restore();
    afterRefusal();
    m_r.motionTimeS = m_motion;
    return std::move(m_r);
}

void Run::restore()
{
    model::ParameterValues back;
    for (const auto& [k, v] : m_written)
        back[k] = m_r.before.at(k);
    Status st = back.empty() ? Status{} : m_drive.writeParameters(m_o.axis, back);
    if (!st) {
        m_r.reason += "; RESTORING THE PARAMETERS FAILED (" + st.error().detail + "): check the drive";
        m_r.restored = false;
        return;
    }
    auto now = m_drive.readParameters(m_o.axis, m_keys);
    if (!now) {
        m_r.reason += "; the parameters could not be read back after restoring (" + now.error().detail + ")";
        m_r.restored = false;
        return;
    }
    std::string differ;
    for (const auto& [k, v] : m_r.before) {
        const auto it = now->find(k);
        if (it == now->end() || !readsBackAs(it->second, v))
            differ += (differ.empty() ? "" : ", ") + k;
    }
    m_r.restored = differ.empty();
    if (!differ.empty())
        m_r.reason += "; after restoring these parameters differ from before: " + differ;
    m_written.clear();
}

bool Run::begin(const char* name)
{
    if (m_o.run.abort && m_o.run.abort->load())
        return false;
    if (m_o.stepStarted)
        m_o.stepStarted(name);
    return true;
}

void Run::done(const Step& s)
{
    m_r.steps.push_back(s);
    if (m_o.stepFinished)
        m_o.stepFinished(s);
}

Status Run::write(const model::ParameterValues& v)
{
    for (const auto& [k, x] : v)
        if (!m_r.before.count(k) || !m_writable.count(k))
            return makeError(ErrorCode::Device, "axis " + m_o.axis + " has no writable parameter '" + k + "'");
    if (auto st = m_drive.writeParameters(m_o.axis, v); !st)
        return st;
    for (const auto& [k, x] : v) {
        m_written[k] = x;
        m_now[k] = x;
    }
    return {};
}

double Run::value(const std::string& key) const
{
    const auto it = m_now.find(key);
    return it == m_now.end() ? std::numeric_limits<double>::quiet_NaN() : it->second;
}

Result<device::AdaptiveFrfResult> Run::frf(double amplitudePct, double budgetS, double& motionS)
{
    device::TestRequest r;
    r.axis = m_o.axis;
    auto& f = r.test.emplace<device::FrfTest>();
    f.method = device::FrfMethod::Multisine;
    f.fminHz = kFrfMinHz;
    f.fmaxHz = 0.975 * m_caps.traceRateHz;
    f.multisineSpacingHz = kFrfSpacingHz;
    f.amplitudePct = amplitudePct;
    budgetS = std::min(budgetS, m_o.timeBudgetS - m_motion);
    if (!(budgetS > 0.0))
        return makeError(ErrorCode::Safety, "the FRF has no time left in the budget (" + num(m_o.timeBudgetS, 3) +
                                                " s, " + num(m_motion, 3) + " s used)");
    device::AdaptiveFrfOptions ao;
    ao.timeBudgetS = budgetS;
    auto a = device::runAdaptiveFrf(m_drive, r, ao, m_o.run);
    if (!a) {
        const auto& e = a.error();
        if (e.code == ErrorCode::Safety)
            return makeError(ErrorCode::Safety, "drive fault during the FRF: " + e.detail);
        return makeError(e.code, "FRF: " + e.detail);
    }
    motionS = a->motionTimeS;
    m_motion += a->motionTimeS;
    return a;
}

std::optional<AutoTuneResult> Run::keepOrRestore(Step& s, const std::string& ruleSuffix)
{
    if (m_o.dryRun) {
        s.rule = "dry run: every parameter written during the run restored and read back" + ruleSuffix;
        done(s);
        restore();
        m_r.outcome = Outcome::DryRun;
        if (!m_r.restored)
            return refuse("dry run: " + m_r.reason, ErrorCode::Device);
        return std::nullopt;
    }
    std::vector<std::string> keys;
    for (const auto& [k, v] : m_written)
        keys.push_back(k);
    auto back = m_drive.readParameters(m_o.axis, keys);
    if (!back)
        return refuse("apply: the parameters could not be read back (" + back.error().detail + ")", back.error().code);
    for (const auto& [k, v] : m_written) {
        const auto it = back->find(k);
        if (it == back->end() || !readsBackAs(it->second, v))
            return refuse("apply: " + k + " reads back " +
                              (it == back->end() ? std::string("nothing") : num(it->second, 7)) + ", written " +
                              num(v, 7),
                          ErrorCode::Device);
    }
    s.rule =
        "the parameters stay written; every one read back equal (relative " + num(kReadBackRel, 2) + ")" + ruleSuffix;
    done(s);
    m_r.outcome = Outcome::Applied;
    return std::nullopt;
}

} // namespace axistune::autotune::detail
