// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The drive link of the GUI (STYLE.md "A device seam"): a DriveWorker on its own QThread owns the
// device::Drive (libmodbus contexts are not thread-safe); the DriveController is the GUI-side facade.
// Every request returns its own DriveRequest at once, and the requester connects to that object's
// `finished` (and, for tests, `progress`) signal: no listener filters the replies of others
// (docs/architecture.md "The drive link of the GUI"). The GUI never blocks on the drive.
//
// Tests run on the worker through device::runTest (core/device/TestRunner.h). Each test request has its
// own cancel token, created when it is queued: DriveRequest::abort() (or DriveController::abort() for
// every queued and running test) sets it, so an Abort that comes before the worker reaches the test
// cancels it (it never starts; nothing changes on the drive), and one that comes while it runs stops the
// motion at once (the drive's abortTest restores the parameters from before the test).
// A device error during a test (lost connection, timeout, drive fault) aborts the test, and a lost
// connection is announced by `connectionLost`.

#include "core/autotune/AutoTune.h"
#include "core/autotune/TravelChoice.h"
#include "core/autotune/Undo.h"
#include "core/device/Drive.h"
#include "core/model/Capture.h"
#include "core/model/Parameter.h"
#include "core/model/Result.h"

#include <QObject>
#include <QPointer>
#include <QString>
#include <QStringList>

#include <atomic>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

class QThread;

namespace axistune::device {
struct AdaptiveFrfOptions;
struct AdaptiveFrfResult;
} // namespace axistune::device

namespace axistune::autotune {
struct PidTuneRequest;
struct PidLoopMeasurement;
struct PidTuneProposal;
struct PidTuneApplied;
struct PidTuneNotchUndo;
struct PidTuneNotchUndone;
} // namespace axistune::autotune

