// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Session saves off the GUI thread (docs/architecture.md "Saving sessions"): a store thread with its own
// connection to the store file (SQLite in WAL mode: the GUI's connection keeps reading meanwhile) writes
// each SessionRecord in one transaction, in the order they were queued, and reports the progress by the
// samples written. Nothing is lost when the window closes: the destructor lets every queued save finish.

#include "core/model/Result.h"
#include "core/store/Database.h"

#include <QObject>
#include <QPointer>
#include <QString>

#include <cstdint>
#include <functional>

class QThread;

namespace axistune {
namespace gui {

class SessionSaveWorker;

class SessionSaver : public QObject {
    Q_OBJECT
public:
    explicit SessionSaver(QObject* parent = nullptr);
    /// Waits until every queued save is in the store.
    ~SessionSaver() override;

    /// Queues a save into the store file `path`; `done` runs on this object's thread with the store's
    /// answer (the session id or the error), unless `context` is gone by then.
    void save(const QString& path, store::SessionRecord record, QObject* context,
              std::function<void(Result<std::int64_t>)> done);
    /// Saves queued and not yet answered.
    int pending() const { return m_pending; }
    /// Blocks until every queued save is written (for shutdown; the GUI uses the signals).
    void waitForAll();

signals:
    /// Fraction written of the save in progress, 0..1 (never falling within one save).
    void progress(double fraction);
    void busyChanged(bool busy);

private:
    QThread* m_thread = nullptr;
    SessionSaveWorker* m_worker = nullptr;
    int m_pending = 0;
};

/// Lives on the store thread; owns its connection to the store. Not for direct use.
class SessionSaveWorker : public QObject {
    Q_OBJECT
public:
    Result<std::int64_t> save(const QString& path, const store::SessionRecord& record,
                              const std::function<void(double)>& progress);

private:
    std::unique_ptr<store::Database> m_db;
    QString m_path;
};

} // namespace gui
} // namespace axistune
