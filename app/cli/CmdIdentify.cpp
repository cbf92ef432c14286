// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli identify: inertia, viscous and Coulomb friction and offset of an axis from a recorded
// motion (IDIM-LS), validated by simulating the model under the record's controller on other
// records; docs/identification.md.
#include "app/cli/CliCommand.h"
#include "core/ident/IdentificationInput.h"
#include "core/ident/IdentificationJson.h"
#include "core/ident/MotionIdentification.h"
#include "core/io/CaptureCsv.h"
#include "core/model/InputLimits.h"

#include <memory>
#include <nlohmann/json.hpp>

namespace axistune::cli {

namespace {

struct IdentifyOptions {
    std::string inPath, outPath, positionUnit, controllerPath;
    std::vector<std::string> validatePaths;
    ident::CaptureColumns cols;
    ident::IdentificationOptions ident;
    // controller from options (when no --controller file)
    double kp = 0.0, kv = 0.0, saturation = 0.0, controllerForceScale = 0.0;
    int delay = 0;
};

Result<ident::PositionController> controllerFor(const IdentifyOptions& o)
{
    const bool anyOption = o.kp != 0.0 || o.kv != 0.0 || o.saturation != 0.0 || o.controllerForceScale != 0.0;
    if (!o.controllerPath.empty()) {
        if (anyOption)
            return makeError(ErrorCode::BadInput,
                             "give the controller either as --controller FILE or as --kp/--kv/--saturation, not both");
        // Regular file, size, depth and number limits (docs/robustness.md).
        auto j = model::readJsonFile(o.controllerPath);
        if (!j)
            return j.error();
        return ident::controllerFromJson(*j, model::displayPath(o.controllerPath));
    }
    if (!(o.kp > 0.0) || !(o.kv > 0.0) || !(o.saturation > 0.0))
        return makeError(ErrorCode::BadInput, "--validate needs the record's controller: --controller FILE.json or "
                                              "--kp, --kv and --saturation (and --delay, --controller-force-scale)");
    ident::PositionController c;
    c.kpPerS = o.kp;
    c.kv = o.kv;
    c.saturation = o.saturation;
    c.delaySamples = o.delay;
    c.forceScale = o.controllerForceScale > 0.0 ? o.controllerForceScale : o.cols.forceScale;
    if (c.delaySamples < 0 || c.delaySamples > 100)
        return makeError(ErrorCode::OutOfRange, "--delay must lie in 0..100 samples");
    return c;
}

Result<nlohmann::json> run(const IdentifyOptions& o)
{
    auto motion = ident::axisMotionFor(o.positionUnit, o.cols.position);
    if (!motion)
        return motion.error();
    auto cap = io::readCaptureCsvFile(o.inPath);
    if (!cap)
        return cap.error();
    auto rec = ident::motionRecordFromCapture(*cap, o.inPath, o.cols);
    if (!rec)
        return rec.error();
    auto res = ident::identifyRigidBody(*rec, o.ident);
    if (!res)
        return makeError(res.error().code, o.inPath + ": " + res.error().detail);
    nlohmann::json j = ident::identificationToJson(*res, *motion);
    j["source"] = {{"file", o.inPath},
                   {"position", o.cols.position},
                   {"force", o.cols.force},
                   {"force_scale", o.cols.forceScale},
                   {"velocity", o.cols.velocity},
                   {"time", o.cols.fsHz > 0.0 ? "" : o.cols.time},
                   {"time_tolerance", o.cols.timeTolerance}};
    j["method"]["cutoff_Hz"] = o.ident.cutoffHz;
    j["validation"] = nlohmann::json::array();
    if (o.validatePaths.empty())
        return j;
    auto ctrl = controllerFor(o);
    if (!ctrl)
        return ctrl.error();
    const auto model =
        ident::RigidBodyModel::symmetric(res->inertia.value, res->viscous.value, res->coulomb.value, res->offset.value);
    for (const auto& path : o.validatePaths) {
        auto vcap = io::readCaptureCsvFile(path);
        if (!vcap)
            return vcap.error();
        auto vrec = ident::validationRecordFromCapture(*vcap, path, o.cols);
        if (!vrec)
            return vrec.error();
        auto v = ident::validateClosedLoop(model, *ctrl, *vrec, o.ident.cutoffHz,
                                           static_cast<std::size_t>(res->borderSamples));
        if (!v)
            return makeError(v.error().code, path + ": " + v.error().detail);
        nlohmann::json vj = ident::validationToJson(*v);
        vj["file"] = path;
        vj["reference"] = o.cols.reference;
        vj["extra"] = o.cols.extra;
        vj["controller"] = ident::controllerToJson(*ctrl);
        j["validation"].push_back(vj);
    }
    return j;
}

CliRegistrar reg{
    {"identify",
     "inertia, viscous/Coulomb friction and offset from a recorded motion (IDIM-LS), with closed-loop validation",
     [](CLI::App& sub) {
         auto o = std::make_shared<IdentifyOptions>();
         sub.add_option("--in", o->inPath, "capture CSV with position and force (or command) columns")->required();
         sub.add_option("--position", o->cols.position, "position column (m or rad)")->required();
         sub.add_option("--force", o->cols.force,
                        "force/torque column, or the command that --force-scale turns into one")
             ->required();
         sub.add_option("--force-scale", o->cols.forceScale, "N (N*m) per unit of the force column (default 1)");
         sub.add_option("--velocity", o->cols.velocity,
                        "measured velocity column (default: differentiate the position)");
         sub.add_option("--position-unit", o->positionUnit,
                        "m (linear axis) or rad (rotary); default from the column suffix _m/_rad");
         sub.add_option("--time", o->cols.time, "time column [s] (default t_s)");
         sub.add_option("--fs", o->cols.fsHz, "sample rate [Hz], overrides the time column");
         sub.add_option("--time-tolerance", o->cols.timeTolerance,
                        "accepted jitter of the time steps, fraction of the median step (default 0.001)");
         sub.add_option("--cutoff", o->ident.cutoffHz, "zero-phase low-pass on the position [Hz] (default 100)");
         sub.add_option("--decimation", o->ident.decimation, "decimation factor (default round(fs/cutoff))");
         sub.add_option("--min-speed", o->ident.minSpeed,
                        "leave out equations slower than this [m/s or rad/s] (default 1 % of the largest speed)");
         sub.add_flag("--asymmetric", o->ident.asymmetric, "also fit per-direction viscous and Coulomb friction");
         sub.add_option("--validate", o->validatePaths, "records to validate on (same columns plus --reference)");
         sub.add_option("--reference", o->cols.reference, "commanded-position column of the validation records");
         sub.add_option("--extra", o->cols.extra, "column added to the controller output in validation (e.g. pulses)");
         sub.add_option("--controller", o->controllerPath,
                        "controller JSON {kp_per_s, kv, saturation, delay_samples, force_scale}");
         sub.add_option("--kp", o->kp, "position gain [1/s]");
         sub.add_option("--kv", o->kv, "velocity gain [command per (m/s) or (rad/s)]");
         sub.add_option("--saturation", o->saturation, "controller output limit [command units]");
         sub.add_option("--delay", o->delay,
                        "samples from a measurement to the start of its command's hold (default 0)");
         sub.add_option("--controller-force-scale", o->controllerForceScale,
                        "N (N*m) per command unit (default --force-scale)");
         sub.add_option("--out", o->outPath, "write the result JSON here instead of stdout");
         return [o] {
             auto j = run(*o);
             if (!j)
                 return reportError("identify", j.error());
             return writeJsonResult("identify", *j, o->outPath);
         };
     }}};

} // namespace

} // namespace axistune::cli
