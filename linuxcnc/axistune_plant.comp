component axistune_plant """Two-mass feed-axis plant for AxisTune's LinuxCNC test machine.

The motor (inertia jm) drives the load (inertia jl) through a spring (k, c); viscous friction bm and bl,
Coulomb friction fc on the motor side, a ball screw of pitch 'lead' turns motor angle into axis position,
and an encoder of resolution 'resolution' quantizes the position feedback.

With kv > 0 the component is a velocity-mode drive: the drive input is 'velocity_cmd' [mm/s] and the drive's
own velocity loop, a proportional gain kv on the motor speed evaluated every substep, makes the torque
kv (velocity_cmd/(lead/2 pi) - motor speed); the 'torque' pin is then not read. With kv = 0 (the default)
the drive input is 'torque' (torque mode).

Each servo period is divided into 'substeps' equal steps h of semi-implicit Euler
(v += a h; x += v h), so with fc = 0 and resolution = 0 the component is the linear recurrence
x[n+1] = A x[n] + B u[n] with A, B the substep matrices raised to the substeps-th power: a test can
compute its exact discrete-time response from these lines. docs/linuxcnc.md gives the equations.""";

pin in float torque "Motor torque command [N·m]: the drive input in torque mode (kv = 0)";
pin in float velocity_cmd "Axis velocity command [mm/s]: the drive input in velocity mode (kv > 0)";
pin out float position "Axis position from the motor encoder [mm], quantized to resolution";
pin out float velocity "Axis velocity at the motor [mm/s]";
pin out float load_position "Load position [mm], not quantized";
pin out float motor_angle "Motor angle [rad], not quantized";

param rw float jm = 0.0002 "Motor inertia [kg·m²]";
param rw float jl = 0.0004 "Load inertia reflected to the motor [kg·m²]";
param rw float k = 56.85 "Coupling stiffness [N·m/rad] (anti-resonance 60 Hz, resonance 104 Hz with the defaults)";
param rw float c = 0.02 "Coupling damping [N·m·s/rad] (resonance damping ratio about 0.11 with the defaults)";
param rw float bm = 0.0005 "Motor viscous friction [N·m·s/rad]";
param rw float bl = 0.0 "Load viscous friction [N·m·s/rad]";
param rw float fc = 0.0 "Coulomb friction on the motor [N·m]";
param rw float lead = 10.0 "Ball-screw lead [mm/rev]";
param rw float resolution = 0.0 "Encoder resolution [mm]; 0: no quantization";
param rw u32 substeps = 20 "Integration steps per servo period";
param rw float kv = 0.0 "Velocity-mode drive: its velocity-loop gain [N·m·s/rad]; 0: torque mode";

variable double thm = 0;
variable double wm = 0;
variable double thl = 0;
variable double wl = 0;

function _ "Advance the plant by one servo period";
license "GPL";
author "AxisTune";
;;
#include <rtapi_math.h>

FUNCTION(_) {
    unsigned n = substeps > 0 ? substeps : 1;
    double h = fperiod / n;
    double mmPerRad = lead / (2.0 * M_PI);
    unsigned i;
    for (i = 0; i < n; ++i) {
        double spring = k * (thm - thl) + c * (wm - wl);
        double drive = kv > 0.0 ? kv * (velocity_cmd / mmPerRad - wm) : torque;
        double wmNew = wm + h * (drive - spring - bm * wm) / jm;
        double wlNew = wl + h * (spring - bl * wl) / jl;
        if (fc > 0.0) {
            /* Coulomb friction: decelerates, and holds the motor when it would reverse within the step */
            double dv = h * fc / jm;
            if (fabs(wmNew) <= dv) wmNew = 0.0;
            else wmNew -= (wmNew > 0.0 ? dv : -dv);
        }
        wm = wmNew;
        wl = wlNew;
        thm += h * wm;
        thl += h * wl;
    }
    motor_angle = thm;
    load_position = thl * mmPerRad;
    velocity = wm * mmPerRad;
    if (resolution > 0.0)
        position = floor(thm * mmPerRad / resolution + 0.5) * resolution;
    else
        position = thm * mmPerRad;
}
