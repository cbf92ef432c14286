// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli import-frf: an FRF from another program (a delimited table with one or several FRFs, an FRF
// CSV with a units key, a UFF58 file) converted to AxisTune's FRF CSV in SI (docs/formats.md "Imports").
#include "app/cli/CliCommand.h"
#include "app/cli/ImportOptions.h"
#include "core/io/FrfCsv.h"
#include "core/io/TableImport.h"
#include "core/io/Uff58.h"
#include "core/model/MetadataJson.h"
#include "core/model/MetadataKeys.h"

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

namespace axistune::cli {

namespace {

struct ImportFrfOptions {
    std::string in, out;
    ImportCliOptions import;
    std::string column, freqColumn, units;
    int record = 0; // UFF: 1-based index among the FRF records; 0: the only one
};

Result<dsp::FrequencyResponse> readForeignFrf(const ImportFrfOptions& o)
{
    const std::string format = detectFormat(o.in, o.import);
    if (format == "uff") {
        auto recs = io::readUff58File(o.in);
        if (!recs)
            return recs.error();
        std::vector<const io::Uff58Record*> frfs;
        for (const auto& r : *recs) {
            if (r.isComplex())
                frfs.push_back(&r);
        }
        if (frfs.empty())
            return makeError(ErrorCode::BadInput, o.in + ": no complex (FRF) record among its " +
                                                      std::to_string(recs->size()) + " dataset-58 records");
        if (o.record == 0 && frfs.size() > 1)
            return makeError(ErrorCode::BadInput,
                             o.in + ": " + std::to_string(frfs.size()) + " FRF records; choose one with --record N");
        if (o.record > static_cast<int>(frfs.size()))
            return makeError(ErrorCode::OutOfRange, o.in + ": --record " + std::to_string(o.record) +
                                                        ", the file has " + std::to_string(frfs.size()) +
                                                        " FRF records");
        auto frf = io::frfFromUff(*frfs[o.record == 0 ? 0 : static_cast<std::size_t>(o.record - 1)], o.in);
        if (frf && !o.units.empty())
            return makeError(ErrorCode::BadInput, "--units is for text files; a UFF58 file states its units");
        return frf;
    }
    if (format == "halscope")
        return makeError(ErrorCode::BadInput, o.in + ": a halscope log holds time series, not an FRF; use frf --in");
    auto t = tableOptions(o.import);
    if (!t)
        return t.error();
    auto table = io::readTableFile(o.in, *t);
    if (!table)
        return table.error();
    io::FrfColumnOptions c;
    c.frequencyColumn = o.freqColumn;
    c.name = o.column;
    c.units = o.units;
    return io::frfFromTable(*table, o.in, c);
}

int runImportFrf(const ImportFrfOptions& o)
{
    const std::string cmd = "import-frf";
    auto frf = readForeignFrf(o);
    if (!frf)
        return reportError(cmd, frf.error());
    if (!frf->metadata.contains(model::meta::kUnits))
        std::cerr << "axistune-cli import-frf: note: " << o.in
                  << " states no units; h is taken as it is (give --units)\n";
    frf.value().metadata.set("imported_from", o.in);
    if (auto st = io::writeFrfCsvFile(o.out, *frf); !st)
        return reportError(cmd, st.error());
    std::cout << nlohmann::json{{"out", o.out}, {"points", frf->size()}, {"metadata", frf->metadata}}.dump() << '\n';
    return 0;
}

const CliRegistrar kRegistrar{CliCommand{
    "import-frf",
    "Convert an FRF from another program (delimited table, FRF CSV with units, UFF58) to an AxisTune FRF CSV in SI",
    [](CLI::App& sub) -> std::function<int()> {
        auto o = std::make_shared<ImportFrfOptions>();
        sub.add_option("--in", o->in, "input file")->required();
        sub.add_option("--out", o->out, "AxisTune FRF CSV to write")->required();
        addImportOptions(sub, o->import);
        sub.add_option("--column", o->column,
                       "the FRF of a table with several: columns <NAME>_re/<NAME>_im (e.g. H11)");
        sub.add_option("--freq-column", o->freqColumn,
                       "frequency column [Hz] (default f_Hz, freq_Hz, f, freq or frequency)");
        sub.add_option("--units", o->units,
                       "unit of h in a text file: m/N, mm/N, um/N, nm/N, m/s/N, mm/s/N, m/s2/N, mm/s2/N, g/N "
                       "(default: the file's '# units=' line)");
        sub.add_option("--record", o->record, "UFF58: which FRF record, 1-based (default: the only one)")
            ->check(CLI::PositiveNumber);
        return [o] { return runImportFrf(*o); };
    }}};

} // namespace

} // namespace axistune::cli
