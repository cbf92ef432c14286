// SPDX-License-Identifier: GPL-3.0-or-later
// Session report: HTML built from the stored session record, plots rendered offscreen with the
// widgets/ plots, PDF through QTextDocument::print (docs/reports.md).
#include "app/gui/Report.h"

#include "app/gui/BallBarText.h"
#include "core/io/AtomicFile.h"
#include "core/model/Constants.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Parameter.h"
#include "core/sim/AxisParameters.h"
#include "core/store/FrfCapture.h"
#include "core/store/SessionRecord.h"
#include "widgets/BodePlot.h"
#include "widgets/CurvePlot.h"
#include "widgets/PolarPlot.h"
#include "widgets/TimeTracePlot.h"

#include <QBuffer>
#include <QFile>
#include <QPageSize>
#include <QPrinter>
#include <QTemporaryDir>
#include <QTextDocument>
#include <QUrl>

#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>

namespace axistune {
namespace gui {

namespace {

constexpr int kPlotWidth = 900;
constexpr int kPlotHeight = 560;
constexpr int kMaxListedValues = 12;

QString esc(const std::string& s)
{
    return QString::fromStdString(s).toHtmlEscaped();
}

QString number(double v)
{
    if (!std::isfinite(v))
        return QStringLiteral("—");
    return QString::number(v, 'g', 6);
}

QString scalarToHtml(const nlohmann::json& j)
{
    if (j.is_null())
        return QStringLiteral("—");
    if (j.is_boolean())
        return j.get<bool>() ? QCoreApplication::translate("SessionReport", "yes")
                             : QCoreApplication::translate("SessionReport", "no");
    if (j.is_number())
        return number(j.get<double>());
    if (j.is_string())
        return esc(j.get<std::string>()).replace('\n', QStringLiteral("<br>"));
    return esc(j.dump());
}

bool isScalar(const nlohmann::json& j)
{
    return !j.is_object() && !j.is_array();
}

QString arrayOfObjectsToHtml(const nlohmann::json& j, int depth)
{
    std::vector<std::string> cols;
    std::set<std::string> seen;
    for (const auto& e : j)
        for (auto it = e.begin(); it != e.end(); ++it)
            if (seen.insert(it.key()).second)
                cols.push_back(it.key());
    QString h = QStringLiteral("<table border=\"1\" cellspacing=\"0\" cellpadding=\"3\"><tr>");
    for (const auto& c : cols)
        h += QStringLiteral("<th>%1</th>").arg(esc(c));
    h += QStringLiteral("</tr>");
    for (const auto& e : j) {
        h += QStringLiteral("<tr>");
        for (const auto& c : cols)
            h += QStringLiteral("<td>%1</td>").arg(e.contains(c) ? jsonToHtml(e[c], depth + 1) : QString());
        h += QStringLiteral("</tr>");
    }
    return h + QStringLiteral("</table>");
}

QString scalarListToHtml(const nlohmann::json& j)
{
    QStringList parts;
    int n = 0;
    for (const auto& e : j) {
        if (n++ == kMaxListedValues)
            break;
        parts << scalarToHtml(e);
    }
    QString s = parts.join(QStringLiteral(", "));
    if (j.size() > static_cast<std::size_t>(kMaxListedValues))
        s += QCoreApplication::translate("SessionReport", ", … (%n values)", nullptr, static_cast<int>(j.size()));
    return s;
}

const model::ParameterMeta* metaFor(const std::string& key)
{
    for (auto kind : {sim::AxisKind::Linear, sim::AxisKind::Rotary})
        if (const auto* m = model::findParameter(sim::axisParameterMetas(kind), key))
            return m;
    return nullptr;
}

QString parameterValue(const std::string& key, double v)
{
    if (const auto* m = metaFor(key))
        return QString::fromStdString(model::formatDisplay(*m, v)).toHtmlEscaped();
    return number(v);
}

QString statusText(store::SessionStatus s)
{
    switch (s) {
    case store::SessionStatus::Completed:
        return QCoreApplication::translate("SessionReport", "completed");
    case store::SessionStatus::Aborted:
        return QCoreApplication::translate("SessionReport", "ABORTED");
    case store::SessionStatus::Failed:
        return QCoreApplication::translate("SessionReport", "FAILED");
    }
    return {};
}

QString sourceText(store::ParameterSource s)
{
    switch (s) {
    case store::ParameterSource::Read:
        return QCoreApplication::translate("SessionReport", "Read from the drive");
    case store::ParameterSource::Proposed:
        return QCoreApplication::translate("SessionReport", "Proposed");
    case store::ParameterSource::Applied:
        return QCoreApplication::translate("SessionReport", "Applied");
    case store::ParameterSource::Imported:
        return QCoreApplication::translate("SessionReport", "Imported");
    }
    return {};
}

/// A ball-bar trace (the lost-motion wizard's layout): metadata content=ballbar or the channels
/// angle_rad and deviation_m.
bool isBallBarCapture(const model::Capture& c)
{
    const auto* content = c.metadata.find(model::meta::kContent);
    if (content && *content == "ballbar")
        return c.channel("angle_rad") && c.channel("deviation_m");
    return c.channel("angle_rad") && c.channel("deviation_m") && c.channels.size() == 2;
}

/// Renders a plot widget offscreen through its exportImage (PNG in a temporary directory).
template <class Plot> QImage renderPlot(Plot& plot, const QTemporaryDir& dir, int index)
{
    plot.resize(kPlotWidth, kPlotHeight);
    plot.replotNow();
    const QString path = dir.filePath(QStringLiteral("plot%1.png").arg(index));
    if (!plot.exportImage(path, kPlotWidth, kPlotHeight))
        return {};
    return QImage(path);
}

} // namespace

QString jsonToHtml(const nlohmann::json& j, int depth)
{
    if (isScalar(j))
        return scalarToHtml(j);
    if (j.is_array()) {
        if (j.empty())
            return QStringLiteral("—");
        bool allObjects = true;
        bool allScalars = true;
        for (const auto& e : j) {
            allObjects = allObjects && e.is_object();
            allScalars = allScalars && isScalar(e);
        }
        if (allScalars)
            return scalarListToHtml(j);
        if (allObjects && depth < 4)
            return arrayOfObjectsToHtml(j, depth);
        QString h = QStringLiteral("<ol>");
        for (const auto& e : j)
            h += QStringLiteral("<li>%1</li>").arg(jsonToHtml(e, depth + 1));
        return h + QStringLiteral("</ol>");
    }
    if (j.empty())
        return QStringLiteral("—");
    QString h = QStringLiteral("<table border=\"1\" cellspacing=\"0\" cellpadding=\"3\">");
    for (auto it = j.begin(); it != j.end(); ++it)
        h += QStringLiteral("<tr><th align=\"left\">%1</th><td>%2</td></tr>")
                 .arg(esc(it.key()), jsonToHtml(it.value(), depth + 1));
    return h + QStringLiteral("</table>");
}

namespace {

struct Builder {
    explicit Builder(const store::SessionRecord& r) : rec(r) {}
    const store::SessionRecord& rec;
    QString html;
    QVector<ReportImage> images;
    QTemporaryDir tmp;

