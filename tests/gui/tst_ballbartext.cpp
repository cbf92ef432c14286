// SPDX-License-Identifier: GPL-3.0-or-later
// The ball-bar diagnostics' rules worded by the GUI (app/gui/BallBarText): in English the GUI's wording
// of every rule key equals core's own text (so the keys and the order of their arguments match), and the
// Japanese translation words every finding and refusal that real traces produce.
#include "app/gui/BallBarText.h"
#include "core/io/BallBarCsv.h"

#include <QRegularExpression>
#include <QTranslator>
#include <QtTest>
#include <nlohmann/json.hpp>

using namespace axistune;

namespace {

io::BallBarTrace load(const char* name)
{
    auto t = io::readBallBarCsvFile(std::string(AXISTUNE_TEST_DATA_DIR) + "/ballbar/" + name);
    if (!t)
        qFatal("%s", t.error().detail.c_str());
    return *t;
}

/// Findings and refusals of CW + CCW full circles, of one direction and of a partial arc.
std::pair<std::vector<tuning::Finding>, std::vector<tuning::RuleText>> everyRule()
{
    std::vector<tuning::Finding> findings;
    std::vector<tuning::RuleText> refused;
    const std::vector<std::vector<io::BallBarTrace>> sets{
        {load("cw.csv"), load("ccw.csv")}, {load("ccw.csv")}, {load("partial.csv")}};
    for (const auto& s : sets) {
        auto rep = tuning::analyzeBallBar(s);
        if (!rep)
            qFatal("%s", rep.error().detail.c_str());
        findings.insert(findings.end(), rep->findings.begin(), rep->findings.end());
        refused.insert(refused.end(), rep->refused.begin(), rep->refused.end());
    }
    return {findings, refused};
}

/// Core writes micrometres as "um"; the GUI as "µm".
QString coreText(const std::string& s) { return QString::fromStdString(s).replace(" um", QString::fromUtf8(" µm")); }

/// Numbers, axis names and directions of a text, in order.
QStringList tokens(const QString& s)
{
    QStringList out;
    auto it = QRegularExpression("\\b(\\d+(\\.\\d+)?|X|Y|CW|CCW)\\b").globalMatch(s);
    while (it.hasNext())
        out << it.next().captured(1);
    return out;
}

bool hasJapanese(const QString& s) { return s.contains(QRegularExpression("[\\x{3040}-\\x{30ff}\\x{4e00}-\\x{9fff}]")); }

} // namespace

class TestBallBarText : public QObject {
    Q_OBJECT
private slots:
    void englishWordingEqualsCore()
    {
        const auto [findings, refused] = everyRule();
        QSet<QString> ids;
        for (const auto& f : findings) {
            QCOMPARE(gui::BallBarText::rule(f), coreText(f.rule));
            ids.insert(QString::fromStdString(f.ruleId));
        }
        // Refusals are worded for people (core starts them with the finding's key): the same numbers and names
        // in the same order.
        for (const auto& r : refused) {
            QCOMPARE(tokens(gui::BallBarText::rule(r)), tokens(coreText(r.text)));
            ids.insert(QString::fromStdString(r.id));
        }
        // The data cover the keys of both directions, one direction and a partial arc.
        for (const char* id : {"squareness.both_directions", "servo_mismatch.both_directions", "squareness.one_direction",
                               "servo_mismatch.one_direction", "backlash", "circularity", "scale_mismatch",
                               "radius_deviation", "center_x", "center_y", "full_circle"})
            QVERIFY2(ids.contains(id), id);
        QVERIFY(ids.contains("cyclic_error.detected") || ids.contains("cyclic_error.not_detected"));
    }

    void japaneseWordsEveryRule()
    {
        QTranslator tr;
        QVERIFY(tr.load(":/i18n/axistune_ja.qm"));
        QCoreApplication::installTranslator(&tr);
        const auto [findings, refused] = everyRule();
        for (const auto& f : findings) {
            const QString name = gui::BallBarText::findingName(f.name);
            const QString rule = gui::BallBarText::rule(f);
            QVERIFY2(hasJapanese(name), qPrintable(name));
            QVERIFY2(hasJapanese(rule), qPrintable(rule));
            QVERIFY2(!rule.contains(QRegularExpression("%\\d")), qPrintable(rule)); // every argument filled
            for (const auto& a : f.ruleArgs)
                QVERIFY2(rule.contains(QString::fromStdString(a)), qPrintable(rule));
        }
        for (const auto& r : refused) {
            const QString text = gui::BallBarText::rule(r);
            QVERIFY2(hasJapanese(text), qPrintable(text));
            QVERIFY2(!text.contains(QRegularExpression("%\\d")), qPrintable(text));
        }
        // A stored diagnostics result (the session's JSON) is worded the same way for the report.
        const auto& f = findings.front();
        nlohmann::json stored{{"findings", {gui::BallBarText::findingJson(f)}},
                              {"refused", {gui::BallBarText::refusalJson(refused.front()), "an old plain refusal"}}};
        const auto out = gui::BallBarText::translatedDiagnostics(stored);
        QCOMPARE(QString::fromStdString(out["findings"][0]["rule"].get<std::string>()), gui::BallBarText::rule(f));
        QCOMPARE(QString::fromStdString(out["findings"][0]["name"].get<std::string>()),
                 gui::BallBarText::findingName(f.name));
        QVERIFY(!out["findings"][0].contains("rule_id"));
        QCOMPARE(QString::fromStdString(out["refused"][0].get<std::string>()), gui::BallBarText::rule(refused.front()));
        QCOMPARE(out["refused"][1].get<std::string>(), std::string("an old plain refusal"));
        QCoreApplication::removeTranslator(&tr);
    }
};

QTEST_MAIN(TestBallBarText)
#include "tst_ballbartext.moc"
