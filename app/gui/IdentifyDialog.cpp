// SPDX-License-Identifier: GPL-3.0-or-later
// Identify from motion: the GUI of core/ident (docs/identification.md "The dialog").
#include "app/gui/IdentifyDialog.h"

#include "app/gui/WidgetUtil.h"
#include "core/ident/IdentificationInput.h"
#include "core/ident/IdentificationJson.h"
#include "core/io/AtomicFile.h"
#include "core/io/CaptureCsv.h"
#include "core/model/Constants.h"
#include "core/model/InputLimits.h"
#include "widgets/TimeTracePlot.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

namespace axistune {
namespace gui {
namespace {

QString num(double v)
{
    return std::isfinite(v) ? QString::number(v, 'g', 6) : QStringLiteral("–");
}

void fillColumns(QComboBox* box, const model::Capture& cap, bool withNone)
{
    const QString keep = box->currentText();
    box->clear();
    if (withNone)
        box->addItem(QString());
    for (const auto& c : cap.channels)
        box->addItem(QString::fromStdString(c.name));
    if (const int i = box->findText(keep); i >= 0)
        box->setCurrentIndex(i);
}

QLineEdit* fileRow(QWidget* parent, QFormLayout* form, const QString& label, const QString& buttonText,
                   const std::function<void()>& browse)
{
    auto* row = new QWidget(parent);
    auto* h = new QHBoxLayout(row);
    h->setContentsMargins(0, 0, 0, 0);
    auto* edit = new QLineEdit(row);
    edit->setReadOnly(true);
    auto* button = new QPushButton(buttonText, row);
    QObject::connect(button, &QPushButton::clicked, parent, browse);
    h->addWidget(edit, 1);
    h->addWidget(button);
    form->addRow(label, row);
    return edit;
}

} // namespace

IdentifyDialog::IdentifyDialog(QWidget* parent) : QDialog(parent)
{
    setObjectName("identifyDialog");
    setWindowTitle(tr("Identify inertia and friction from motion"));
    auto* lay = new QVBoxLayout(this);
    auto* top = new QHBoxLayout;
    top->addWidget(buildInputs(), 3);
    top->addWidget(buildController(), 2);
    lay->addLayout(top);

    auto* run = new QPushButton(tr("Identify"), this);
    run->setObjectName("identifyRun");
    connect(run, &QPushButton::clicked, this, [this] { identify(); });
    m_save = new QPushButton(tr("Save result…"), this);
    m_save->setEnabled(false);
    connect(m_save, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Identification result"),
                                                          QStringLiteral("identification.json"), tr("JSON (*.json)"));
        QString error;
        if (!path.isEmpty() && !saveTo(path, &error))
            setStatus(error, true);
    });
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(run);
    buttons->addWidget(m_save);
    buttons->addStretch(1);
    lay->addLayout(buttons);

    m_status = new QLabel(this);
    m_status->setObjectName("identifyStatus");
    m_status->setWordWrap(true);
    lay->addWidget(m_status);
    m_table = makeTable(this, {tr("Parameter"), tr("Value"), tr("Std. deviation"), tr("Std. dev. [%]"), tr("Unit")},
                        "identifyTable");
    m_table->setMinimumHeight(150);
    lay->addWidget(m_table);
    m_validation = new QLabel(this);
    m_validation->setObjectName("identifyValidation");
    m_validation->setWordWrap(true);
    lay->addWidget(m_validation);
    m_plot = new widgets::TimeTracePlot(this);
    m_plot->setMinimumHeight(340);
    lay->addWidget(m_plot, 1);
    auto* close = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(close, &QDialogButtonBox::rejected, this, &QDialog::reject);
    lay->addWidget(close);
    resize(1100, 960);
}

