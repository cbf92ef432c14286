// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The drive seam (STYLE.md "A device seam"): synchronous, created and used on one I/O thread.
// Implementations register in DriveRegistry.h (docs/drive-seam.md): sim:, modbus://, replay:.

#include "core/device/Scope.h"
#include "core/dsp/FrequencyResponse.h"
#include "core/dsp/Multisine.h"
#include "core/dsp/SineDemodulation.h"
#include "core/model/BallBarTrace.h"
#include "core/model/Capture.h"
#include "core/model/Parameter.h"
#include "core/model/Result.h"

#include <complex>
#include <memory>
#include <span>
#include <string>
#include <variant>
#include <vector>

namespace axistune::device {

struct DriveIdentity {
    std::string vendor;
    std::string model;
    std::string firmware;
    std::string machine;            ///< preset or machine name
    std::vector<std::string> axes;  ///< axis names, one drive axis each
};

/// The kinds of test; each has its own request type below (StepTest, JogTest, ...), in this order in TestKind.
enum class TestType {
    Step,        ///< StepTest: a velocity step at the motor (hal:: a position step of the command)
    Jog,         ///< JogTest: a position move, optionally back
    Hold,        ///< HoldTest: the axis holds its position while recorded
    Frf,         ///< FrfTest: frequency response, torque injection in the closed velocity loop (FrfTest.h)
    Circle,      ///< CircleTest: ball-bar circle of two axes together (CircleDriveTest.h, docs/ballbar.md)
    CurrentStep, ///< CurrentStepTest: q-axis current step, loops open (docs/simulator.md "Current-step test")
};

/// Excitation and analysis of an FRF test (docs/frequency-response-sim.md).
enum class FrfMethod {
    MultiSweep,    ///< sine stream at phase offsets 0, +120°, −120°: valid below the trace rate fs
    Conventional,  ///< sine stream at one phase offset: valid below fs/2
    Prbs,          ///< PRBS with Welch H1 and coherence: valid below fs/2
    Multisine,     ///< three-phase multisine, all lines at once: valid below fs (docs/multisine.md)
};

const char* frfMethodName(FrfMethod m);

/// What an FRF test reports (a drive states in DriveCapabilities::frfQuantities which ones it offers).
enum class FrfQuantity {
    Default,  ///< the drive's own: the closed velocity loop (sim:, modbus://), the plant (hal:)
    Plant,    ///< feedback / drive input (hal:: the drive input is the PID output plus the injection)
    OpenLoop, ///< −(controller output) / drive input: the open position loop with the running gains (hal:)
};

/// TestType::Step. A drive takes the step quantity its capabilities name and refuses the other (BadInput, before
/// anything moves), so that a velocity step in rad/s is never taken for millimetres, nor millimetres for rad/s.
struct StepTest {
    /// A drive whose step is a motor velocity step (sim:, modbus://): the step [rad/s at the motor].
    double velocityRadS = 0.0;
    /// A drive whose step is a position step of the command (DriveCapabilities::stepIsPositionStep, hal:): the step
    /// in the command's units, held for recordS and stepped back.
    double position = 0.0;
    double recordS = 0.1; ///< recording length [s]
};

/// TestType::Jog: a position move, optionally back (a reversal). Units: m or rad, or the command's own units where
/// DriveCapabilities::jogInCommandUnits (hal:).
struct JogTest {
    double distance = 0.0;
    double velocity = 0.0;
    double acceleration = 0.0;
    double jerk = 0.0;          ///< jerk limit (rectangular jerk); 0: a trapezoid
    bool returnToStart = false; ///< move back to the start (a reversal)
    double dwellS = 0.1;        ///< dwell before and after the move [s]
};

/// TestType::Hold: the axis holds its position while it is recorded.
struct HoldTest {
    double recordS = 0.1; ///< recording length [s]
};

/// TestType::CurrentStep (docs/simulator.md "Current-step test"): velocity and position loops open, the q-axis
/// current command steps from 0 to currentA 10 % into the recording and holds, traced at every current-loop period.
/// Afterwards the axis holds its position again. Refused beyond the drive's limits (DriveLimits: current, record
/// length, motor speed reached).
struct CurrentStepTest {
    double currentA = 0.0; ///< the q-axis current step [A]
    double recordS = 0.1;  ///< recording length [s]
};

/// TestType::Frf (FrfTest.h): torque injection in the closed velocity loop. The record length follows from the plan.
struct FrfTest {
    FrfMethod method = FrfMethod::MultiSweep;
    double fminHz = 10.0;
    double fmaxHz = 3900.0;
    int points = 60; ///< frequencies of the sine streams and PRBS (multisine: not used)
    /// % of rated torque (multisine: its PEAK); refused above DriveLimits::frfAmplitudeMaxPct.
    double amplitudePct = 5.0;
    /// The excitation's peak in the units of the drive's injection point instead of amplitudePct (0: not given).
    /// Only drives whose capabilities say frfPeakInOutputUnits take it (hal:: the PID output's units); the others
    /// refuse a request that gives it.
    double amplitudePeak = 0.0;
    FrfQuantity quantity = FrfQuantity::Default; ///< refused unless in DriveCapabilities::frfQuantities
    double settleS = 0.0;     ///< settle per frequency (multisine: before the record) [s]; 0: from the loop's dynamics
    double minMeasureS = 0.0; ///< measured time per frequency at least [s]; 0: from the loop's dynamics
    // FrfMethod::Multisine (docs/multisine.md).
    double multisineSpacingHz = 0.0;                ///< line spacing of the band fminHz..fmaxHz; 0: fminHz/2
    std::vector<dsp::MultisineBand> multisineBands{}; ///< bands with their own spacing; empty: the one band above
    int multisinePeriods = 0;                       ///< averaged periods (three phases each); 0: from the loop's dynamics
    dsp::MultisinePhases multisinePhases = dsp::MultisinePhases::Clipping;
    std::vector<std::pair<double, double>> multisineShape{}; ///< (f [Hz], relative amplitude); empty: flat
    /// Phases that keep the crest factor low as seen through this response (f [Hz], gain), e.g. the current loop's
    /// voltage per injected torque (dsp::MultisineDesignOptions::crestThrough); empty: the excitation's own.
    std::vector<std::pair<double, std::complex<double>>> multisineCrestThrough{};
};

/// TestType::Circle (CircleDriveTest.h; docs/ballbar.md "Circle tests through the drive"): the request's axis is the
/// first plane axis ("x" role), secondAxis the second. The drive first moves both axes to the start point, dwells
/// dwellS, then runs lead-in arc, 360° data arc and lead-out arc. The trace carries both axes (CircleRun.h).
struct CircleTest {
    std::string secondAxis{};
    double radiusM = 0.0;
    double feedMPerS = 0.0;
    model::CircleDirection direction = model::CircleDirection::Ccw;
    double centerXM = 0.0;          ///< circle centre: position of the first axis [m]
    double centerYM = 0.0;          ///< circle centre: position of the second axis [m]
    double dataStartDeg = 45.0;     ///< angle at which the 360° data arc begins [deg]
    double leadArcDeg = 90.0;       ///< lead-in and lead-out arcs [deg]
    double positioningMPerS = 0.0;  ///< speed of the move to the start point [m/s]; 0: kCirclePositioningSpeedMPerS
    double positioningMPerS2 = 0.0; ///< its acceleration [m/s²]; 0: kCirclePositioningAccelMPerS2
    double dwellS = 0.1;            ///< dwell at the start point before the lead-in arc [s]
};

/// One test kind's fields; the alternatives are in TestType's order (TestRequest::type()).
using TestKind = std::variant<StepTest, JogTest, HoldTest, FrfTest, CircleTest, CurrentStepTest>;

/// A test on one axis: the kind with its own fields, and what every kind shares.
struct TestRequest {
    std::string axis{};
    TestKind test{};
    int traceDivider = 0; ///< 0: the drive's trace.divider parameter

