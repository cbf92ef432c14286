// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/device/hal/LinuxCncMotion.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <emc.hh>
#include <emc_nml.hh>
#include <rcs.hh>
#include <rcs_print.hh>
#pragma GCC diagnostic pop

#include <cmath>
#include <cstdio>
#include <fcntl.h>
#include <unistd.h>
#include <thread>

namespace axistune::device::hal {

struct LinuxCncMotion::Channels {
    std::unique_ptr<RCS_CMD_CHANNEL> command;
    std::unique_ptr<RCS_STAT_CHANNEL> status;
    EMC_STAT* stat() { return static_cast<EMC_STAT*>(status->get_address()); }
    bool poll() { return status->peek() != -1 && stat() != nullptr; }
};

LinuxCncMotion::LinuxCncMotion(std::unique_ptr<Channels> c) : m_c(std::move(c)) {}
LinuxCncMotion::~LinuxCncMotion() = default;

Result<std::unique_ptr<LinuxCncMotion>> LinuxCncMotion::open(const std::string& nmlFile)
{
    // NML prints its own diagnostics to stdout by default; AxisTune reports what failed itself.
    set_rcs_print_destination(RCS_PRINT_TO_NULL);
    auto c = std::make_unique<Channels>();
    c->command = std::make_unique<RCS_CMD_CHANNEL>(emcFormat, "emcCommand", "xemc", nmlFile.c_str());
    c->status = std::make_unique<RCS_STAT_CHANNEL>(emcFormat, "emcStatus", "xemc", nmlFile.c_str());
    // The first status read tries LinuxCNC's tool-table memory map and, when the task's user is another one (HAL run
    // as its own user), prints two lines about it on stdout, where the CLI writes its JSON: that read goes to
    // /dev/null (LinuxCNC prints them once per process).
    bool polled = false;
    if (c->command->valid() && c->status->valid()) {
        std::fflush(stdout);
        const int saved = ::dup(STDOUT_FILENO);
        const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
        if (saved >= 0 && null >= 0)
            ::dup2(null, STDOUT_FILENO);
        polled = c->poll();
        std::fflush(stdout);
        if (saved >= 0 && null >= 0)
            ::dup2(saved, STDOUT_FILENO);
        if (saved >= 0)
            ::close(saved);
        if (null >= 0)
            ::close(null);
    }
    if (!polled)
        return makeError(ErrorCode::Device, "no LinuxCNC task answers on the NML channels of " + nmlFile +
                                                " (is LinuxCNC running from this configuration?)");
    return std::unique_ptr<LinuxCncMotion>(new LinuxCncMotion(std::move(c)));
}

Result<bool> LinuxCncMotion::machineOn()
{
    if (!m_c->poll())
        return makeError(ErrorCode::Device, "LinuxCNC's status channel no longer answers");
    return m_c->stat()->task.state == EMC_TASK_STATE_ON;
}

Result<LinuxCncMotion::JointState> LinuxCncMotion::joint(int joint)
{
    if (!m_c->poll())
        return makeError(ErrorCode::Device, "LinuxCNC's status channel no longer answers");
    if (joint < 0 || joint >= EMCMOT_MAX_JOINTS || joint >= m_c->stat()->motion.traj.joints)
        return makeError(ErrorCode::NotFound, "LinuxCNC has no joint " + std::to_string(joint));
    const EMC_JOINT_STAT& j = m_c->stat()->motion.joint[joint];
    return JointState{j.input, j.output, j.inpos != 0, j.enabled != 0};
}

Status LinuxCncMotion::send(::RCS_CMD_MSG& message, const char* what)
{
    message.serial_number = ++m_serial;
    if (m_c->command->write(&message) != 0)
        return makeError(ErrorCode::Device, std::string("LinuxCNC's command channel refused ") + what);
    // The channel numbers the message as it writes it (LinuxCNC 2.9: the serial number written is the channel's, not
    // the one set above); the task echoes that number when it has taken the command, RCS_ERROR when it refused it.
    m_serial = message.serial_number;
    for (int i = 0; i < 500; ++i) {
        if (!m_c->poll())
            return makeError(ErrorCode::Device, "LinuxCNC's status channel no longer answers");
        const EMC_STAT* s = m_c->stat();
        if (s->echo_serial_number == m_serial && s->status != RCS_EXEC) {
            if (s->status == RCS_ERROR)
                return makeError(ErrorCode::Device, std::string("LinuxCNC's task refused ") + what +
                                                        " (its message is in LinuxCNC's error channel)");
            return Status::success();
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return makeError(ErrorCode::Device, std::string("LinuxCNC's task did not take ") + what + " within 5 s");
}

Status LinuxCncMotion::jogIncrement(int joint, double increment, double velocity, const std::atomic<bool>& abort,
                                    std::chrono::milliseconds timeout)
{
    if (!std::isfinite(increment) || increment == 0.0 || !std::isfinite(velocity) || !(velocity > 0.0))
        return makeError(ErrorCode::OutOfRange, "a jog needs a non-zero increment and a positive velocity");
    auto on = machineOn();
    if (!on)
        return on.error();
    if (!*on)
        return makeError(ErrorCode::Safety, "LinuxCNC's machine is not on (E-stop or off): no jog");
    auto before = this->joint(joint);
    if (!before)
        return before.error();
    EMC_TASK_SET_MODE mode;
    mode.mode = EMC_TASK_MODE_MANUAL;
    if (auto st = send(mode, "manual mode"); !st)
        return st;
    EMC_TRAJ_SET_TELEOP_ENABLE teleop;
    teleop.enable = 0; // joint jogging
    if (auto st = send(teleop, "joint mode"); !st)
        return st;
    EMC_JOG_INCR jog;
    jog.joint_or_axis = joint;
    jog.incr = increment;
    jog.vel = velocity;
    jog.jjogmode = 1;
    if (auto st = send(jog, "the jog"); !st)
        return st;
    // Done when the joint is in position again near the target (motion's own rounding leaves its command a few nm
    // from the start + increment: a thousandth of the increment tells the end of the move from its start).
    const double target = before->command + increment;
    const double tolerance = 1e-3 * std::abs(increment);
    const auto t0 = std::chrono::steady_clock::now();
    for (;;) {
        if (abort.load()) {
            (void)stopJog(joint);
            return makeError(ErrorCode::Aborted, "aborted");
        }
        auto j = this->joint(joint);
        if (!j)
            return j.error();
        if (!j->enabled)
            return makeError(ErrorCode::Device, "LinuxCNC disabled joint " + std::to_string(joint) +
                                                    " during the jog (following error, a limit or E-stop)");
        if (j->inPosition && std::abs(j->command - target) <= tolerance)
            return Status::success();
        if (std::chrono::steady_clock::now() - t0 > timeout) {
            (void)stopJog(joint);
            return makeError(ErrorCode::Device, "the jog of joint " + std::to_string(joint) + " did not end within " +
                                                    std::to_string(timeout.count()) + " ms");
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
}

Status LinuxCncMotion::stopJog(int joint)
{
    EMC_JOG_STOP stop;
    stop.joint_or_axis = joint;
    stop.jjogmode = 1;
    return send(stop, "stopping the jog");
}

} // namespace axistune::device::hal
