// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Preferences: language (English / 日本語, switched at once: the translator is installed or removed
// and every window retranslates on QEvent::LanguageChange), store file and operator name.
// Persisted in QSettings: "ui/language" ("en"/"ja"), "store/path", "ui/operator".

#include <QDialog>
#include <QString>

class QComboBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace axistune {
namespace gui {

class AppContext;

/// Installs (code "ja") or removes (anything else) the Japanese translator of the application.
/// Returns false when the translation could not be loaded (English stays).
bool setApplicationLanguage(const QString& code);
/// The language in use: "ja" or "en".
QString applicationLanguage();
/// The store file: QSettings "store/path", default AppDataLocation/axistune.sqlite.
QString defaultStorePath();

class SettingsDialog : public QDialog {
    Q_OBJECT
public:
    explicit SettingsDialog(AppContext& ctx, QWidget* parent = nullptr);

    void setLanguage(const QString& code);  ///< selects "en" or "ja" in the combo
    /// Applies the settings (language at once, store reopened when its path changed) and saves them.
    void apply();

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();
    void browseStore();

    AppContext& m_ctx;
    QLabel* m_languageLabel = nullptr;
    QComboBox* m_language = nullptr;
    QLabel* m_storeLabel = nullptr;
    QLineEdit* m_store = nullptr;
    QPushButton* m_browse = nullptr;
    QLabel* m_operatorLabel = nullptr;
    QLineEdit* m_operator = nullptr;
    QDialogButtonBox* m_buttons = nullptr;
};

}  // namespace gui
}  // namespace axistune
