// SPDX-License-Identifier: GPL-3.0-or-later
// Sessions from the CLI: records one store session per run of a capture/analysis command
// (issue 5 item 3; docs/storage.md "Sessions from the CLI"). Digests: SHA-256, FIPS 180-4.
#include "app/cli/SessionRecorder.h"

#include "app/cli/CliCommand.h"
#include "core/io/CaptureCsv.h"
#include "core/io/FrfCsv.h"
#include "core/io/Profile.h"
#include "core/model/InputLimits.h"
#include "core/store/Database.h"
#include "core/store/FrfCapture.h"
#include "core/store/SessionRecord.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <nlohmann/json.hpp>

namespace axistune::cli {

namespace {

namespace fs = std::filesystem;

constexpr std::uintmax_t kMaxInlineJsonBytes = 64 * 1024;       // input JSON files stored by content
constexpr std::size_t kMaxInlineTextBytes = 1024 * 1024;         // non-JSON stdout stored as text

std::uint32_t rotr(std::uint32_t x, int n) { return (x >> n) | (x << (32 - n)); }

void sha256Block(std::array<std::uint32_t, 8>& h, const unsigned char* p)
{
    static constexpr std::array<std::uint32_t, 64> k = {
        0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1, 0x923f82a4, 0xab1c5ed5,
        0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3, 0x72be5d74, 0x80deb1fe, 0x9bdc06a7, 0xc19bf174,
        0xe49b69c1, 0xefbe4786, 0x0fc19dc6, 0x240ca1cc, 0x2de92c6f, 0x4a7484aa, 0x5cb0a9dc, 0x76f988da,
        0x983e5152, 0xa831c66d, 0xb00327c8, 0xbf597fc7, 0xc6e00bf3, 0xd5a79147, 0x06ca6351, 0x14292967,
        0x27b70a85, 0x2e1b2138, 0x4d2c6dfc, 0x53380d13, 0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85,
        0xa2bfe8a1, 0xa81a664b, 0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585, 0x106aa070,
        0x19a4c116, 0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a, 0x5b9cca4f, 0x682e6ff3,
        0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208, 0x90befffa, 0xa4506ceb, 0xbef9a3f7, 0xc67178f2};
    std::array<std::uint32_t, 64> w{};
    for (int i = 0; i < 16; ++i)
        w[i] = (std::uint32_t(p[4 * i]) << 24) | (std::uint32_t(p[4 * i + 1]) << 16) | (std::uint32_t(p[4 * i + 2]) << 8)
               | std::uint32_t(p[4 * i + 3]);
    for (int i = 16; i < 64; ++i) {
        const auto s0 = rotr(w[i - 15], 7) ^ rotr(w[i - 15], 18) ^ (w[i - 15] >> 3);
        const auto s1 = rotr(w[i - 2], 17) ^ rotr(w[i - 2], 19) ^ (w[i - 2] >> 10);
        w[i] = w[i - 16] + s0 + w[i - 7] + s1;
    }
    auto v = h;
    for (int i = 0; i < 64; ++i) {
        const auto s1 = rotr(v[4], 6) ^ rotr(v[4], 11) ^ rotr(v[4], 25);
        const auto ch = (v[4] & v[5]) ^ (~v[4] & v[6]);
        const auto t1 = v[7] + s1 + ch + k[i] + w[i];
        const auto s0 = rotr(v[0], 2) ^ rotr(v[0], 13) ^ rotr(v[0], 22);
        const auto maj = (v[0] & v[1]) ^ (v[0] & v[2]) ^ (v[1] & v[2]);
        v = {t1 + s0 + maj, v[0], v[1], v[2], v[3] + t1, v[4], v[5], v[6]};
    }
    for (int i = 0; i < 8; ++i)
        h[i] += v[i];
}

/// Copies everything written to a stream to its original buffer and keeps a copy.
class TeeBuf : public std::streambuf {
public:
    explicit TeeBuf(std::streambuf* target) : m_target(target) {}
    const std::string& text() const { return m_text; }

protected:
    int overflow(int c) override
    {
        if (c == traits_type::eof())
            return traits_type::not_eof(c);
        m_text.push_back(static_cast<char>(c));
        return m_target->sputc(static_cast<char>(c));
    }
    std::streamsize xsputn(const char* s, std::streamsize n) override
    {
        m_text.append(s, static_cast<std::size_t>(n));
        return m_target->sputn(s, n);
    }
    int sync() override { return m_target->pubsync(); }

private:
    std::streambuf* m_target;
    std::string m_text;
};

/// Redirects a stream into a TeeBuf for its lifetime.
class StreamTee {
public:
    explicit StreamTee(std::ostream& s) : m_stream(s), m_buf(s.rdbuf()) { m_old = s.rdbuf(&m_buf); }
    ~StreamTee() { m_stream.rdbuf(m_old); }
    StreamTee(const StreamTee&) = delete;
    StreamTee& operator=(const StreamTee&) = delete;
    const std::string& text() const { return m_buf.text(); }

private:
    std::ostream& m_stream;
    TeeBuf m_buf;
    std::streambuf* m_old = nullptr;
};

struct SessionFlags {
    std::string db;
    std::string machine;
    std::string operatorName;
    std::string note;
};

bool isOwnOption(const std::string& name)
{
    return name == "db" || name == "machine" || name == "operator" || name == "note" || name == "help";
}
bool isOutputOption(const std::string& name) { return name.find("out") != std::string::npos; }

std::string optionName(const CLI::Option* opt)
{
    const auto& l = opt->get_lnames();
    return l.empty() ? opt->get_name() : l.front();
}

std::optional<std::string> readWholeFile(const fs::path& p)
{
    auto text = model::readInputFile(p.string());
    if (!text)
        return std::nullopt;
    return std::move(text).value();
}

bool isRegularFile(const std::string& path)
{
    std::error_code ec;
    return !path.empty() && fs::is_regular_file(path, ec);
}

nlohmann::json fileEntry(const std::string& option, const std::string& path, bool withContent)
{
    nlohmann::json e{{"option", "--" + option}, {"path", model::displayPath(path)}};
    auto bytes = readWholeFile(path);
    if (!bytes)
        return e;
    e["bytes"] = bytes->size();
    e["sha256"] = sha256Hex(*bytes);
    if (withContent && bytes->size() <= kMaxInlineJsonBytes) {
        if (auto j = model::parseJsonText(*bytes, path))
            e["content"] = std::move(j).value();
    }
    return e;
}

/// The options given, the defaults of the others and every input file named by an option.
nlohmann::json inputsJson(const CLI::App& sub)
{
    nlohmann::json options = nlohmann::json::object();
    nlohmann::json defaults = nlohmann::json::object();
    nlohmann::json files = nlohmann::json::array();
    for (const CLI::Option* opt : sub.get_options()) {
        const auto name = optionName(opt);
        if (isOwnOption(name))
            continue;
        if (opt->count() == 0) {
            if (!opt->get_default_str().empty())
                defaults["--" + name] = opt->get_default_str();
            continue;
        }
        const auto& res = opt->results();
        options["--" + name] = res.size() == 1 ? nlohmann::json(res.front()) : nlohmann::json(res);
        if (isOutputOption(name))
            continue;
        for (const auto& v : res) {
            if (isRegularFile(v))
                files.push_back(fileEntry(name, v, true));
        }
    }
    return {{"command", sub.get_name()}, {"options", options}, {"defaults", defaults}, {"files", files}};
}

struct FileStamp {
    bool exists = false;
    fs::file_time_type time{};
    std::uintmax_t size = 0;
};

FileStamp stamp(const std::string& path)
{
    std::error_code ec;
    FileStamp s;
    s.exists = fs::is_regular_file(path, ec);
    if (s.exists) {
        s.time = fs::last_write_time(path, ec);
        s.size = fs::file_size(path, ec);
    }
    return s;
}

struct OutputFile {
    std::string option;
    std::string path;
    FileStamp before;
};

std::vector<OutputFile> outputFiles(const CLI::App& sub)
{
    std::vector<OutputFile> out;
    for (const CLI::Option* opt : sub.get_options()) {
        const auto name = optionName(opt);
        if (isOwnOption(name) || !isOutputOption(name) || opt->count() == 0)
            continue;
        for (const auto& v : opt->results())
            out.push_back({name, v, stamp(v)});
    }
    return out;
}

/// Adds a file the command wrote: a capture (capture or FRF CSV), a result (JSON) or its digest.
void addOutput(store::SessionRecord& rec, const OutputFile& f)
{
    const auto now = stamp(f.path);
    if (!now.exists || (f.before.exists && now.time == f.before.time && now.size == f.before.size))
        return;  // not written by this run
    const nlohmann::json where{{"option", "--" + f.option}, {"path", model::displayPath(f.path)}};
    auto bytes = readWholeFile(f.path);
    if (!bytes)
        return;
    if (auto j = model::parseJsonText(*bytes, f.path)) {
        rec.results.push_back({f.option, {{"file", where}, {"data", std::move(j).value()}}, {}});
        return;
    }
    if (auto frf = io::readFrfCsvFile(f.path)) {
        rec.captures.push_back({f.option, store::frfAsCapture(*frf)});
    } else if (auto cap = io::readCaptureCsvFile(f.path)) {
        rec.captures.push_back({f.option, std::move(cap).value()});
    } else {
        rec.results.push_back({f.option, {{"file", where}, {"bytes", bytes->size()}, {"sha256", sha256Hex(*bytes)}}, {}});
        return;
    }
    rec.captures.back().capture.metadata.set("file", model::displayPath(f.path));
}

void addStdout(store::SessionRecord& rec, const std::string& text)
{
    if (text.empty())
        return;
    if (auto j = model::parseJsonText(text, "stdout"))
        rec.results.push_back({"stdout", std::move(j).value(), {}});
    else if (text.size() <= kMaxInlineTextBytes)
        rec.results.push_back({"stdout", {{"text", text}}, {}});
    else
        rec.results.push_back({"stdout", {{"bytes", text.size()}, {"sha256", sha256Hex(text)}}, {}});
}

std::string toLower(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

/// The store's spelling of the command's --axis, if the machine has that axis (never creates one).
std::string sessionAxis(const CLI::App& sub, const io::MachineProfile& profile)
{
    const CLI::Option* opt = nullptr;
    try {
        opt = sub.get_option("--axis");
    } catch (const CLI::OptionNotFound&) {
        return {};
    }
    if (opt->count() == 0 || opt->results().empty())
        return {};
    const auto wanted = toLower(opt->results().front());
    for (const auto& a : profile.axes) {
        if (toLower(a.name) == wanted)
            return a.name;
    }
    return {};
}

store::SessionStatus statusFor(int exitCode)
{
    if (exitCode == 0)
        return store::SessionStatus::Completed;
    if (exitCode == exitCodeFor(ErrorCode::Safety))
        return store::SessionStatus::Aborted;
    return store::SessionStatus::Failed;
}

/// Opens the store and loads the machine; a missing store or machine is bad input naming both.
Result<io::MachineProfile> openMachine(const SessionFlags& f, std::optional<store::Database>& db)
{
    const std::string howTo = "create it with 'axistune-cli profile import --db " + f.db + " --in PROFILE.json'";
    auto opened = store::Database::open(f.db, store::OpenMode::MustExist);
    if (!opened) {
        if (opened.error().code == ErrorCode::NotFound)
            return makeError(ErrorCode::BadInput, "store " + f.db + " does not exist; " + howTo
                                                      + " (a profile with machine '" + f.machine + "')");
        return makeError(opened.error().code,
                         opened.error().detail + " (checked before running; nothing was measured)");
    }
    auto machines = opened->listMachines();
    if (!machines)
        return machines.error();
    if (std::find(machines->begin(), machines->end(), f.machine) == machines->end()) {
        std::string known;
        for (const auto& m : *machines)
            known += (known.empty() ? "" : ", ") + m;
        return makeError(ErrorCode::BadInput, "machine '" + f.machine + "' is not in store " + f.db + " (machines: "
                                                  + (known.empty() ? "none" : known) + "); " + howTo);
    }
    auto profile = opened->loadProfile(f.machine);
    if (!profile)
        return profile.error();
    // Before the command runs: a test is never measured for a session the store cannot take.
    if (auto st = opened->checkWritable(); !st)
        return makeError(st.error().code, st.error().detail + " (checked before running; nothing was measured)");
    db.emplace(std::move(opened).value());
    return profile;
}

int runRecorded(const CLI::App& sub, const SessionFlags& flags, const std::function<int()>& run)
{
    const std::string cmd = sub.get_name();
    std::optional<store::Database> db;
    auto profile = openMachine(flags, db);
    if (!profile)
        return reportError(cmd, profile.error());

    store::SessionRecord rec;
    rec.info.machine = flags.machine;
    rec.info.axis = sessionAxis(sub, *profile);
    rec.info.kind = cmd;
    rec.info.operatorName = flags.operatorName;
    rec.info.note = flags.note;
    rec.info.started = store::nowIso8601();
    rec.inputs = inputsJson(sub);
    const auto outputs = outputFiles(sub);

    int rc = 0;
    std::string outText;
    std::string errText;
    {
        StreamTee out(std::cout);
        StreamTee err(std::cerr);
        try {
            rc = run();
        } catch (const std::exception& e) {
            rc = 1;
            std::cerr << "axistune-cli " << cmd << ": " << e.what() << '\n';
        }
        std::cout.flush();
        outText = out.text();
        errText = err.text();
    }
    rec.info.finished = store::nowIso8601();
    rec.info.status = statusFor(rc);
    addStdout(rec, outText);
    for (const auto& f : outputs)
        addOutput(rec, f);
    if (rc != 0)
        rec.results.push_back({"error", {{"exit_code", rc}, {"message", errText}}, {}});

    auto id = db->recordSession(rec);
    if (!id) {
        const int storeRc = reportError(cmd, id.error());
        return rc != 0 ? rc : storeRc;
    }
    std::cerr << "axistune-cli " << cmd << ": recorded session " << *id << " (" << store::toString(rec.info.status)
              << ") in " << flags.db << '\n';
    return rc;
}

}  // namespace

std::string sha256Hex(const std::string& bytes)
{
    std::array<std::uint32_t, 8> h = {0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a,
                                      0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19};
    std::string msg = bytes;
    const std::uint64_t bits = static_cast<std::uint64_t>(bytes.size()) * 8;
    msg.push_back(static_cast<char>(0x80));
    while (msg.size() % 64 != 56)
        msg.push_back('\0');
    for (int i = 7; i >= 0; --i)
        msg.push_back(static_cast<char>((bits >> (8 * i)) & 0xff));
    for (std::size_t off = 0; off < msg.size(); off += 64)
        sha256Block(h, reinterpret_cast<const unsigned char*>(msg.data() + off));
    static constexpr char kHex[] = "0123456789abcdef";
    std::string out;
    for (auto w : h) {
        for (int i = 7; i >= 0; --i)
            out.push_back(kHex[(w >> (4 * i)) & 0xf]);
    }
    return out;
}

std::function<int()> recordSessions(CLI::App& sub, std::function<int()> run)
{
    auto flags = std::make_shared<SessionFlags>();
    auto* db = sub.add_option("--db", flags->db, "store file: record this run as a session (needs --machine)");
    auto* machine = sub.add_option("--machine", flags->machine, "machine of the session (must be in the store)");
    db->needs(machine);
    machine->needs(db);
    sub.add_option("--operator", flags->operatorName, "operator recorded with the session")->needs(db);
    sub.add_option("--note", flags->note, "note recorded with the session")->needs(db);
    CLI::App* app = &sub;
    return [app, flags, run = std::move(run)] {
        if (flags->db.empty())
            return run();
        return runRecorded(*app, *flags, run);
    };
}

}  // namespace axistune::cli