    void addImage(const QImage& image, const QString& title)
    {
        if (image.isNull()) {
            html += QStringLiteral("<p><i>%1</i></p>")
                        .arg(QCoreApplication::translate("SessionReport", "Plot \"%1\" could not be rendered.")
                                 .arg(title.toHtmlEscaped()));
            return;
        }
        ReportImage ri{QStringLiteral("plot%1.png").arg(images.size() + 1), title, image};
        html +=
            QStringLiteral("<p><b>%1</b><br><img src=\"%2\" width=\"640\"></p>").arg(title.toHtmlEscaped(), ri.name);
        images.push_back(ri);
    }

    void summary()
    {
        const auto& i = rec.info;
        auto row = [this](const QString& k, const QString& v) {
            html += QStringLiteral("<tr><th align=\"left\">%1</th><td>%2</td></tr>").arg(k, v);
        };
        html += QStringLiteral("<h1>%1</h1>")
                    .arg(QCoreApplication::translate("SessionReport", "Session %1: %2").arg(i.id).arg(esc(i.kind)));
        const bool bad = i.status != store::SessionStatus::Completed;
        if (bad)
            html += QStringLiteral("<p style=\"color:#b00000\"><b>%1</b></p>")
                        .arg(QCoreApplication::translate("SessionReport", "This session was %1. Reason: %2")
                                 .arg(statusText(i.status),
                                      i.note.empty() ? QCoreApplication::translate("SessionReport", "not recorded")
                                                     : esc(i.note)));
        html += QStringLiteral("<table border=\"1\" cellspacing=\"0\" cellpadding=\"3\">");
        const QString none = QCoreApplication::translate("SessionReport", "(none)");
        row(QCoreApplication::translate("SessionReport", "Machine"), i.machine.empty() ? none : esc(i.machine));
        row(QCoreApplication::translate("SessionReport", "Axis"), i.axis.empty() ? none : esc(i.axis));
        row(QCoreApplication::translate("SessionReport", "Kind"), esc(i.kind));
        row(QCoreApplication::translate("SessionReport", "Status"),
            bad ? QStringLiteral("<span style=\"color:#b00000\"><b>%1</b></span>").arg(statusText(i.status))
                : statusText(i.status));
        row(QCoreApplication::translate("SessionReport", "Started"), esc(i.started));
        row(QCoreApplication::translate("SessionReport", "Finished"), esc(i.finished));
        row(QCoreApplication::translate("SessionReport", "Operator"),
            i.operatorName.empty() ? none : esc(i.operatorName));
        row(QCoreApplication::translate("SessionReport", "Notes"),
            i.note.empty() ? none : esc(i.note).replace('\n', QStringLiteral("<br>")));
        row(QCoreApplication::translate("SessionReport", "AxisTune version"), esc(i.appVersion));
        suppressionRows(row);
        html += QStringLiteral("</table>");
    }

