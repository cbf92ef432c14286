// SPDX-License-Identifier: GPL-3.0-or-later
// The test registers of a Modbus map and the request (core/device/TestRegisterCodec.h, docs/modbus.md "Test
// block"): one quantity per register, every test kind through the registers and back unchanged, a request the map
// cannot carry refused before anything is written, and maps whose fields carry nonsense refused when loaded.
#include "core/device/RegisterMap.h"
#include "core/device/TestRegisterCodec.h"

#include <cstring>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

using namespace axistune;
using namespace axistune::device;

namespace {

nlohmann::json committedMap()
{
    std::ifstream f(std::string(AXISTUNE_TEST_DATA_DIR) + "/../../resources/drives/axistune-sim.json");
    return nlohmann::json::parse(f);
}

RegisterMap simMap()
{
    auto m = loadRegisterMap("axistune-sim");
    EXPECT_TRUE(m.ok()) << m.error().detail;
    return m.ok() ? *m : RegisterMap{};
}

const std::vector<std::string> kAxes{"X", "Y", "Z"};

Result<int> indexOf(const std::string& axis)
{
    for (std::size_t i = 0; i < kAxes.size(); ++i) {
        if (kAxes[i] == axis)
            return static_cast<int>(i);
    }
    return makeError(ErrorCode::NotFound, "no axis " + axis);
}

/// What a server sees: the registers written, decoded and checked field by field as the served drive does.
Result<TestRequest> throughRegisters(const TestRequest& r, const RegisterMap& map)
{
    auto values = testValuesOf(r, map, indexOf);
    if (!values)
        return values.error();
    auto writes = encodeTestRegisters(*values, map);
    if (!writes)
        return writes.error();
    std::map<int, std::uint16_t> regs;
    for (const auto& w : *writes) {
        EXPECT_LE(w.words.size(), 123u);
        for (std::size_t k = 0; k < w.words.size(); ++k)
            regs[w.address + static_cast<int>(k)] = w.words[k];
    }
    TestValues seen;
    for (const auto& [n, f] : map.fields) {
        if (f.carries.empty())
            continue;
        std::vector<std::uint16_t> words;
        for (int a = f.address; a < f.address + f.count; ++a)
            words.push_back(regs.at(a));
        const double v = decodeCarried(f, words.data(), map.wordOrder);
        if (auto st = checkTestValue(f, map, v); !st)
            return st.error();
        seen[f.carries] = v;
    }
    return testRequestOf(seen, map, r.axis, kAxes);
}

/// The four f64 registers of `v` high word first (IEEE 754 bits, not the code under test's encoder).
std::vector<std::uint16_t> f64Words(double v)
{
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    return {static_cast<std::uint16_t>(bits >> 48), static_cast<std::uint16_t>(bits >> 32),
            static_cast<std::uint16_t>(bits >> 16), static_cast<std::uint16_t>(bits)};
}

std::vector<std::uint16_t> wordsAt(const std::vector<RegisterWrite>& writes, int address, int count)
{
    for (const auto& w : writes) {
        if (address >= w.address && address + count <= w.address + static_cast<int>(w.words.size()))
            return {w.words.begin() + (address - w.address), w.words.begin() + (address - w.address + count)};
    }
    return {};
}

std::string withField(const std::string& name, const nlohmann::json& field)
{
    auto j = committedMap();
    j["fields"][name] = field;
    return j.dump();
}

} // namespace

// Version 1 carried the step's rad/s, the current step's A, the FRF's % and the jog's jerk in one register
// (test.amplitude). Now every field of the committed map names the one quantity it carries, no quantity twice.
TEST(TestRegisters, EveryTestFieldOfTheCommittedMapCarriesOneQuantity)
{
    const auto j = committedMap();
    EXPECT_EQ(j["version"].get<int>(), 2);
    EXPECT_FALSE(j["fields"].contains("test.amplitude"));
    std::set<std::string> carried;
    std::set<int> addresses;
    for (const auto& [name, f] : j["fields"].items()) {
        if (name.rfind("test.", 0) != 0 && name.rfind("circle.", 0) != 0)
            continue;
        ASSERT_TRUE(f.contains("carries")) << name;
        const auto q = f["carries"].get<std::string>();
        if (q == "reserved")
            continue;
        EXPECT_TRUE(carried.insert(q).second) << q << " twice";
        EXPECT_TRUE(addresses.insert(f["address"].get<int>()).second) << name;
    }
    for (const char* q : {"step.velocity_rad_s", "current_step.current_a", "frf.amplitude_pct", "jog.jerk"})
        EXPECT_TRUE(carried.count(q)) << q;
}

