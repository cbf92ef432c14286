// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/ConnectDialog.h"

#include "app/gui/AppContext.h"

#include "core/sim/MachineDefinition.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QEvent>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QSettings>
#include <QSpinBox>
#include <QStackedWidget>
#include <QVBoxLayout>

namespace axistune {
namespace gui {

ConnectDialog::ConnectDialog(AppContext& ctx, QWidget* parent) : QDialog(parent), m_ctx(ctx)
{
    setObjectName("connectDialog");
    auto* lay = new QVBoxLayout(this);
    m_simRadio = new QRadioButton(this);
    m_simRadio->setObjectName("simRadio");
    m_modbusRadio = new QRadioButton(this);
    m_modbusRadio->setObjectName("modbusRadio");
    lay->addWidget(m_simRadio);
    lay->addWidget(m_modbusRadio);

    m_stack = new QStackedWidget(this);
    auto* simPage = new QWidget(m_stack);
    auto* simForm = new QFormLayout(simPage);
    m_preset = new QComboBox(simPage);
    m_preset->setObjectName("presetCombo");
    for (const auto& p : sim::presetNames())
        m_preset->addItem(QString::fromStdString(p));
    m_seed = new QSpinBox(simPage);
    m_seed->setObjectName("seedSpin");
    m_seed->setRange(0, 999999);
    m_seed->setValue(1);
    m_presetLabel = new QLabel(simPage);
    m_seedLabel = new QLabel(simPage);
    simForm->addRow(m_presetLabel, m_preset);
    simForm->addRow(m_seedLabel, m_seed);
    // An identified rigid-body model as one axis's plant (docs/identification.md "Using the result").
    m_model = new QLineEdit(simPage);
    m_model->setObjectName("modelEdit");
    m_modelAxis = new QLineEdit(simPage);
    m_modelAxis->setObjectName("modelAxisEdit");
    m_modelLabel = new QLabel(simPage);
    m_modelAxisLabel = new QLabel(simPage);
    simForm->addRow(m_modelLabel, m_model);
    simForm->addRow(m_modelAxisLabel, m_modelAxis);
    m_stack->addWidget(simPage);

    auto* mbPage = new QWidget(m_stack);
    auto* mbForm = new QFormLayout(mbPage);
    m_host = new QLineEdit("127.0.0.1", mbPage);
    m_host->setObjectName("hostEdit");
    m_port = new QSpinBox(mbPage);
    m_port->setObjectName("portSpin");
    m_port->setRange(1, 65535);
    m_port->setValue(502);
    m_timeout = new QSpinBox(mbPage);
    m_timeout->setRange(50, 60000);
    m_timeout->setValue(1000);
    m_timeout->setSuffix(" ms");
    m_map = new QLineEdit("axistune-sim", mbPage);
    m_hostLabel = new QLabel(mbPage);
    m_portLabel = new QLabel(mbPage);
    m_timeoutLabel = new QLabel(mbPage);
    m_mapLabel = new QLabel(mbPage);
    m_unitNote = new QLabel(mbPage);
    m_unitNote->setWordWrap(true);
    mbForm->addRow(m_hostLabel, m_host);
    mbForm->addRow(m_portLabel, m_port);
    mbForm->addRow(m_timeoutLabel, m_timeout);
    mbForm->addRow(m_mapLabel, m_map);
    mbForm->addRow(m_unitNote);
    m_stack->addWidget(mbPage);
    lay->addWidget(m_stack);

    m_status = new QLabel(this);
    m_status->setObjectName("connectStatus");
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    lay->addWidget(m_status);
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    m_connectButton = m_buttons->addButton(QString(), QDialogButtonBox::AcceptRole);
    m_connectButton->setObjectName("connectButton");
    m_connectButton->setDefault(true);
    lay->addWidget(m_buttons);

    // The last choice is the default; the simulated machine the first time.
    QSettings s;
    m_simRadio->setChecked(s.value("connect/mode", "sim").toString() != "modbus");
    m_modbusRadio->setChecked(!m_simRadio->isChecked());
    const int idx = m_preset->findText(s.value("connect/preset", "vmc").toString());
    m_preset->setCurrentIndex(std::max(0, idx));
    m_host->setText(s.value("connect/host", "127.0.0.1").toString());
    m_port->setValue(s.value("connect/port", 502).toInt());

    connect(m_simRadio, &QRadioButton::toggled, this, &ConnectDialog::updateMode);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &ConnectDialog::startConnect);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    retranslateUi();
    updateMode();
}

void ConnectDialog::retranslateUi()
{
    setWindowTitle(tr("Connect"));
    m_simRadio->setText(tr("Built-in simulated machine"));
    m_modbusRadio->setText(tr("Drive over Modbus TCP"));
    m_presetLabel->setText(tr("Machine preset:"));
    m_seedLabel->setText(tr("Noise seed:"));
    m_modelLabel->setText(tr("Identified model (optional):"));
    m_model->setPlaceholderText(tr("result JSON of Identify from motion"));
    m_modelAxisLabel->setText(tr("Axis of the model:"));
    m_hostLabel->setText(tr("Host:"));
    m_portLabel->setText(tr("Port:"));
    m_timeoutLabel->setText(tr("Response timeout:"));
    m_mapLabel->setText(tr("Register map:"));
    m_unitNote->setText(tr("Unit ids: one per axis, from the register map (axis i answers on unit id base + i; "
                           "see docs/modbus.md)."));
    m_connectButton->setText(tr("Connect"));
}

void ConnectDialog::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QDialog::changeEvent(event);
}