    TestType type() const { return static_cast<TestType>(test.index()); }
    template <class T> bool is() const { return std::holds_alternative<T>(test); }
    // The kind's fields; std::bad_variant_access when the request is of another kind (check type() or is<T>()).
    StepTest& step() { return std::get<StepTest>(test); }
    const StepTest& step() const { return std::get<StepTest>(test); }
    JogTest& jog() { return std::get<JogTest>(test); }
    const JogTest& jog() const { return std::get<JogTest>(test); }
    HoldTest& hold() { return std::get<HoldTest>(test); }
    const HoldTest& hold() const { return std::get<HoldTest>(test); }
    CurrentStepTest& currentStep() { return std::get<CurrentStepTest>(test); }
    const CurrentStepTest& currentStep() const { return std::get<CurrentStepTest>(test); }
    FrfTest& frf() { return std::get<FrfTest>(test); }
    const FrfTest& frf() const { return std::get<FrfTest>(test); }
    CircleTest& circle() { return std::get<CircleTest>(test); }
    const CircleTest& circle() const { return std::get<CircleTest>(test); }
};

/// A request kind with every field at its default.
TestKind testKindOf(TestType type);

/// The request's record length (step, hold, current step) or dwell (jog, circle) [s], the time
/// DriveLimits::testDurationMaxS bounds; 0 for an FRF, whose length follows from its plan.
double recordOrDwellS(const TestRequest& request);

/// The result of an FRF test: the closed velocity loop T = −T_c/d (spec §3.2 eq. 3.1) with validity.
struct FrfMeasurement {
    dsp::FrequencyResponse frf;
    dsp::SweepRecording sweep;  ///< sine streams: excitation d and response −T_c per window (empty for PRBS)
    double motionTimeS = 0.0;   ///< machine time of the excitation (settling included)
    std::vector<double> relativeNoise;  ///< multisine: σ_H/|H| per point from the scatter over the periods (else empty)
};

enum class TestState { Idle, Running, Completed, Aborted, Faulted };

struct TestStatus {
    TestState state = TestState::Idle;
    double progress = 0.0;  ///< 0..1
    std::string detail;     ///< fault or abort reason
};

const char* testStateName(TestState s);

/// What a drive offers on one axis (docs/drive-seam.md): the tests and FRF methods it runs, its
/// trace rates, and whether it evaluates FRFs itself or only hands raw samples to the host.
struct DriveCapabilities {
    std::vector<TestType> testTypes;   ///< tests startTest() accepts
    std::vector<FrfMethod> frfMethods; ///< methods of TestType::Frf (empty: no FRF test)
    double traceRateHz = 0.0;          ///< fastest velocity-loop trace rate (trace divider 1) [Hz]; 0: none
    double currentTraceRateHz = 0.0;   ///< trace rate of a current step [Hz]; 0: no current step
    bool evaluatesFrf = false;         ///< readFrequencyResponse() answers; false: the host evaluates the trace
    bool writesParameters = true;      ///< writeParameters() can change values (false: a read-only backend)
    bool hasLink = true;               ///< a connection that can be lost (false: a file or an in-process drive)
    /// FRF amplitudes in the injection point's own units (FrfTest::amplitudePeak; hal:: the PID output's
    /// units, amplitudePct then is % of the pid's maxoutput); false: % of rated torque only.
    bool frfPeakInOutputUnits = false;
    /// Jog distance, speed, acceleration and jerk in the command's own units (hal:: the configuration's, e.g. mm and
    /// mm/s); false: m or rad.
    bool jogInCommandUnits = false;
    /// TestType::Step is a position step of the command by StepTest::position in the command's own units (hal:: the
    /// configuration's, e.g. mm), held for recordS and stepped back; false: a motor velocity step
    /// StepTest::velocityRadS.
    bool stepIsPositionStep = false;
    std::vector<FrfQuantity> frfQuantities; ///< quantities besides Default an FRF test can report (hal:: plant, open loop)
    /// frfPeakInOutputUnits: the signal whose units the peak is in (hal:: "pid.x.output"); empty otherwise.
    std::string frfOutputSignal;
    /// Highest frequency an FRF line may have [Hz], exclusive (hal:: half the servo rate, where a line would fold);
    /// 0: no limit of the drive's own (the methods' validity up to traceRateHz applies).
    double frfMaxHz = 0.0;
    bool scope = false;                ///< the scope answers (Drive::scopeCapabilities, armScope; docs/scope.md)

