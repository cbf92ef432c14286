// SPDX-License-Identifier: GPL-3.0-or-later
// seeds: resources/samples/capture-*.csv resources/samples/frf-*.csv resources/samples/ballbar-*.csv
// Delimited-table import (io::readTable, auto separator, decimal mark and header; docs/formats.md
// "Imports"): refused with the source named, or channels of one length holding only finite values.
#include "core/io/TableImport.h"

#include <sstream>

#include "tests/fuzz/FuzzTarget.h"

using namespace axistune;

AXISTUNE_FUZZ_TARGET(table_import)
{
    std::istringstream in(input);
    fuzz::expect(io::readTable(in, fuzz::kSource, io::TableImportOptions{}), [](const model::Capture& c) {
        for (const auto& ch : c.channels) {
            fuzz::require(ch.data.size() == c.size(), "channels of different lengths");
            for (double v : ch.data)
                fuzz::requireFinite(v, "value of " + ch.name);
        }
    });
}
