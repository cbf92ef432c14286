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

/// A metadata key with the kind of value it holds. The keys that more than one place writes or reads are constants
/// in core/model/MetadataKeys.h (model::meta), so a writer and a reader cannot disagree on the name or on whether the
/// value is a number: Metadata's overloads for a typed key take and give only its kind (a number key cannot be set
/// to a text, a text key cannot be read as a number). Keys that are data (a file's own, "unit.CHANNEL") stay names.
template <class T> struct MetadataKey {
    std::string_view name;
};
using NumberKey = MetadataKey<double>;     ///< a finite number
using IntegerKey = MetadataKey<long long>; ///< a whole number
using TextKey = MetadataKey<std::string>;  ///< a text

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

    /// Typed keys (model::meta): the value is a number, a whole number or a text, as the key says.
    void set(NumberKey key, double value) { set(key.name, MetadataValue(value)); }
    /// Up to 2^53 in magnitude the number itself, beyond that its digits (a double would round it); either is
    /// written as the digits.
    template <std::integral I>
    requires(!std::same_as<I, bool>) void set(IntegerKey key, I value)
    {
        constexpr long double kExact = 9007199254740992.0L; // 2^53
        if (static_cast<long double>(value) <= kExact && static_cast<long double>(value) >= -kExact)
            set(key.name, MetadataValue(static_cast<double>(value)));
        else
            set(key.name, MetadataValue(std::to_string(value))); // integers: no locale in std::to_string
    }
    void set(TextKey key, std::string value) { set(key.name, MetadataValue(std::move(value))); }
    template <class T> bool erase(MetadataKey<T> key) { return erase(key.name); }
    template <class T> bool contains(MetadataKey<T> key) const { return contains(key.name); }
    template <class T> const MetadataValue* find(MetadataKey<T> key) const { return find(key.name); }
    /// The text a file holds, of any kind of key (a number in its written form, for messages and echoes).
    template <class T> std::optional<std::string> text(MetadataKey<T> key) const { return text(key.name); }
    template <class T> std::string textOr(MetadataKey<T> key, std::string_view fallback) const
    {
        return textOr(key.name, fallback);
    }
    Result<double> number(NumberKey key) const { return number(key.name); }
    Result<std::optional<double>> optionalNumber(NumberKey key) const { return optionalNumber(key.name); }
    Result<long long> integer(IntegerKey key) const { return integer(key.name); }

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
