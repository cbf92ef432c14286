// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The report of one stored session (docs/reports.md): machine, axis, kind, status (aborted or failed
// marked with the reason), times, operator and notes, inputs, plots (the FRF captures in one Bode
// plot, every time capture in a time-trace plot, result arrays as curves; rendered offscreen to PNG),
// proposed and applied parameter sets with units where the key's metadata is known, models, journal,
// results and verification as tables. Output: a QTextDocument (plots as image resources), one HTML
// file (plots embedded as data URIs) and a PDF through Qt's printing.

#include "core/store/Database.h"
#include "core/store/SessionRecord.h"

#include <QCoreApplication>
#include <QImage>
#include <QString>
#include <QVector>
#include <nlohmann/json_fwd.hpp>

class QTextDocument;
class QObject;

namespace axistune {
namespace gui {

struct ReportImage {
    QString name;  ///< resource name used in the HTML, "plot1.png"
    QString title; ///< caption
    QImage image;
};

class SessionReport {
    Q_DECLARE_TR_FUNCTIONS(SessionReport)

public:
    /// Builds the report (renders the plots; GUI thread).
    static SessionReport build(const store::SessionRecord& record);

    const store::SessionRecord& record() const { return m_record; }
    /// The HTML with <img src="plotN.png"> for the images (resources of document()).
    QString html() const { return m_html; }
    const QVector<ReportImage>& images() const { return m_images; }

    /// A new document holding the HTML and the plot images as resources.
    QTextDocument* createDocument(QObject* parent = nullptr) const;
    /// One self-contained HTML file: the plots embedded as PNG data URIs.
    QString standaloneHtml() const;
    bool saveHtml(const QString& path, QString* error) const;
    /// A PDF through QTextDocument::print on a QPrinter in PdfFormat (A4).
    bool savePdf(const QString& path, QString* error) const;

private:
    store::SessionRecord m_record;
    QString m_html;
    QVector<ReportImage> m_images;
};

/// Key/value JSON as HTML tables and lists (objects: two-column tables; arrays of objects: one row
/// per element; arrays of numbers: a list, long ones shortened).
QString jsonToHtml(const nlohmann::json& j, int depth = 0);

} // namespace gui
} // namespace axistune
