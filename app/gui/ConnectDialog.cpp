// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/ConnectDialog.h"

#include "app/gui/AppContext.h"
#include "core/device/DriveRegistry.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QEvent>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
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

namespace {

QString trBackend(const std::string& text)
{
    return text.empty() ? QString() : QCoreApplication::translate("DriveRegistry", text.c_str());
}

QString qs(const std::string& s)
{
    return QString::fromStdString(s);
}

} // namespace

QString backendKey(const device::DriveBackend& backend)
{
    QString k = qs(backend.scheme);
    k.remove(':').remove('/');
    return k;
}

ConnectDialog::ConnectDialog(AppContext& ctx, QWidget* parent) : QDialog(parent), m_ctx(ctx)
{
    setObjectName("connectDialog");
    auto* lay = new QVBoxLayout(this);
    m_group = new QButtonGroup(this);
    m_stack = new QStackedWidget(this);
    QSettings saved;
    for (const auto& b : device::registeredBackends()) {
        Page p;
        p.backend = &b;
        const QString key = backendKey(b);
        p.radio = new QRadioButton(this);
        p.radio->setObjectName("backendRadio_" + key);
        m_group->addButton(p.radio, static_cast<int>(m_pages.size()));
        lay->addWidget(p.radio);
        auto* page = new QWidget(m_stack);
        auto* form = new QFormLayout(page);
        p.form = new QLabel(page);
        p.form->setWordWrap(true);
        p.form->setTextFormat(Qt::PlainText);
        p.form->setObjectName("backendForm_" + key);
        form->addRow(p.form);
        for (const auto& s : b.settings) {
            Field f;
            f.label = new QLabel(page);
            const QString name = "setting_" + key + "_" + qs(s.name);
            const QString stored = saved.value("connect/" + key + "/" + qs(s.name), qs(s.defaultValue)).toString();
            switch (s.type) {
            case device::BackendSetting::Type::Integer: {
                auto* spin = new QSpinBox(page);
                spin->setRange(static_cast<int>(s.minimum), static_cast<int>(s.maximum));
                spin->setValue(stored.toInt());
                if (!s.unit.empty())
                    spin->setSuffix(" " + qs(s.unit));
                f.editor = spin;
                break;
            }
            case device::BackendSetting::Type::Choice: {
                auto* combo = new QComboBox(page);
                for (const auto& c : s.choices)
                    combo->addItem(qs(c));
                combo->setCurrentIndex(std::max(0, combo->findText(stored)));
                f.editor = combo;
                break;
            }
            case device::BackendSetting::Type::File: {
                auto* row = new QWidget(page);
                auto* h = new QHBoxLayout(row);
                h->setContentsMargins(0, 0, 0, 0);
                auto* edit = new QLineEdit(stored, row);
                edit->setObjectName(name);
                auto* browse = new QPushButton(row);
                browse->setObjectName(name + "_browse");
                h->addWidget(edit, 1);
                h->addWidget(browse);
                connect(browse, &QPushButton::clicked, this, [this, edit, label = s.label] {
                    const QString chosen = QFileDialog::getOpenFileName(this, trBackend(label), edit->text());
                    if (!chosen.isEmpty())
                        edit->setText(chosen);
                });
                f.editor = row;
                break;
            }
            case device::BackendSetting::Type::Text:
                f.editor = new QLineEdit(stored, page);
                break;
            }
            if (s.type != device::BackendSetting::Type::File)
                f.editor->setObjectName(name);
            form->addRow(f.label, f.editor);
            p.fields.push_back(f);
        }
        if (b.usesSeed) {
            p.seed = new QSpinBox(page);
            p.seed->setObjectName("seed_" + key);
            p.seed->setRange(0, 999999);
            p.seed->setValue(1);
            p.seedLabel = new QLabel(page);
            form->addRow(p.seedLabel, p.seed);
        }
        m_stack->addWidget(page);
        m_pages.push_back(p);
    }
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

    // The last choice is the default; the first registered backend (the simulated machine) the first time.
    if (!m_pages.empty() && !selectBackend(saved.value("connect/scheme").toString()))
        m_pages.front().radio->setChecked(true);

    connect(m_group, &QButtonGroup::idToggled, this, [this](int, bool on) {
        if (on)
            updateMode();
    });
    connect(m_buttons, &QDialogButtonBox::accepted, this, &ConnectDialog::startConnect);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    retranslateUi();
    updateMode();
}

void ConnectDialog::retranslateUi()
{
    setWindowTitle(tr("Connect"));
    for (auto& p : m_pages) {
        p.radio->setText(trBackend(p.backend->label));
        p.form->setText(trBackend(p.backend->description) + "\n" + tr("Address form: %1").arg(qs(p.backend->uriForm)));
        for (std::size_t i = 0; i < p.fields.size(); ++i) {
            const auto& s = p.backend->settings[i];
            p.fields[i].label->setText(tr("%1:").arg(trBackend(s.label)));
            if (auto* e = qobject_cast<QLineEdit*>(p.fields[i].editor))
                e->setPlaceholderText(trBackend(s.hint));
            if (auto* b = p.fields[i].editor->findChild<QPushButton*>()) {
                b->setText(tr("Browse…"));
                if (auto* e = p.fields[i].editor->findChild<QLineEdit*>())
                    e->setPlaceholderText(trBackend(s.hint));
            }
        }
        if (p.seedLabel)
            p.seedLabel->setText(tr("Noise seed:"));
    }
    m_connectButton->setText(tr("Connect"));
}