    /// The two-inertia wizard's vibration-suppression filter and the load error of its verification.
    template <class Row> void suppressionRows(Row& row)
    {
        constexpr double deg = model::kDegPerRad;
        for (const auto& r : rec.results) {
            const auto& d = r.data;
            auto num = [&d](const char* k) { return d.contains(k) && d[k].is_number() ? d[k].get<double>() : 0.0; };
            if (r.name == "filter" && d.is_object() && d.contains("f0_Hz")) {
                const bool full = d.value("mode", std::string()) == "full";
                QString text = (full ? QCoreApplication::translate("SessionReport", "F_L (full-closed)")
                                     : QCoreApplication::translate("SessionReport", "F_m (semi-closed)")) +
                               QCoreApplication::translate("SessionReport", ": f₀ %1 Hz, ζ %2")
                                   .arg(num("f0_Hz"), 0, 'f', 3)
                                   .arg(num("zeta"), 0, 'f', 4);
                if (full)
                    text += QCoreApplication::translate("SessionReport", ", τ %1 ms").arg(num("tau_s") * 1e3, 0, 'f', 2);
                row(QCoreApplication::translate("SessionReport", "Suppression filter"), text);
            }
            if (r.name == "verification" && d.is_object() && d.contains("measured_max_load_error_rad"))
                row(QCoreApplication::translate("SessionReport", "Maximum load error (verification)"),
                    QCoreApplication::translate("SessionReport",
                                                "measured %1° with the filter; predicted %2° without, %3° with it")
                        .arg(num("measured_max_load_error_rad") * deg, 0, 'f', 3)
                        .arg(num("predicted_max_load_error_without_filter_rad") * deg, 0, 'f', 3)
                        .arg(num("predicted_max_load_error_with_filter_rad") * deg, 0, 'f', 3));
        }
    }

