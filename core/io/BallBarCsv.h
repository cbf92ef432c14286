// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Ball-bar CSV (DESIGN.md "File formats", docs/ballbar.md): "# key=value" metadata lines, then the
// header "angle_deg,deviation_um", then one row per sample in the order of travel.
//
// Required metadata: radius_mm (nominal ball-bar length), feed_mm_min, direction (ccw|cw).
// Optional: plane (XY, default), center_x_mm / center_y_mm (circle centre in machine coordinates,
// default 0), dT_x_Nm / dT_y_Nm (reversal torque change per axis, peak-to-peak), any other keys
// (kept in `metadata`).
//
// Angles are the geometric angle of the bar, counter-clockwise from +X (first axis of the plane), in
// degrees; they must be strictly monotonic, increasing or decreasing (either order is accepted, the
// travel direction comes from `direction`), and may run past 360 or below 0. Deviation is the
// measured radius minus the nominal radius, in µm (outward positive). Inside core everything is SI.

#include "core/model/BallBarTrace.h"
#include "core/model/Result.h"

#include <istream>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace axistune::io {

// The trace type lives in core/model so the simulator can produce it without depending on io.
using model::BallBarTrace;
using model::CircleDirection;

/// Fewest samples a trace may have.
inline constexpr std::size_t kBallBarMinSamples = 8;

/// Reads a trace; `sourceName` names the file in error messages ("a.csv line 12, column 'deviation_um': ...").
Result<BallBarTrace> readBallBarCsv(std::istream& in, const std::string& sourceName);
Result<BallBarTrace> readBallBarCsvFile(const std::string& path);

/// Writes the metadata (radius, feed, direction, plane, centre, dT when known, then other keys),
/// the header and the rows in full precision. Refuses traces that the reader would refuse.
Status writeBallBarCsv(std::ostream& out, const BallBarTrace& trace);
Status writeBallBarCsvFile(const std::string& path, const BallBarTrace& trace);

} // namespace axistune::io