QWidget* IdentifyDialog::buildInputs()
{
    auto* box = new QGroupBox(tr("Records"), this);
    auto* form = new QFormLayout(box);
    m_estFile = fileRow(box, form, tr("Estimation record:"), tr("Browse…"), [this] {
        const QString p =
            QFileDialog::getOpenFileName(this, tr("Estimation record"), {}, tr("Capture CSV (*.csv);;All files (*)"));
        if (!p.isEmpty())
            loadEstimation(p);
    });
    m_position = new QComboBox(box);
    m_position->setObjectName("identifyPosition");
    m_force = new QComboBox(box);
    m_force->setObjectName("identifyForce");
    m_unit = new QComboBox(box);
    m_unit->addItem(tr("m (linear axis)"), QStringLiteral("m"));
    m_unit->addItem(tr("rad (rotary axis)"), QStringLiteral("rad"));
    m_forceScale = spin(box, 1e-9, 1e9, 1.0, 8, QString(), "identifyForceScale");
    m_forceScale->setToolTip(tr("N (linear) or N·m (rotary) per unit of the force column, e.g. the drive gain in N/V"));
    m_cutoff = spin(box, 1.0, 10000.0, 100.0, 1, tr(" Hz"), "identifyCutoff");
    m_cutoff->setToolTip(
        tr("Zero-phase low-pass on the position before differentiating; the decimation follows from it"));
    m_asymmetric = new QCheckBox(tr("Also per-direction friction"), box);
    form->addRow(tr("Position column:"), m_position);
    form->addRow(tr("Position unit:"), m_unit);
    form->addRow(tr("Force column:"), m_force);
    form->addRow(tr("Force scale:"), m_forceScale);
    form->addRow(tr("Low-pass cutoff:"), m_cutoff);
    form->addRow(QString(), m_asymmetric);
    m_valFile = fileRow(box, form, tr("Validation record (optional):"), tr("Browse…"), [this] {
        const QString p =
            QFileDialog::getOpenFileName(this, tr("Validation record"), {}, tr("Capture CSV (*.csv);;All files (*)"));
        if (!p.isEmpty())
            loadValidation(p);
    });
    m_reference = new QComboBox(box);
    m_reference->setObjectName("identifyReference");
    m_extra = new QComboBox(box);
    m_extra->setObjectName("identifyExtra");
    m_extra->setToolTip(tr("A column added to the controller output, e.g. force pulses (empty: none)"));
    form->addRow(tr("Reference column:"), m_reference);
    form->addRow(tr("Added to the command:"), m_extra);
    return box;
}

QWidget* IdentifyDialog::buildController()
{
    auto* box = new QGroupBox(tr("Controller of the validation record"), this);
    auto* form = new QFormLayout(box);
    auto* note = new QLabel(tr("u = sat(kv·(kp·(r − q) − v)), v from a two-tap average of q and a backward difference; "
                               "force = scale·u"),
                            box);
    note->setWordWrap(true);
    form->addRow(note);
    m_kp = spin(box, 0.0, 1e5, 0.0, 3, tr(" 1/s"), "identifyKp");
    m_kv = spin(box, 0.0, 1e9, 0.0, 4, QString(), "identifyKv");
    m_saturation = spin(box, 0.0, 1e9, 0.0, 3, QString(), "identifySaturation");
    m_delay = new QSpinBox(box);
    m_delay->setRange(0, 100);
    m_delay->setSuffix(tr(" samples"));
    m_ctrlScale = spin(box, 0.0, 1e9, 0.0, 8, QString(), "identifyCtrlScale");
    m_ctrlScale->setToolTip(tr("0: the force scale of the estimation record"));
    form->addRow(tr("Position gain kp:"), m_kp);
    form->addRow(tr("Velocity gain kv:"), m_kv);
    form->addRow(tr("Saturation ±:"), m_saturation);
    form->addRow(tr("Delay:"), m_delay);
    form->addRow(tr("Force per command unit:"), m_ctrlScale);
    auto* load = new QPushButton(tr("Load controller file…"), box);
    connect(load, &QPushButton::clicked, this, [this] {
        const QString p = QFileDialog::getOpenFileName(this, tr("Controller"), {}, tr("JSON (*.json)"));
        if (!p.isEmpty())
            loadController(p);
    });
    form->addRow(load);
    return box;
}

std::optional<model::Capture> IdentifyDialog::readCapture(const QString& path)
{
    auto cap = io::readCaptureCsvFile(path.toStdString());
    if (!cap) {
        setStatus(QString::fromStdString(cap.error().detail), true);
        return std::nullopt;
    }
    return std::move(cap).value();
}

bool IdentifyDialog::loadEstimation(const QString& path)
{
    m_estCapture = readCapture(path);
    if (!m_estCapture)
        return false;
    m_estFile->setText(path);
    fillColumns(m_position, *m_estCapture, false);
    fillColumns(m_force, *m_estCapture, false);
    setStatus(tr("%1: %2 samples, %3 columns").arg(path).arg(m_estCapture->size()).arg(m_estCapture->channels.size()),
              false);
    return true;
}