    void plots()
    {
        html += QStringLiteral("<h2>%1</h2>").arg(QCoreApplication::translate("SessionReport", "Plots"));
        const int before = images.size();
        widgets::BodePlot bode;
        QStringList frfNames;
        for (const auto& c : rec.captures) {
            if (!store::isFrfCapture(c.capture))
                continue;
            auto frf = store::frfFromCapture(c.capture);
            if (!frf) {
                html += QStringLiteral("<p>%1</p>")
                            .arg(QCoreApplication::translate("SessionReport", "FRF \"%1\" is unreadable: %2")
                                     .arg(esc(c.name), esc(frf.error().detail)));
                continue;
            }
            bode.addResponse(*frf, QString::fromStdString(c.name));
            frfNames << QString::fromStdString(c.name);
        }
        if (!frfNames.isEmpty()) {
            bode.rescale();
            addImage(renderPlot(bode, tmp, images.size() + 1),
                     QCoreApplication::translate("SessionReport", "Frequency response: %1").arg(frfNames.join(", ")));
        }
        ballBars();
        for (const auto& c : rec.captures) {
            if (store::isFrfCapture(c.capture) || isBallBarCapture(c.capture) || c.capture.size() == 0)
                continue;
            widgets::TimeTracePlot trace;
            trace.setCapture(std::make_shared<const model::Capture>(c.capture));
            trace.rescale();
            addImage(renderPlot(trace, tmp, images.size() + 1),
                     QCoreApplication::translate("SessionReport", "Capture: %1").arg(QString::fromStdString(c.name)));
        }
        for (const auto& r : rec.results)
            resultArrays(r);
        if (images.size() == before)
            html += QStringLiteral("<p>%1</p>").arg(QCoreApplication::translate("SessionReport", "No plots recorded."));
    }

    /// Every ball-bar trace in one polar plot (nominal circle, magnified deviation).
    void ballBars()
    {
        widgets::PolarPlot polar;
        QStringList names;
        for (const auto& c : rec.captures) {
            if (!isBallBarCapture(c.capture))
                continue;
            const auto* a = c.capture.channel("angle_rad");
            const auto* d = c.capture.channel("deviation_m");
            if (a->data.size() != d->data.size() || a->data.empty())
                continue;
            if (const auto* radius = c.capture.metadata.find(model::meta::kRadiusM); radius && names.isEmpty()) {
                if (const auto r = radius->number(); r && *r > 0)
                    polar.setNominalRadius(*r);
            }
            polar.addTrace(QString::fromStdString(c.name), a->data, d->data);
            names << QString::fromStdString(c.name);
        }
        if (names.isEmpty())
            return;
        addImage(renderPlot(polar, tmp, images.size() + 1),
                 QCoreApplication::translate("SessionReport", "Ball-bar traces: %1").arg(names.join(", ")));
    }

    /// Arrays of a result: the first is the x axis, the others of the same length are curves.
    void resultArrays(const store::SessionResult& r)
    {
        if (r.arrays.size() < 2)
            return;
        const auto& x = r.arrays.front();
        widgets::CurvePlot plot;
        plot.setAxes(QString::fromStdString(x.name), QString(), QString::fromStdString(r.name), QString());
        for (std::size_t k = 1; k < r.arrays.size(); ++k)
            if (r.arrays[k].data.size() == x.data.size())
                plot.addCurve(QString::fromStdString(r.arrays[k].name), x.data, r.arrays[k].data);
        if (plot.curveCount() == 0)
            return;
        plot.rescale();
        addImage(renderPlot(plot, tmp, images.size() + 1),
                 QCoreApplication::translate("SessionReport", "Result: %1").arg(QString::fromStdString(r.name)));
    }

