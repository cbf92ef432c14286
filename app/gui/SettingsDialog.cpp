// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/SettingsDialog.h"

#include "app/gui/AppContext.h"

#include <QApplication>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QLibraryInfo>
#include <QTranslator>
#include <QVBoxLayout>

namespace axistune {
namespace gui {

namespace {
QTranslator*& translator()
{
    static QTranslator* t = nullptr;
    return t;
}
QTranslator*& qtTranslator()
{
    static QTranslator* t = nullptr;
    return t;
}
}  // namespace

bool setApplicationLanguage(const QString& code)
{
    if (code == "ja") {
        if (translator())
            return true;
        auto* t = new QTranslator(qApp);
        if (!t->load(":/i18n/axistune_ja.qm")) {
            delete t;
            return false;
        }
        // Qt's own texts (wizard buttons, standard dialogs) from Debian's qt6-translations-l10n;
        // without that package they stay English, ours are still Japanese.
        auto* qt = new QTranslator(qApp);
        if (qt->load("qtbase_ja", QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
            qtTranslator() = qt;
            QApplication::installTranslator(qt);
        } else {
            delete qt;
        }
        translator() = t;
        QApplication::installTranslator(t);  // sends QEvent::LanguageChange to every widget
        return true;
    }
    for (QTranslator** t : {&translator(), &qtTranslator()}) {
        if (*t) {
            QApplication::removeTranslator(*t);
            delete *t;
            *t = nullptr;
        }
    }
    return true;
}

QString applicationLanguage() { return translator() ? "ja" : "en"; }

QString defaultStorePath()
{
    const QString dir = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
    return QSettings().value("store/path", dir + "/axistune.sqlite").toString();
}

SettingsDialog::SettingsDialog(AppContext& ctx, QWidget* parent) : QDialog(parent), m_ctx(ctx)
{
    setObjectName("settingsDialog");
    auto* lay = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    m_language = new QComboBox(this);
    m_language->setObjectName("languageCombo");
    m_language->addItem("English", "en");
    m_language->addItem(QString::fromUtf8("日本語"), "ja");
    m_language->setCurrentIndex(applicationLanguage() == "ja" ? 1 : 0);
    m_languageLabel = new QLabel(this);
    form->addRow(m_languageLabel, m_language);

    auto* storeRow = new QHBoxLayout;
    m_store = new QLineEdit(ctx.databasePath().isEmpty() ? defaultStorePath() : ctx.databasePath(), this);
    m_store->setObjectName("storeEdit");
    m_browse = new QPushButton(this);
    storeRow->addWidget(m_store, 1);
    storeRow->addWidget(m_browse);
    m_storeLabel = new QLabel(this);
    form->addRow(m_storeLabel, storeRow);

    m_operator = new QLineEdit(ctx.operatorName(), this);
    m_operator->setObjectName("operatorEdit");
    m_operatorLabel = new QLabel(this);
    form->addRow(m_operatorLabel, m_operator);
    lay->addLayout(form);

    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Apply | QDialogButtonBox::Cancel, this);
    lay->addWidget(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, [this] {
        apply();
        accept();
    });
    connect(m_buttons->button(QDialogButtonBox::Apply), &QPushButton::clicked, this, &SettingsDialog::apply);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_browse, &QPushButton::clicked, this, &SettingsDialog::browseStore);
    retranslateUi();
}

void SettingsDialog::retranslateUi()
{
    setWindowTitle(tr("Preferences"));
    m_languageLabel->setText(tr("Language:"));
    m_storeLabel->setText(tr("Store file:"));
    m_browse->setText(tr("Browse…"));
    m_operatorLabel->setText(tr("Operator name:"));
    m_store->setToolTip(tr("The SQLite file holding machines, profiles, sessions and the journal"));
}

void SettingsDialog::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QDialog::changeEvent(event);
}

void SettingsDialog::setLanguage(const QString& code) { m_language->setCurrentIndex(code == "ja" ? 1 : 0); }

void SettingsDialog::browseStore()
{
    const QString f = QFileDialog::getSaveFileName(this, tr("Store file"), m_store->text(), tr("AxisTune store (*.sqlite)"),
                                                   nullptr, QFileDialog::DontConfirmOverwrite);
    if (!f.isEmpty())
        m_store->setText(f);
}

void SettingsDialog::apply()
{
    QSettings s;
    const QString code = m_language->currentData().toString();
    if (!setApplicationLanguage(code))
        m_ctx.log(tr("The Japanese translation could not be loaded"));
    s.setValue("ui/language", code);

    m_ctx.setOperatorName(m_operator->text().trimmed());
    s.setValue("ui/operator", m_operator->text().trimmed());

    const QString path = m_store->text().trimmed();
    if (!path.isEmpty() && path != m_ctx.databasePath()) {
        QDir().mkpath(QFileInfo(path).absolutePath());
        if (m_ctx.openDatabase(path))
            s.setValue("store/path", path);
    }
}

}  // namespace gui
}  // namespace axistune
