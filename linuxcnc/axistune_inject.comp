component axistune_inject """AxisTune's excitation injection at a PID output, guarded in the servo thread.

out = in + excitation while the injection is armed; out = in otherwise. The injection is armed only
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

param rw float timeout = 0.04 "Heartbeat timeout [s]";
param rw float limit = 0.0 "Largest |excitation| accepted; 0: refuse every excitation";
param rw float maxerror = 0.0 "Largest |error| during the injection; 0: not watched";

variable unsigned lastBeat = 0;
variable double age = 1e9;
variable int latched = 0;

function _ "Add the guarded injection";
license "GPL";
author "AxisTune";
;;
#include <rtapi_math.h>

FUNCTION(_) {
    if (heartbeat != lastBeat) {
        lastBeat = heartbeat;
        age = 0.0;
    } else {
        age += fperiod;
    }
    if (!enable) {
        latched = 0;
        trip = 0;
    } else if (!latched) {
        if (age >= timeout) { latched = 1; trip = 1; }
        else if (fabs(excitation) > limit) { latched = 1; trip = 2; }
        else if (maxerror > 0.0 && fabs(error) > maxerror) { latched = 1; trip = 3; }
    }
    armed = enable && !latched;
    injected = armed ? excitation : 0.0;
    out = in + injected;
}
