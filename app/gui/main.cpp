// SPDX-License-Identifier: GPL-3.0-or-later
// axistune: the desktop app. Starts on the built-in simulated machine (preset from --preset, vmc by
// default). --lang ja|en chooses the language (default: the system's).
#include "app/gui/MainWindow.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>

int main(int argc, char** argv)
{
    QApplication app(argc, argv);
    QApplication::setApplicationName("AxisTune");
    QApplication::setApplicationVersion(AXISTUNE_VERSION);

    QCommandLineParser parser;
    parser.setApplicationDescription(QApplication::translate("main", "Commissioning and tuning of NC feed axes"));
    parser.addHelpOption();
    parser.addVersionOption();
    QCommandLineOption preset("preset", QApplication::translate("main", "Simulated machine preset (vmc, dd-table, two-inertia)."),
                              "name", "vmc");
    QCommandLineOption lang("lang", QApplication::translate("main", "Language: en or ja."), "code");
    QCommandLineOption shot("screenshot", QApplication::translate("main", "Save a screenshot of the main window and quit."),
                            "file");
    parser.addOptions({preset, lang, shot});
    parser.process(app);

    QTranslator translator;
    const QString code = parser.isSet(lang) ? parser.value(lang) : QLocale::system().name().left(2);
    if (code == "ja" && translator.load(":/i18n/axistune_ja.qm"))
        QApplication::installTranslator(&translator);

    axistune::gui::MainWindow w;
    w.show();
    if (!w.connectSimulated(parser.value(preset)))
        return 2;
    if (parser.isSet(shot)) {
        QApplication::processEvents();
        return w.grab().save(parser.value(shot)) ? 0 : 1;
    }
    return QApplication::exec();
}
