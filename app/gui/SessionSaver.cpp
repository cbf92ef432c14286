// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/SessionSaver.h"
#include "core/store/SessionRecord.h"

#include <QMetaObject>
#include <QSemaphore>
#include <QThread>

namespace axistune {
namespace gui {

Result<std::int64_t> SessionSaveWorker::save(const QString& path, const store::SessionRecord& record,
                                             const std::function<void(double)>& progress)
{
    if (!m_db || m_path != path) {
        m_db.reset();
        auto db = store::Database::open(path.toStdString());
        if (!db)
            return db.error();
        m_db = std::make_unique<store::Database>(std::move(db).value());
        m_path = path;
    }
    return m_db->recordSession(record, progress);
}

SessionSaver::SessionSaver(QObject* parent) : QObject(parent)
{
    m_thread = new QThread(this);
    m_thread->setObjectName("store");
    m_worker = new SessionSaveWorker;
    m_worker->moveToThread(m_thread);
    connect(m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
    m_thread->start();
}

SessionSaver::~SessionSaver()
{
    waitForAll();
    m_thread->quit();
    m_thread->wait();
}

void SessionSaver::waitForAll()
{
    // A marker queued behind every save: when it runs, they are all written.
    QSemaphore done;
    QMetaObject::invokeMethod(
        m_worker, [&done] { done.release(); }, Qt::QueuedConnection);
    done.acquire();
}

void SessionSaver::save(const QString& path, store::SessionRecord record, QObject* context,
                        std::function<void(Result<std::int64_t>)> done)
{
    if (m_pending++ == 0)
        emit busyChanged(true);
    QPointer<SessionSaver> self(this);
    QPointer<QObject> ctx(context);
    SessionSaveWorker* w = m_worker;
    QMetaObject::invokeMethod(
        w,
        [self, ctx, w, path, rec = std::move(record), done = std::move(done)]() mutable {
            double last = -1.0;
            auto progress = [self, &last](double f) {
                if (f - last < 0.01 && f < 1.0)
                    return; // a signal per percent at most
                last = f;
                if (self)
                    QMetaObject::invokeMethod(
                        self.data(),
                        [self, f] {
                            if (self)
                                emit self->progress(f);
                        },
                        Qt::QueuedConnection);
            };
            auto result = std::make_shared<Result<std::int64_t>>(w->save(path, rec, progress));
            if (!self)
                return;
            QMetaObject::invokeMethod(
                self.data(),
                [self, ctx, result, done = std::move(done)] {
                    if (!self)
                        return;
                    if (--self->m_pending == 0)
                        emit self->busyChanged(false);
                    if (ctx && done)
                        done(*result);
                },
                Qt::QueuedConnection);
        },
        Qt::QueuedConnection);
}

} // namespace gui
} // namespace axistune
