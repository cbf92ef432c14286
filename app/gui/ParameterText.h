// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Translated labels of drive parameters: core/ keeps English labels (no Qt there); the GUI shows
// them through the "Parameter" translation context.

#include <QString>

#include <string>

namespace axistune {
namespace gui {

/// The label in the user's language.
QString parameterLabel(const std::string& label);
/// True when the label is in the translation list (tested for every parameter).
bool hasParameterLabel(const std::string& label);

}  // namespace gui
}  // namespace axistune
