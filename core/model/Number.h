// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Numbers as data: written and read with '.' as the decimal point whatever the C library locale
// (std::to_chars / std::from_chars). A GUI process runs under the user's locale (QApplication calls
// setlocale), where printf's %g writes "0,5" and strtod stops at the '.'; files, metadata, register
// texts and messages that are parsed again use these functions, never printf/strtod/atof/stod.

#include <optional>
#include <string>
#include <string_view>

namespace axistune::model {

/// The shortest text that reads back as the same double ("0.5", "4000", "1e-06", "inf", "nan").
std::string formatShortest(double v);
/// `v` with `significant` digits in printf's %g form ("0.6102", "1e-06"; 17 digits round-trip a double).
std::string formatNumber(double v, int significant);
/// `v` with `decimals` digits after the point, printf's %.*f form ("0.500", "-12").
std::string formatFixed(double v, int decimals);
/// `v` in exponent form with `decimals` digits after the point, printf's %.*e form ("1.500000000e-03").
std::string formatScientific(double v, int decimals);

/// The number the whole of `text` spells: an optional sign ('+' or '-'), digits with '.' as the decimal
/// point, an optional exponent; "inf"/"nan" only when `allowNonFinite`. No white space, no ',' and nothing
/// after the number; nullopt otherwise (also for a value outside the range of double).
std::optional<double> parseNumber(std::string_view text, bool allowNonFinite = false);
/// A whole integer (optional sign, decimal digits only); nullopt when not an integer or out of range.
std::optional<long long> parseInteger(std::string_view text);

} // namespace axistune::model
