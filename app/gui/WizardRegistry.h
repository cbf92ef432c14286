// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Wizards register themselves (one static WizardRegistrar in each wizard's .cpp); the main window's
// Wizards menu lists them in `order`. axistune_gui is an OBJECT library, so no registrar is dropped.
//
//   static const WizardRegistrar kReg{"frf", QT_TRANSLATE_NOOP("Wizards", "Frequency response…"), 10,
//       [](AppContext& ctx, QWidget* parent) -> QWizard* { return new FrfWizard(ctx, parent); }};

#include <QString>

#include <functional>
#include <vector>

class QWidget;
class QWizard;

namespace axistune {
namespace gui {

class AppContext;

struct WizardEntry {
    QString id;              ///< stable id, e.g. "frf" (used by tests and --wizard)
    const char* title;       ///< QT_TRANSLATE_NOOP("Wizards", ...) source text
    int order = 100;         ///< position in the menu
    bool needsDrive = true;  ///< false: works offline (e.g. from files or saved sessions)
    std::function<QWizard*(AppContext&, QWidget* parent)> create;
};

/// All registered wizards, sorted by order.
std::vector<WizardEntry> registeredWizards();
/// The wizard with this id, or nullptr.
const WizardEntry* findWizard(const QString& id);
/// Translated title of an entry.
QString wizardTitle(const WizardEntry& entry);

struct WizardRegistrar {
    WizardRegistrar(QString id, const char* title, int order, std::function<QWizard*(AppContext&, QWidget*)> create,
                    bool needsDrive = true);
};

}  // namespace gui
}  // namespace axistune
