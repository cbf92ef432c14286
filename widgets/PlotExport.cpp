// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/PlotExport.h"

#include "core/io/AtomicFile.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStringList>
#include <QSvgGenerator>
#include <qcustomplot.h>

namespace axistune {
namespace widgets {

namespace {

// Translation context for the messages of this file (lupdate reads Q_DECLARE_TR_FUNCTIONS).
class PlotExport {
    Q_DECLARE_TR_FUNCTIONS(PlotExport)
};

bool writeSvg(QCustomPlot& plot, const QString& path, int width, int height)
{
    QSvgGenerator generator;
    generator.setFileName(path);
    generator.setSize(QSize(width, height));
    generator.setViewBox(QRect(0, 0, width, height));
    generator.setTitle(plot.windowTitle());
    QCPPainter painter;
    if (!painter.begin(&generator))
        return false;
    plot.toPainter(&painter, width, height);
    return painter.end();
}

}  // namespace

QStringList plotImageSuffixes()
{
    return {QStringLiteral("png"), QStringLiteral("svg"), QStringLiteral("pdf")};
}

bool exportPlotImage(QCustomPlot& plot, const QString& path, int width, int height, QString* error)
{
    auto fail = [&](const QString& message) {
        if (error)
            *error = message;
        return false;
    };
    const QFileInfo info(path);
    const QString suffix = info.suffix().toLower();
    if (!plotImageSuffixes().contains(suffix))
        return fail(PlotExport::tr("%1: unknown image type '%2' (use .png, .svg or .pdf)").arg(path, info.suffix()));
    if (!info.absoluteDir().exists())
        return fail(PlotExport::tr("%1: the folder %2 does not exist").arg(path, info.absolutePath()));
    if (width < 0 || height < 0)
        return fail(PlotExport::tr("%1: negative image size %2×%3").arg(path).arg(width).arg(height));
    // A plot that was never shown has no useful size of its own: take that of the widget holding it
    // (sized by resize() before export), else 1000×700.
    QSize size = plot.size();
    if (!plot.isVisible() && plot.parentWidget())
        size = plot.parentWidget()->size();
    if (size.width() < 100 || size.height() < 100)
        size = QSize(1000, 700);
    if (width == 0)
        width = size.width();
    if (height == 0)
        height = size.height();

    // Written to a temporary file next to `path` and renamed over it (core/io/AtomicFile.h): a failed
    // export leaves the older file of the same name as it was, never half an image.
    const auto st = io::writeFileAtomicVia(path.toStdString(), [&](const std::string& tmpPath) -> Status {
        const QString tmp = QString::fromStdString(tmpPath);
        bool ok = false;
        if (suffix == QLatin1String("png"))
            ok = plot.savePng(tmp, width, height);
        else if (suffix == QLatin1String("pdf"))
            ok = plot.savePdf(tmp, width, height, QCP::epNoCosmetic);
        else
            ok = writeSvg(plot, tmp, width, height);
        // QSvgGenerator and QPdfWriter do not report write errors: check the file.
        const QFileInfo written(tmp);
        if (!ok || !written.exists() || written.size() == 0)
            return makeError(ErrorCode::Io, "the image writer failed");
        return Status::success();
    });
    if (!st)
        return fail(PlotExport::tr("%1: could not write the image (is the folder writable and the disk not full?)").arg(path));
    return true;
}

}  // namespace widgets
}  // namespace axistune
