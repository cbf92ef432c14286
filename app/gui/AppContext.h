// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What every window and wizard of the app shares: the drive link, the store, the connected machine,
// the operator, the proposed parameter values per axis (shown by the parameter inspector), and the
// log. Owned by the main window; wizards get a reference.

#include "app/gui/DriveController.h"

#include "core/model/Parameter.h"
#include "core/model/Result.h"
#include "core/store/Database.h"

#include <QObject>
#include <QString>
#include <QStringList>

class QWidget;

#include <functional>
#include <map>
#include <memory>

namespace axistune {
namespace gui {

class AppContext : public QObject {
    Q_OBJECT
public:
    explicit AppContext(QObject* parent = nullptr);
    ~AppContext() override;

    DriveController& drive() { return *m_drive; }

    /// Opens (or creates) the store; on failure database() is null and the error is logged.
    bool openDatabase(const QString& path);
    store::Database* database() { return m_db.get(); }
    QString databasePath() const { return m_dbPath; }

    /// The connected machine's name (the preset or the drive's machine string) and axes; empty when
    /// not connected.
    QString machine() const;
    QStringList axes() const;

    QString operatorName() const { return m_operator; }
    void setOperatorName(const QString& name) { m_operator = name; }

    /// Proposed values of an axis (from a wizard), shown beside the device and profile values.
    void setProposed(const QString& axis, const model::ParameterValues& values);
    model::ParameterValues proposed(const QString& axis) const;

    /// Saves a session (fills machine, operator and axes of the machine when empty), logs the result
    /// and emits sessionSaved. Errors are logged and returned. The store is written on the store thread
    /// (SessionSaver); `done` runs on the GUI thread with the answer unless `context` is gone.
    void saveSessionAsync(store::SessionRecord record, QObject* context,
                          std::function<void(Result<std::int64_t>)> done = {});
    /// The same for callers that need the id at once: the GUI event loop keeps running (timers, repaints,
    /// drive replies; user input waits) until the store thread answers, with the progress in
    /// sessionSaveProgress.
    Result<std::int64_t> saveSession(store::SessionRecord record);
    /// Blocks until every queued save is in the store (the main window calls it when it closes).
    void waitForSaves();

    /// Asks the main window to show `widget` as a document tab in the centre (it takes ownership).
    /// Wizards use it for plots the user keeps after the wizard closes.
    void showDocument(QWidget* widget, const QString& title) { emit documentRequested(widget, title); }

public slots:
    void log(const QString& message);

signals:
    void logged(const QString& timeStampedMessage);
    void proposedChanged(const QString& axis);
    void sessionSaved(qint64 id);
    /// A session save in progress (fraction written 0..1), and whether saves are queued.
    void sessionSaveProgress(double fraction);
    void savingChanged(bool saving);
    /// Applied parameters (journal written) for an axis.
    void parametersApplied(const QString& axis);
    /// openDatabase() opened another store (or failed: database() is null).
    void databaseChanged();
    /// See showDocument().
    void documentRequested(QWidget* widget, const QString& title);

private:
    DriveController* m_drive = nullptr;
    class SessionSaver* m_saver = nullptr;
    std::unique_ptr<store::Database> m_db;
    QString m_dbPath;
    QString m_operator;
    std::map<QString, model::ParameterValues> m_proposed;
};

}  // namespace gui
}  // namespace axistune