TEST(TestRegisters, EachQuantityLandsInItsOwnRegisters)
{
    const auto map = simMap();
    const auto j = committedMap();
    auto at = [&](const char* field) { return j["fields"][field]["address"].get<int>(); };
    auto encode = [&](const TestRequest& r) {
        auto w = encodeTestRegisters(*testValuesOf(r, map, indexOf), map);
        EXPECT_TRUE(w.ok());
        return w.ok() ? *w : std::vector<RegisterWrite>{};
    };
    TestRequest step;
    step.axis = "X";
    step.type = TestType::Step;
    step.stepVelocityRadS = 12.5;
    auto w = encode(step);
    EXPECT_EQ(wordsAt(w, at("test.step_velocity"), 4), f64Words(12.5));
    EXPECT_EQ(wordsAt(w, at("test.current_step"), 4), f64Words(0.0));
    TestRequest current = step;
    current.type = TestType::CurrentStep;
    current.stepVelocityRadS = 0.0;
    current.currentA = 3.0;
    w = encode(current);
    EXPECT_EQ(wordsAt(w, at("test.current_step"), 4), f64Words(3.0));
    EXPECT_EQ(wordsAt(w, at("test.step_velocity"), 4), f64Words(0.0));
    TestRequest jog = step;
    jog.type = TestType::Jog;
    jog.stepVelocityRadS = 0.0;
    jog.jerk = 125000.0;
    jog.acceleration = 1250.0;
    w = encode(jog);
    EXPECT_EQ(wordsAt(w, at("test.jog_jerk"), 4), f64Words(125000.0));
    EXPECT_EQ(wordsAt(w, at("test.acceleration"), 4), f64Words(1250.0));
    // Two writes: the test block 200-299, then circle block, jerk and FRF amplitude 340-373.
    ASSERT_EQ(w.size(), 2u);
    EXPECT_EQ(w[0].address, 200);
    EXPECT_EQ(w[0].words.size(), 100u);
    EXPECT_EQ(w[1].address, 340);
    EXPECT_EQ(w[1].words.size(), 34u);
}