namespace axistune {
namespace gui {

/// The answer to one request. `ok` false: `error` says why (already translated where it comes from
/// the GUI; drive messages are passed on verbatim) and `code` classifies it.
struct DriveReply {
    enum class Kind {
        Connect,
        Disconnect,
        Metadata,
        ReadParameters,
        WriteParameters,
        Test,
        Describe,
        Plan,
        Scope,
        AutoTune,
        AutoTuneUndo,
        PidTune ///< measure and propose, or apply and verify, a position PID the NC closes (DriveControllerPidTune.cpp)
    };
    int id = 0;
    Kind kind = Kind::Connect;
    bool ok = false;
    QString error;
    ErrorCode code = ErrorCode::Internal;
    QString axis;
    // Connect
    std::optional<device::DriveIdentity> identity;
    // Metadata
    std::vector<model::ParameterMeta> metadata;
    // ReadParameters: the values read; WriteParameters: the values read back after the write
    model::ParameterValues values;
    // Test
    device::TestState testState = device::TestState::Idle;
    std::shared_ptr<const model::Capture> capture;     ///< trace (not for Frf tests)
    std::shared_ptr<const device::FrfMeasurement> frf; ///< Frf tests
    /// runAdaptiveFrf: the passes, the lines left invalid and why (`frf` holds the combined measurement)
    std::shared_ptr<const device::AdaptiveFrfResult> adaptive;
    // Describe: what the drive offers on the axis and the limits it enforces (DriveControllerDescribe.cpp)
    std::optional<device::DriveCapabilities> capabilities;
    std::optional<device::DriveLimits> limits;
    // Plan: the drive's plan of a test request (motion time, record length)
    std::optional<device::TestPlan> plan;
    // Scope (DriveControllerScope.cpp): what the request asked for, the drive's answer
    std::shared_ptr<const device::ScopeCapabilities> scopeCaps; ///< scopeCapabilities
    std::optional<device::ScopeStatus> scopeStatus;             ///< pollScope
    std::shared_ptr<const device::ScopeRows> scopeRows;         ///< pollScope in roll mode: rows from `rollFrom`
    std::shared_ptr<const device::ScopeCapture> scopeCapture;   ///< pollScope: a complete capture newer than known
    // AutoTune (DriveControllerAutoTune.cpp): the sequence's result (also a refusal or an abort, with every
    // parameter restored); `ok` false only for errors before anything moved (bad options, unknown axis).
    std::shared_ptr<const autotune::AutoTuneResult> autotune;
    // Describe by autoTuneTravel: whether the axis can be tuned over its travel, and the window (no motion)
    std::optional<autotune::TravelChoice> travel;
    // AutoTuneUndo (autotune::undoTune): `ok` the parameters undone, each read back equal to its value before the run
    // (`values`: the read-back). Refused without `force` because the drive no longer holds what the run applied:
    // `code` Safety (NotFound for a missing key), `undoChanged` those parameters, `values` every applied key as the
    // drive holds it now; nothing was written.
    std::vector<autotune::UndoneParameter> undone;
    std::vector<autotune::ChangedParameter> undoChanged;
    // PidTune (DriveControllerPidTune.cpp): measurePidTune's measurement and proposal (`pidProposal` empty with
    // `ok` false when the measurement is kept but no proposal could be made: `error` says why), applyPidTune's
    // outcome (also a verified refusal, with what ran before put back).
    std::shared_ptr<const autotune::PidLoopMeasurement> pidLoop;
    std::shared_ptr<const autotune::PidTuneProposal> pidProposal;
    std::shared_ptr<const autotune::PidTuneApplied> pidApplied;
    // AutoTuneUndo by undoPidTune: `undone` the gains (each from what HAL held just before), and the notch HAL held
    // just before and the one put back (`changed` false when the tune left the notch as it was).
    std::shared_ptr<const autotune::PidTuneNotchUndone> pidNotchUndone;
};

class DriveWorker;

/// One request to the drive and its answer. Created by the DriveController, which deletes it (deleteLater)
/// after `finished`; keep a QPointer when it must outlive that. Connect at once after the call: the reply
/// is delivered through the event loop, never before the caller returns.
class DriveRequest : public QObject {
    Q_OBJECT
public:
    int id() const { return m_id; }
    DriveReply::Kind kind() const { return m_kind; }
    bool isFinished() const { return m_finished; }
    /// Tests: cancels the test while it is queued (it never starts) or stops it while it runs (thread-safe
    /// flag, checked by device::runTest). Other requests: no effect.
    void abort();

signals:
    /// Progress of a running test, 0..1 (never falling), with the drive's detail text. For the one-button
    /// tuner: of the whole sequence (the steps count equal).
    void progress(double fraction, const QString& detail);
    /// The one-button tuner began a step (its name as in the result's steps[]).
    void stepStarted(const QString& name);
    /// The one-button tuner finished a step: its record as in the result JSON (name, measured, chosen, rule).
    void stepFinished(const QString& name, const QString& stepJson);
    /// The answer; emitted once.
    void finished(const axistune::gui::DriveReply& reply);

private:
    friend class DriveController;
    DriveRequest(int id, DriveReply::Kind kind, QObject* parent);
    int m_id = 0;
    DriveReply::Kind m_kind = DriveReply::Kind::Connect;
    bool m_finished = false;
    std::shared_ptr<std::atomic<bool>> m_cancel = std::make_shared<std::atomic<bool>>(false);
};

class DriveController : public QObject {
    Q_OBJECT
public:
    explicit DriveController(QObject* parent = nullptr);
    ~DriveController() override; ///< aborts a running test and joins the worker thread