bool IdentifyDialog::loadValidation(const QString& path)
{
    m_valCapture = readCapture(path);
    if (!m_valCapture)
        return false;
    m_valFile->setText(path);
    fillColumns(m_reference, *m_valCapture, false);
    fillColumns(m_extra, *m_valCapture, true);
    return true;
}

void IdentifyDialog::selectColumns(const QString& position, const QString& force, const QString& reference,
                                   const QString& extra)
{
    for (const auto& [box, name] : {std::pair{m_position, position}, std::pair{m_force, force},
                                    std::pair{m_reference, reference}, std::pair{m_extra, extra}}) {
        if (const int i = box->findText(name); i >= 0)
            box->setCurrentIndex(i);
    }
}

bool IdentifyDialog::loadController(const QString& path)
{
    // Through the input limits (docs/robustness.md): a FIFO, device or directory is refused, not read.
    auto j = model::readJsonFile(path.toStdString());
    auto c = j ? ident::controllerFromJson(*j, model::displayPath(path.toStdString()))
               : Result<ident::PositionController>(j.error());
    if (!c) {
        setStatus(QString::fromStdString(c.error().detail), true);
        return false;
    }
    m_kp->setValue(c->kpPerS);
    m_kv->setValue(c->kv);
    m_saturation->setValue(c->saturation);
    m_delay->setValue(c->delaySamples);
    m_ctrlScale->setValue(c->forceScale);
    return true;
}

bool IdentifyDialog::identify()
{
    m_result.reset();
    m_save->setEnabled(false);
    m_table->setRowCount(0);
    m_validation->clear();
    m_plot->clear();
    if (!m_estCapture) {
        setStatus(tr("Load the estimation record first."), true);
        return false;
    }
    ident::CaptureColumns cols;
    cols.position = m_position->currentText().toStdString();
    cols.force = m_force->currentText().toStdString();
    cols.forceScale = m_forceScale->value();
    cols.reference = m_reference->currentText().toStdString();
    cols.extra = m_extra->currentText().toStdString();
    const auto motion =
        m_unit->currentData().toString() == QLatin1String("m") ? ident::AxisMotion::Linear : ident::AxisMotion::Rotary;
    const std::string src = m_estFile->text().toStdString();
    ident::IdentificationOptions opt;
    opt.cutoffHz = m_cutoff->value();
    opt.asymmetric = m_asymmetric->isChecked();
    auto rec = ident::motionRecordFromCapture(*m_estCapture, src, cols);
    auto res = rec ? ident::identifyRigidBody(*rec, opt) : Result<ident::IdentificationResult>(rec.error());
    if (!res) {
        setStatus(tr("Not identified: %1").arg(QString::fromStdString(res.error().detail)), true);
        return false;
    }
    showResult(*res, motion);
    nlohmann::json j = ident::identificationToJson(*res, motion);
    j["source"] = {{"file", src}, {"position", cols.position}, {"force", cols.force}, {"force_scale", cols.forceScale}};
    j["method"]["cutoff_Hz"] = opt.cutoffHz;
    j["validation"] = nlohmann::json::array();
    if (m_valCapture) {
        ident::PositionController c{m_kp->value(), m_kv->value(), m_saturation->value(), m_delay->value(),
                                    m_ctrlScale->value() > 0.0 ? m_ctrlScale->value() : m_forceScale->value()};
        auto vrec = ident::validationRecordFromCapture(*m_valCapture, m_valFile->text().toStdString(), cols);
        const auto model = ident::RigidBodyModel::symmetric(res->inertia.value, res->viscous.value, res->coulomb.value,
                                                            res->offset.value);
        auto v = vrec ? ident::validateClosedLoop(model, c, *vrec, opt.cutoffHz,
                                                  static_cast<std::size_t>(res->borderSamples))
                      : Result<ident::ValidationResult>(vrec.error());
        if (!v) {
            m_validation->setText(tr("Validation not possible: %1").arg(QString::fromStdString(v.error().detail)));
        } else {
            showValidation(*vrec, *v, motion);
            auto vj = ident::validationToJson(*v);
            vj["file"] = m_valFile->text().toStdString();
            vj["controller"] = ident::controllerToJson(c);
            j["validation"].push_back(vj);
        }
    }
    m_result = j;
    m_save->setEnabled(true);
    return true;
}