TEST(TestRegisters, EveryTestKindComesBackUnchanged)
{
    const auto map = simMap();
    std::vector<TestRequest> kinds;
    TestRequest r;
    r.axis = "Y";
    r.type = TestType::Step;
    r.stepVelocityRadS = -7.25;
    r.durationS = 0.3;
    r.traceDivider = 3;
    kinds.push_back(r);
    r = {};
    r.axis = "X";
    r.type = TestType::Jog;
    r.distance = -0.0125;
    r.velocity = 0.05;
    r.acceleration = 0.75;
    r.jerk = 40.0;
    r.returnToStart = true;
    r.durationS = 0.02;
    kinds.push_back(r);
    r = {};
    r.axis = "Z";
    r.type = TestType::Hold;
    r.durationS = 1.5;
    kinds.push_back(r);
    r = {};
    r.axis = "X";
    r.type = TestType::CurrentStep;
    r.currentA = 2.5;
    r.durationS = 0.004;
    kinds.push_back(r);
    r = {};
    r.axis = "X";
    r.type = TestType::Frf;
    r.frfMethod = FrfMethod::Prbs;
    r.fminHz = 20.0;
    r.fmaxHz = 1000.0;
    r.points = 40;
    r.amplitudePct = 7.5;
    r.settleS = 0.125;
    r.minMeasureS = 0.0625;
    kinds.push_back(r);
    r.frfMethod = FrfMethod::Multisine;
    r.multisinePeriods = 6;
    r.multisinePhases = dsp::MultisinePhases::Schroeder;
    r.multisineBands = {{20.0, 200.0, 2.5}, {200.0, 3900.0, 10.0}};
    kinds.push_back(r);
    r = {};
    r.axis = "X";
    r.type = TestType::Circle;
    r.secondAxis = "Y";
    r.radiusM = 0.05;
    r.feedMPerS = 0.025;
    r.direction = model::CircleDirection::Cw;
    r.centerXM = 0.01;
    r.centerYM = -0.02;
    r.dataStartDeg = 30.0;
    r.leadArcDeg = 60.0;
    r.durationS = 0.1;
    kinds.push_back(r);
    for (const auto& want : kinds) {
        const std::string kind = testTypeName(want.type);
        auto got = throughRegisters(want, map);
        ASSERT_TRUE(got.ok()) << kind << ": " << got.error().detail;
        EXPECT_EQ(got->axis, want.axis) << kind;
        EXPECT_EQ(got->type, want.type) << kind;
        EXPECT_EQ(got->stepVelocityRadS, want.stepVelocityRadS) << kind;
        EXPECT_EQ(got->currentA, want.currentA) << kind;
        EXPECT_EQ(got->distance, want.distance) << kind;
        EXPECT_EQ(got->velocity, want.velocity) << kind;
        EXPECT_EQ(got->acceleration, want.acceleration) << kind;
        EXPECT_EQ(got->jerk, want.jerk) << kind;
        EXPECT_EQ(got->returnToStart, want.returnToStart) << kind;
        EXPECT_EQ(got->durationS, want.durationS) << kind;
        EXPECT_EQ(got->traceDivider, want.traceDivider) << kind;
        if (want.type == TestType::Frf) {
            EXPECT_EQ(got->frfMethod, want.frfMethod) << kind;
            EXPECT_EQ(got->fminHz, want.fminHz);
            EXPECT_EQ(got->fmaxHz, want.fmaxHz);
            EXPECT_EQ(got->points, want.points);
            EXPECT_EQ(got->amplitudePct, want.amplitudePct);
            EXPECT_EQ(got->settleS, want.settleS);
            EXPECT_EQ(got->minMeasureS, want.minMeasureS);
            if (want.frfMethod == FrfMethod::Multisine) {
                EXPECT_EQ(got->multisinePeriods, 6);
                EXPECT_EQ(got->multisinePhases, dsp::MultisinePhases::Schroeder);
                ASSERT_EQ(got->multisineBands.size(), 2u);
                EXPECT_EQ(got->multisineBands[1].fminHz, 200.0);
                EXPECT_EQ(got->multisineBands[1].fmaxHz, 3900.0);
                EXPECT_EQ(got->multisineBands[1].spacingHz, 10.0);
            }
        }
        if (want.type == TestType::Circle) {
            EXPECT_EQ(got->secondAxis, "Y");
            EXPECT_EQ(got->direction, model::CircleDirection::Cw);
            EXPECT_EQ(got->radiusM, 0.05);
            EXPECT_EQ(got->feedMPerS, 0.025);
            EXPECT_EQ(got->centerXM, 0.01);
            EXPECT_EQ(got->centerYM, -0.02);
            EXPECT_EQ(got->dataStartDeg, 30.0);
            EXPECT_EQ(got->leadArcDeg, 60.0);
        }
    }
}

// A request the map has no register for is refused before anything is written, naming the quantity: a position
// step never reaches a drive that would take it for rad/s.
TEST(TestRegisters, AQuantityTheMapDoesNotCarryIsRefusedByName)
{
    const auto map = simMap();
    TestRequest step;
    step.axis = "X";
    step.type = TestType::Step;
    step.stepPosition = 0.002;
    auto v = testValuesOf(step, map, indexOf);
    ASSERT_FALSE(v);
    EXPECT_EQ(v.error().code, ErrorCode::BadInput);
    EXPECT_NE(v.error().detail.find("has no register for step.position"), std::string::npos) << v.error().detail;
    TestRequest frf;
    frf.axis = "X";
    frf.type = TestType::Frf;
    frf.frfQuantity = FrfQuantity::Plant;
    frf.amplitudePeak = 0.5;
    v = testValuesOf(frf, map, indexOf);
    ASSERT_FALSE(v);
    EXPECT_NE(v.error().detail.find("frf.amplitude_peak, frf.quantity"), std::string::npos) << v.error().detail;
    frf.frfQuantity = FrfQuantity::Default;
    frf.amplitudePeak = 0.0;
    frf.frfMethod = FrfMethod::Multisine;
    frf.multisineShape = {{10.0, 1.0}, {100.0, 2.0}};
    v = testValuesOf(frf, map, indexOf);
    ASSERT_FALSE(v);
    EXPECT_NE(v.error().detail.find("multisine.shape"), std::string::npos) << v.error().detail;
    frf.multisineShape.clear();
    frf.multisineBands.assign(5, {10.0, 100.0, 5.0});
    v = testValuesOf(frf, map, indexOf);
    ASSERT_FALSE(v);
    EXPECT_NE(v.error().detail.find("at most 4 multisine bands"), std::string::npos) << v.error().detail;
    TestRequest circle;
    circle.axis = "X";
    circle.type = TestType::Circle;
    circle.secondAxis = "Q";
    v = testValuesOf(circle, map, indexOf);
    ASSERT_FALSE(v);
    EXPECT_NE(v.error().detail.find("second plane axis: no axis Q"), std::string::npos) << v.error().detail;
    TestRequest many;
    many.axis = "X";
    many.type = TestType::Frf;
    many.points = 70000;
    v = testValuesOf(many, map, indexOf);
    ASSERT_TRUE(v.ok());
    auto w = encodeTestRegisters(*v, map);
    ASSERT_FALSE(w);
    EXPECT_EQ(w.error().code, ErrorCode::OutOfRange);
    EXPECT_NE(w.error().detail.find("frf.points must be a whole number in 0..65535"), std::string::npos)
        << w.error().detail;
}