    /// "sim:PRESET" or "modbus://HOST:PORT"; replaces an existing connection.
    DriveRequest* connectTo(const QString& uri, quint64 seed = 1);
    DriveRequest* disconnectFrom();
    DriveRequest* readMetadata(const QString& axis);
    /// Empty keys: every parameter of the axis.
    DriveRequest* readParameters(const QString& axis, const QStringList& keys = {});
    /// Writes (the drive range-checks everything before changing anything), then reads the written
    /// keys back; the reply fails with ErrorCode::Device when a read-back value differs.
    DriveRequest* writeParameters(const QString& axis, const model::ParameterValues& values);
    /// Queues a test and runs it to its end (device::runTest); the reply carries the trace and, for FRF
    /// tests, the FRF (evaluated on the host when the drive only streams samples).
    DriveRequest* runTest(const device::TestRequest& request);
    /// An adaptive multisine (device::runAdaptiveFrf: passes until every line is valid or the time budget is spent),
    /// as one test request: one progress over all passes, Abort stops the pass that runs (its parameters restored).
    /// Reply kind Test with `frf` (the combined measurement) and `adaptive`.
    DriveRequest* runAdaptiveFrf(const device::TestRequest& request, const device::AdaptiveFrfOptions& options);
    /// The drive's capabilities and limits on an axis (reply kind Describe; DriveControllerDescribe.cpp).
    DriveRequest* describeAxis(const QString& axis);
    /// The drive's plan of a request before it runs (reply kind Plan): motion time and record length, or
    /// the drive's reason to refuse the request.
    DriveRequest* planTest(const device::TestRequest& request);
    /// Runs the one-button tuner (core/autotune) on the worker, as one request: the drive is used by the worker
    /// thread only; `abort()` on the request (or the controller) stops it at the next poll or step, and the
    /// sequence restores every parameter it wrote (reply kind AutoTune; DriveControllerAutoTune.cpp). The options'
    /// `run`, `stepStarted` and `stepFinished` are set by the controller.
    DriveRequest* runAutoTune(const autotune::Options& options);
    /// Undoes an applied run on the worker (autotune::undoTune, the CLI's `autotune --undo` rules): refused with
    /// nothing written when the drive no longer holds what the run applied, unless `force`; otherwise every value
    /// before the run in one write, read back (reply kind AutoTuneUndo; DriveControllerAutoTune.cpp).
    DriveRequest* undoAutoTune(const autotune::AppliedTune& tune, bool force);
    /// Whether `axis` can be tuned over its travel and the travel window (autotune::travelChoice; reply kind
    /// Describe with `travel`); nothing moves.
    DriveRequest* autoTuneTravel(const QString& axis);
    /// A position PID the NC closes (hal:, linuxcnc:; core/autotune/PidTune.h): measures the open loop with the
    /// running gains and proposes (reply kind PidTune with pidLoop and pidProposal); abortable like a test.
    DriveRequest* measurePidTune(const autotune::PidTuneRequest& request);
    /// Applies a proposal (notch, gains) and verifies it by measuring again; a loop that misses the margins, an
    /// abort or a failed measurement puts back what ran before (reply kind PidTune with pidApplied).
    DriveRequest* applyPidTune(const autotune::PidTuneRequest& request,
                               std::shared_ptr<const autotune::PidLoopMeasurement> measured,
                               std::shared_ptr<const autotune::PidTuneProposal> proposal);
    /// Undoes an applied PID tune: the gains as undoAutoTune and AxisTune's notch put back as it ran before (refused,
    /// nothing changed, when HAL no longer holds the gains or the notch the tune applied, unless `force`; reply kind
    /// AutoTuneUndo).
    DriveRequest* undoPidTune(const autotune::AppliedTune& tune, const autotune::PidTuneNotchUndo& notch, bool force);
    // The scope (docs/scope.md "The GUI scope"). These requests also run between the polls of a running test
    // (the worker serves them from its side queue whenever the test reports progress), so the scope stays
    // live while a jog or a wizard's test moves the axis.
    DriveRequest* scopeCapabilities(const QString& axis);
    DriveRequest* armScope(const device::ScopeRequest& request);
    /// Polls the scope; in roll mode (`rollFrom` set) also reads the rows from that sample on (at most
    /// `maxRows`), in triggered modes reads the last capture when the drive has more than `knownCaptures`.
    DriveRequest* pollScope(std::optional<std::uint64_t> rollFrom, std::uint64_t knownCaptures,
                            std::size_t maxRows = 262144);
    DriveRequest* stopScope();
    /// Aborts every queued test (they never start) and the running one (stopped at once, parameters
    /// restored). Tests queued after the call run normally.
    void abort();

    bool isConnected() const { return m_connected; }
    bool isBusy() const { return m_pending > 0; }
    /// A test or the one-button tuner is queued or running (requests of kind Test and AutoTune without a reply yet).
    bool isTestRunning() const { return m_tests > 0; }
    QString uri() const { return m_uri; }
    const std::optional<device::DriveIdentity>& identity() const { return m_identity; }

signals:
    /// Every reply, after its request's own `finished`: for observers (the log, the status bar), not for
    /// requesters, which connect to their DriveRequest.
    void replied(const axistune::gui::DriveReply& reply);
    /// Progress of the running test, 0..1, with the drive's detail text (observers; see DriveRequest).
    void progress(int id, double fraction, const QString& detail);
    void connectionChanged(bool connected, const QString& description);
    /// The connection failed during a request (the request itself also replies with an error).
    void connectionLost(const QString& reason);
    void busyChanged(bool busy);
    /// isTestRunning() changed.
    void testRunningChanged(bool running);

private:
    DriveRequest* post(DriveReply::Kind kind, std::function<DriveReply(DriveWorker&, int id)> job, bool side = false);
    void onReply(const axistune::gui::DriveReply& reply);

