// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/SessionReviewView.h"

#include "app/gui/WidgetUtil.h"
#include "core/io/CaptureCsv.h"
#include "core/io/FrfCsv.h"
#include "core/model/MetadataKeys.h"
#include "core/store/FrfCapture.h"
#include "core/store/SessionRecord.h"
#include "widgets/BodePlot.h"
#include "widgets/TimeTracePlot.h"

#include <QDir>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QTabWidget>
#include <QTableWidget>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <nlohmann/json.hpp>

namespace axistune {
namespace gui {

namespace {
/// A file-name-safe form of a capture name.
QString safeName(const std::string& name)
{
    QString s = qs(name);
    s.replace(QRegularExpression("[^A-Za-z0-9_.-]"), "_");
    return s.isEmpty() ? QString("capture") : s;
}

void addJson(QTreeWidgetItem* parent, const QString& key, const nlohmann::json& j)
{
    auto* item = new QTreeWidgetItem(parent, {key});
    if (j.is_object()) {
        for (auto it = j.begin(); it != j.end(); ++it)
            addJson(item, qs(it.key()), it.value());
    } else if (j.is_array()) {
        // Long numeric arrays are summarised; every value is in the CSV/JSON export of the CLI.
        if (j.size() > 50 && !j.empty() && j.front().is_number()) {
            item->setText(1, QObject::tr("[%1 values] %2 … %3")
                                 .arg(j.size())
                                 .arg(qs(j.front().dump()), qs(j.back().dump())));
            return;
        }
        for (std::size_t i = 0; i < j.size(); ++i)
            addJson(item, QString("[%1]").arg(i), j[i]);
    } else {
        item->setText(1, j.is_string() ? qs(j.get<std::string>()) : qs(j.dump()));
    }
}

QTableWidget* table(const QStringList& headers, QWidget* parent)
{
    auto* t = new QTableWidget(0, static_cast<int>(headers.size()), parent);
    t->setHorizontalHeaderLabels(headers);
    t->setEditTriggers(QAbstractItemView::NoEditTriggers);
    t->verticalHeader()->hide();
    t->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    t->horizontalHeader()->setStretchLastSection(true);
    return t;
}

}  // namespace

int addFrfWithBands(widgets::BodePlot& plot, const dsp::FrequencyResponse& frf, const QString& name)
{
    const int id = plot.addResponse(frf, name);
    // Runs of invalid points: not measurable by the method used.
    for (std::size_t i = 0; i < frf.size();) {
        if (i < frf.valid.size() && !frf.valid[i]) {
            std::size_t j = i;
            while (j + 1 < frf.size() && !frf.valid[j + 1])
                ++j;
            const double lo = i > 0 ? std::sqrt(frf.freqHz[i - 1] * frf.freqHz[i]) : frf.freqHz[i];
            const double hi = j + 1 < frf.size() ? std::sqrt(frf.freqHz[j] * frf.freqHz[j + 1]) : frf.freqHz[j];
            plot.addBand(lo, hi, widgets::BodePlot::BandKind::NotMeasurable);
            i = j + 1;
        } else {
            ++i;
        }
    }
    // Above the observation Nyquist fs/2 only the multi-sweep methods measure (up to fs).
    const auto* method = frf.metadata.find(model::meta::kMethod);
    if (frf.metadata.contains(model::meta::kFsHz) && method && !frf.empty() &&
        (*method == "multisweep" || *method == "multisine" || *method == "sine-stream-mixed")) {
        // Only a band on the plot: an unreadable rate draws none.
        const auto parsed = frf.metadata.number(model::meta::kFsHz);
        const double fsHz = parsed ? *parsed : 0.0;
        if (fsHz > 0.0 && frf.freqHz.back() > fsHz / 2.0)
            plot.addBand(fsHz / 2.0, std::min(fsHz, frf.freqHz.back()), widgets::BodePlot::BandKind::MultiSweepOnly);
    }
    return id;
}

SessionView::SessionView(store::SessionRecord record, QWidget* parent) : QWidget(parent), m_record(std::move(record))
{
    setObjectName("sessionView");
    auto* lay = new QVBoxLayout(this);
    const auto& info = m_record.info;
    auto* header = new QLabel(this);
    header->setObjectName("sessionHeader");
    header->setWordWrap(true);
    const bool aborted = info.status != store::SessionStatus::Completed;
    header->setText(tr("<b>Session %1</b> — %2, machine %3, axis %4, %5 … %6, operator %7, status %8%9")
                        .arg(info.id)
                        .arg(qs(info.kind), qs(info.machine), qs(info.axis), qs(info.started), qs(info.finished),
                             qs(info.operatorName).isEmpty() ? tr("(none)") : qs(info.operatorName),
                             aborted ? QString("<span style='color:#b00020'><b>%1</b></span>")
                                           .arg(qs(store::toString(info.status)).toUpper())
                                     : qs(store::toString(info.status)),
                             info.note.empty() ? QString() : tr("<br>Note: %1").arg(qs(info.note).toHtmlEscaped())));
    lay->addWidget(header);
    m_tabs = new QTabWidget(this);
    m_tabs->setObjectName("sessionTabs");
    lay->addWidget(m_tabs, 1);
    auto* buttons = new QHBoxLayout;
    auto* csv = new QPushButton(tr("Export captures as CSV…"), this);
    auto* img = new QPushButton(tr("Export plots…"), this);
    buttons->addWidget(csv);
    buttons->addWidget(img);
    buttons->addStretch(1);
    lay->addLayout(buttons);
    connect(csv, &QPushButton::clicked, this, &SessionView::exportCsvInteractive);
    connect(img, &QPushButton::clicked, this, &SessionView::exportImagesInteractive);
    buildPlots();
    buildTables();
}

void SessionView::buildPlots()
{
    for (const auto& c : m_record.captures) {
        if (!store::isFrfCapture(c.capture))
            continue;
        auto frf = store::frfFromCapture(c.capture);
        if (!frf)
            continue;
        if (!m_bode) {
            m_bode = new widgets::BodePlot(m_tabs);
            m_bode->setObjectName("sessionBode");
            m_tabs->addTab(m_bode, tr("Frequency response"));
        }
        m_responseIds.emplace_back(qs(c.name), addFrfWithBands(*m_bode, *frf, qs(c.name)));
    }
    if (m_bode)
        m_bode->rescale();
    for (const auto& c : m_record.captures) {
        if (store::isFrfCapture(c.capture))
            continue;
        auto* plot = new widgets::TimeTracePlot(m_tabs);
        plot->setObjectName("sessionTrace");
        plot->setCapture(std::make_shared<const model::Capture>(c.capture));
        m_tabs->addTab(plot, tr("Trace: %1").arg(qs(c.name)));
        m_traces.push_back(plot);
    }
}

void SessionView::buildTables()
{
    auto* tree = new QTreeWidget(m_tabs);
    tree->setObjectName("sessionData");
    tree->setColumnCount(2);
    tree->setHeaderLabels({tr("Key"), tr("Value")});
    tree->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    addJson(tree->invisibleRootItem(), tr("inputs"), m_record.inputs);
    for (const auto& r : m_record.results) {
        addJson(tree->invisibleRootItem(), tr("result: %1").arg(qs(r.name)), r.data);
        for (const auto& a : r.arrays) {
            auto* item =
                new QTreeWidgetItem(tree->invisibleRootItem()->child(tree->topLevelItemCount() - 1), {qs(a.name)});
            item->setText(1, tr("[%1 values]").arg(a.data.size()));
        }
    }
    tree->expandToDepth(0);
    m_tabs->addTab(tree, tr("Inputs and results"));

    auto* sets = table({tr("Axis"), tr("Source"), tr("Time"), tr("Parameter"), tr("Value (SI)"), tr("Note")}, m_tabs);
    sets->setObjectName("sessionParameterSets");
    for (const auto& s : m_record.parameterSets)
        for (const auto& [k, v] : s.values)
            addRow(sets, {qs(s.axis), qs(store::toString(s.source)), qs(s.time), qs(k), QString::number(v, 'g', 8),
                          qs(s.note)});
    m_tabs->addTab(sets, tr("Parameter sets"));

    auto* journal = table({tr("Time"), tr("Axis"), tr("Parameter"), tr("Old (SI)"), tr("New (SI)")}, m_tabs);
    journal->setObjectName("sessionJournal");
    for (const auto& e : m_record.journal)
        addRow(journal, {qs(e.time), qs(e.axis), qs(e.key),
                         e.oldValue ? QString::number(*e.oldValue, 'g', 8) : tr("not recorded"),
                         QString::number(e.newValue, 'g', 8)});
    m_tabs->addTab(journal, tr("Journal"));
}

int SessionView::responseId(const QString& captureName) const
{
    for (const auto& [n, id] : m_responseIds)
        if (n == captureName)
            return id;
    return -1;
}

bool SessionView::exportCsv(const QString& dir, QStringList* files, QString* error) const
{
    QDir().mkpath(dir);
    for (const auto& c : m_record.captures) {
        const QString path = QDir(dir).filePath(QString("session%1-%2.csv").arg(m_record.info.id).arg(safeName(c.name)));
        Status s = Status::success();
        if (store::isFrfCapture(c.capture)) {
            auto frf = store::frfFromCapture(c.capture);
            s = frf ? io::writeFrfCsvFile(path.toStdString(), *frf) : Status(frf.error());
        } else {
            s = io::writeCaptureCsvFile(path.toStdString(), c.capture);
        }
        if (!s) {
            if (error)
                *error = qs(s.error().detail);
            return false;
        }
        if (files)
            *files << path;
    }
    return true;
}

bool SessionView::exportImages(const QString& dir, const QString& suffix, QStringList* files, QString* error)
{
    QDir().mkpath(dir);
    const QString base = QDir(dir).filePath(QString("session%1-").arg(m_record.info.id));
    if (m_bode) {
        const QString p = base + "bode." + suffix;
        if (!m_bode->exportImage(p)) {
            if (error)
                *error = m_bode->lastError();
            return false;
        }
        if (files)
            *files << p;
    }
    int i = 0;
    for (auto* t : m_traces) {
        const QString p = base + "trace" + QString::number(++i) + "." + suffix;
        if (!t->exportImage(p)) {
            if (error)
                *error = t->lastError();
            return false;
        }
        if (files)
            *files << p;
    }
    return true;
}

void SessionView::exportCsvInteractive()
{
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Export captures to"));
    if (dir.isEmpty())
        return;
    QStringList files;
    QString err;
    if (!exportCsv(dir, &files, &err))
        QMessageBox::warning(this, tr("Export failed"), err);
    else
        QMessageBox::information(this, tr("Export"), tr("%n file(s) written to %1", "", files.size()).arg(dir));
}

void SessionView::exportImagesInteractive()
{
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Export plots to"));
    if (dir.isEmpty())
        return;
    bool ok = false;
    const QString suffix = QInputDialog::getItem(this, tr("Image format"), tr("Format:"), {"png", "svg", "pdf"}, 0, false, &ok);
    if (!ok)
        return;
    QStringList files;
    QString err;
    if (!exportImages(dir, suffix, &files, &err))
        QMessageBox::warning(this, tr("Export failed"), err);
    else
        QMessageBox::information(this, tr("Export"), tr("%n file(s) written to %1", "", files.size()).arg(dir));
}

SessionOverlay::SessionOverlay(const std::vector<store::SessionRecord>& sessions, QWidget* parent) : QWidget(parent)
{
    setObjectName("sessionOverlay");
    auto* lay = new QVBoxLayout(this);
    m_bode = new widgets::BodePlot(this);
    m_bode->setObjectName("overlayBode");
    lay->addWidget(m_bode);
    for (const auto& s : sessions)
        for (const auto& c : s.captures) {
            if (!store::isFrfCapture(c.capture))
                continue;
            if (auto frf = store::frfFromCapture(c.capture))
                m_bode->addResponse(*frf, tr("session %1: %2").arg(s.info.id).arg(qs(c.name)));
        }
    m_bode->rescale();
}

QStringList SessionOverlay::responseNames() const { return m_bode->responseNames(); }

}  // namespace gui
}  // namespace axistune
