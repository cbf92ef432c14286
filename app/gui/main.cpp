// SPDX-License-Identifier: GPL-3.0-or-later
// axistune: the desktop app (docs/gui.md). Starts on the built-in simulated machine (--preset, vmc by
// default; --connect URI for another drive, --no-connect for none). --lang ja|en overrides the
// language of the settings; --db FILE the store; --screenshot FILE saves the main window once the
// first axis's parameters are shown, and quits.
#include "app/gui/AppContext.h"
#include "app/gui/MainWindow.h"
#include "app/gui/ParameterInspector.h"
#include "app/gui/SettingsDialog.h"
#include "core/io/AtomicFile.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QLocale>
#include <QPixmap>
#include <QSettings>
#include <QTimer>

int main(int argc, char** argv)
{
    QApplication app(argc, argv);
    QApplication::setOrganizationName("AxisTune");
    QApplication::setApplicationName("AxisTune");
    QApplication::setApplicationVersion(AXISTUNE_VERSION);

    QCommandLineParser parser;
    parser.setApplicationDescription(QApplication::translate("main", "Commissioning and tuning of NC feed axes"));
    parser.addHelpOption();
    parser.addVersionOption();
    QCommandLineOption preset(
        "preset", QApplication::translate("main", "Simulated machine preset (vmc, dd-table, two-inertia, long-axis)."),
        "name", "vmc");
    QCommandLineOption uri("connect", QApplication::translate("main", "Connect to this drive: sim:PRESET or modbus://HOST:PORT."),
                           "uri");
    QCommandLineOption noConnect("no-connect", QApplication::translate("main", "Start without a connection."));
    QCommandLineOption lang("lang", QApplication::translate("main", "Language: en or ja (overrides the settings)."), "code");
    QCommandLineOption db("db", QApplication::translate("main", "Store file (default: the one of the settings)."), "file");
    QCommandLineOption shot("screenshot", QApplication::translate("main", "Save a screenshot of the main window and quit."),
                            "file");
    parser.addOptions({preset, uri, noConnect, lang, db, shot});
    parser.process(app);

    const QString code = parser.isSet(lang)
                             ? parser.value(lang)
                             : QSettings().value("ui/language", QLocale::system().name().left(2)).toString();
    axistune::gui::setApplicationLanguage(code);

    axistune::gui::MainWindow w(parser.value(db));
    w.show();
    if (!parser.isSet(noConnect))
        w.connectTo(parser.isSet(uri) ? parser.value(uri) : "sim:" + parser.value(preset));

    if (parser.isSet(shot)) {
        // Wait (without blocking the event loop) for the connection and the first axis's device
        // values, then save the window; 20 s at most.
        auto* timer = new QTimer(&w);
        auto* clock = new QElapsedTimer;
        clock->start();
        const QString file = parser.value(shot);
        QObject::connect(timer, &QTimer::timeout, &w, [&w, timer, clock, file] {
            const bool ready = w.context().drive().isConnected() && w.inspector()->deviceValuesShown() &&
                               !w.inspector()->axis().isEmpty();
            if (!ready && clock->elapsed() < 20000)
                return;
            timer->stop();
            QApplication::processEvents();
            const QPixmap shotPixmap = w.grab();
            const bool ok = axistune::io::writeFileAtomicVia(file.toStdString(), [&](const std::string& tmp) {
                                return shotPixmap.save(QString::fromStdString(tmp), "PNG")
                                           ? axistune::Status::success()
                                           : axistune::makeError(axistune::ErrorCode::Io, "the PNG writer failed");
                            }).ok();
            delete clock;
            QApplication::exit(ok && ready ? 0 : 1);
        });
        timer->start(100);
    }
    return QApplication::exec();
}
