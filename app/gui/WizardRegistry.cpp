// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/WizardRegistry.h"

#include <QCoreApplication>

#include <algorithm>

namespace axistune {
namespace gui {

namespace {
std::vector<WizardEntry>& registry()
{
    static std::vector<WizardEntry> r;
    return r;
}
}  // namespace

WizardRegistrar::WizardRegistrar(QString id, const char* title, int order,
                                 std::function<QWizard*(AppContext&, QWidget*)> create, bool needsDrive)
{
    registry().push_back({std::move(id), title, order, needsDrive, std::move(create)});
}

std::vector<WizardEntry> registeredWizards()
{
    auto r = registry();
    std::stable_sort(r.begin(), r.end(), [](const WizardEntry& a, const WizardEntry& b) { return a.order < b.order; });
    return r;
}

const WizardEntry* findWizard(const QString& id)
{
    for (const auto& e : registry())
        if (e.id == id)
            return &e;
    return nullptr;
}

QString wizardTitle(const WizardEntry& entry) { return QCoreApplication::translate("Wizards", entry.title); }

}  // namespace gui
}  // namespace axistune
