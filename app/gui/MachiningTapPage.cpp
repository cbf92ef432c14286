// SPDX-License-Identifier: GPL-3.0-or-later
// The machining wizard's tap-test page (app/gui/MachiningTapPage.h; method in core/dsp/ImpactTest.h).
#include "app/gui/MachiningTapPage.h"

#include "app/gui/MachiningWizard.h"
#include "core/io/FrfCsv.h"
#include "core/io/SampleTime.h"
#include "core/io/TableImport.h"
#include "core/machining/ExponentialWindow.h"
#include "core/model/MetadataKeys.h"
#include "widgets/BodePlot.h"

#include <QComboBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QLocale>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>
#include <QWizard>

#include <algorithm>
#include <cmath>

namespace axistune {
namespace gui {

namespace {

// One record with its rate: '# fs_Hz=' or a time column (t_s, t, time) within the jitter tolerance.
Result<std::pair<model::Capture, double>> loadRecord(const QString& path)
{
    const std::string p = path.toStdString();
    auto cap = io::readTimeSeriesFile(p, {});
    if (!cap)
        return cap.error();
    if (const auto* v = cap->metadata.find(model::meta::kFsHz)) {
        double fs = 0.0;
        if (io::detail::parseDouble(v->text(), fs) && fs > 0.0 && std::isfinite(fs))
            return std::pair{std::move(cap).value(), fs};
        return makeError(ErrorCode::BadInput, p + ": metadata fs_Hz is not a positive number");
    }
    for (const char* name : {"t_s", "t", "time", "Time"}) {
        if (const auto* t = cap->channel(name)) {
            auto timing = io::sampleTiming(t->data, p + ", column '" + name + "'");
            if (!timing)
                return timing.error();
            const double fs = timing->fsHz;
            return std::pair{std::move(cap).value(), fs};
        }
    }
    return makeError(ErrorCode::BadInput, p + ": no sampling rate (a time column t_s or a '# fs_Hz=' line)");
}

} // namespace

MachiningTapPage::MachiningTapPage(MachiningToolPage& tool, QWidget* parent) : QWizardPage(parent), m_tool(tool)
{
    setTitle(tr("Tap test"));
    setSubTitle(tr("Impact-hammer records at the tool tip: the receptance (m/N) from hammer force and response, "
                   "averaged over the hits, used as the tool's FRF."));
    m_records = new QListWidget(this);
    m_records->setObjectName("tapRecords");
    m_records->setMaximumHeight(70);
    auto* add = new QPushButton(tr("Add record…"), this);
    add->setObjectName("tapAddRecord");
    auto* remove = new QPushButton(tr("Remove"), this);
    m_force = new QComboBox(this);
    m_force->setObjectName("tapForce");
    m_response = new QComboBox(this);
    m_response->setObjectName("tapResponse");
    m_responseType = new QComboBox(this);
    m_responseType->setObjectName("tapResponseType");
    m_responseType->addItem(tr("acceleration [m/s²]"), int(dsp::MotionQuantity::Acceleration));
    m_responseType->addItem(tr("velocity [m/s]"), int(dsp::MotionQuantity::Velocity));
    m_responseType->addItem(tr("displacement [m]"), int(dsp::MotionQuantity::Displacement));
    m_trigger = new QLineEdit(this);
    m_trigger->setObjectName("tapTrigger");
    m_trigger->setPlaceholderText(tr("10 % of the largest force"));
    m_expTau = new QLineEdit(this);
    m_expTau->setObjectName("tapExpTau");
    m_expTau->setPlaceholderText(tr("none"));
    m_doubleHit = new QComboBox(this);
    m_doubleHit->setObjectName("tapDoubleHit");
    m_doubleHit->addItem(tr("refuse the records"), int(dsp::DoubleHitPolicy::Refuse));
    m_doubleHit->addItem(tr("drop that hit"), int(dsp::DoubleHitPolicy::Drop));
    m_modes = new QSpinBox(this);
    m_modes->setObjectName("tapModes");
    m_modes->setRange(1, 6);
    auto* form = new QFormLayout;
    form->addRow(tr("Force column [N]"), m_force);
    form->addRow(tr("Response column"), m_response);
    form->addRow(tr("Response measures"), m_responseType);
    form->addRow(tr("Trigger level [N]"), m_trigger);
    form->addRow(tr("Exponential window τ [ms]"), m_expTau);
    form->addRow(tr("Double hit"), m_doubleHit);
    form->addRow(tr("Modes to fit per direction"), m_modes);
    auto* computeButton = new QPushButton(tr("Compute"), this);
    computeButton->setObjectName("tapCompute");
    auto* save = new QPushButton(tr("Save FRF…"), this);
    auto* useX = new QPushButton(tr("Use as x FRF"), this);
    useX->setObjectName("tapUseX");
    auto* useY = new QPushButton(tr("Use as y FRF"), this);
    useY->setObjectName("tapUseY");
    auto* useXY = new QPushButton(tr("Use for x and y"), this);
    useXY->setObjectName("tapUseXY");
    m_plot = new widgets::BodePlot(this);
    m_plot->setObjectName("tapPlot");
    m_plot->setMinimumHeight(220);
    m_summary = new QLabel(this);
    m_summary->setObjectName("tapSummary");
    m_summary->setWordWrap(true);
    m_error = new QLabel(this);
    m_error->setObjectName("tapError");
    m_error->setStyleSheet("color: #b00020;");
    m_error->setWordWrap(true);
    m_error->setVisible(false);

    auto* recButtons = new QVBoxLayout;
    recButtons->addWidget(add);
    recButtons->addWidget(remove);
    recButtons->addStretch();
    auto* top = new QHBoxLayout;
    top->addWidget(m_records, 1);
    top->addLayout(recButtons);
    top->addLayout(form, 1);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(computeButton);
    buttons->addWidget(save);
    buttons->addStretch();
    buttons->addWidget(useX);
    buttons->addWidget(useY);
    buttons->addWidget(useXY);
    auto* lay = new QVBoxLayout(this);
    lay->addLayout(top);
    lay->addLayout(buttons);
    lay->addWidget(m_plot, 1);
    lay->addWidget(m_summary);
    lay->addWidget(m_error);

    connect(add, &QPushButton::clicked, this, [this] {
        const QStringList paths = QFileDialog::getOpenFileNames(
            this, tr("Impact records"), QString(), tr("Records (*.csv *.txt *.log *.unv *.uff);;All files (*)"));
        for (const auto& p : paths)
            addRecord(p);
    });
    connect(remove, &QPushButton::clicked, this, [this] { delete m_records->takeItem(m_records->currentRow()); });
    connect(computeButton, &QPushButton::clicked, this, [this] { compute(); });
    connect(save, &QPushButton::clicked, this, [this] {
        const QString p = QFileDialog::getSaveFileName(this, tr("Save receptance"), QString(), tr("FRF CSV (*.csv)"));
        if (!p.isEmpty())
            saveFrf(p);
    });
    connect(useX, &QPushButton::clicked, this, [this] { useAsToolFrf("x"); });
    connect(useY, &QPushButton::clicked, this, [this] { useAsToolFrf("y"); });
    connect(useXY, &QPushButton::clicked, this, [this] { useAsToolFrf("xy"); });
}

void MachiningTapPage::setError(const QString& text)
{
    m_error->setText(text);
    m_error->setVisible(!text.isEmpty());
}

void MachiningTapPage::fillColumns(const QStringList& names)
{
    for (auto* box : {m_force, m_response}) {
        const QString keep = box->currentText();
        box->clear();
        box->addItems(names);
        if (names.contains(keep))
            box->setCurrentText(keep);
    }
    for (const auto& n : names) {
        if (n.contains("force", Qt::CaseInsensitive))
            m_force->setCurrentText(n);
        if (n.contains("acc", Qt::CaseInsensitive) || n.contains("vel", Qt::CaseInsensitive) ||
            n.contains("disp", Qt::CaseInsensitive))
            m_response->setCurrentText(n);
    }
}

bool MachiningTapPage::addRecord(const QString& path)
{
    auto rec = loadRecord(path);
    if (!rec) {
        setError(QString::fromStdString(rec.error().detail));
        return false;
    }
    setError({});
    m_records->addItem(path);
    if (m_records->count() == 1) {
        QStringList names;
        for (const auto& c : rec->first.channels)
            names << QString::fromStdString(c.name);
        fillColumns(names);
    }
    return true;
}

bool MachiningTapPage::compute()
{
    m_result.reset();
    m_plot->clear();
    m_summary->clear();
    if (m_records->count() == 0) {
        setError(tr("Add at least one impact record."));
        return false;
    }
    std::vector<dsp::ImpactRecord> recs;
    double fs = 0.0;
    for (int i = 0; i < m_records->count(); ++i) {
        const QString path = m_records->item(i)->text();
        auto rec = loadRecord(path);
        if (!rec) {
            setError(QString::fromStdString(rec.error().detail));
            return false;
        }
        const auto* f = rec->first.channel(m_force->currentText().toStdString());
        const auto* x = rec->first.channel(m_response->currentText().toStdString());
        if (!f || !x) {
            setError(tr("%1: no column '%2'").arg(path, f ? m_response->currentText() : m_force->currentText()));
            return false;
        }
        if (i > 0 && std::abs(rec->second - fs) > 1e-6 * fs) {
            setError(tr("%1: sampled at %2 Hz, the first record at %3 Hz").arg(path).arg(rec->second).arg(fs));
            return false;
        }
        fs = rec->second;
        recs.push_back({path.toStdString(), f->data, x->data});
    }
    dsp::ImpactOptions o;
    o.fsHz = fs;
    o.response = static_cast<dsp::MotionQuantity>(m_responseType->currentData().toInt());
    o.output = dsp::MotionQuantity::Displacement; // the tool model needs receptance
    o.doubleHit = static_cast<dsp::DoubleHitPolicy>(m_doubleHit->currentData().toInt());
    for (auto [edit, dst, scale] :
         {std::tuple{m_trigger, &o.triggerLevelN, 1.0}, std::tuple{m_expTau, &o.expTauS, 1e-3}}) {
        if (edit->text().trimmed().isEmpty())
            continue;
        const auto v = machiningNumber(edit->text());
        if (!v || *v <= 0.0) {
            setError(tr("'%1' is not a positive number").arg(edit->text()));
            return false;
        }
        *dst = *v * scale;
    }
    auto r = dsp::impactFrf(recs, o);
    if (!r) {
        setError(QString::fromStdString(r.error().detail));
        return false;
    }
    setError({});
    m_result = std::move(r).value();
    m_plot->addResponse(m_result->frf, tr("receptance"));
    m_plot->setFrequencyRange(10.0, std::min(fs / 2.0, 2.0 * m_result->forceBandHz));
    double peak = 0.0, peakHz = 0.0;
    for (std::size_t i = 0; i < m_result->frf.size(); ++i) {
        if (m_result->frf.valid[i] && std::abs(m_result->frf.h[i]) > peak) {
            peak = std::abs(m_result->frf.h[i]);
            peakHz = m_result->frf.freqHz[i];
        }
    }
    QLocale loc;
    loc.setNumberOptions(QLocale::OmitGroupSeparator);
    QStringList lines;
    lines << tr("%1 hit(s) averaged, %2 dropped; block %3 s; valid to %4 Hz (force spectrum within 40 dB).")
                 .arg(m_result->used)
                 .arg(m_result->hits.size() - m_result->used)
                 .arg(loc.toString(m_result->blockS, 'g', 4))
                 .arg(loc.toString(m_result->forceBandHz, 'f', 0));
    lines << tr("Largest receptance %1 µm/N at %2 Hz.")
                 .arg(loc.toString(peak * 1e6, 'g', 4))
                 .arg(loc.toString(peakHz, 'f', 1));
    if (m_result->used < 2)
        lines << tr("One hit: no coherence. Average several hits to see how repeatable the measurement is.");
    for (const auto& n : m_result->notes)
        lines << QString::fromStdString(n);
    m_summary->setText(lines.join("\n"));
    return true;
}

bool MachiningTapPage::saveFrf(const QString& path)
{
    if (!m_result) {
        setError(tr("Compute the receptance first."));
        return false;
    }
    if (auto st = io::writeFrfCsvFile(path.toStdString(), m_result->frf); !st) {
        setError(QString::fromStdString(st.error().detail));
        return false;
    }
    return true;
}

bool MachiningTapPage::useAsToolFrf(const QString& direction)
{
    if (!m_result && !compute())
        return false;
    const QString path = m_dir.filePath(QString("tap-%1.csv").arg(++m_saved));
    if (!saveFrf(path))
        return false;
    if (direction.contains('x'))
        m_xPath = path;
    if (direction.contains('y'))
        m_yPath = path;
    if (m_xPath.isEmpty() || m_yPath.isEmpty()) {
        m_summary->setText(m_summary->text() + "\n" +
                           tr("Now the other direction's tap test (or use this one for both)."));
        return true;
    }
    if (!m_tool.fitToolFrfs(m_xPath, m_yPath, m_modes->value())) {
        setError(m_tool.errorLabel()->text());
        return false;
    }
    // the modes were fitted to H(s + σ): remove the window's damping per direction
    auto tool = m_tool.tool();
    if (!tool) {
        setError(QString::fromStdString(tool.error().detail));
        return false;
    }
    for (const auto& [frfPath, modes] :
         {std::pair{m_xPath, &tool.value().modesX}, std::pair{m_yPath, &tool.value().modesY}}) {
        auto frf = io::readFrfCsvFile(frfPath.toStdString());
        if (!frf) {
            setError(QString::fromStdString(frf.error().detail));
            return false;
        }
        if (auto st = machining::removeExponentialWindow(*modes, *frf); !st) {
            setError(QString::fromStdString(st.error().detail));
            return false;
        }
    }
    m_tool.setTool(*tool);
    setError({});
    if (wizard())
        wizard()->back(); // show the fitted modes on the tool page
    return true;
}

int MachiningTapPage::nextId() const
{
    return MachiningWizard::CutId;
}

} // namespace gui
} // namespace axistune
