// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// LinuxCNC's own motion controller, commanded through its NML channels (`emcCommand` and `emcStatus` of the
// configuration's NML file: the interface LinuxCNC's GUIs, halui and its Python module use). The linuxcnc: backend
// jogs a joint through it, so a move runs with LinuxCNC's trajectory planner, limits and following-error checks
// (docs/linuxcnc.md "A jog through LinuxCNC's motion").

#include "core/model/Result.h"

#include <atomic>
#include <chrono>
#include <memory>
#include <string>

class RCS_CMD_MSG; // LinuxCNC's NML command message (cmd_msg.hh)

namespace axistune::device::hal {

class LinuxCncMotion {
public:
    /// The NML file of a configuration: [EMC]NML_FILE of its INI, else LinuxCNC's default.
    static constexpr const char* kDefaultNmlFile = "/usr/share/linuxcnc/linuxcnc.nml";

    /// Attaches to a running LinuxCNC's task through `nmlFile`; refused (Device) when no LinuxCNC answers there.
    static Result<std::unique_ptr<LinuxCncMotion>> open(const std::string& nmlFile);
    ~LinuxCncMotion();
    LinuxCncMotion(const LinuxCncMotion&) = delete;
    LinuxCncMotion& operator=(const LinuxCncMotion&) = delete;

    struct JointState {
        double position = 0.0; ///< motion's feedback position of the joint [machine units]
        double command = 0.0;  ///< motion's commanded position [machine units]
        bool inPosition = false;
        bool enabled = false;
    };
    /// The task's state: machine on (not in E-stop, not off).
    Result<bool> machineOn();
    Result<JointState> joint(int joint);

    /// Jogs `joint` by `increment` at `velocity` (machine units, units/s) with motion's planner and the joint's
    /// acceleration limit: manual mode and joint jogging are selected first. Returns when the joint is in position
    /// again; while waiting, `abort` stops the jog (motion decelerates). Errors: the machine is off, the task refused
    /// the command (its error text), the move did not end within `timeout`, aborted.
    Status jogIncrement(int joint, double increment, double velocity, const std::atomic<bool>& abort,
                        std::chrono::milliseconds timeout);
    /// Stops a jog of `joint` (motion decelerates to rest).
    Status stopJog(int joint);

private:
    struct Channels;
    explicit LinuxCncMotion(std::unique_ptr<Channels> c);
    Status send(::RCS_CMD_MSG& message, const char* what);
    std::unique_ptr<Channels> m_c;
    int m_serial = 0;
};

} // namespace axistune::device::hal
