// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Helpers shared by the GUI tests: waiting on the event loop, a fresh store file, the language from
// the environment, and screenshots of wizard pages for docs/ (docs/gui.md "Screenshots").

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QLibraryInfo>
#include <QPixmap>
#include <QString>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QTranslator>
#include <QWidget>

#include <algorithm>
#include <functional>

namespace axistune::testing {

/// Runs the event loop until pred() holds or timeoutMs passes; returns pred().
inline bool waitUntil(const std::function<bool()>& pred, int timeoutMs = 60000)
{
    QElapsedTimer t;
    t.start();
    while (!pred() && t.elapsed() < timeoutMs)
        QTest::qWait(10);
    return pred();
}

/// A timer on the GUI thread (every 10 ms): how often it ticked and the largest gap between two ticks, i.e.
/// how long the event loop stalled while it ran.
class TickMeter {
public:
    explicit TickMeter(int periodMs = 10)
    {
        QObject::connect(&m_timer, &QTimer::timeout, [this] {
            if (m_ticks++ > 0)
                m_maxGapMs = std::max(m_maxGapMs, m_since.elapsed());
            m_since.start();
        });
        m_timer.start(periodMs);
    }
    int ticks() const { return m_ticks; }
    qint64 maxGapMs() const { return m_maxGapMs; }
    void stop() { m_timer.stop(); }

private:
    QTimer m_timer;
    QElapsedTimer m_since;
    qint64 m_maxGapMs = 0;
    int m_ticks = 0;
};

/// AXISTUNE_LANG=ja installs the Japanese translation (for Japanese screenshots); returns the code.
inline QString installLanguageFromEnv()
{
    const QString lang = qEnvironmentVariable("AXISTUNE_LANG", "en");
    if (lang == "ja") {
        static QTranslator tr;
        static QTranslator qt;
        if (qt.load("qtbase_ja", QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
            QApplication::installTranslator(&qt);
        if (tr.load(":/i18n/axistune_ja.qm"))
            QApplication::installTranslator(&tr);
    }
    return lang;
}

/// With AXISTUNE_SCREENSHOT_DIR set, saves a PNG of the widget as DIR/NAME-LANG.png.
inline void maybeScreenshot(QWidget* w, const QString& name)
{
    const QString dir = qEnvironmentVariable("AXISTUNE_SCREENSHOT_DIR");
    if (dir.isEmpty() || !w)
        return;
    QDir().mkpath(dir);
    QApplication::processEvents();
    w->grab().save(dir + "/" + name + "-" + qEnvironmentVariable("AXISTUNE_LANG", "en") + ".png");
}

}  // namespace axistune::testing
