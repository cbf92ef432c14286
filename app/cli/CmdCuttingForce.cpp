// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli cutting-force: the adaptive cutting force observer of seed 003 (eq. (3) torsion torque,
// eq. (2) cutting force, switching RLS) run offline on a captured trace (docs/machining.md).
#include "app/cli/CliCommand.h"
#include "app/cli/SessionRecorder.h"
#include "core/io/CaptureCsv.h"
#include "core/machining/StageJson.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Units.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

namespace axistune::cli {
namespace {

struct CuttingForceArgs {
    std::string in, stage, out;
};

Result<double> samplePeriod(const model::Capture& cap, const std::string& src)
{
    const auto* t = cap.channel("t_s");
    if (t && t->data.size() >= 2) {
        const double dt = (t->data.back() - t->data.front()) / static_cast<double>(t->data.size() - 1);
        if (dt > 0.0 && std::isfinite(dt))
            return dt;
        return makeError(ErrorCode::BadInput, src + ", column 't_s': time does not increase");
    }
    if (const auto ts = cap.metadata.samplePeriodS(); !ts)
        return makeError(ErrorCode::BadInput, src + ": " + ts.error().detail);
    else if (ts->has_value())
        return **ts;
    return makeError(ErrorCode::BadInput,
                     src + ": neither a column 't_s' nor a metadata line 'fs_Hz' gives the sample rate");
}

struct InputColumns {
    const model::Channel *current, *torque, *motorVel, *tablePos, *loadVel;
};

/// T_M: K_t × current_A if traced, else torque_Nm, else torque_cmd_Nm; ω_M; the load side from the scale
/// (table_pos_m) or load_vel_rad_s.
Result<InputColumns> inputColumns(const model::Capture& cap, const std::string& src)
{
    InputColumns c{};
    c.current = cap.channel("current_A");
    c.torque = c.current ? nullptr : cap.channel("torque_Nm");
    if (!c.current && !c.torque)
        c.torque = cap.channel("torque_cmd_Nm");
    c.motorVel = cap.channel("motor_vel_rad_s");
    c.tablePos = cap.channel("table_pos_m");
    c.loadVel = c.tablePos ? nullptr : cap.channel("load_vel_rad_s");
    if (!c.current && !c.torque)
        return makeError(ErrorCode::BadInput, src + ": needs a column 'current_A', 'torque_Nm' or 'torque_cmd_Nm'");
    if (!c.motorVel)
        return makeError(ErrorCode::BadInput, src + ": missing column 'motor_vel_rad_s'");
    if (!c.tablePos && !c.loadVel)
        return makeError(ErrorCode::BadInput,
                         src + ": needs the load side: column 'table_pos_m' (linear scale) or 'load_vel_rad_s'");
    return c;
}

int runCuttingForce(const CuttingForceArgs& a)
{
    const std::string cmd = "cutting-force";
    auto cap = io::readCaptureCsvFile(a.in);
    if (!cap)
        return reportError(cmd, cap.error());
    auto stage = machining::readStageJsonFile(a.stage);
    if (!stage)
        return reportError(cmd, stage.error());
    auto ts = samplePeriod(*cap, a.in);
    if (!ts)
        return reportError(cmd, ts.error());
    const std::size_t n = cap->size();
    if (n < 3)
        return reportError(cmd, makeError(ErrorCode::BadInput, a.in + ": fewer than 3 samples"));
    auto cols = inputColumns(*cap, a.in);
    if (!cols)
        return reportError(cmd, cols.error());
    const auto [current, torque, wm, xt, wl] = *cols;

    const double r = stage->leadMPerRad();
    auto obs = machining::CuttingForceObserver::create(stage->motor, stage->load, stage->observer, *ts);
    if (!obs)
        return reportError(cmd, makeError(obs.error().code, a.stage + ": " + obs.error().detail));
    auto rls = machining::SwitchingRls::create(stage->load, stage->rls, *ts);
    if (!rls)
        return reportError(cmd, makeError(rls.error().code, a.stage + ": " + rls.error().detail));
    machining::CuttingForceObserver motorSide = obs.value();
    machining::SwitchingRls adaptive = rls.value();

    model::Capture outCap;
    outCap.metadata.set(model::meta::kSource, a.in);
    outCap.metadata.set(model::meta::kFsHz, 1.0 / *ts);
    outCap.metadata.set("motor_torque_from", current ? "current_A x torque_constant" : torque->name);
    outCap.metadata.set("load_velocity_from", xt ? "table_pos_m (backward difference / R)" : "load_vel_rad_s");
    outCap.metadata.set(model::meta::kCuttingForceSign,
                        "force of the process on the table along +axis (= -F_cut/R of seed 003 eq. (1))");
    std::vector<double> tcol(n), tsHat(n), fcut(n), force(n), mode(n), jl(n), bl(n), fcl(n);
    const auto* tIn = cap->channel("t_s");
    double sumForce = 0.0;
    std::size_t counted = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const std::string at = a.in + " data row " + std::to_string(i + 1);
        const double tm = current ? stage->torqueConstantNmPerA * current->data[i] : torque->data[i];
        double omegaL = 0.0;
        if (xt)
            omegaL = i > 0 ? (xt->data[i] - xt->data[i - 1]) / (*ts * r) : 0.0;
        else
            omegaL = wl->data[i];
        if (!std::isfinite(tm) || !std::isfinite(wm->data[i]) || !std::isfinite(omegaL))
            return reportError(cmd, makeError(ErrorCode::BadInput, at + ": not a finite number"));
        tsHat[i] = motorSide.torsionTorque(tm, wm->data[i]);
        const auto s = adaptive.step(tsHat[i], omegaL);
        tcol[i] = tIn ? tIn->data[i] : static_cast<double>(i) * *ts;
        fcut[i] = s.forceHat;
        force[i] = -s.forceHat / r;
        mode[i] = static_cast<double>(static_cast<int>(s.mode));
        jl[i] = s.estimate.inertia;
        bl[i] = s.estimate.viscous;
        fcl[i] = s.estimate.coulomb;
    }
    // Mean over the second half (after the filters and the identification have settled).
    for (std::size_t i = n / 2; i < n; ++i, ++counted)
        sumForce += force[i];
    outCap.channels = {
        {"t_s", tcol},      {"torsion_torque_Nm", tsHat}, {"cutting_torque_Nm", fcut}, {"cutting_force_N", force},
        {"rls_mode", mode}, {"J_L_hat_kgm2", jl},         {"B_L_hat_Nms_per_rad", bl}, {"F_CL_hat_Nm", fcl}};
    if (auto st = io::writeCaptureCsvFile(a.out, outCap); !st)
        return reportError(cmd, st.error());
    const auto* counts = adaptive.modeCounts();
    nlohmann::json j;
    j["input"] = a.in;
    j["output"] = a.out;
    j["samples"] = n;
    j["mean_cutting_force_second_half_N"] = sumForce / static_cast<double>(counted);
    j["mode_samples"] = {{"hold", counts[0]}, {"rls3", counts[1]}, {"rls4", counts[2]}};
    j["final_estimate"] = {{"J_L_kgm2", jl.back()}, {"B_L_Nms_per_rad", bl.back()}, {"F_CL_Nm", fcl.back()}};
    return writeJsonResult(cmd, j, "");
}

const CliRegistrar kRegistrar{{
    "cutting-force",
    "Cutting force observer with switching RLS (seed 003) on a capture → force CSV",
    [](CLI::App& sub) -> std::function<int()> {
        auto a = std::make_shared<CuttingForceArgs>();
        sub.add_option(
               "--in", a->in,
               "capture CSV: t_s, motor_vel_rad_s, current_A|torque_Nm|torque_cmd_Nm, table_pos_m|load_vel_rad_s")
            ->required();
        sub.add_option("--stage", a->stage, "stage.json (docs/machining.md)")->required();
        sub.add_option("--out", a->out, "force CSV to write (t_s, cutting_force_N, estimates)")->required();
        return recordSessions(sub, [a] { return runCuttingForce(*a); });
    },
}};

} // namespace
} // namespace axistune::cli
