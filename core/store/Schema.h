// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The store's schema as ordered migrations. Migration N turns a version N-1 file into version N; it
// runs in one transaction together with `PRAGMA user_version = N`, so an interrupted migration
// leaves the file at N-1. Never edit a released migration: append a new one.

#include <vector>

namespace axistune::store {

struct Migration {
    int version;              ///< user_version after this migration
    const char* description;
    const char* sql;          ///< one or more statements
};

/// All migrations in ascending version order; the last one's version is Database::kSchemaVersion.
const std::vector<Migration>& migrations();

}  // namespace axistune::store
