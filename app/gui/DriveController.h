// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The drive link of the GUI (STYLE.md "A device seam"): a DriveWorker on its own QThread owns the
// device::Drive (libmodbus contexts are not thread-safe); the DriveController is the GUI-side facade.
// Every request returns an id at once; the result arrives as one `replied` signal with that id.
// The GUI never blocks on the drive.
//
// Tests run on the worker in a poll loop: progress is relayed as `progress` signals, and abort()
// sets an atomic flag that the loop checks between polls, so Abort stops the motion at once even
// while the worker is busy (the drive's abortTest restores the parameters from before the test).
// A device error during a test (lost connection, timeout, drive fault) aborts the test, and a lost
// connection is announced by `connectionLost`.

#include "core/device/Drive.h"
#include "core/model/Capture.h"
#include "core/model/Parameter.h"
#include "core/model/Result.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

class QThread;

namespace axistune {
namespace gui {

/// The answer to one request. `ok` false: `error` says why (already translated where it comes from
/// the GUI; drive messages are passed on verbatim) and `code` classifies it.
struct DriveReply {
    enum class Kind { Connect, Disconnect, Metadata, ReadParameters, WriteParameters, Test, Describe, Plan };
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
    std::shared_ptr<const model::Capture> capture;          ///< trace (not for Frf tests)
    std::shared_ptr<const device::FrfMeasurement> frf;      ///< Frf tests
    // Describe: what the drive offers on the axis and the limits it enforces (DriveControllerDescribe.cpp)
    std::optional<device::DriveCapabilities> capabilities;
    std::optional<device::DriveLimits> limits;
    // Plan: the drive's plan of a test request (motion time, record length)
    std::optional<device::TestPlan> plan;
};

class DriveWorker;

class DriveController : public QObject {
    Q_OBJECT
public:
    explicit DriveController(QObject* parent = nullptr);
    ~DriveController() override;  ///< aborts a running test and joins the worker thread

    /// "sim:PRESET" or "modbus://HOST:PORT"; replaces an existing connection.
    int connectTo(const QString& uri, quint64 seed = 1);
    int disconnectFrom();
    int readMetadata(const QString& axis);
    /// Empty keys: every parameter of the axis.
    int readParameters(const QString& axis, const QStringList& keys = {});
    /// Writes (the drive range-checks everything before changing anything), then reads the written
    /// keys back; the reply fails with ErrorCode::Device when a read-back value differs.
    int writeParameters(const QString& axis, const model::ParameterValues& values);
    /// Starts a test and polls it to its end; the reply carries the trace or the FRF.
    int runTest(const device::TestRequest& request);
    /// The drive's capabilities and limits on an axis (reply kind Describe; DriveControllerDescribe.cpp).
    int describeAxis(const QString& axis);
    /// The drive's plan of a request before it runs (reply kind Plan): motion time and record length, or
    /// the drive's reason to refuse the request.
    int planTest(const device::TestRequest& request);
    /// Stops the running test at once (thread-safe; no-op when none runs).
    void abort();

    bool isConnected() const { return m_connected; }
    bool isBusy() const { return m_pending > 0; }
    QString uri() const { return m_uri; }
    const std::optional<device::DriveIdentity>& identity() const { return m_identity; }

signals:
    void replied(const axistune::gui::DriveReply& reply);
    /// Progress of the running test, 0..1, with the drive's detail text.
    void progress(int id, double fraction, const QString& detail);
    void connectionChanged(bool connected, const QString& description);
    /// The connection failed during a request (the request itself also replies with an error).
    void connectionLost(const QString& reason);
    void busyChanged(bool busy);

private:
    int post(std::function<DriveReply(DriveWorker&)> job);
    void onReply(const axistune::gui::DriveReply& reply);

    QThread* m_thread = nullptr;
    DriveWorker* m_worker = nullptr;
    std::shared_ptr<std::atomic<bool>> m_abort;
    int m_nextId = 1;
    int m_pending = 0;
    bool m_connected = false;
    QString m_uri;
    std::optional<device::DriveIdentity> m_identity;
};

/// Lives on the controller's thread; owns the Drive. Not for direct use.
class DriveWorker : public QObject {
    Q_OBJECT
public:
    explicit DriveWorker(std::shared_ptr<std::atomic<bool>> abortFlag);
    ~DriveWorker() override;

    DriveReply doConnect(int id, const QString& uri, quint64 seed);
    DriveReply doDisconnect(int id);
    DriveReply doMetadata(int id, const QString& axis);
    DriveReply doRead(int id, const QString& axis, const QStringList& keys);
    DriveReply doWrite(int id, const QString& axis, const model::ParameterValues& values);
    DriveReply doTest(int id, const device::TestRequest& request);
    DriveReply doDescribe(int id, const QString& axis);
    DriveReply doPlan(int id, const device::TestRequest& request);

signals:
    void progress(int id, double fraction, const QString& detail);
    void connectionLost(const QString& reason);

private:
    DriveReply fail(DriveReply r, const Error& e);
    std::unique_ptr<device::Drive> m_drive;
    std::shared_ptr<std::atomic<bool>> m_abort;
};

/// True for errors that mean the link to the drive is gone (not a refused request).
bool isConnectionError(ErrorCode code);

}  // namespace gui
}  // namespace axistune

Q_DECLARE_METATYPE(axistune::gui::DriveReply)
