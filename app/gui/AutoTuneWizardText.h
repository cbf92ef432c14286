// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Small text and table helpers of the one-button tuning wizard's pages (AutoTuneWizard.cpp, AutoTuneResultPage.cpp).

#include "core/autotune/AutoTune.h"

#include <QString>
#include <QTableWidgetItem>

#include <string>

namespace axistune::gui::autotunetext {

inline QString qs(const std::string& s)
{
    return QString::fromStdString(s);
}

/// A refusal that was the user's Abort.
inline bool wasAborted(const autotune::AutoTuneResult& r)
{
    return r.outcome == autotune::Outcome::Refused && r.reasonCode == ErrorCode::Aborted;
}

/// A read-only table cell.
inline QTableWidgetItem* item(const QString& text)
{
    auto* it = new QTableWidgetItem(text);
    it->setFlags(it->flags() & ~Qt::ItemIsEditable);
    return it;
}

} // namespace axistune::gui::autotunetext
