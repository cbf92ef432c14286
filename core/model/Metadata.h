// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Metadata of captures and FRFs (the "# key=value" lines of their CSV files, DESIGN.md "File formats"):
// each value is a number or a text. A number set in code stays a double (no text in between, no digits
// lost); a file's value is a number when its text is exactly the spelling MetadataValue::text() writes
// ("4000", "100000", "0.5", "1e-06"), any other text ("step", "3000:12000", "0012", "4.0") stays text, so a file read
// and written again is the same byte for byte. Reading a number names the key when it is missing or not a number; there
// are no silent defaults. Numbers are written with std::to_chars (core/model/Number.h): the locale never changes a
// file.

#include "core/model/Result.h"

#include <concepts>
#include <cstddef>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

namespace axistune::model {

/// One metadata value: a number or a text.
class MetadataValue {
public:
    MetadataValue() = default;
    MetadataValue(double v) : m_value(v) {}
    MetadataValue(std::string text) : m_value(std::move(text)) {}
    MetadataValue(const char* text) : m_value(std::string(text)) {}
    /// No bool: write "true"/"false" (a bool would silently become 1 or 0). Integers become numbers.
    template <class T>
    requires std::same_as<T, bool> MetadataValue(T)
    = delete;

    /// A value read from a file: a number when `text` is exactly formatShortest of one, text otherwise.
    static MetadataValue fromText(std::string text);

    bool isNumber() const { return std::holds_alternative<double>(m_value); }
    /// The number when finite; a text value counts when the whole of it is one ("4.0", "+5"; parseNumber). A value
    /// that is no number, or not a finite one (inf, nan), gives nullopt.
    std::optional<double> number() const;
    /// The text a file holds: a whole number below 1e17 in full ("4000", "100000"), any other number in its
    /// shortest round-trip form ("0.5", "1e-06", "1e+17", "inf", "nan").
    std::string text() const;

    /// Compares the text form: `value == "frf"`.
    friend bool operator==(const MetadataValue& a, std::string_view b) { return a.text() == b; }
    friend bool operator==(const MetadataValue& a, const char* b) { return a.text() == b; }
    friend bool operator==(const MetadataValue& a, const std::string& b) { return a.text() == b; }
    friend bool operator==(const MetadataValue& a, const MetadataValue& b) = default;

private:
    std::variant<std::string, double> m_value;
};

/// The metadata of one capture or FRF, ordered by key.
class Metadata {
public:
    using Map = std::map<std::string, MetadataValue, std::less<>>;
    using const_iterator = Map::const_iterator;

    Metadata() = default;
    Metadata(std::initializer_list<std::pair<const std::string, MetadataValue>> entries) : m_entries(entries) {}

    /// Sets `key` to a number or a text (replacing what it held).
    void set(std::string_view key, MetadataValue value);
    /// Sets `key` from a file's text (MetadataValue::fromText).
    void setFromText(std::string_view key, std::string text);
    bool erase(std::string_view key);
    void clear() { m_entries.clear(); }

    bool contains(std::string_view key) const { return m_entries.find(key) != m_entries.end(); }
    /// The value of `key`, nullptr when missing.
    const MetadataValue* find(std::string_view key) const;
    /// The text of `key` (numbers in their shortest form); nullopt when missing.
    std::optional<std::string> text(std::string_view key) const;
    /// The text of `key`, or `fallback` when missing.
    std::string textOr(std::string_view key, std::string_view fallback) const;

    /// The number at `key`: NotFound "metadata 'fs_Hz' is missing", BadInput "metadata 'fs_Hz' is not a
    /// number ('4,0')" (also for inf and nan).
    Result<double> number(std::string_view key) const;
    /// As number(), but a missing key gives nullopt (a present value that is not a number is still an error).
    Result<std::optional<double>> optionalNumber(std::string_view key) const;
    /// A whole number (e.g. "nperseg", "injection_hold_ticks").
    Result<long long> integer(std::string_view key) const;
    /// The sample period [s] 1/fs_Hz: nullopt without fs_Hz, an error naming the key when fs_Hz is not a
    /// positive number.
    Result<std::optional<double>> samplePeriodS() const;

    std::size_t size() const { return m_entries.size(); }
    bool empty() const { return m_entries.empty(); }
    const_iterator begin() const { return m_entries.begin(); }
    const_iterator end() const { return m_entries.end(); }

    friend bool operator==(const Metadata& a, const Metadata& b) = default;

private:
    Map m_entries;
};

} // namespace axistune::model
