// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The "no NaN, Inf or null where a number belongs" check of every CLI output (docs/robustness.md):
// CliRunner's runCli scans the stdout of every successful command and every JSON or CSV file it named
// after an output option (--out, --out-frf, --measured-out, ...; a folder is scanned file by file).
// JSON is parsed and walked (null anywhere fails; nlohmann cannot even read NaN/Inf, so those fail as
// "not JSON" when the text looked like JSON); CSV and other text is split into cells and a cell that
// reads nan, inf, infinity or null (any case and sign) fails. '#' metadata lines and quoted text are
// not cells of numbers and are left alone.

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace axistune::testing {

/// JSON pointers of the null values in `j`.
inline void findNulls(const nlohmann::json& j, const std::string& at, std::vector<std::string>& out)
{
    if (j.is_null())
        out.push_back(at.empty() ? "/" : at);
    else if (j.is_object())
        for (auto it = j.begin(); it != j.end(); ++it)
            findNulls(it.value(), at + "/" + it.key(), out);
    else if (j.is_array())
        for (std::size_t i = 0; i < j.size(); ++i)
            findNulls(j[i], at + "/" + std::to_string(i), out);
}

inline bool isBadNumberCell(std::string cell)
{
    std::transform(cell.begin(), cell.end(), cell.begin(), [](unsigned char c) { return std::tolower(c); });
    if (!cell.empty() && (cell[0] == '+' || cell[0] == '-'))
        cell.erase(0, 1);
    return cell == "nan" || cell == "inf" || cell == "infinity" || cell == "null" || cell == "nan(ind)";
}

/// What is wrong with `text` (named `what` in the messages); empty when it holds no NaN, Inf or null.
inline std::vector<std::string> scanOutputText(const std::string& text, const std::string& what)
{
    std::vector<std::string> bad;
    const auto first = text.find_first_not_of(" \t\r\n");
    if (first != std::string::npos && (text[first] == '{' || text[first] == '[')) {
        try {
            std::vector<std::string> nulls;
            findNulls(nlohmann::json::parse(text), "", nulls);
            for (const auto& p : nulls)
                bad.push_back(what + ": null at " + p);
            return bad;
        } catch (const nlohmann::json::exception& e) {
            // Not a single JSON document (NaN/Inf make it invalid, as do JSON lines): scan it as text.
        }
    }
    std::istringstream in(text);
    std::string line;
    for (int lineNo = 1; std::getline(in, line); ++lineNo) {
        if (!line.empty() && line[0] == '#')
            continue;
        std::string cell;
        bool quoted = false;
        auto flush = [&] {
            if (isBadNumberCell(cell))
                bad.push_back(what + " line " + std::to_string(lineNo) + ": '" + cell + "'");
            cell.clear();
        };
        for (char c : line) {
            if (c == '"') {
                quoted = !quoted;
                cell.clear();
                continue;
            }
            if (quoted)
                continue;
            if (c == ',' || c == ';' || c == '\t' || c == ' ' || c == ':' || c == '=' || c == '[' || c == ']' ||
                c == '{' || c == '}' || c == '\r')
                flush();
            else
                cell += c;
        }
        flush();
    }
    return bad;
}

/// The output files a command line names: the word after every option whose name contains "out"
/// (or "--opt=path"), when it is a file or a folder.
inline std::vector<std::filesystem::path> outputPathsOf(const std::string& args)
{
    std::vector<std::string> words;
    std::istringstream in(args);
    for (std::string w; in >> w;)
        words.push_back(w);
    std::vector<std::filesystem::path> out;
    for (std::size_t i = 0; i < words.size(); ++i) {
        const std::string& w = words[i];
        if (w.rfind("--", 0) != 0 || w.find("out") == std::string::npos)
            continue;
        std::string path;
        if (auto eq = w.find('='); eq != std::string::npos)
            path = w.substr(eq + 1);
        else if (i + 1 < words.size())
            path = words[i + 1];
        if (!path.empty() && path != "-" && std::filesystem::exists(path))
            out.emplace_back(path);
    }
    return out;
}

/// Every NaN, Inf or null in the stdout of a successful command and its JSON/CSV output files.
inline std::vector<std::string> scanCliOutputs(const std::string& args, const std::string& stdoutText)
{
    auto bad = scanOutputText(stdoutText, "stdout");
    auto scanFile = [&bad](const std::filesystem::path& p) {
        const auto ext = p.extension().string();
        if (ext != ".json" && ext != ".csv")
            return;
        std::ifstream f(p);
        std::stringstream s;
        s << f.rdbuf();
        auto b = scanOutputText(s.str(), p.string());
        bad.insert(bad.end(), b.begin(), b.end());
    };
    for (const auto& p : outputPathsOf(args)) {
        if (std::filesystem::is_directory(p)) {
            for (const auto& e : std::filesystem::recursive_directory_iterator(p))
                if (e.is_regular_file())
                    scanFile(e.path());
        } else if (std::filesystem::is_regular_file(p)) {
            scanFile(p);
        }
    }
    return bad;
}

} // namespace axistune::testing