    bool offers(TestType t) const;
    bool offers(FrfMethod m) const;
};

/// The limits a drive enforces on one axis before a test starts; +infinity: no limit of its own.
struct DriveLimits {
    double frfAmplitudeMaxPct = 0.0;      ///< FRF excitation (multisine: its peak) [% of rated torque]
    /// DriveCapabilities::frfPeakInOutputUnits: the largest FRF peak in those units (hal:: half of the pid's
    /// maxoutput); 0 otherwise.
    double frfPeakMax = 0.0;
    double currentStepMaxA = 0.0;         ///< largest q-axis current step [A]
    double currentStepMaxS = 0.0;         ///< longest current-step record [s]
    double currentStepMaxSpeedRadS = 0.0; ///< motor speed a current step may reach [rad/s]
    double motorSpeedMaxRadS = 0.0;       ///< step amplitude, jog and circle speeds at the motor [rad/s]
    double testDurationMaxS = 0.0;        ///< step, hold and current-step record, jog dwell [s]
    double travelWindow = 0.0;            ///< |position| of jog targets and circles [m or rad]
};

/// The axis is a position loop the NC closes with a PID around the drive (hal:, linuxcnc:): its FRF reports the plant
/// and the open position loop in the PID output's units, and there is no drive velocity loop or notch slot to tune; its
/// tuner is `axistune-cli pid-tune` (docs/linuxcnc.md).
bool isNcPositionPid(const DriveCapabilities& caps);

/// What a test request will do, before it runs (Drive::planTest).
struct TestPlan {
    double motionTimeS = 0.0;      ///< machine time from start to completion (settling, dwell, hold included)
    std::size_t recordSamples = 0; ///< samples per channel of the trace the test records
    double traceRateHz = 0.0;      ///< sample rate of that trace [Hz]
};

const char* testTypeName(TestType t);

/// For a drive that takes FRF amplitudes in % of rated torque and measures its own quantity only (sim:, modbus://):
/// refuses a request that gives amplitudePeak or asks for another FrfQuantity, naming the CLI option.
Status checkRatedTorqueFrfRequest(const TestRequest& request);

class Drive {
public:
    virtual ~Drive() = default;
    virtual Result<DriveIdentity> identify() = 0;
    /// Metadata of every parameter of an axis (units, limits, writability).
    virtual Result<std::vector<model::ParameterMeta>> parameterMetadata(const std::string& axis) = 0;
    virtual Result<model::ParameterValues> readParameters(const std::string& axis, std::span<const std::string> keys) = 0;
    /// Range-checked before anything changes; refused while a test runs unless writable during tests.
    virtual Status writeParameters(const std::string& axis, const model::ParameterValues& values) = 0;
    virtual Status startTest(const TestRequest& request) = 0;
    /// Advances and reports the running test.
    virtual Result<TestStatus> pollTest() = 0;
    /// The trace of the last completed test, channels in SI.
    virtual Result<model::Capture> readTrace() = 0;
    /// Stops the motion at once and restores the parameters from before the test.
    virtual Status abortTest() = 0;
    /// The FRF of the last completed Frf test.
    virtual Result<FrfMeasurement> readFrequencyResponse()
    {
        return makeError(ErrorCode::NotFound, "this drive does not evaluate frequency-response tests");
    }
    /// Tests, methods and trace rates the drive offers on an axis.
    virtual Result<DriveCapabilities> capabilities(const std::string& axis)
    {
        return makeError(ErrorCode::NotFound, "this drive does not describe its capabilities (axis " + axis + ")");
    }
    /// The limits the drive itself enforces on an axis.
    virtual Result<DriveLimits> limits(const std::string& axis)
    {
        return makeError(ErrorCode::NotFound, "this drive does not describe its limits (axis " + axis + ")");
    }
    /// Checks a request as startTest() would and returns its plan without moving anything; a request
    /// startTest() would refuse is refused here with the same message.
    virtual Result<TestPlan> planTest(const TestRequest& request)
    {
        return makeError(ErrorCode::NotFound, "this drive cannot plan tests (axis " + request.axis + ")");
    }