    void parameterSets()
    {
        if (rec.parameterSets.empty())
            return;
        html += QStringLiteral("<h2>%1</h2>").arg(QCoreApplication::translate("SessionReport", "Parameter sets"));
        for (const auto& s : rec.parameterSets) {
            html += QStringLiteral("<h3>%1 — %2</h3>")
                        .arg(sourceText(s.source),
                             QCoreApplication::translate("SessionReport", "axis %1, %2").arg(esc(s.axis), esc(s.time)));
            if (!s.note.empty())
                html += QStringLiteral("<p>%1</p>").arg(esc(s.note));
            html += QStringLiteral("<table border=\"1\" cellspacing=\"0\" cellpadding=\"3\"><tr><th>%1</th><th>%2</th>"
                                   "<th>%3</th></tr>")
                        .arg(QCoreApplication::translate("SessionReport", "Parameter"),
                             QCoreApplication::translate("SessionReport", "Description"),
                             QCoreApplication::translate("SessionReport", "Value"));
            for (const auto& [key, v] : s.values) {
                const auto* m = metaFor(key);
                html += QStringLiteral("<tr><td>%1</td><td>%2</td><td align=\"right\">%3</td></tr>")
                            .arg(esc(key), m ? esc(m->label) : QString(), parameterValue(key, v));
            }
            html += QStringLiteral("</table>");
        }
    }

    void journal()
    {
        if (rec.journal.empty())
            return;
        html += QStringLiteral("<h2>%1</h2>").arg(QCoreApplication::translate("SessionReport", "Journal of writes"));
        html += QStringLiteral("<table border=\"1\" cellspacing=\"0\" cellpadding=\"3\"><tr><th>%1</th><th>%2</th>"
                               "<th>%3</th><th>%4</th><th>%5</th></tr>")
                    .arg(QCoreApplication::translate("SessionReport", "Time"),
                         QCoreApplication::translate("SessionReport", "Axis"),
                         QCoreApplication::translate("SessionReport", "Parameter"),
                         QCoreApplication::translate("SessionReport", "Old value"),
                         QCoreApplication::translate("SessionReport", "New value"));
        for (const auto& e : rec.journal)
            html += QStringLiteral("<tr><td>%1</td><td>%2</td><td>%3</td><td align=\"right\">%4</td>"
                                   "<td align=\"right\">%5</td></tr>")
                        .arg(esc(e.time), esc(e.axis), esc(e.key),
                             e.oldValue ? parameterValue(e.key, *e.oldValue)
                                        : QCoreApplication::translate("SessionReport", "not recorded"),
                             parameterValue(e.key, e.newValue));
        html += QStringLiteral("</table>");
    }

    void results()
    {
        const store::SessionResult* verification = nullptr;
        bool heading = false;
        for (const auto& r : rec.results) {
            if (r.name == "verification") {
                verification = &r;
                continue;
            }
            if (!heading)
                html += QStringLiteral("<h2>%1</h2>").arg(QCoreApplication::translate("SessionReport", "Results"));
            heading = true;
            oneResult(r);
        }
        if (!rec.models.empty()) {
            html +=
                QStringLiteral("<h2>%1</h2>").arg(QCoreApplication::translate("SessionReport", "Identified models"));
            for (const auto& m : rec.models)
                html += QStringLiteral("<h3>%1 (%2)</h3>%3")
                            .arg(esc(m.kind), QCoreApplication::translate("SessionReport", "axis %1").arg(esc(m.axis)),
                                 jsonToHtml(m.data));
        }
        html += QStringLiteral("<h2>%1</h2>").arg(QCoreApplication::translate("SessionReport", "Verification"));
        if (verification)
            oneResult(*verification, false);
        else
            html += QStringLiteral("<p>%1</p>")
                        .arg(QCoreApplication::translate("SessionReport", "No verification was recorded."));
    }