void ConnectDialog::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QDialog::changeEvent(event);
}

int ConnectDialog::current() const
{
    return m_group->checkedId();
}

void ConnectDialog::updateMode()
{
    // A refusal or failure belongs to the form it was about: another backend's form starts without it.
    if (m_stack->currentIndex() != std::max(0, current()))
        m_status->clear();
    m_stack->setCurrentIndex(std::max(0, current()));
}

QString ConnectDialog::value(const Page& page, std::size_t i) const
{
    QWidget* e = page.fields[i].editor;
    if (auto* spin = qobject_cast<QSpinBox*>(e))
        return QString::number(spin->value());
    if (auto* combo = qobject_cast<QComboBox*>(e))
        return combo->currentText();
    if (auto* edit = qobject_cast<QLineEdit*>(e))
        return edit->text().trimmed();
    if (auto* edit = e->findChild<QLineEdit*>())
        return edit->text().trimmed();
    return {};
}

void ConnectDialog::setValue(Page& page, std::size_t i, const QString& v)
{
    QWidget* e = page.fields[i].editor;
    if (auto* spin = qobject_cast<QSpinBox*>(e))
        spin->setValue(v.toInt());
    else if (auto* combo = qobject_cast<QComboBox*>(e))
        combo->setCurrentIndex(std::max(0, combo->findText(v)));
    else if (auto* edit = qobject_cast<QLineEdit*>(e))
        edit->setText(v);
    else if (auto* inner = e->findChild<QLineEdit*>())
        inner->setText(v);
}

QString ConnectDialog::settingsError() const
{
    if (current() < 0)
        return tr("Choose a connection.");
    const Page& p = m_pages[static_cast<std::size_t>(current())];
    device::SettingValues v;
    for (std::size_t i = 0; i < p.fields.size(); ++i)
        v[p.backend->settings[i].name] = value(p, i).toStdString();
    // The backend's own check names the setting by its English label; the form names it translated.
    for (std::size_t i = 0; i < p.fields.size(); ++i) {
        const auto& s = p.backend->settings[i];
        if (s.required && value(p, i).isEmpty())
            return tr("Enter %1.").arg(trBackend(s.label));
    }
    auto u = p.backend->uriFromSettings(v);
    return u ? QString() : qs(u.error().detail);
}

QString ConnectDialog::uri() const
{
    if (current() < 0)
        return {};
    const Page& p = m_pages[static_cast<std::size_t>(current())];
    device::SettingValues v;
    for (std::size_t i = 0; i < p.fields.size(); ++i)
        v[p.backend->settings[i].name] = value(p, i).toStdString();
    auto u = p.backend->uriFromSettings(v);
    return u ? qs(*u) : QString();
}

quint64 ConnectDialog::seed() const
{
    if (current() < 0)
        return 1;
    const Page& p = m_pages[static_cast<std::size_t>(current())];
    return p.seed ? static_cast<quint64>(p.seed->value()) : 1;
}

bool ConnectDialog::selectBackend(const QString& scheme)
{
    for (auto& p : m_pages) {
        if (qs(p.backend->scheme) == scheme) {
            p.radio->setChecked(true);
            updateMode();
            return true;
        }
    }
    return false;
}

bool ConnectDialog::setSetting(const QString& name, const QString& v)
{
    if (current() < 0)
        return false;
    Page& p = m_pages[static_cast<std::size_t>(current())];
    for (std::size_t i = 0; i < p.fields.size(); ++i) {
        if (qs(p.backend->settings[i].name) == name) {
            setValue(p, i, v);
            return true;
        }
    }
    return false;
}

void ConnectDialog::setSimulated(const QString& preset, quint64 seed)
{
    if (!selectBackend("sim:"))
        return;
    setSetting("preset", preset);
    if (auto& p = m_pages[static_cast<std::size_t>(current())]; p.seed)
        p.seed->setValue(static_cast<int>(seed));
}

void ConnectDialog::setModbus(const QString& host, int port)
{
    if (!selectBackend("modbus://"))
        return;
    setSetting("host", host);
    setSetting("port", QString::number(port));
}

QString ConnectDialog::errorText() const
{
    return m_failed ? m_status->text() : QString();
}

void ConnectDialog::startConnect()
{
    if (m_request >= 0)
        return;
    if (const QString why = settingsError(); !why.isEmpty()) {
        m_failed = true;
        m_status->setStyleSheet("color: #b00020;");
        m_status->setText(why);
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
    // Remembered per backend: the choice and every setting.
    QSettings s;
    const Page& p = m_pages[static_cast<std::size_t>(current())];
    s.setValue("connect/scheme", qs(p.backend->scheme));
    for (std::size_t i = 0; i < p.fields.size(); ++i)
        s.setValue("connect/" + backendKey(*p.backend) + "/" + qs(p.backend->settings[i].name), value(p, i));
    accept();
}

} // namespace gui
} // namespace axistune
