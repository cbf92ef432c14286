// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A fresh directory under the temporary directory (TMPDIR, std::filesystem::temp_directory_path) that is
// removed with all its contents when the object goes out of scope — also when an ASSERT ends the test early.
// GoogleTest binaries use it; QtTest binaries use QTemporaryDir. Check: run a test binary with TMPDIR (and
// TEST_TMPDIR) pointing to an empty directory; it is empty again afterwards (README.md).

#include <cerrno>
#include <filesystem>
#include <ostream>
#include <stdlib.h>
#include <string>
#include <system_error>
#include <utility>

namespace axistune::testing {

class ScopedTempDir {
public:
    /// Creates <temp>/axistune-<tag>-XXXXXX; throws std::filesystem::filesystem_error if that fails (a test
    /// must never fall back to writing into, and then removing, the temporary directory itself).
    explicit ScopedTempDir(const std::string& tag = "test")
    {
        std::string tmpl = (std::filesystem::temp_directory_path() / ("axistune-" + tag + "-XXXXXX")).string();
        if (!mkdtemp(tmpl.data()))
            throw std::filesystem::filesystem_error("cannot create a temporary directory", tmpl,
                                                    std::error_code(errno, std::generic_category()));
        m_path = tmpl;
    }
    ~ScopedTempDir() { reset(); }
    ScopedTempDir(const ScopedTempDir&) = delete;
    ScopedTempDir& operator=(const ScopedTempDir&) = delete;
    ScopedTempDir(ScopedTempDir&& o) noexcept : m_path(std::exchange(o.m_path, {})) {}
    ScopedTempDir& operator=(ScopedTempDir&& o) noexcept
    {
        if (this != &o) {
            reset();
            m_path = std::exchange(o.m_path, {});
        }
        return *this;
    }

    const std::filesystem::path& path() const& { return m_path; }
    std::string string() const& { return m_path.string(); }
    std::filesystem::path operator/(const std::filesystem::path& p) const& { return m_path / p; }
    operator const std::filesystem::path&() const& { return m_path; }
    // A temporary ScopedTempDir would remove its directory at the end of the expression, before the path is used.
    const std::filesystem::path& path() const&& = delete;
    std::string string() const&& = delete;
    std::filesystem::path operator/(const std::filesystem::path& p) const&& = delete;
    operator const std::filesystem::path&() const&& = delete;

    /// Removes the directory now (errors ignored: a destructor must not throw).
    void reset()
    {
        if (m_path.empty())
            return;
        std::error_code ec;
        std::filesystem::remove_all(m_path, ec);
        m_path.clear();
    }

    friend std::ostream& operator<<(std::ostream& os, const ScopedTempDir& d) { return os << d.m_path; }

private:
    std::filesystem::path m_path;
};

} // namespace axistune::testing
