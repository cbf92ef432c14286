// SPDX-License-Identifier: GPL-3.0-or-later
// Foreign-file options of axistune-cli (app/cli/ImportOptions.h).
#include "app/cli/ImportOptions.h"

namespace axistune::cli {

void addImportOptions(CLI::App& sub, ImportCliOptions& o, bool withUff)
{
    std::vector<std::string> formats{"auto", "csv", "halscope"};
    if (withUff)
        formats.push_back("uff");
    sub.add_option(
           "--format", o.format,
           "input format: auto (default: .unv/.uff = UFF58, 'Sampling period is' = halscope log, else delimited text), "
           "csv, halscope" +
               std::string(withUff ? ", uff" : ""))
        ->check(CLI::IsMember(formats));
    sub.add_option("--separator", o.separator,
                   "column separator of a text file: auto (default), comma, semicolon, tab, space")
        ->check(CLI::IsMember({"auto", "comma", "semicolon", "tab", "space"}));
    sub.add_option("--decimal", o.decimal, "decimal mark: auto (default), point, comma")
        ->check(CLI::IsMember({"auto", "point", "comma"}));
    sub.add_flag("--no-header", o.noHeader, "the first line is data (columns named by --names, else col1, col2, ...)");
    sub.add_option("--names", o.names, "column names of a headerless file, comma separated")->delimiter(',');
    sub.add_option(
        "--unit", o.units,
        "unit of a column in the file, COL=UNIT (e.g. accel=g, force=kN, t=ms); converted to SI; repeatable");
}

Result<io::TableImportOptions> tableOptions(const ImportCliOptions& o)
{
    io::TableImportOptions t;
    t.separator = o.separator == "comma"       ? ','
                  : o.separator == "semicolon" ? ';'
                  : o.separator == "tab"       ? '\t'
                  : o.separator == "space"     ? ' '
                                               : 0;
    t.decimal = o.decimal == "comma"   ? io::DecimalMark::Comma
                : o.decimal == "point" ? io::DecimalMark::Point
                                       : io::DecimalMark::Auto;
    t.header = o.noHeader ? io::HeaderMode::Absent : io::HeaderMode::Auto;
    t.names = o.names;
    for (const auto& u : o.units) {
        const auto eq = u.find('=');
        if (eq == std::string::npos || eq == 0 || eq + 1 == u.size())
            return makeError(ErrorCode::BadInput, "--unit '" + u + "': expected COL=UNIT");
        t.units[u.substr(0, eq)] = u.substr(eq + 1);
    }
    return t;
}

std::string detectFormat(const std::string& path, const ImportCliOptions& o)
{
    return o.format != "auto" ? o.format : io::detectImportFormat(path);
}

Result<model::Capture> readTimeSeries(const std::string& path, const ImportCliOptions& o)
{
    auto t = tableOptions(o);
    if (!t)
        return t.error();
    return io::readTimeSeriesFile(path, *t, o.format);
}

} // namespace axistune::cli
