// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/AppContext.h"

#include "app/gui/SessionSaver.h"
#include "core/store/SessionRecord.h"

#include <QDateTime>
#include <QEventLoop>
#include <QPointer>

#include <optional>

namespace axistune {
namespace gui {

AppContext::AppContext(QObject* parent)
    : QObject(parent), m_drive(new DriveController(this)), m_saver(new SessionSaver(this))
{
    connect(m_saver, &SessionSaver::progress, this, &AppContext::sessionSaveProgress);
    connect(m_saver, &SessionSaver::busyChanged, this, &AppContext::savingChanged);
}

AppContext::~AppContext()
{
    m_saver->waitForAll();
}

void AppContext::waitForSaves()
{
    m_saver->waitForAll();
}

bool AppContext::openDatabase(const QString& path)
{
    auto db = store::Database::open(path.toStdString());
    if (!db) {
        m_db.reset();
        log(tr("Could not open the store %1: %2").arg(path, QString::fromStdString(db.error().detail)));
        emit databaseChanged();
        return false;
    }
    m_db = std::make_unique<store::Database>(std::move(db).value());
    m_dbPath = path;
    log(tr("Store: %1").arg(path));
    emit databaseChanged();
    return true;
}

QString AppContext::machine() const
{
    const auto& id = m_drive->identity();
    return id && m_drive->isConnected() ? QString::fromStdString(id->machine) : QString();
}

QStringList AppContext::axes() const
{
    QStringList out;
    const auto& id = m_drive->identity();
    if (id && m_drive->isConnected())
        for (const auto& a : id->axes)
            out << QString::fromStdString(a);
    return out;
}

void AppContext::setProposed(const QString& axis, const model::ParameterValues& values)
{
    m_proposed[axis] = values;
    emit proposedChanged(axis);
}

model::ParameterValues AppContext::proposed(const QString& axis) const
{
    const auto it = m_proposed.find(axis);
    return it == m_proposed.end() ? model::ParameterValues{} : it->second;
}

void AppContext::saveSessionAsync(store::SessionRecord record, QObject* context,
                                  std::function<void(Result<std::int64_t>)> done)
{
    if (!m_db) {
        log(tr("The session was not saved: no store is open"));
        if (done)
            done(makeError(ErrorCode::Io, "no store is open"));
        return;
    }
    if (record.info.machine.empty())
        record.info.machine = machine().toStdString();
    if (record.info.operatorName.empty())
        record.info.operatorName = m_operator.toStdString();
    if (record.machineAxes.empty() && m_drive->identity())
        record.machineAxes = m_drive->identity()->axes;
    const QString kind = QString::fromStdString(record.info.kind);
    const QString status = QString::fromStdString(store::toString(record.info.status));
    QPointer<QObject> ctx(context);
    m_saver->save(m_dbPath, std::move(record), this, [this, ctx, kind, status, done](Result<std::int64_t> id) {
        if (!id)
            log(tr("Saving the session failed: %1").arg(QString::fromStdString(id.error().detail)));
        else
            log(tr("Session %1 saved (%2, %3)").arg(*id).arg(kind, status));
        if (id)
            emit sessionSaved(*id);
        if (ctx && done)
            done(id);
    });
}

Result<std::int64_t> AppContext::saveSession(store::SessionRecord record)
{
    std::optional<Result<std::int64_t>> answer;
    QEventLoop loop;
    saveSessionAsync(std::move(record), this, [&answer, &loop](Result<std::int64_t> id) {
        answer = std::move(id);
        loop.quit();
    });
    if (!answer)
        loop.exec(QEventLoop::ExcludeUserInputEvents);
    return *answer;
}

void AppContext::log(const QString& message)
{
    emit logged(QDateTime::currentDateTime().toString("HH:mm:ss  ") + message);
}

}  // namespace gui
}  // namespace axistune