    QThread* m_thread = nullptr;
    DriveWorker* m_worker = nullptr;
    struct Open {
        QPointer<DriveRequest> request;
        std::shared_ptr<std::atomic<bool>> cancel; ///< the request's token (kept if the request is deleted)
        DriveReply::Kind kind = DriveReply::Kind::Connect;
    };
    std::map<int, Open> m_open; ///< requests without a reply yet
    int m_nextId = 1;
    int m_pending = 0;
    int m_tests = 0; ///< open requests of kind Test or AutoTune
    bool m_connected = false;
    QString m_uri;
    std::optional<device::DriveIdentity> m_identity;
};

/// Lives on the controller's thread; owns the Drive. Not for direct use.
class DriveWorker : public QObject {
    Q_OBJECT
public:
    DriveWorker() = default;
    ~DriveWorker() override;

    DriveReply doConnect(int id, const QString& uri, quint64 seed);
    DriveReply doDisconnect(int id);
    DriveReply doMetadata(int id, const QString& axis);
    DriveReply doRead(int id, const QString& axis, const QStringList& keys);
    DriveReply doWrite(int id, const QString& axis, const model::ParameterValues& values);
    /// Runs the test unless `cancel` is set; `cancel` aborts it while it runs.
    /// `adaptive` set: device::runAdaptiveFrf with those options instead of device::runTest.
    DriveReply doTest(int id, const device::TestRequest& request, std::shared_ptr<std::atomic<bool>> cancel,
                      std::shared_ptr<const device::AdaptiveFrfOptions> adaptive = nullptr);
    DriveReply doDescribe(int id, const QString& axis);
    DriveReply doPlan(int id, const device::TestRequest& request);
    DriveReply doAutoTune(int id, autotune::Options options, std::shared_ptr<std::atomic<bool>> cancel);
    DriveReply doAutoTuneTravel(int id, const QString& axis);
    DriveReply doAutoTuneUndo(int id, const autotune::AppliedTune& tune, bool force);
    DriveReply doPidTune(int id, std::shared_ptr<const autotune::PidTuneRequest> request,
                         std::shared_ptr<const autotune::PidLoopMeasurement> measured,
                         std::shared_ptr<const autotune::PidTuneProposal> proposal,
                         std::shared_ptr<std::atomic<bool>> cancel);
    DriveReply doPidTuneUndo(int id, const autotune::AppliedTune& tune, const autotune::PidTuneNotchUndo& notch,
                             bool force);
    DriveReply doScopeCapabilities(int id, const QString& axis);
    DriveReply doArmScope(int id, const device::ScopeRequest& request);
    DriveReply doPollScope(int id, std::optional<std::uint64_t> rollFrom, std::uint64_t knownCaptures,
                           std::size_t maxRows);
    DriveReply doStopScope(int id);

    /// Side queue (thread-safe): jobs run by drainSide() on the worker, in order, either from the event loop
    /// or between the polls of a running test.
    void enqueueSide(std::function<void()> job);
    void drainSide();

signals:
    void progress(int id, double fraction, const QString& detail);
    void connectionLost(const QString& reason);
    /// A step of the one-button tuner began (finished false, json empty) or ended (its record as JSON).
    void autoTuneStep(int id, const QString& name, bool finished, const QString& json);

private:
    DriveReply fail(DriveReply r, const Error& e);
    /// "Not connected" (Device), translated.
    static Error notConnected();
    /// A long job's refusal before it starts: Aborted when `cancel` was set while it was queued (it never started,
    /// nothing changed on the drive), Device when no drive is connected; none when the job may run.
    std::optional<DriveReply> refuseBeforeStart(DriveReply r, const std::atomic<bool>& cancel);
    std::unique_ptr<device::Drive> m_drive;
    std::mutex m_sideMutex;
    std::deque<std::function<void()>> m_side;
    bool m_draining = false; ///< worker thread only: no nested drain
};

/// Connects a request's reply to a member of the requester and returns the request's id (which pages keep to
/// ignore the reply of a request a newer one has superseded).
template <class Receiver>
int connectReply(DriveRequest* request, Receiver* receiver, void (Receiver::*slot)(const DriveReply&))
{
    QObject::connect(request, &DriveRequest::finished, receiver, slot);
    return request->id();
}

/// True for errors that mean the link to the drive is gone (not a refused request).
bool isConnectionError(ErrorCode code);

} // namespace gui
} // namespace axistune

Q_DECLARE_METATYPE(axistune::gui::DriveReply)
