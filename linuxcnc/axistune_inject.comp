component axistune_inject """AxisTune's excitation injection at a PID output or a PID command, guarded in the servo thread.

out = in + excitation while the injection is armed; out = in otherwise (at a PID output: 'rate' 0). At a
PID command (a move: the excitation is a position offset) 'rate' is the move's speed, and a trip does not drop
the offset at once (a position step) but returns it to zero at that speed: the axis stops its move and
goes back to where it started. The injection is armed only
while 'enable' is set, AxisTune's 'heartbeat' pin keeps changing (it stops counting when AxisTune
hangs, dies or is killed: the injection falls to zero 'timeout' seconds later), |excitation| stays
within 'limit' and |error| within 'maxerror'. Every trip latches until 'enable' falls; AxisTune
starts the heartbeat before it sets 'enable'.
docs/linuxcnc.md "Safety".""";

pin in float in "PID output (the drive command without injection)";
pin in float excitation "Excitation from AxisTune's stream, in the PID output's units";
pin in float error "Following error to watch (pid.N.error)";
pin in bit enable "AxisTune arms the injection; a falling edge clears a trip";
pin in u32 heartbeat "Counter AxisTune increments while it runs";
pin out float out "Drive command: in plus the injection while armed";
pin out float injected "The injection added this period";
pin out bit armed "The injection is being added";
pin out u32 trip "0: none, 1: heartbeat lost, 2: excitation above limit, 3: following error above maxerror";

param rw float timeout = 0.03 "Heartbeat timeout [s]";
param rw float limit = 0.0 "Largest |excitation| accepted; 0: refuse every excitation";
param rw float maxerror = 0.0 "Largest |error| during the injection; 0: not watched";
param rw float rate = 0.0 "After a trip or disarm, the injection returns to zero at this speed [units/s]; 0: at once";

variable unsigned lastBeat = 0;
variable rtapi_s64 lastBeatNs = 0;
variable int latched = 0;
variable double held = 0.0;

function _ "Add the guarded injection";
license "GPL";
author "AxisTune";
;;
#include <rtapi_math.h>

FUNCTION(_) {
    /* The age of the heartbeat in wall-clock time, not in servo periods: a thread that runs late catches up with
       several periods in a row, which says nothing about whether AxisTune still runs. */
    rtapi_s64 now = rtapi_get_time();
    double age;
    if (heartbeat != lastBeat || lastBeatNs == 0) {
        lastBeat = heartbeat;
        lastBeatNs = now;
    }
    age = (now - lastBeatNs) * 1e-9;
    if (!enable) {
        latched = 0;
        trip = 0;
    } else if (!latched) {
        if (age >= timeout) { latched = 1; trip = 1; }
        else if (fabs(excitation) > limit) { latched = 1; trip = 2; }
        else if (maxerror > 0.0 && fabs(error) > maxerror) { latched = 1; trip = 3; }
    }
    armed = enable && !latched;
    if (armed) {
        held = excitation;
    } else if (rate > 0.0 && fabs(held) > rate * fperiod) {
        held -= (held > 0.0 ? rate : -rate) * fperiod;
    } else {
        held = 0.0;
    }
    injected = held;
    out = in + injected;
}
