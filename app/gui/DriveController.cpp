// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/DriveController.h"
#include "app/gui/WidgetUtil.h"

#include <QCoreApplication>
#include <QMetaObject>
#include <QPointer>
#include <QThread>

#include <cmath>

namespace axistune {
namespace gui {

namespace {
/// Relative tolerance of the read-back check (float32 on the Modbus link has 6e-8).
constexpr double kReadBackRelTol = 1e-6;
}  // namespace

bool isConnectionError(ErrorCode code) { return code == ErrorCode::Device || code == ErrorCode::Io; }

// ---------------------------------------------------------------------------------------------
// Worker (runs on the drive thread)

DriveWorker::DriveWorker(std::shared_ptr<std::atomic<bool>> abortFlag) : m_abort(std::move(abortFlag)) {}

DriveWorker::~DriveWorker() = default;

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
        return fail(r, {ErrorCode::Device, QCoreApplication::translate("DriveController", "Not connected").toStdString()});
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
        return fail(r, {ErrorCode::Device, QCoreApplication::translate("DriveController", "Not connected").toStdString()});
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
        return fail(r, {ErrorCode::Device, QCoreApplication::translate("DriveController", "Not connected").toStdString()});
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

DriveReply DriveWorker::doTest(int id, const device::TestRequest& request)
{
    DriveReply r;
    r.id = id;
    r.kind = DriveReply::Kind::Test;
    r.axis = qs(request.axis);
    if (!m_drive)
        return fail(r, {ErrorCode::Device, QCoreApplication::translate("DriveController", "Not connected").toStdString()});
    if (auto s = m_drive->startTest(request); !s)
        return fail(r, s.error());
    double lastReported = -1.0;
    for (;;) {
        if (m_abort->load()) {
            auto s = m_drive->abortTest();
            r.testState = device::TestState::Aborted;
            r.code = ErrorCode::Aborted;
            r.error = QCoreApplication::translate("DriveController", "Aborted by the user");
            if (!s)
                return fail(r, s.error());
            return r;
        }
        auto st = m_drive->pollTest();
        if (!st) {
            // Lost link or fault: stop the motion if the drive still listens, then report.
            (void)m_drive->abortTest();
            r.testState = device::TestState::Aborted;
            return fail(r, st.error());
        }
        if (st->progress - lastReported >= 0.005 || st->state != device::TestState::Running) {
            lastReported = st->progress;
            emit progress(id, st->progress, qs(st->detail));
        }
        r.testState = st->state;
        if (st->state == device::TestState::Running)
            continue;
        if (st->state != device::TestState::Completed) {
            r.code = st->state == device::TestState::Faulted ? ErrorCode::Device : ErrorCode::Aborted;
            r.error = st->detail.empty() ? QCoreApplication::translate("DriveController", "The test ended: %1")
                                               .arg(qs(device::testStateName(st->state)))
                                         : qs(st->detail);
            (void)m_drive->abortTest();
            return r;
        }
        break;
    }
    if (request.type == device::TestType::Frf) {
        auto f = m_drive->readFrequencyResponse();
        if (!f)
            return fail(r, f.error());
        r.frf = std::make_shared<const device::FrfMeasurement>(std::move(f).value());
    } else {
        auto c = m_drive->readTrace();
        if (!c)
            return fail(r, c.error());
        r.capture = std::make_shared<const model::Capture>(std::move(c).value());
    }
    r.ok = true;
    return r;
}

// ---------------------------------------------------------------------------------------------
// Controller (GUI thread)

DriveController::DriveController(QObject* parent)
    : QObject(parent), m_abort(std::make_shared<std::atomic<bool>>(false))
{
    qRegisterMetaType<axistune::gui::DriveReply>();
    m_thread = new QThread(this);
    m_thread->setObjectName("drive");
    m_worker = new DriveWorker(m_abort);
    m_worker->moveToThread(m_thread);
    connect(m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
    connect(m_worker, &DriveWorker::progress, this, &DriveController::progress, Qt::QueuedConnection);
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
    m_abort->store(true);
    m_thread->quit();
    m_thread->wait();
}

int DriveController::post(std::function<DriveReply(DriveWorker&)> job)
{
    const int id = m_nextId++;
    if (m_pending++ == 0)
        emit busyChanged(true);
    QPointer<DriveController> self(this);
    DriveWorker* w = m_worker;
    QMetaObject::invokeMethod(
        w,
        [self, w, job = std::move(job)]() {
            DriveReply r = job(*w);
            if (self)
                QMetaObject::invokeMethod(
                    self.data(), [self, r]() {
                        if (self)
                            self->onReply(r);
                    },
                    Qt::QueuedConnection);
        },
        Qt::QueuedConnection);
    return id;
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
    emit replied(reply);
}

int DriveController::connectTo(const QString& uri, quint64 seed)
{
    m_uri = uri;
    const int id = m_nextId;
    post([id, uri, seed](DriveWorker& w) { return w.doConnect(id, uri, seed); });
    return id;
}

int DriveController::disconnectFrom()
{
    const int id = m_nextId;
    post([id](DriveWorker& w) { return w.doDisconnect(id); });
    return id;
}

int DriveController::readMetadata(const QString& axis)
{
    const int id = m_nextId;
    post([id, axis](DriveWorker& w) { return w.doMetadata(id, axis); });
    return id;
}

int DriveController::readParameters(const QString& axis, const QStringList& keys)
{
    const int id = m_nextId;
    post([id, axis, keys](DriveWorker& w) { return w.doRead(id, axis, keys); });
    return id;
}

int DriveController::writeParameters(const QString& axis, const model::ParameterValues& values)
{
    const int id = m_nextId;
    post([id, axis, values](DriveWorker& w) { return w.doWrite(id, axis, values); });
    return id;
}

int DriveController::runTest(const device::TestRequest& request)
{
    const int id = m_nextId;
    m_abort->store(false);
    post([id, request](DriveWorker& w) { return w.doTest(id, request); });
    return id;
}

void DriveController::abort() { m_abort->store(true); }

}  // namespace gui
}  // namespace axistune
