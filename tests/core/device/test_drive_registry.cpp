// SPDX-License-Identifier: GPL-3.0-or-later
// The backend registry (core/device/DriveRegistry.h): what is registered, how connect() dispatches,
// and the URIs the settings forms make (docs/drive-seam.md).
#include "core/device/DriveRegistry.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace axistune::device {
namespace {

const DriveBackend& backend(const std::string& scheme)
{
    const auto* b = findBackend(scheme);
    EXPECT_NE(b, nullptr) << scheme;
    return *b;
}

TEST(DriveRegistry, ListsTheBackendsInRegistrationOrder)
{
    std::vector<std::string> schemes;
    for (const auto& b : registeredBackends()) {
        schemes.push_back(b.scheme);
        EXPECT_FALSE(b.label.empty()) << b.scheme;
        EXPECT_FALSE(b.description.empty()) << b.scheme;
        EXPECT_EQ(b.uriForm.rfind(b.scheme, 0), 0u) << b.uriForm;
        EXPECT_TRUE(b.open && b.uriFromSettings) << b.scheme;
    }
    EXPECT_EQ(schemes, (std::vector<std::string>{"sim:", "modbus://", "replay:", "hal:", "linuxcnc:"}));
    EXPECT_EQ(registeredUriForms(), "sim:PRESET[?model=PATH&axis=NAME], modbus://HOST:PORT[?timeout_ms=N&map=FAMILY], "
                                    "replay:FILE.csv, hal: or linuxcnc:PATH/machine.ini");
}

TEST(DriveRegistry, ConnectDispatchesByScheme)
{
    auto d = connect({"sim:vmc", 1});
    ASSERT_TRUE(d.ok()) << d.error().detail;
    EXPECT_EQ((*d)->identify()->machine, "vmc");
    auto bad = connect({"canopen://1", 1});
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().code, ErrorCode::BadInput);
    EXPECT_NE(bad.error().detail.find("'canopen://1': unknown scheme; expected sim:PRESET"), std::string::npos)
        << bad.error().detail;
    EXPECT_NE(bad.error().detail.find("replay:FILE.csv"), std::string::npos);
    // Each backend's own errors name the URI.
    auto noFile = connect({"replay:/no/such/capture.csv", 1});
    ASSERT_FALSE(noFile.ok());
    EXPECT_NE(noFile.error().detail.find("/no/such/capture.csv"), std::string::npos) << noFile.error().detail;
    auto noPreset = connect({"sim:no-such-machine", 1});
    ASSERT_FALSE(noPreset.ok());
    EXPECT_NE(noPreset.error().detail.find("connection 'sim:no-such-machine'"), std::string::npos);
}

TEST(DriveRegistry, SettingsFormsMakeTheirUris)
{
    const auto& sim = backend("sim:");
    auto v = defaultSettings(sim);
    EXPECT_EQ(v.at("preset"), "vmc");
    EXPECT_EQ(sim.uriFromSettings(v).value(), "sim:vmc");
    v["model"] = "/tmp/m.json";
    v["axis"] = "X";
    EXPECT_EQ(sim.uriFromSettings(v).value(), "sim:vmc?model=/tmp/m.json&axis=X");
    v["preset"] = "no-such-preset";
    auto badPreset = sim.uriFromSettings(v);
    ASSERT_FALSE(badPreset.ok());
    EXPECT_NE(badPreset.error().detail.find("Machine preset 'no-such-preset' is not one of the choices"),
              std::string::npos);

    const auto& mb = backend("modbus://");
    auto m = defaultSettings(mb);
    EXPECT_EQ(mb.uriFromSettings(m).value(), "modbus://127.0.0.1:502");
    m["timeout_ms"] = "500";
    m["map"] = "other-family";
    EXPECT_EQ(mb.uriFromSettings(m).value(), "modbus://127.0.0.1:502?timeout_ms=500&map=other-family");
    m["port"] = "0";
    auto badPort = mb.uriFromSettings(m);
    ASSERT_FALSE(badPort.ok());
    EXPECT_EQ(badPort.error().detail, "Drive over Modbus TCP: Port '0' must be a whole number in 1..65535");
    m["port"] = "502";
    m["host"] = "";
    EXPECT_EQ(mb.uriFromSettings(m).error().detail, "Drive over Modbus TCP: Host is required");
    // The timeout's unit is part of its description (the form shows it).
    for (const auto& s : mb.settings) {
        if (s.name == "timeout_ms") {
            EXPECT_EQ(s.unit, "ms");
        }
    }

    const auto& replay = backend("replay:");
    auto r = defaultSettings(replay);
    EXPECT_FALSE(replay.uriFromSettings(r).ok());
    r["file"] = "/data/step.csv";
    EXPECT_EQ(replay.uriFromSettings(r).value(), "replay:/data/step.csv");
}

TEST(DriveRegistry, UriQueriesAreKeyValuePairs)
{
    auto q = parseUriQuery("a=1&b=two");
    ASSERT_TRUE(q.ok());
    EXPECT_EQ(q->at("a"), "1");
    EXPECT_EQ(q->at("b"), "two");
    EXPECT_TRUE(parseUriQuery("").value().empty());
    for (const char* bad : {"a", "a=", "=1", "a=1&b"}) {
        auto e = parseUriQuery(bad);
        ASSERT_FALSE(e.ok()) << bad;
        EXPECT_NE(e.error().detail.find("is not KEY=VALUE"), std::string::npos) << bad;
    }
}

TEST(DriveRegistry, TheEmbeddedDriveInjectsOnlyALostLink)
{
    auto d = connect({"sim:vmc?fault=drop-after:3", 1});
    ASSERT_TRUE(d.ok()) << d.error().detail;
    EXPECT_TRUE((*d)->identify().ok());
    EXPECT_TRUE((*d)->identify().ok());
    auto third = (*d)->identify();
    ASSERT_FALSE(third.ok());
    EXPECT_EQ(third.error().detail, "connection lost: fault drop-after:3 injected");
    auto delay = connect({"sim:vmc?fault=delay:100", 1});
    ASSERT_FALSE(delay.ok());
    EXPECT_NE(delay.error().detail.find("the embedded drive injects drop-after:N only"), std::string::npos);
    auto unknown = connect({"sim:vmc?colour=red", 1});
    ASSERT_FALSE(unknown.ok());
    EXPECT_NE(unknown.error().detail.find("unknown or empty option 'colour=red'"), std::string::npos);
}

} // namespace
} // namespace axistune::device