    // The scope (core/device/Scope.h, docs/scope.md): one scope per drive, on one axis, independent of the
    // tests (it keeps sampling while a test runs). A backend without one keeps these defaults, which refuse
    // with NotFound, and reports DriveCapabilities::scope = false. A backend that only streams samples to the
    // host (a LinuxCNC sampler on HAL pins) implements them with a ScopeRecorder on the host.
    /// Traceable channels with units, the fastest rate and the sizes the scope takes.
    virtual Result<ScopeCapabilities> scopeCapabilities(const std::string& axis)
    {
        return makeError(ErrorCode::NotFound, "this drive has no scope (axis " + axis + ")");
    }
    /// Arms a triggered capture or starts roll mode (checked as checkScopeRequest does); re-arming replaces
    /// the running scope.
    virtual Status armScope(const ScopeRequest& request)
    {
        return makeError(ErrorCode::NotFound, "this drive has no scope (axis " + request.axis + ")");
    }
    /// State, sample counter and captures. On a drive whose machine time advances with the calls (the
    /// embedded simulator) it also lets the scope's axis run one slice while no test moves it.
    virtual Result<ScopeStatus> pollScope() { return makeError(ErrorCode::NotFound, "this drive has no scope"); }
    /// Roll mode: rows from sample `from` (firstSample > from: the ones before were overwritten, lost).
    virtual Result<ScopeRows> readScopeRows(std::uint64_t from, std::size_t maxRows)
    {
        (void)from;
        (void)maxRows;
        return makeError(ErrorCode::NotFound, "this drive has no scope");
    }
    /// The last complete triggered capture, with its channels and units.
    virtual Result<ScopeCapture> readScopeCapture() { return makeError(ErrorCode::NotFound, "this drive has no scope"); }
    /// Stops sampling; a complete capture stays readable.
    virtual Status stopScope() { return makeError(ErrorCode::NotFound, "this drive has no scope"); }
};

struct ConnectionSettings {
    std::string uri; ///< "SCHEME:..." of a registered backend (DriveRegistry.h): sim:, modbus://, replay:
    std::uint64_t seed = 1;
};

/// Opens a connection from a URI through the backend registry (DriveRegistry.h); errors name the URI
/// and what is wrong with it.
Result<std::unique_ptr<Drive>> connect(const ConnectionSettings& settings);

}  // namespace axistune::device