void ConnectDialog::updateMode() { m_stack->setCurrentIndex(m_simRadio->isChecked() ? 0 : 1); }

QString ConnectDialog::uri() const
{
    if (m_simRadio->isChecked()) {
        QString u = "sim:" + m_preset->currentText();
        if (!m_model->text().trimmed().isEmpty()) {
            u += "?model=" + m_model->text().trimmed();
            if (!m_modelAxis->text().trimmed().isEmpty())
                u += "&axis=" + m_modelAxis->text().trimmed();
        }
        return u;
    }
    QString u = QString("modbus://%1:%2").arg(m_host->text().trimmed()).arg(m_port->value());
    QStringList query;
    if (m_timeout->value() != 1000)
        query << QString("timeout_ms=%1").arg(m_timeout->value());
    if (!m_map->text().trimmed().isEmpty() && m_map->text().trimmed() != "axistune-sim")
        query << "map=" + m_map->text().trimmed();
    return query.isEmpty() ? u : u + "?" + query.join('&');
}

quint64 ConnectDialog::seed() const { return static_cast<quint64>(m_seed->value()); }

void ConnectDialog::setSimulated(const QString& preset, quint64 seed)
{
    m_simRadio->setChecked(true);
    m_preset->setCurrentIndex(std::max(0, m_preset->findText(preset)));
    m_seed->setValue(static_cast<int>(seed));
}

void ConnectDialog::setModbus(const QString& host, int port)
{
    m_modbusRadio->setChecked(true);
    m_host->setText(host);
    m_port->setValue(port);
}

QString ConnectDialog::errorText() const { return m_failed ? m_status->text() : QString(); }

void ConnectDialog::startConnect()
{
    if (m_request >= 0)
        return;
    if (m_modbusRadio->isChecked() && m_host->text().trimmed().isEmpty()) {
        m_failed = true;
        m_status->setStyleSheet("color: #b00020;");
        m_status->setText(tr("Enter the host name or address of the drive."));
        return;
    }
    m_failed = false;
    m_status->setStyleSheet(QString());
    m_status->setText(tr("Connecting to %1 …").arg(uri()));
    m_connectButton->setEnabled(false);
    auto* req = m_ctx.drive().connectTo(uri(), seed());
    m_request = req->id();
    connect(req, &DriveRequest::finished, this, &ConnectDialog::onReply);
}

void ConnectDialog::onReply(const DriveReply& reply)
{
    if (reply.id != m_request)
        return;
    m_request = -1;
    m_connectButton->setEnabled(true);
    if (!reply.ok) {
        m_failed = true;
        m_status->setStyleSheet("color: #b00020;");
        m_status->setText(tr("The connection failed: %1").arg(reply.error));
        return;
    }
    QSettings s;
    s.setValue("connect/mode", m_simRadio->isChecked() ? "sim" : "modbus");
    s.setValue("connect/preset", m_preset->currentText());
    s.setValue("connect/host", m_host->text().trimmed());
    s.setValue("connect/port", m_port->value());
    accept();
}

}  // namespace gui
}  // namespace axistune