    void oneResult(const store::SessionResult& r, bool withTitle = true)
    {
        if (withTitle)
            html += QStringLiteral("<h3>%1</h3>").arg(esc(r.name));
        // Ball-bar findings carry rule keys: worded in the user's language (BallBarText).
        html += jsonToHtml(r.name == "diagnostics" ? BallBarText::translatedDiagnostics(r.data) : r.data);
        if (!r.arrays.empty()) {
            QStringList names;
            for (const auto& a : r.arrays)
                names << QStringLiteral("%1 (%2)").arg(esc(a.name)).arg(a.data.size());
            html += QStringLiteral("<p>%1</p>")
                        .arg(QCoreApplication::translate("SessionReport", "Arrays (values): %1").arg(names.join(", ")));
        }
    }
};

} // namespace

SessionReport SessionReport::build(const store::SessionRecord& record)
{
    Builder b(record);
    b.html = QStringLiteral("<html><head><meta charset=\"utf-8\"><title>%1</title></head><body>")
                 .arg(tr("AxisTune session %1").arg(record.info.id));
    b.summary();
    b.html += QStringLiteral("<h2>%1</h2>%2").arg(tr("Inputs"), jsonToHtml(record.inputs));
    b.plots();
    b.parameterSets();
    b.journal();
    b.results();
    b.html += QStringLiteral("<hr><p><small>%1</small></p></body></html>")
                  .arg(tr("Report made by AxisTune from session %1 of the store.").arg(record.info.id));
    SessionReport r;
    r.m_record = record;
    r.m_html = b.html;
    r.m_images = b.images;
    return r;
}

QTextDocument* SessionReport::createDocument(QObject* parent) const
{
    auto* doc = new QTextDocument(parent);
    for (const auto& im : m_images)
        doc->addResource(QTextDocument::ImageResource, QUrl(im.name), im.image);
    doc->setHtml(m_html);
    return doc;
}

QString SessionReport::standaloneHtml() const
{
    QString h = m_html;
    for (const auto& im : m_images) {
        QByteArray png;
        QBuffer buf(&png);
        buf.open(QIODevice::WriteOnly);
        im.image.save(&buf, "PNG");
        h.replace(QStringLiteral("src=\"%1\"").arg(im.name),
                  QStringLiteral("src=\"data:image/png;base64,%1\"").arg(QString::fromLatin1(png.toBase64())));
    }
    return h;
}

bool SessionReport::saveHtml(const QString& path, QString* error) const
{
    const QByteArray bytes = standaloneHtml().toUtf8();
    if (auto st = io::writeFileAtomic(path.toStdString(),
                                      std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
        !st) {
        if (error)
            *error = tr("Cannot write %1: %2").arg(path, QString::fromStdString(st.error().detail));
        return false;
    }
    return true;
}

bool SessionReport::savePdf(const QString& path, QString* error) const
{
    // Printed to a temporary file next to `path`, then renamed over it (core/io/AtomicFile.h).
    const auto st = io::writeFileAtomicVia(path.toStdString(), [&](const std::string& tmpPath) -> Status {
        const QString tmp = QString::fromStdString(tmpPath);
        QPrinter printer(QPrinter::HighResolution);
        printer.setOutputFormat(QPrinter::PdfFormat);
        printer.setPageSize(QPageSize(QPageSize::A4));
        printer.setOutputFileName(tmp);
        printer.setDocName(tr("AxisTune session %1").arg(m_record.info.id));
        std::unique_ptr<QTextDocument> doc(createDocument());
        doc->print(&printer);
        QFile f(tmp); // QPrinter does not report write errors: check the file
        if (!f.exists() || f.size() == 0)
            return makeError(ErrorCode::Io, "the PDF writer failed");
        return Status::success();
    });
    if (!st) {
        if (error)
            *error = tr("Cannot write %1").arg(path);
        return false;
    }
    return true;
}

} // namespace gui
} // namespace axistune
