// SPDX-License-Identifier: GPL-3.0-or-later
// The machining wizard: registration, the tool and cut pages, saving (docs/wizards/machining.md).
// The maths is in core/machining (lobes by semi-discretization, spec/chatter-stability-and-spindle-speed.md
// §2; the stable-pocket rule §3.0.2; chatter detection, spec/cutting-force-observer-and-chatter-detection.md).
#include "app/gui/MachiningWizard.h"

#include "app/gui/AppContext.h"
#include "app/gui/MachiningAvoidancePage.h"
#include "app/gui/MachiningTapPage.h"
#include "app/gui/WizardRegistry.h"
#include "core/io/FrfCsv.h"
#include "core/machining/MachiningJson.h"
#include "core/machining/ToolModeFit.h"
#include "core/store/SessionRecord.h"

#include <QComboBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>
#include <nlohmann/json.hpp>

namespace axistune {
namespace gui {

namespace {

const WizardRegistrar kRegistrar{
    "machining", QT_TRANSLATE_NOOP("Wizards", "Machining (chatter)…"), 70,
    [](AppContext& ctx, QWidget* parent) -> QWizard* { return new MachiningWizard(ctx, parent); }, false};

QString g(double v, int digits = 6)
{
    return QLocale().toString(v, 'g', digits);
}

void setErrorText(QLabel* label, const QString& text)
{
    label->setText(text);
    label->setVisible(!text.isEmpty());
}

} // namespace

std::optional<double> machiningNumber(const QString& text)
{
    bool ok = false;
    const QString t = text.trimmed();
    double v = QLocale().toDouble(t, &ok);
    if (!ok)
        v = QLocale::c().toDouble(t, &ok);
    if (!ok || !std::isfinite(v))
        return std::nullopt;
    return v;
}

// ---------------------------------------------------------------------------------------------- tool page

MachiningToolPage::MachiningToolPage(QWidget* parent) : QWizardPage(parent)
{
    setTitle(tr("Tool"));
    setSubTitle(tr("Modal parameters of the tool tip per direction (x = feed direction). Modes of one direction "
                   "add their compliances."));
    m_table = new QTableWidget(0, 4, this);
    m_table->setObjectName("machToolTable");
    m_table->setHorizontalHeaderLabels(
        {tr("Direction"), tr("Mass [kg]"), tr("Damping [N·s/m]"), tr("Stiffness [N/m]")});
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_table->verticalHeader()->setVisible(false);
    auto* load = new QPushButton(tr("Load tool.json…"), this);
    load->setObjectName("machLoadTool");
    auto* addX = new QPushButton(tr("Add x mode"), this);
    auto* addY = new QPushButton(tr("Add y mode"), this);
    auto* remove = new QPushButton(tr("Remove mode"), this);
    m_error = new QLabel(this);
    m_error->setObjectName("machToolError");
    m_error->setStyleSheet("color: #b00020;");
    m_error->setWordWrap(true);
    m_derived = new QLabel(this);
    m_derived->setObjectName("machToolDerived");
    m_derived->setWordWrap(true);

    auto* fit = new QPushButton(tr("Fit to tool-tip FRFs…"), this);
    fit->setObjectName("machiningFitFrf");
    fit->setToolTip(tr("Modes fitted to measured tool-tip receptances (FRF CSV, h in m/N) in x and y"));
    // Fit settings (core/machining/ToolModeFit.h): band and number of modes, automatic when left empty / 0.
    m_fitMin = new QLineEdit(this);
    m_fitMin->setObjectName("machFitMinHz");
    m_fitMin->setPlaceholderText(tr("auto"));
    m_fitMax = new QLineEdit(this);
    m_fitMax->setObjectName("machFitMaxHz");
    m_fitMax->setPlaceholderText(tr("auto"));
    m_fitModes = new QSpinBox(this);
    m_fitModes->setObjectName("machFitModes");
    m_fitModes->setRange(0, 10);
    m_fitModes->setSpecialValueText(tr("auto"));
    m_fitModes->setToolTip(tr("Modes fitted per direction; auto = one per resonance peak above 25 % of the largest"));
    m_fitMin->setToolTip(tr("Fit band lower edge; empty = chosen from the resonance peaks"));
    m_fitMax->setToolTip(tr("Fit band upper edge; empty = chosen from the resonance peaks"));
    m_fitStatus = new QLabel(this);
    m_fitStatus->setObjectName("machFitStatus");
    m_fitStatus->setWordWrap(true);
    auto* fitRow = new QHBoxLayout;
    fitRow->addWidget(new QLabel(tr("FRF fit band [Hz]"), this));
    fitRow->addWidget(m_fitMin);
    fitRow->addWidget(new QLabel(tr("to"), this));
    fitRow->addWidget(m_fitMax);
    fitRow->addSpacing(12);
    fitRow->addWidget(new QLabel(tr("Modes per direction"), this));
    fitRow->addWidget(m_fitModes);
    fitRow->addStretch();
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(load);
    buttons->addWidget(fit);
    buttons->addStretch();
    buttons->addWidget(addX);
    buttons->addWidget(addY);
    buttons->addWidget(remove);
    auto* lay = new QVBoxLayout(this);
    lay->addWidget(m_table, 1);
    lay->addLayout(buttons);
    lay->addLayout(fitRow);
    lay->addWidget(m_fitStatus);
    lay->addWidget(m_derived);
    lay->addWidget(m_error);

    // Table 1 of seed 000 (spec/chatter-stability-and-spindle-speed.md §1.6) as the example to start from.
    const machining::ModalParameters table1{0.40, 83.0, 30.1e6};
    setTool({{table1}, {table1}});
    m_source = tr("entered");

    connect(m_table, &QTableWidget::itemChanged, this, [this] {
        m_source = tr("entered");
        m_fitError.clear();
        revalidate();
    });
    connect(load, &QPushButton::clicked, this, [this] {
        const QString path =
            QFileDialog::getOpenFileName(this, tr("Tool data"), QString(), tr("Tool JSON (*.json);;All files (*)"));
        if (!path.isEmpty())
            loadToolFile(path);
    });
    connect(fit, &QPushButton::clicked, this, [this] {
        const QString x = QFileDialog::getOpenFileName(this, tr("Tool-tip FRF in x (feed direction)"), QString(),
                                                       tr("FRF CSV (*.csv);;All files (*)"));
        if (x.isEmpty())
            return;
        const QString y = QFileDialog::getOpenFileName(this, tr("Tool-tip FRF in y"), QString(),
                                                       tr("FRF CSV (*.csv);;All files (*)"));
        if (!y.isEmpty())
            fitToolFrfs(x, y);
    });
    connect(addX, &QPushButton::clicked, this, [this] {
        addRow("x", {0.4, 80.0, 3.0e7});
        m_fitError.clear();
        revalidate();
    });
    connect(addY, &QPushButton::clicked, this, [this] {
        addRow("y", {0.4, 80.0, 3.0e7});
        m_fitError.clear();
        revalidate();
    });
    connect(remove, &QPushButton::clicked, this, [this] {
        const int r = m_table->currentRow();
        if (r >= 0)
            m_table->removeRow(r);
        revalidate();
    });
}

void MachiningToolPage::addRow(const QString& dir, const machining::ModalParameters& m)
{
    QSignalBlocker block(m_table);
    const int r = m_table->rowCount();
    m_table->insertRow(r);
    auto* d = new QTableWidgetItem(dir);
    d->setFlags(d->flags() & ~Qt::ItemIsEditable);
    m_table->setItem(r, 0, d);
    m_table->setItem(r, 1, new QTableWidgetItem(g(m.massKg)));
    m_table->setItem(r, 2, new QTableWidgetItem(g(m.dampingNsPerM)));
    m_table->setItem(r, 3, new QTableWidgetItem(g(m.stiffnessNPerM)));
}

void MachiningToolPage::setTool(const machining::ToolModes& tool)
{
    {
        QSignalBlocker block(m_table);
        m_table->setRowCount(0);
    }
    for (const auto& m : tool.modesX)
        addRow("x", m);
    for (const auto& m : tool.modesY)
        addRow("y", m);
    revalidate();
}

bool MachiningToolPage::loadToolFile(const QString& path)
{
    auto tool = machining::readToolJsonFile(path.toStdString());
    if (!tool) {
        setErrorText(m_error, QString::fromStdString(tool.error().detail));
        return false;
    }
    m_fitError.clear();
    setTool(*tool);
    m_source = path;
    return true;
}

bool MachiningToolPage::fitToolFrfs(const QString& xPath, const QString& yPath, int modesPerDirection)
{
    // Modes per direction fitted to the receptance (core/machining/ToolModeFit.h: resonance peaks, automatic
    // or given band, √|H|-weighted least squares with residual terms, quality gate). A refused fit empties
    // the table, so no lobes are computed from it, and shows the reason.
    auto refuse = [this](const QString& reason) {
        m_fitError = reason;
        m_fitStatus->clear();
        setTool({});
        m_source = tr("fit refused");
        return false;
    };
    machining::ToolModeFitOptions opt;
    opt.modes = modesPerDirection >= 0 ? modesPerDirection : m_fitModes->value();
    for (auto [edit, out] : {std::pair{m_fitMin, &opt.minHz}, std::pair{m_fitMax, &opt.maxHz}}) {
        if (edit->text().trimmed().isEmpty())
            continue;
        auto v = machiningNumber(edit->text());
        if (!v)
            return refuse(tr("FRF fit band: '%1' is not a number").arg(edit->text()));
        *out = *v;
    }
    machining::ToolModes tool;
    QStringList quality;
    for (const auto& [path, modes] : {std::pair{xPath, &tool.modesX}, std::pair{yPath, &tool.modesY}}) {
        auto frf = io::readFrfCsvFile(path.toStdString());
        if (!frf)
            return refuse(QString::fromStdString(frf.error().detail));
        auto fit = machining::fitToolModes(*frf, opt);
        if (!fit)
            return refuse(path + ": " + QString::fromStdString(fit.error().detail));
        *modes = fit->modes;
        quality << tr("%1: %2 mode(s), band %3–%4 Hz (%5), weighted residual %6 %")
                       .arg(modes == &tool.modesX ? "x" : "y")
                       .arg(fit->modes.size())
                       .arg(g(fit->bandMinHz, 5), g(fit->bandMaxHz, 5))
                       .arg(fit->automaticBand ? tr("automatic") : tr("given"))
                       .arg(g(100.0 * fit->residualRatio, 3));
    }
    m_fitError.clear();
    setTool(tool);
    m_fitStatus->setText(quality.join("\n"));
    m_source = tr("fitted to %1 and %2").arg(xPath, yPath);
    return true;
}

Result<machining::ToolModes> MachiningToolPage::tool() const
{
    machining::ToolModes t;
    const char* keys[] = {"", "mass_kg", "damping_Ns_per_m", "stiffness_N_per_m"};
    for (int r = 0; r < m_table->rowCount(); ++r) {
        double v[4] = {0, 0, 0, 0};
        for (int c = 1; c < 4; ++c) {
            const auto* item = m_table->item(r, c);
            auto n = machiningNumber(item ? item->text() : QString());
            if (!n)
                return makeError(ErrorCode::BadInput, tr("row %1, %2: not a number")
                                                              .arg(r + 1)
                                                              .arg(m_table->horizontalHeaderItem(c)->text())
                                                              .toStdString() +
                                                          " (" + keys[c] + ")");
            v[c] = *n;
        }
        const machining::ModalParameters m{v[1], v[2], v[3]};
        (m_table->item(r, 0)->text() == "x" ? t.modesX : t.modesY).push_back(m);
    }
    if (auto st = machining::validateTool(t); !st)
        return st.error();
    return t;
}

void MachiningToolPage::revalidate()
{
    auto t = tool();
    if (!m_fitError.isEmpty()) {
        setErrorText(m_error, m_fitError);
        m_derived->clear();
    } else if (!t) {
        setErrorText(m_error, QString::fromStdString(t.error().detail));
        m_derived->clear();
    } else {
        setErrorText(m_error, {});
        QStringList lines;
        for (const auto* modes : {&t->modesX, &t->modesY})
            for (const auto& m : *modes)
                lines << tr("%1: natural frequency %2 Hz, damping ratio %3 %")
                             .arg(modes == &t->modesX ? "x" : "y")
                             .arg(g(machining::naturalFrequencyHz(m), 5))
                             .arg(g(100.0 * machining::dampingRatio(m), 3));
        m_derived->setText(lines.join("\n"));
    }
    emit completeChanged();
}

bool MachiningToolPage::isComplete() const
{
    return tool().ok();
}

// ----------------------------------------------------------------------------------------------- cut page

MachiningCutPage::MachiningCutPage(QWidget* parent) : QWizardPage(parent)
{
    setTitle(tr("Cutting data"));
    setSubTitle(tr("The cutter, the material's specific cutting forces, the engagement and the current operating "
                   "point."));
    auto mk = [this](const char* name, const QString& value) {
        auto* e = new QLineEdit(value, this);
        e->setObjectName(name);
        connect(e, &QLineEdit::textChanged, this, &MachiningCutPage::revalidate);
        return e;
    };
    m_teeth = new QSpinBox(this);
    m_teeth->setObjectName("machTeeth");
    m_teeth->setRange(0, 64);
    m_teeth->setValue(4);
    connect(m_teeth, &QSpinBox::valueChanged, this, &MachiningCutPage::revalidate);
    // Table 1(c) and Table 2 of seed 000: A6063, a_e = 7 mm of D = 12 mm, down milling.
    m_kt = mk("machKt", g(0.980));
    m_kr = mk("machKr", g(0.294));
    m_immersion = mk("machImmersion", g(7.0 / 12.0, 4));
    m_milling = new QComboBox(this);
    m_milling->setObjectName("machMilling");
    m_milling->addItem(tr("Down milling (climb)"));
    m_milling->addItem(tr("Up milling (conventional)"));
    connect(m_milling, &QComboBox::currentIndexChanged, this, &MachiningCutPage::revalidate);
    m_rpm = mk("machRpm", g(2800));
    m_depth = mk("machDepth", g(1.5));
    m_rpmMin = mk("machRpmMin", g(2000));
    m_rpmMax = mk("machRpmMax", g(6000));
    m_rpmStep = mk("machRpmStep", g(25));
    m_steps = new QSpinBox(this);
    m_steps->setObjectName("machSteps");
    m_steps->setRange(10, 400);
    m_steps->setValue(80);
    m_steps->setToolTip(tr("Time steps per tooth period of the semi-discretization: 40 gives the limit depth "
                           "within ~8 %, 80 within ~3 %, 160 within ~1 % (docs/machining.md)."));
    m_error = new QLabel(this);
    m_error->setObjectName("machCutError");
    m_error->setStyleSheet("color: #b00020;");
    m_error->setWordWrap(true);
    auto* load = new QPushButton(tr("Load cut.json…"), this);
    connect(load, &QPushButton::clicked, this, [this] {
        const QString path =
            QFileDialog::getOpenFileName(this, tr("Cutting data"), QString(), tr("Cut JSON (*.json);;All files (*)"));
        if (!path.isEmpty())
            loadCutFile(path);
    });

    auto* form = new QFormLayout;
    form->addRow(tr("Teeth"), m_teeth);
    form->addRow(tr("Tangential specific cutting force K_t [GPa = kN/mm²]"), m_kt);
    form->addRow(tr("Radial specific cutting force K_r [GPa = kN/mm²]"), m_kr);
    form->addRow(tr("Radial immersion a_e/D (0–1]"), m_immersion);
    form->addRow(tr("Milling"), m_milling);
    form->addRow(tr("Spindle speed [min⁻¹]"), m_rpm);
    form->addRow(tr("Axial depth of cut [mm]"), m_depth);
    auto* range = new QHBoxLayout;
    range->addWidget(m_rpmMin);
    range->addWidget(new QLabel(tr("to"), this));
    range->addWidget(m_rpmMax);
    range->addWidget(new QLabel(tr("step"), this));
    range->addWidget(m_rpmStep);
    form->addRow(tr("Lobe diagram speeds [min⁻¹]"), range);
    form->addRow(tr("Steps per tooth period"), m_steps);
    auto* lay = new QVBoxLayout(this);
    lay->addLayout(form);
    lay->addWidget(load, 0, Qt::AlignLeft);
    lay->addWidget(m_error);
    lay->addStretch();
    revalidate();
}

bool MachiningCutPage::loadCutFile(const QString& path)
{
    auto cut = machining::readCutJsonFile(path.toStdString());
    if (!cut) {
        setErrorText(m_error, QString::fromStdString(cut.error().detail));
        return false;
    }
    m_teeth->setValue(cut->teeth);
    m_kt->setText(g(cut->ktNPerM2 * 1e-9));
    m_kr->setText(g(cut->krNPerM2 * 1e-9));
    m_immersion->setText(g(cut->radialImmersion));
    m_milling->setCurrentIndex(cut->milling == machining::MillingDirection::Up ? 1 : 0);
    revalidate();
    return true;
}

Result<MachiningCutInputs> MachiningCutPage::inputs() const
{
    MachiningCutInputs in;
    struct Field {
        const QLineEdit* edit;
        QString name;
        double scale;
        double* out;
    };
    const Field fields[] = {
        {m_kt, tr("K_t"), 1e9, &in.cut.ktNPerM2},
        {m_kr, tr("K_r"), 1e9, &in.cut.krNPerM2},
        {m_immersion, tr("radial immersion"), 1.0, &in.cut.radialImmersion},
        {m_rpm, tr("spindle speed"), 1.0, &in.rpm},
        {m_depth, tr("axial depth"), 1e-3, &in.depthM},
        {m_rpmMin, tr("lowest speed"), 1.0, &in.rpmMin},
        {m_rpmMax, tr("highest speed"), 1.0, &in.rpmMax},
        {m_rpmStep, tr("speed step"), 1.0, &in.rpmStep},
    };
    for (const auto& f : fields) {
        auto v = machiningNumber(f.edit->text());
        if (!v)
            return makeError(ErrorCode::BadInput,
                             tr("%1: '%2' is not a number").arg(f.name, f.edit->text()).toStdString());
        *f.out = *v * f.scale;
    }
    in.cut.teeth = m_teeth->value();
    in.cut.milling =
        m_milling->currentIndex() == 1 ? machining::MillingDirection::Up : machining::MillingDirection::Down;
    in.stepsPerPeriod = m_steps->value();
    if (auto st = machining::validateCut(in.cut); !st)
        return st.error();
    if (!(in.rpm > 0.0))
        return makeError(ErrorCode::OutOfRange, tr("spindle speed must be > 0 min⁻¹").toStdString());
    if (!(in.depthM >= 0.0))
        return makeError(ErrorCode::OutOfRange, tr("axial depth must be ≥ 0 mm").toStdString());
    auto grid = machining::rpmGrid(in.rpmMin, in.rpmMax, in.rpmStep);
    if (!grid)
        return makeError(grid.error().code, tr("lobe diagram speeds: ").toStdString() + grid.error().detail);
    if (grid->size() > 2000)
        return makeError(
            ErrorCode::OutOfRange,
            tr("lobe diagram speeds: %1 speeds; at most 2000 (a larger step)").arg(grid->size()).toStdString());
    return in;
}

void MachiningCutPage::revalidate()
{
    auto in = inputs();
    setErrorText(m_error, in ? QString() : QString::fromStdString(in.error().detail));
    emit completeChanged();
}

bool MachiningCutPage::isComplete() const
{
    return inputs().ok();
}

// ---------------------------------------------------------------------------------------------- save page

MachiningSavePage::MachiningSavePage(QWidget* parent) : QWizardPage(parent)
{
    setTitle(tr("Save"));
    setSubTitle(tr("The session (kind \"machining\") stores the tool and cut data, the lobes, the advice, the "
                   "chatter intervals and the analysed cut."));
    m_status = new QLabel(this);
    m_status->setObjectName("machSaveStatus");
    m_status->setWordWrap(true);
    auto* lay = new QVBoxLayout(this);
    lay->addWidget(m_status);
    lay->addStretch();
}

void MachiningSavePage::showSaved(const QString& text)
{
    m_status->setText(text);
}

// -------------------------------------------------------------------------------------------------- wizard

MachiningWizard::MachiningWizard(AppContext& ctx, QWidget* parent) : QWizard(parent), m_ctx(ctx)
{
    setWindowTitle(tr("Machining: stability lobes and chatter"));
    setOption(QWizard::NoBackButtonOnLastPage, true);
    m_tool = new MachiningToolPage(this);
    m_cut = new MachiningCutPage(this);
    m_lobes = new MachiningLobesPage(*m_tool, *m_cut, this);
    m_advice = new MachiningAdvicePage(*m_cut, *m_lobes, this);
    m_analysis = new MachiningAnalysisPage(*m_tool, *m_cut, this);
    m_save = new MachiningSavePage(this);
    setPage(ToolId, m_tool);
    setPage(CutId, m_cut);
    setPage(LobesId, m_lobes);
    setPage(AdviceId, m_advice);
    setPage(AnalysisId, m_analysis);
    setPage(SaveId, m_save);
    m_tap = new MachiningTapPage(*m_tool, this);
    setPage(TapId, m_tap);
    m_avoid = new MachiningAvoidancePage(*m_tool, *m_cut, *m_lobes, this);
    setPage(AvoidId, m_avoid);
    setButtonText(QWizard::CustomButton1, tr("Tap test…"));
    button(QWizard::CustomButton1)->setObjectName("machTapTest");
    button(QWizard::CustomButton1)->setToolTip(tr("Measure the tool-tip receptance with an impact hammer"));
    setOption(QWizard::HaveCustomButton1, true);
    connect(this, &QWizard::customButtonClicked, this, [this](int which) {
        if (which == QWizard::CustomButton1)
            openTapTest();
    });
    connect(this, &QWizard::currentIdChanged, this, &MachiningWizard::onPageChanged);
}

void MachiningWizard::openTapTest()
{
    if (currentId() != ToolId)
        return;
    m_tapRequested = true;
    next();
    m_tapRequested = false;
}

int MachiningWizard::nextId() const
{
    // the tap page sits outside the linear order: from the tool page only on request, never after Save
    switch (currentId()) {
    case ToolId:
        return m_tapRequested ? int(TapId) : int(CutId);
    case TapId:
        return CutId;
    case AnalysisId:
        return AvoidId;
    case AvoidId:
        return SaveId;
    case SaveId:
        return -1;
    default:
        return QWizard::nextId();
    }
}

void MachiningWizard::onPageChanged(int id)
{
    setOption(QWizard::HaveCustomButton1, id == ToolId);
    if (id == SaveId)
        save();
}

void MachiningWizard::save()
{
    auto tool = m_tool->tool();
    auto in = m_cut->inputs();
    if (!tool || !in) {
        m_save->showSaved(tr("Nothing saved: the tool or cut data are not valid."));
        return;
    }
    store::SessionRecord rec;
    rec.info.kind = "machining";
    rec.info.status = store::SessionStatus::Completed;
    nlohmann::json modes = nlohmann::json::object();
    for (const auto& [key, list] : {std::pair{"modes_x", &tool->modesX}, std::pair{"modes_y", &tool->modesY}}) {
        auto& a = modes[key] = nlohmann::json::array();
        for (const auto& m : *list)
            a.push_back({{"mass_kg", m.massKg},
                         {"damping_Ns_per_m", m.dampingNsPerM},
                         {"stiffness_N_per_m", m.stiffnessNPerM}});
    }
    const auto& c = in->cut;
    rec.inputs = {{"tool", modes},
                  {"tool_source", m_tool->source().toStdString()},
                  {"cut",
                   {{"teeth", c.teeth},
                    {"Kt_N_per_m2", c.ktNPerM2},
                    {"Kr_N_per_m2", c.krNPerM2},
                    {"radial_immersion", c.radialImmersion},
                    {"milling", c.milling == machining::MillingDirection::Up ? "up" : "down"}}},
                  {"spindle_rpm", in->rpm},
                  {"axial_depth_m", in->depthM},
                  {"lobes",
                   {{"rpm_min", in->rpmMin},
                    {"rpm_max", in->rpmMax},
                    {"rpm_step", in->rpmStep},
                    {"steps_per_period", in->stepsPerPeriod}}}};
    if (m_lobes->done()) {
        const auto& r = m_lobes->result();
        model::Channel rpm{"rpm", {}}, depth{"limit_depth_m", {}};
        for (const auto& p : r.lobes) {
            rpm.data.push_back(p.rpm);
            depth.data.push_back(p.limitDepthM); // +inf: stable up to the search limit
        }
        const bool stable = in->depthM < r.limitAtCurrentM;
        rec.results.push_back({"lobes",
                               {{"method", "semi-discretization"},
                                {"limit_at_current_rpm_m", std::isinf(r.limitAtCurrentM) ? -1.0 : r.limitAtCurrentM},
                                {"current_point_stable", stable}},
                               {rpm, depth}});
    }
    if (const auto& a = m_advice->advice()) {
        nlohmann::json cands = nlohmann::json::array();
        for (const auto& cand : a->candidates)
            cands.push_back({{"lobe", cand.lobe}, {"rpm", cand.rpm}});
        rec.results.push_back({"advice",
                               {{"chatter_Hz", machiningNumber(m_advice->chatterHz()->text()).value_or(0.0)},
                                {"chatter_source", m_advice->estimateSource().toStdString()},
                                {"tooth_passing_Hz", a->toothPassingHz},
                                {"ratio", a->ratio},
                                {"lobe", a->lobe},
                                {"pocket_rpm", a->rpm},
                                {"candidates", cands}},
                               {}});
    }
    const auto& an = m_analysis->analysis();
    if (m_analysis->analysed()) {
        nlohmann::json ivs = nlohmann::json::array();
        if (an.chatter)
            for (const auto& iv : an.chatter->intervals)
                ivs.push_back({{"start_s", iv.startS},
                               {"end_s", iv.endS},
                               {"frequency_Hz", iv.frequencyHz},
                               {"score", iv.score}});
        rec.results.push_back({"chatter-detection",
                               {{"source", an.source.toStdString()},
                                {"stage", an.stageSource.toStdString()},
                                {"chatter", !ivs.empty()},
                                {"intervals", ivs},
                                {"flagged_fraction", an.chatter ? an.chatter->flaggedFraction : 0.0}},
                               {}});
        model::Capture cut = *an.capture;
        if (!an.forceEstimateN.empty())
            cut.channels.push_back({"cutting_force_estimate_N", an.forceEstimateN});
        rec.captures.push_back({"cut", std::move(cut)});
    }
    auto id = m_ctx.saveSession(rec);
    if (!id) {
        m_save->showSaved(tr("Not saved: %1").arg(QString::fromStdString(id.error().detail)));
        return;
    }
    m_sessionId = *id;
    m_save->showSaved(tr("Saved as session %1: inputs, %2 results, %3 capture(s).")
                          .arg(*id)
                          .arg(rec.results.size())
                          .arg(rec.captures.size()));
    emit sessionSaved(*id);
}

} // namespace gui
} // namespace axistune
