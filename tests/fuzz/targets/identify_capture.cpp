// SPDX-License-Identifier: GPL-3.0-or-later
// seeds: tests/data/ident/*.csv
// The capture reader of `identify --in` and the identification on it (columns t_s, x_m, f_N as in the
// seed): refused with the file named, or an identification whose result JSON holds only finite
// numbers and no null (model::dumpResultJson accepts it, as the CLI's output does).
#include "core/ident/IdentificationInput.h"
#include "core/ident/IdentificationJson.h"
#include "core/io/CaptureCsv.h"

#include <sstream>

#include "tests/fuzz/FuzzTarget.h"

using namespace axistune;

AXISTUNE_FUZZ_TARGET(identify_capture)
{
    std::istringstream in(input);
    auto cap = io::readCaptureCsv(in, fuzz::kSource);
    if (!cap) {
        fuzz::requireRefusal(cap.error());
        return;
    }
    ident::CaptureColumns cols;
    cols.position = "x_m";
    cols.force = "f_N";
    auto rec = ident::motionRecordFromCapture(*cap, fuzz::kSource, cols);
    if (!rec) {
        fuzz::requireRefusal(rec.error());
        return;
    }
    auto res = ident::identifyRigidBody(*rec, ident::IdentificationOptions{});
    if (!res) {
        // The CLI prefixes the file (CmdIdentify.cpp); the error itself must still be a refusal.
        fuzz::require(exitCodeFor(res.error().code) == 2,
                      "identification error is not a refusal: " + res.error().detail);
        return;
    }
    fuzz::requireFinite(res->inertia.value, "inertia");
    fuzz::requireFinite(res->viscous.value, "viscous");
    fuzz::requireFinite(res->coulomb.value, "coulomb");
    fuzz::requireFinite(res->offset.value, "offset");
    auto text = model::dumpResultJson(ident::identificationToJson(*res, ident::AxisMotion::Linear));
    fuzz::require(text.ok(), "result JSON refused: " + (text ? std::string() : text.error().detail));
}
