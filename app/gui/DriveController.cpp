// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/DriveController.h"

#include "app/gui/WidgetUtil.h"
#include "core/device/AdaptiveFrf.h"
#include "core/device/TestRunner.h"

#include <QCoreApplication>
#include <QMetaObject>
#include <QPointer>
#include <QThread>

#include <cmath>
#include <nlohmann/json.hpp>

namespace axistune {
namespace gui {

namespace {
/// Relative tolerance of the read-back check (float32 on the Modbus link has 6e-8).
constexpr double kReadBackRelTol = 1e-6;
} // namespace

bool isConnectionError(ErrorCode code)
{
    return code == ErrorCode::Device || code == ErrorCode::Io;
}

// ---------------------------------------------------------------------------------------------
// Worker (runs on the drive thread)

DriveWorker::~DriveWorker() = default;

Error DriveWorker::notConnected()
{
    return {ErrorCode::Device, QCoreApplication::translate("DriveController", "Not connected").toStdString()};
}

std::optional<DriveReply> DriveWorker::refuseBeforeStart(DriveReply r, const std::atomic<bool>& cancel)
{
    if (cancel.load()) {
        r.code = ErrorCode::Aborted;
        r.error = QCoreApplication::translate("DriveController", "Aborted by the user before the test started");
        return r;
    }
    if (!m_drive)
        return fail(r, notConnected());
    return std::nullopt;
}

DriveReply DriveWorker::fail(DriveReply r, const Error& e)
{
    r.ok = false;
    r.code = e.code;
    r.error = qs(e.detail);
    if (m_drive && isConnectionError(e.code)) {
        // Tell a refused request from a dead link: a link that cannot even identify is lost.
        if (!m_drive->identify()) {
            m_drive.reset();
            emit connectionLost(r.error);
        }
    }
    return r;
}

DriveReply DriveWorker::doConnect(int id, const QString& uri, quint64 seed)
{
    DriveReply r;
    r.id = id;
    r.kind = DriveReply::Kind::Connect;
    m_drive.reset();
    auto d = device::connect({uri.toStdString(), seed});
    if (!d)
        return fail(r, d.error());
    auto ident = (*d)->identify();
    if (!ident)
        return fail(r, ident.error());
    m_drive = std::move(d).value();
    r.identity = *ident;
    r.ok = true;
    return r;
}

DriveReply DriveWorker::doDisconnect(int id)
{
    DriveReply r;
    r.id = id;
    r.kind = DriveReply::Kind::Disconnect;
    m_drive.reset();
    r.ok = true;
    return r;
}

DriveReply DriveWorker::doMetadata(int id, const QString& axis)
{
    DriveReply r;
    r.id = id;
    r.kind = DriveReply::Kind::Metadata;
    r.axis = axis;
    if (!m_drive)
        return fail(r, notConnected());
    auto m = m_drive->parameterMetadata(axis.toStdString());
    if (!m)
        return fail(r, m.error());
    r.metadata = std::move(m).value();
    r.ok = true;
    return r;
}

DriveReply DriveWorker::doRead(int id, const QString& axis, const QStringList& keys)
{
    DriveReply r;
    r.id = id;
    r.kind = DriveReply::Kind::ReadParameters;
    r.axis = axis;
    if (!m_drive)
        return fail(r, notConnected());
    std::vector<std::string> k;
    for (const auto& s : keys)
        k.push_back(s.toStdString());
    auto v = m_drive->readParameters(axis.toStdString(), k);
    if (!v)
        return fail(r, v.error());
    r.values = std::move(v).value();
    r.ok = true;
    return r;
}

DriveReply DriveWorker::doWrite(int id, const QString& axis, const model::ParameterValues& values)
{
    DriveReply r;
    r.id = id;
    r.kind = DriveReply::Kind::WriteParameters;
    r.axis = axis;
    if (!m_drive)
        return fail(r, notConnected());
    const std::string a = axis.toStdString();
    if (auto s = m_drive->writeParameters(a, values); !s)
        return fail(r, s.error());
    std::vector<std::string> keys;
    for (const auto& [k, v] : values)
        keys.push_back(k);
    auto back = m_drive->readParameters(a, keys);
    if (!back)
        return fail(r, back.error());
    r.values = *back;
    // Modbus carries float32: a read-back within 1e-6 relative is the value written.
    for (const auto& [k, v] : values) {
        const auto it = back->find(k);
        const double tol = kReadBackRelTol * std::max(1.0, std::abs(v));
        if (it == back->end() || !(std::abs(it->second - v) <= tol)) {
            r.ok = false;
            r.code = ErrorCode::Device;
            r.error = QCoreApplication::translate("DriveController", "Read-back of %1 on axis %2 gave %3 instead of %4")
                          .arg(qs(k), axis)
                          .arg(it == back->end() ? std::nan("") : it->second, 0, 'g', 10)
                          .arg(v, 0, 'g', 10);
            return r;
        }
    }
    r.ok = true;
    return r;
}

DriveReply DriveWorker::doTest(int id, const device::TestRequest& request, std::shared_ptr<std::atomic<bool>> cancel,
                               std::shared_ptr<const device::AdaptiveFrfOptions> adaptive)
{
    DriveReply r;
    r.id = id;
    r.kind = DriveReply::Kind::Test;
    r.axis = qs(request.axis);
    r.testState = device::TestState::Aborted;
    if (auto refused = refuseBeforeStart(r, *cancel))
        return *refused;
    device::RunOptions o;
    o.abort = cancel.get();
    double lastReported = -1.0;
    o.progress = [&](double f, const std::string& detail) {
        drainSide(); // scope requests between the test's polls
        if (f - lastReported >= 0.005 || f >= 1.0) {
            lastReported = f;
            emit progress(id, f, qs(detail));
        }
    };
    auto run = [&]() -> Result<device::TestRun> {
        if (!adaptive)
            return device::runTest(*m_drive, request, o);
        auto a = device::runAdaptiveFrf(*m_drive, request, *adaptive, o);
        if (!a)
            return a.error();
        r.adaptive = std::make_shared<const device::AdaptiveFrfResult>(std::move(a).value());
        device::TestRun t;
        t.frf = r.adaptive->measurement; // the combined measurement, as a plain FRF test's reply
        return t;
    }();
    if (!run) {
        if (cancel->load() && run.error().code == ErrorCode::Aborted) {
            r.code = ErrorCode::Aborted;
            r.error = QCoreApplication::translate("DriveController", "Aborted by the user");
            return r;
        }
        r.testState = run.error().code == ErrorCode::Safety ? device::TestState::Faulted : device::TestState::Aborted;
        // A fault stopped by the drive is a refused run, not a lost link.
        if (run.error().code == ErrorCode::Safety) {
            r.code = ErrorCode::Device;
            r.error = qs(run.error().detail);
            return r;
        }
        return fail(r, run.error());
    }
    r.testState = device::TestState::Completed;
    if (run->frf)
        r.frf = std::make_shared<const device::FrfMeasurement>(std::move(*run->frf));
    else if (run->trace)
        r.capture = std::make_shared<const model::Capture>(std::move(*run->trace));
    r.ok = true;
    return r;
}

// ---------------------------------------------------------------------------------------------
// Controller (GUI thread)

DriveRequest::DriveRequest(int id, DriveReply::Kind kind, QObject* parent) : QObject(parent), m_id(id), m_kind(kind) {}

void DriveRequest::abort()
{
    m_cancel->store(true);
}

DriveController::DriveController(QObject* parent) : QObject(parent)
{
    qRegisterMetaType<axistune::gui::DriveReply>();
    m_thread = new QThread(this);
    m_thread->setObjectName("drive");
    m_worker = new DriveWorker;
    m_worker->moveToThread(m_thread);
    connect(m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
    connect(
        m_worker, &DriveWorker::progress, this,
        [this](int id, double f, const QString& detail) {
            if (auto it = m_open.find(id); it != m_open.end() && it->second.request)
                emit it->second.request->progress(f, detail);
            emit progress(id, f, detail);
        },
        Qt::QueuedConnection);
    connect(
        m_worker, &DriveWorker::autoTuneStep, this,
        [this](int id, const QString& name, bool finished, const QString& json) {
            if (auto it = m_open.find(id); it != m_open.end() && it->second.request) {
                if (finished)
                    emit it->second.request->stepFinished(name, json);
                else
                    emit it->second.request->stepStarted(name);
            }
        },
        Qt::QueuedConnection);
    connect(
        m_worker, &DriveWorker::connectionLost, this,
        [this](const QString& reason) {
            const bool was = m_connected;
            m_connected = false;
            emit connectionLost(reason);
            if (was)
                emit connectionChanged(false, tr("Connection lost: %1").arg(reason));
        },
        Qt::QueuedConnection);
    m_thread->start();
}

DriveController::~DriveController()
{
    abort();
    m_thread->quit();
    m_thread->wait();
}

namespace {
bool isTestKind(DriveReply::Kind k)
{
    return k == DriveReply::Kind::Test || k == DriveReply::Kind::AutoTune || k == DriveReply::Kind::PidTune;
}
} // namespace

DriveRequest* DriveController::post(DriveReply::Kind kind, std::function<DriveReply(DriveWorker&, int)> job, bool side)
{
    const int id = m_nextId++;
    auto* req = new DriveRequest(id, kind, this);
    m_open[id] = {req, req->m_cancel, kind};
    if (m_pending++ == 0)
        emit busyChanged(true);
    if (isTestKind(kind) && m_tests++ == 0)
        emit testRunningChanged(true);
    QPointer<DriveController> self(this);
    DriveWorker* w = m_worker;
    std::function<void()> run = [self, w, id, job = std::move(job)]() {
        DriveReply r = job(*w, id);
        if (self)
            QMetaObject::invokeMethod(
                self.data(),
                [self, r]() {
                    if (self)
                        self->onReply(r);
                },
                Qt::QueuedConnection);
    };
    if (side) {
        w->enqueueSide(std::move(run));
        QMetaObject::invokeMethod(
            w, [w]() { w->drainSide(); }, Qt::QueuedConnection);
    } else {
        QMetaObject::invokeMethod(w, std::move(run), Qt::QueuedConnection);
    }
    return req;
}

void DriveController::onReply(const DriveReply& reply)
{
    if (reply.kind == DriveReply::Kind::Connect) {
        m_connected = reply.ok;
        m_identity = reply.identity;
        emit connectionChanged(reply.ok, reply.ok ? tr("Connected: %1").arg(m_uri)
                                                  : tr("Connection to %1 failed: %2").arg(m_uri, reply.error));
    } else if (reply.kind == DriveReply::Kind::Disconnect) {
        m_connected = false;
        m_identity.reset();
        emit connectionChanged(false, tr("Not connected"));
    }
    if (--m_pending == 0)
        emit busyChanged(false);
    QPointer<DriveRequest> req;
    if (auto it = m_open.find(reply.id); it != m_open.end()) {
        req = it->second.request;
        if (isTestKind(it->second.kind) && --m_tests == 0)
            emit testRunningChanged(false);
        m_open.erase(it);
    }
    if (req) {
        req->m_finished = true;
        emit req->finished(reply);
        req->deleteLater();
    }
    emit replied(reply);
}

DriveRequest* DriveController::connectTo(const QString& uri, quint64 seed)
{
    m_uri = uri;
    return post(DriveReply::Kind::Connect, [uri, seed](DriveWorker& w, int id) { return w.doConnect(id, uri, seed); });
}

DriveRequest* DriveController::disconnectFrom()
{
    return post(DriveReply::Kind::Disconnect, [](DriveWorker& w, int id) { return w.doDisconnect(id); });
}

DriveRequest* DriveController::readMetadata(const QString& axis)
{
    return post(DriveReply::Kind::Metadata, [axis](DriveWorker& w, int id) { return w.doMetadata(id, axis); });
}

DriveRequest* DriveController::readParameters(const QString& axis, const QStringList& keys)
{
    return post(DriveReply::Kind::ReadParameters,
                [axis, keys](DriveWorker& w, int id) { return w.doRead(id, axis, keys); });
}

DriveRequest* DriveController::writeParameters(const QString& axis, const model::ParameterValues& values)
{
    return post(DriveReply::Kind::WriteParameters,
                [axis, values](DriveWorker& w, int id) { return w.doWrite(id, axis, values); });
}

DriveRequest* DriveController::runTest(const device::TestRequest& request)
{
    // The token exists before the job is queued: an abort() from now on reaches this test.
    auto token = std::make_shared<std::atomic<bool>>(false);
    DriveRequest* req =
        post(DriveReply::Kind::Test, [request, token](DriveWorker& w, int id) { return w.doTest(id, request, token); });
    req->m_cancel = token;
    m_open[req->id()].cancel = token;
    return req;
}

DriveRequest* DriveController::runAdaptiveFrf(const device::TestRequest& request,
                                              const device::AdaptiveFrfOptions& options)
{
    auto token = std::make_shared<std::atomic<bool>>(false);
    auto opts = std::make_shared<const device::AdaptiveFrfOptions>(options);
    DriveRequest* req = post(DriveReply::Kind::Test, [request, token, opts](DriveWorker& w, int id) {
        return w.doTest(id, request, token, opts);
    });
    req->m_cancel = token;
    m_open[req->id()].cancel = token;
    return req;
}

void DriveController::abort()
{
    for (const auto& [id, open] : m_open)
        open.cancel->store(true);
}

} // namespace gui
} // namespace axistune
