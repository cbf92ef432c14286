// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Reading numbers out of program output and files in tests. std::stod/strtod follow the C library's
// locale, which every test binary takes from the environment (tests/TestMain.cpp; scripts/test runs
// the suite under de_DE.UTF-8 too, where strtod("0.5") is 0), so tests use this instead.

#include <cctype>
#include <charconv>
#include <stdexcept>
#include <string>
#include <string_view>

namespace axistune::testutil {

/// As std::stod in the "C" locale: skips leading white space and reads the longest number at the
/// start (text after it is ignored; `used`, when given, receives the characters read); throws
/// std::invalid_argument when there is none.
inline double stod(std::string_view s, std::size_t* used = nullptr)
{
    std::size_t i = 0;
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i])))
        ++i;
    if (i < s.size() && s[i] == '+')
        ++i;
    double v = 0.0;
    const auto r = std::from_chars(s.data() + i, s.data() + s.size(), v);
    if (r.ec == std::errc::invalid_argument)
        throw std::invalid_argument("not a number: '" + std::string(s) + "'");
    if (r.ec != std::errc())
        throw std::out_of_range("number out of range: '" + std::string(s) + "'");
    if (used)
        *used = static_cast<std::size_t>(r.ptr - s.data());
    return v;
}

} // namespace axistune::testutil