void IdentifyDialog::showResult(const ident::IdentificationResult& r, ident::AxisMotion motion)
{
    const auto u = ident::unitsJson(motion);
    auto unit = [&](const char* k) { return QString::fromStdString(u[k].get<std::string>()); };
    auto row = [&](const QString& name, const ident::Estimate& e, const char* k) {
        addRow(m_table, {name, num(e.value), num(e.std), num(e.stdPct()), unit(k)});
    };
    row(tr("Inertia"), r.inertia, "inertia");
    row(tr("Viscous friction"), r.viscous, "viscous");
    row(tr("Coulomb friction"), r.coulomb, "coulomb");
    row(tr("Offset"), r.offset, "offset");
    if (r.asymmetric) {
        row(tr("Viscous friction, forward"), r.asymmetric->viscousPositive, "viscous");
        row(tr("Viscous friction, backward"), r.asymmetric->viscousNegative, "viscous");
        row(tr("Coulomb friction, forward"), r.asymmetric->coulombPositive, "coulomb");
        row(tr("Coulomb friction, backward"), r.asymmetric->coulombNegative, "coulomb");
    }
    m_table->resizeColumnsToContents();
    setStatus(
        tr("Identified from %1 equations (decimation %2, %3 Hz): condition number %4 (scaled %5), residual %6 %7 rms "
           "(%8 % of the force)")
            .arg(r.rows)
            .arg(r.decimation)
            .arg(num(r.sampleRateHz))
            .arg(num(r.condition), num(r.scaledCondition), num(r.residualRms), unit("force"), num(r.residualRelPct)),
        false);
}

void IdentifyDialog::showValidation(const ident::ValidationRecord& rec, const ident::ValidationResult& v,
                                    ident::AxisMotion motion)
{
    const bool linear = motion == ident::AxisMotion::Linear;
    // Linear: positions in mm and the error in µm; rotary: rad and the error in degrees (own strips).
    const double posScale = linear ? 1e3 : 1.0, errScale = linear ? 1e6 : model::kDegPerRad;
    const QString posUnit = linear ? QStringLiteral("mm") : QStringLiteral("rad");
    const QString errUnit = linear ? QStringLiteral("um") : QStringLiteral("deg");
    std::vector<double> t(rec.position.size()), q(t.size()), qs(t.size()), e(t.size());
    for (std::size_t k = 0; k < t.size(); ++k) {
        t[k] = static_cast<double>(k) * rec.periodS;
        q[k] = rec.position[k] * posScale;
        qs[k] = v.simulatedPosition[k] * posScale;
        e[k] = (rec.position[k] - v.simulatedPosition[k]) * errScale;
    }
    m_plot->addSeries(tr("measured position"), t, q, posUnit, QColor(0, 90, 200));
    m_plot->addSeries(tr("simulated position"), t, qs, posUnit, QColor(220, 80, 0), Qt::DashLine);
    m_plot->addSeries(tr("position error"), t, e, errUnit, QColor(40, 140, 40));
    m_plot->rescale();
    const QString u = linear ? QStringLiteral("m") : QStringLiteral("rad");
    m_validation->setText(
        tr("Validation on %1: position error %2 %3 rms, %4 %3 max, %5 % of the motion's rms; benchmark "
           "errors: position %6 %, force %7 %")
            .arg(m_valFile->text(), num(v.positionErrorRms), u, num(v.positionErrorMax),
                 num(v.positionErrorPctOfMotion), num(v.benchmarkPositionPct), num(v.benchmarkForcePct)));
}

bool IdentifyDialog::saveTo(const QString& path, QString* error) const
{
    if (!m_result) {
        *error = tr("Nothing to save: run the identification first.");
        return false;
    }
    // No NaN, Inf or null in the file (dumpResultJson), written to a temporary file and renamed.
    auto text = model::dumpResultJson(*m_result);
    if (!text) {
        *error = QString::fromStdString(text.error().detail);
        return false;
    }
    if (auto st = io::writeFileAtomic(QFile::encodeName(path).toStdString(), *text + "\n"); !st) {
        *error = tr("%1 cannot be written: %2").arg(path, QString::fromStdString(st.error().detail));
        return false;
    }
    return true;
}

QString IdentifyDialog::statusText() const
{
    return m_status->text();
}
QString IdentifyDialog::validationText() const
{
    return m_validation->text();
}

void IdentifyDialog::setStatus(const QString& text, bool error)
{
    m_status->setText(text);
    m_status->setStyleSheet(error ? QStringLiteral("color: #b00000;") : QString());
}

IdentifyDialog* showIdentifyDialog(QWidget* parent)
{
    auto* d = new IdentifyDialog(parent);
    d->setAttribute(Qt::WA_DeleteOnClose);
    d->show();
    return d;
}

} // namespace gui
} // namespace axistune