TEST(TestRegisters, ServedValuesOutsideTheirQuantityAreRefused)
{
    const auto map = simMap();
    EXPECT_FALSE(checkTestValue(map.field("test.step_velocity"), map, std::nan("")));
    const auto bad = checkTestValue(map.field("test.type"), map, 9.0);
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().detail, "test.type: unknown test_type code 9");
    EXPECT_FALSE(checkTestValue(map.field("test.multisine_band_count"), map, 5.0));
    EXPECT_TRUE(checkTestValue(map.field("test.multisine_band_count"), map, 4.0));
    EXPECT_TRUE(checkTestValue(map.field("test.frf_method"), map, 3.0)); // multisine
}

TEST(TestRegisters, AMapWhoseFieldsCarryNonsenseIsRefusedWhenLoaded)
{
    auto m = parseRegisterMap(
        withField("test.extra", {{"address", 380}, {"type", "f64"}, {"carries", "step.velocity_m_s"}}), "bad.json");
    ASSERT_FALSE(m);
    EXPECT_NE(m.error().detail.find("field 'test.extra': carries unknown quantity 'step.velocity_m_s'"),
              std::string::npos)
        << m.error().detail;
    m = parseRegisterMap(withField("test.extra", {{"address", 380}, {"type", "f64"}, {"carries", "jog.jerk"}}),
                         "bad.json");
    ASSERT_FALSE(m);
    EXPECT_NE(m.error().detail.find("both carry jog.jerk"), std::string::npos) << m.error().detail;
    m = parseRegisterMap(withField("test.extra", {{"address", 380}, {"type", "u16"}, {"carries", "step.position"}}),
                         "bad.json");
    ASSERT_FALSE(m);
    EXPECT_NE(m.error().detail.find("step.position needs a f32 or f64 field"), std::string::npos)
        << m.error().detail;
    // An enumeration whose codes are not unique would decode a test as another one.
    auto j = committedMap();
    j["enums"]["test_type"]["frf"] = 0;
    m = parseRegisterMap(j.dump(), "bad.json");
    ASSERT_FALSE(m);
    EXPECT_NE(m.error().detail.find("enum 'test_type': 'frf' and 'step' have the same code 0"), std::string::npos)
        << m.error().detail;
    // A version 1 map (no "carries") is refused with the reason, not read as a drive without tests.
    j = committedMap();
    j["fields"]["test.type"].erase("carries");
    m = parseRegisterMap(j.dump(), "v1.json");
    ASSERT_FALSE(m);
    EXPECT_NE(m.error().detail.find("'test.type' must carry test.type (register map version 2"), std::string::npos)
        << m.error().detail;
    // A family that carries the position step (a drive that steps its position command) takes it.
    m = parseRegisterMap(withField("test.position_step", {{"address", 380}, {"type", "f64"}, {"carries", "step.position"}}),
                         "ok.json");
    ASSERT_TRUE(m.ok()) << m.error().detail;
    TestRequest step;
    step.axis = "X";
    step.type = TestType::Step;
    step.stepPosition = 0.002;
    auto back = throughRegisters(step, *m);
    ASSERT_TRUE(back.ok()) << back.error().detail;
    EXPECT_EQ(back->stepPosition, 0.002);
    EXPECT_EQ(back->stepVelocityRadS, 0.0);
}
