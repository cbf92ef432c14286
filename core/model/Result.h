// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Errors are values (STYLE.md): Result<T> holds a value or an Error with a code and a detail that
// names what failed (file, line, field, key, limits). Only app/ turns an Error into words for a person.

#include <cassert>
#include <string>
#include <utility>
#include <variant>

namespace axistune {

enum class ErrorCode {
    BadInput,    ///< malformed or inconsistent input (CLI exit 2)
    OutOfRange,  ///< a value outside its limits; never clamped (CLI exit 2)
    NotFound,    ///< unknown key, preset, axis or file (CLI exit 2)
    Busy,        ///< the operation is not allowed now (e.g. parameter write during a test)
    Device,      ///< communication or drive error (CLI exit 3)
    Safety,      ///< a safety limit stopped the motion (CLI exit 4)
    Aborted,     ///< cancelled by the user
    Io,          ///< file system or database
    Internal,
};

const char* errorCodeName(ErrorCode code);
/// The CLI exit code for an error (DESIGN.md: 2 bad input, 3 device error, 4 safety stop).
int exitCodeFor(ErrorCode code);

struct Error {
    ErrorCode code = ErrorCode::Internal;
    std::string detail;
};

template <typename T>
class [[nodiscard]] Result {
public:
    Result(T value) : m_v(std::move(value)) {}  // NOLINT(google-explicit-constructor)
    Result(Error error) : m_v(std::move(error)) {}  // NOLINT(google-explicit-constructor)

    bool ok() const { return std::holds_alternative<T>(m_v); }
    explicit operator bool() const { return ok(); }
    const T& value() const& { assert(ok()); return std::get<T>(m_v); }
    T& value() & { assert(ok()); return std::get<T>(m_v); }
    T&& value() && { assert(ok()); return std::get<T>(std::move(m_v)); }
    const T& operator*() const& { return value(); }
    const T* operator->() const { return &value(); }
    const Error& error() const { assert(!ok()); return std::get<Error>(m_v); }

private:
    std::variant<T, Error> m_v;
};

class [[nodiscard]] Status {
public:
    Status() = default;
    Status(Error error) : m_error(std::move(error)), m_ok(false) {}  // NOLINT(google-explicit-constructor)
    static Status success() { return {}; }
    bool ok() const { return m_ok; }
    explicit operator bool() const { return m_ok; }
    const Error& error() const { assert(!m_ok); return m_error; }

private:
    Error m_error;
    bool m_ok = true;
};

inline Error makeError(ErrorCode code, std::string detail) { return Error{code, std::move(detail)}; }

}  // namespace axistune
