// SPDX-License-Identifier: GPL-3.0-or-later
// Writes resources/drives/axistune-sim.json from the simulator's parameter catalogue
// (axistune-simdrive --write-map FILE). The drive and the client never use this code: they read the
// JSON file, so another drive family is another file.
#include "app/simdrive/RegisterMapTemplate.h"

#include "core/device/TestRegisterCodec.h"
#include "core/sim/AxisParameters.h"

#include <algorithm>
#include <nlohmann/json.hpp>

namespace axistune::simdrive {

std::string simRegisterMapJson()
{
    using nlohmann::ordered_json;
    ordered_json j;
    j["family"] = "axistune-sim";
    j["version"] = 3;
    j["description"] =
        "AxisTune simulated drive (axistune-simdrive). All data in holding registers (function codes 3, 6, 16, 23). "
        "Addresses are 0-based PDU addresses. Unit id = unit_id_base + axis index.";
    j["word_order"] = "high_word_first";
    j["unit_id_base"] = 1;
    j["max_registers_per_read"] = 125;
    j["magic"] = 0x4154; // "AT"
    ordered_json f;
    auto add = [&f](const std::string& name, int address, const std::string& type, int count, const std::string& what) {
        ordered_json e{{"address", address}, {"type", type}};
        if (type == "string" || type == "window")
            e["count"] = count;
        e["description"] = what;
        f[name] = e;
    };
    add("identity.magic", 0, "u16", 1, "0x4154 ('AT'): this is an AxisTune register map");
    add("identity.map_version", 1, "u16", 1, "register map version");
    add("identity.axis_count", 2, "u16", 1, "number of axes (unit ids unit_id_base .. unit_id_base + n - 1)");
    add("identity.axis_index", 3, "u16", 1, "axis index of the unit id asked");
    add("identity.axis_kind", 4, "u16", 1, "enum axis_kind");
    add("identity.parameter_count", 5, "u16", 1, "parameters available on this axis");
    add("identity.reserved", 6, "string", 2, "reserved, reads 0 (keeps the block contiguous for one read)");
    add("identity.vendor", 8, "string", 8, "16 ASCII characters");
    add("identity.model", 16, "string", 16, "32 ASCII characters");
    add("identity.firmware", 32, "string", 8, "16 ASCII characters");
    add("identity.machine", 40, "string", 16, "machine (preset) name, 32 ASCII characters");
    add("identity.axis_name", 56, "string", 4, "axis name, 8 ASCII characters");
    add("status.state", 100, "u16", 1, "enum state of the drive's test");
    add("status.fault_code", 101, "u16", 1, "enum fault: why the last test stopped");
    add("status.position", 102, "f32", 2, "load position [m or rad]");
    add("status.velocity", 104, "f32", 2, "motor velocity [rad/s]");
    add("status.torque", 106, "f32", 2, "motor torque [N m]");
    add("status.progress", 108, "u16", 1, "test progress in 1/10000");
    add("status.heartbeat_echo", 109, "u16", 1, "last value written to heartbeat.counter");
    add("status.command_token_echo", 110, "u16", 1, "sequence token of the last executed command");
    add("status.command_result", 111, "u16", 1, "0 or the Modbus exception code of the last command");
    add("status.trace_samples", 112, "u32", 2, "samples per channel of the trace of the last completed test");
    add("status.trace_channels", 114, "u16", 1, "channels in the trace");
    add("status.reserved", 115, "u16", 1, "reserved, reads 0");
    add("status.trace_rate_hz", 116, "f64", 4, "trace sample rate [Hz]");
    add("status.message", 120, "string", 64,
        "why the last request or test was refused or stopped, 128 ASCII characters");
    // The test configuration: every field carries one quantity of the request (core/device/TestRegisterCodec.h),
    // described by the codec's own words.
    auto carry = [&](const std::string& name, int address, const std::string& type, const std::string& quantity) {
        add(name, address, type, 1, device::findTestQuantity(quantity)->meaning);
        f[name]["carries"] = quantity;
    };
    carry("test.type", 200, "u16", "test.type");
    carry("test.flags", 201, "u16", "test.flags");
    carry("test.trace_divider", 202, "u16", "test.trace_divider");
    carry("test.freq_count", 203, "u16", "frf.points");
    carry("test.trace_channel_mask", 204, "u32", "trace.channel_mask");
    carry("test.step_velocity", 206, "f64", "step.velocity_rad_s");
    carry("test.distance", 210, "f64", "jog.distance");
    carry("test.velocity", 214, "f64", "jog.velocity");
    carry("test.acceleration", 218, "f64", "jog.acceleration");
    carry("test.record", 222, "f64", "test.record_s");
    carry("test.current_step", 226, "f64", "current_step.current_a");
    carry("test.freq_start", 230, "f64", "frf.fmin_hz");
    carry("test.freq_end", 234, "f64", "frf.fmax_hz");
    carry("test.frf_method", 238, "u16", "frf.method");
    carry("test.reserved", 239, "u16", "reserved");
    carry("test.settle", 240, "f64", "frf.settle_s");
    carry("test.min_measure", 244, "f64", "frf.min_measure_s");
    carry("test.multisine_periods", 248, "u16", "multisine.periods");
    carry("test.multisine_phases", 249, "u16", "multisine.phases");
    carry("test.multisine_band_count", 250, "u16", "multisine.band_count");
    carry("test.multisine_reserved", 251, "u16", "reserved");
    for (int b = 0; b < 4; ++b) {
        const std::string n = "test.multisine_band" + std::to_string(b + 1), q = "multisine.band" + std::to_string(b + 1);
        carry(n + "_fmin", 252 + 12 * b, "f64", q + ".fmin_hz");
        carry(n + "_fmax", 256 + 12 * b, "f64", q + ".fmax_hz");
        carry(n + "_spacing", 260 + 12 * b, "f64", q + ".spacing_hz");
    }
    add("command.code", 300, "u16", 1, "enum command; written together with command.token");
    add("command.token", 301, "u16", 1, "sequence token: a command repeated with the same token is not executed twice");
    add("heartbeat.counter", 310, "u16", 1,
        "written by the client while a test runs; the watchdog stops the test when it goes silent");
    carry("circle.second_axis", 340, "u16", "circle.second_axis");
    carry("circle.direction", 341, "u16", "circle.direction");
    carry("circle.radius", 342, "f64", "circle.radius_m");
    carry("circle.feed", 346, "f64", "circle.feed_m_per_s");
    carry("circle.center_x", 350, "f64", "circle.center_x_m");
    carry("circle.center_y", 354, "f64", "circle.center_y_m");
    carry("circle.data_start_deg", 358, "f64", "circle.data_start_deg");
    carry("circle.lead_arc_deg", 362, "f64", "circle.lead_arc_deg");
    // Map version 2: the test block 200-299 is full; the jog's jerk and the FRF excitation follow the circle block
    // (version 1 carried the step, the current step, the FRF amplitude and the jerk in one register, test.amplitude).
    carry("test.jog_jerk", 366, "f64", "jog.jerk");
    carry("test.frf_amplitude", 370, "f64", "frf.amplitude_pct");
    // Map version 3: one request type per test kind (core/device/Drive.h). Version 2's test.duration meant the record
    // length of a step, hold or current step and the dwell of a jog or circle, and a circle's move to its start point
    // used the jog's velocity and acceleration; the dwell and that move now have registers of their own.
    carry("test.dwell", 374, "f64", "test.dwell_s");
    carry("circle.positioning_speed", 378, "f64", "circle.positioning_m_per_s");
    carry("circle.positioning_accel", 382, "f64", "circle.positioning_m_per_s2");
    // The drive describes itself (docs/drive-seam.md, docs/modbus.md "Capabilities, limits and plans").
    add("describe.test_types", 600, "u16", 1, "bit i: the axis runs test_type i");
    add("describe.frf_methods", 601, "u16", 1, "bit i: frf_method i is offered");
    add("describe.flags", 602, "u16", 1, "bit set of enum describe_flag");
    add("describe.reserved", 603, "u16", 1, "reserved, reads 0");
    add("describe.trace_rate_hz", 604, "f64", 4, "fastest velocity-loop trace rate (trace divider 1) [Hz]");
    add("describe.current_trace_rate_hz", 608, "f64", 4, "trace rate of a current step [Hz]");
    add("limits.frf_amplitude_max_pct", 612, "f64", 4,
        "largest FRF excitation (multisine: its peak) [% of rated torque]");
    add("limits.current_step_max_a", 616, "f64", 4, "largest q-axis current step [A]");
    add("limits.current_step_max_s", 620, "f64", 4, "longest current-step record [s]");
    add("limits.current_step_max_speed_rad_s", 624, "f64", 4, "motor speed a current step may reach [rad/s]");
    add("limits.motor_speed_max_rad_s", 628, "f64", 4, "step amplitude, jog and circle speeds at the motor [rad/s]");
    add("limits.test_duration_max_s", 632, "f64", 4, "longest step, hold or current-step record, jog dwell [s]");
    add("limits.travel_window", 636, "f64", 4, "|position| of jog targets and circles [m or rad]; +inf: none");
    add("plan.token", 640, "u16", 1, "command.token of the plan_test command the plan block answers");
    add("plan.reserved", 641, "u16", 1, "reserved, reads 0");
    add("plan.record_samples", 642, "u32", 2, "samples per channel the planned test records");
    add("plan.motion_s", 644, "f64", 4, "machine time of the planned test, start to completion [s]");
    add("plan.trace_rate_hz", 648, "f64", 4, "sample rate of the planned test's trace [Hz]");
    // The scope (docs/scope.md, docs/modbus.md "Scope"): configuration 700-715 written in one request, then
    // command arm_scope; status 720-757 read in one request; readout by function 23 (read_source, read_from
    // written, window read).
    add("scope.mode", 700, "u16", 1, "enum scope_mode");
    add("scope.divider", 701, "u16", 1, "sample every N-th period of the fastest scope rate (1..scope.max_divider)");
    add("scope.channel_mask", 702, "u32", 2, "bit i: trace scope channel i (the list read with read_source channels)");
    add("scope.trigger_channel", 704, "u16", 1, "scope channel index of the trigger (one of the mask)");
    add("scope.trigger_edge", 705, "u16", 1, "enum scope_edge");
    add("scope.length", 706, "u32", 2, "rows per triggered capture");
    add("scope.trigger_level", 708, "f64", 4, "trigger level in the trigger channel's unit");
    add("scope.pre_trigger_pct", 712, "f64", 4, "share of the capture before the trigger row [%], 0..100");
    add("scope.state", 720, "u16", 1, "enum scope_state");
    add("scope.channel_count", 721, "u16", 1, "channels of the armed scope");
    add("scope.captures", 722, "u32", 2, "complete triggered captures since the scope was armed");
    add("scope.rate_hz", 724, "f64", 4, "sample rate of the armed scope [Hz]");
    add("scope.next_sample", 728, "f64", 4, "sample number the next row will get (an integer)");
    add("scope.oldest_sample", 732, "f64", 4, "oldest sample number still in the roll ring (an integer)");
    add("scope.capture_first", 736, "f64", 4, "sample number of the first row of the last complete capture");
    add("scope.capture_trigger", 740, "f64", 4, "sample number of its trigger row");
    add("scope.capture_rows", 744, "u32", 2, "rows of the last complete capture");
    add("scope.signal_count", 746, "u16", 1, "traceable scope channels of this axis (0: no scope)");
    add("scope.max_channels", 747, "u16", 1, "channels traced at once");
    add("scope.fastest_rate_hz", 748, "f64", 4, "scope rate at divider 1 [Hz]");
    add("scope.max_values", 752, "u32", 2, "channels x rows of one triggered capture");
    add("scope.ring_values", 754, "u32", 2, "channels x rows the roll ring holds");
    add("scope.max_divider", 756, "u16", 1, "largest scope.divider");
    add("scope.read_source", 757, "u16", 1, "enum scope_source: what scope.window shows");
    add("scope.read_from", 758, "f64", 4, "first sample number (ring, capture) or byte offset (channels) of the window");
    add("scope.window", 770, "window", 124,
        "ring/capture: first sample (f64), rows (u16), capture number mod 65536 (u16), then rows x channels "
        "float64, row by row; channels: 248 bytes of 'name TAB unit TAB description' lines");
    add("trace.select_offset", 400, "u32", 2, "first sample (or byte, for the text channels) of the window");
    add("trace.select_channel", 402, "u16", 1, "trace channel index, or enum trace_channel");
    add("trace.window", 410, "window", 124,
        "31 float64 samples of the selected channel (NaN past the end) or 248 text bytes");
    j["fields"] = f;
    j["enums"] = {
        {"state", {{"idle", 0}, {"running", 1}, {"completed", 2}, {"aborted", 3}, {"faulted", 4}}},
        {"fault",
         {{"none", 0},
          {"amplitude_limit", 1},
          {"travel_limit", 2},
          {"speed_limit", 3},
          {"following_error", 4},
          {"heartbeat_lost", 5},
          {"drive_fault", 6},
          {"aborted", 7}}},
        {"command", {{"start_test", 1}, {"abort_test", 2}, {"clear", 3}, {"plan_test", 4}, {"arm_scope", 5}, {"stop_scope", 6}}},
        {"describe_flag", {{"evaluates_frf", 1}, {"writes_parameters", 2}, {"scope", 4}}},
        {"scope_mode", {{"single", 0}, {"normal", 1}, {"roll", 2}}},
        {"scope_edge", {{"rising", 0}, {"falling", 1}, {"either", 2}}},
        {"scope_state", {{"idle", 0}, {"filling", 1}, {"waiting", 2}, {"triggered", 3}, {"done", 4}, {"rolling", 5}}},
        {"scope_source", {{"ring", 0}, {"capture", 1}, {"channels", 2}}},
        {"test_type", {{"step", 0}, {"jog", 1}, {"hold", 2}, {"frf", 3}, {"current_step", 4}, {"circle", 5}}},
        {"circle_direction", {{"ccw", 0}, {"cw", 1}}},
        {"frf_method", {{"multisweep", 0}, {"conventional", 1}, {"prbs", 2}, {"multisine", 3}}},
        {"multisine_phases", {{"clipping", 0}, {"schroeder", 1}}},
        {"test_flag", {{"return_to_start", 1}}},
        {"axis_kind", {{"linear", 0}, {"rotary", 1}}},
        {"trace_channel", {{"frf_metadata", 65532}, {"frf_data", 65533}, {"names", 65534}, {"metadata", 65535}}},
    };
    // Every drive parameter (the union of linear and rotary axes), in catalogue order.
    ordered_json params = ordered_json::array();
    const auto& lin = sim::axisParameterMetas(sim::AxisKind::Linear);
    const auto& rot = sim::axisParameterMetas(sim::AxisKind::Rotary);
    int address = 1000;
    for (const auto& m : lin) {
        if (sim::isPlantParameter(m.key))
            continue;
        const bool onRot = std::any_of(rot.begin(), rot.end(), [&](const auto& r) { return r.key == m.key; });
        ordered_json p{{"key", m.key},           {"address", address},
                       {"type", "f32"},          {"label", m.label},
                       {"si_unit", m.siUnit},    {"display_unit", m.displayUnit},
                       {"min", m.minSi},         {"max", m.maxSi},
                       {"writable", m.writable}, {"writable_during_test", m.writableDuringTest},
                       {"integer", m.integer},   {"group", m.group}};
        if (!onRot)
            p["axis_kinds"] = {"linear"};
        params.push_back(p);
        address += 2;
    }
    j["parameters"] = params;
    return j.dump(2) + "\n";
}

} // namespace axistune::simdrive
