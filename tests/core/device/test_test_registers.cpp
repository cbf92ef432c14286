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
// Version 3 (one request type per test kind, Drive.h): test.duration is test.record, the jog's and the circle's dwell
// and the circle's move to its start point have registers of their own.
TEST(TestRegisters, EveryTestFieldOfTheCommittedMapCarriesOneQuantity)
{
    const auto j = committedMap();
    EXPECT_EQ(j["version"].get<int>(), 3);
    EXPECT_FALSE(j["fields"].contains("test.amplitude"));
    EXPECT_FALSE(j["fields"].contains("test.duration"));
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
    for (const char* q : {"step.velocity_rad_s", "current_step.current_a", "frf.amplitude_pct", "jog.jerk",
                          "test.record_s", "test.dwell_s", "circle.positioning_m_per_s", "circle.positioning_m_per_s2"})
        EXPECT_TRUE(carried.count(q)) << q;
    auto field = [&](const char* name, const char* quantity, int address) {
        ASSERT_TRUE(j["fields"].contains(name)) << name;
        EXPECT_EQ(j["fields"][name]["carries"].get<std::string>(), quantity) << name;
        EXPECT_EQ(j["fields"][name]["address"].get<int>(), address) << name;
    };
    field("test.record", "test.record_s", 222);
    field("test.dwell", "test.dwell_s", 374);
    field("circle.positioning_speed", "circle.positioning_m_per_s", 378);
    field("circle.positioning_accel", "circle.positioning_m_per_s2", 382);
}

// The map the simulator serves (the committed map, generated from its catalogue) has a register for every quantity
// of the test block, so that every field of every request kind reaches the simulated drive; except the three its
// drive does not take, which stay without a register so that a request giving them is refused by name
// (AQuantityTheMapDoesNotCarryIsRefusedByName): a position step (the simulator steps the motor velocity), an FRF
// peak in the injection point's units and an FRF quantity other than the drive's own.
TEST(TestRegisters, TheSimulatorsMapCarriesEveryTestQuantity)
{
    const auto map = simMap();
    std::set<std::string> carried;
    for (const auto& [n, f] : map.fields) {
        if (!f.carries.empty())
            carried.insert(f.carries);
    }
    const std::set<std::string> notTaken{"step.position", "frf.amplitude_peak", "frf.quantity"};
    ASSERT_FALSE(testQuantities().empty());
    for (const auto& q : testQuantities()) {
        if (q.name == "reserved")
            continue;
        if (notTaken.count(q.name))
            EXPECT_FALSE(carried.count(q.name)) << q.name << " has a register in " << map.family;
        else
            EXPECT_TRUE(carried.count(q.name)) << q.name << " has no register in " << map.family;
    }
    for (const char* q : {"test.record_s", "test.dwell_s", "circle.positioning_m_per_s", "circle.positioning_m_per_s2"})
        EXPECT_NE(findTestQuantity(q), nullptr) << q;
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
    step.test.emplace<StepTest>().velocityRadS = 12.5;
    auto w = encode(step);
    EXPECT_EQ(wordsAt(w, at("test.step_velocity"), 4), f64Words(12.5));
    EXPECT_EQ(wordsAt(w, at("test.current_step"), 4), f64Words(0.0));
    TestRequest current;
    current.axis = "X";
    current.test.emplace<CurrentStepTest>().currentA = 3.0;
    w = encode(current);
    EXPECT_EQ(wordsAt(w, at("test.current_step"), 4), f64Words(3.0));
    EXPECT_EQ(wordsAt(w, at("test.step_velocity"), 4), f64Words(0.0));
    TestRequest jog;
    jog.axis = "X";
    auto& j1 = jog.test.emplace<JogTest>();
    j1.jerk = 125000.0;
    j1.acceleration = 1250.0;
    w = encode(jog);
    EXPECT_EQ(wordsAt(w, at("test.jog_jerk"), 4), f64Words(125000.0));
    EXPECT_EQ(wordsAt(w, at("test.acceleration"), 4), f64Words(1250.0));
    // Two writes: the test block 200-299, then the circle block, jerk, FRF amplitude, dwell and the circle's
    // positioning 340-385.
    ASSERT_EQ(w.size(), 2u);
    EXPECT_EQ(w[0].address, 200);
    EXPECT_EQ(w[0].words.size(), 100u);
    EXPECT_EQ(w[1].address, 340);
    EXPECT_EQ(w[1].words.size(), 46u);
}

namespace {

/// Every field of the request's kind equals the wanted one's (the request built by the test is the expectation).
void expectSameRequest(const TestRequest& got, const TestRequest& want)
{
    const std::string kind = testTypeName(want.type());
    EXPECT_EQ(got.axis, want.axis) << kind;
    EXPECT_EQ(got.traceDivider, want.traceDivider) << kind;
    ASSERT_EQ(got.type(), want.type()) << kind;
    switch (want.type()) {
    case TestType::Step:
        EXPECT_EQ(got.step().velocityRadS, want.step().velocityRadS);
        EXPECT_EQ(got.step().position, want.step().position);
        EXPECT_EQ(got.step().recordS, want.step().recordS);
        break;
    case TestType::Jog: {
        const auto& g = got.jog();
        const auto& e = want.jog();
        EXPECT_EQ(g.distance, e.distance);
        EXPECT_EQ(g.velocity, e.velocity);
        EXPECT_EQ(g.acceleration, e.acceleration);
        EXPECT_EQ(g.jerk, e.jerk);
        EXPECT_EQ(g.returnToStart, e.returnToStart);
        EXPECT_EQ(g.dwellS, e.dwellS);
        break;
    }
    case TestType::Hold:
        EXPECT_EQ(got.hold().recordS, want.hold().recordS);
        break;
    case TestType::CurrentStep:
        EXPECT_EQ(got.currentStep().currentA, want.currentStep().currentA);
        EXPECT_EQ(got.currentStep().recordS, want.currentStep().recordS);
        break;
    case TestType::Frf: {
        const auto& g = got.frf();
        const auto& e = want.frf();
        EXPECT_EQ(g.method, e.method);
        EXPECT_EQ(g.fminHz, e.fminHz);
        EXPECT_EQ(g.fmaxHz, e.fmaxHz);
        EXPECT_EQ(g.points, e.points);
        EXPECT_EQ(g.amplitudePct, e.amplitudePct);
        EXPECT_EQ(g.amplitudePeak, e.amplitudePeak);
        EXPECT_EQ(g.quantity, e.quantity);
        EXPECT_EQ(g.settleS, e.settleS);
        EXPECT_EQ(g.minMeasureS, e.minMeasureS);
        EXPECT_EQ(g.multisineSpacingHz, e.multisineSpacingHz);
        EXPECT_EQ(g.multisinePeriods, e.multisinePeriods);
        EXPECT_EQ(g.multisinePhases, e.multisinePhases);
        ASSERT_EQ(g.multisineBands.size(), e.multisineBands.size());
        for (std::size_t i = 0; i < e.multisineBands.size(); ++i) {
            EXPECT_EQ(g.multisineBands[i].fminHz, e.multisineBands[i].fminHz) << i;
            EXPECT_EQ(g.multisineBands[i].fmaxHz, e.multisineBands[i].fmaxHz) << i;
            EXPECT_EQ(g.multisineBands[i].spacingHz, e.multisineBands[i].spacingHz) << i;
        }
        EXPECT_EQ(g.multisineShape, e.multisineShape);
        break;
    }
    case TestType::Circle: {
        const auto& g = got.circle();
        const auto& e = want.circle();
        EXPECT_EQ(g.secondAxis, e.secondAxis);
        EXPECT_EQ(g.direction, e.direction);
        EXPECT_EQ(g.radiusM, e.radiusM);
        EXPECT_EQ(g.feedMPerS, e.feedMPerS);
        EXPECT_EQ(g.centerXM, e.centerXM);
        EXPECT_EQ(g.centerYM, e.centerYM);
        EXPECT_EQ(g.dataStartDeg, e.dataStartDeg);
        EXPECT_EQ(g.leadArcDeg, e.leadArcDeg);
        EXPECT_EQ(g.positioningMPerS, e.positioningMPerS);
        EXPECT_EQ(g.positioningMPerS2, e.positioningMPerS2);
        EXPECT_EQ(g.dwellS, e.dwellS);
        break;
    }
    }
}

/// One request of every kind, every field the sim map carries away from its default.
std::vector<TestRequest> oneOfEachKind()
{
    std::vector<TestRequest> kinds;
    TestRequest r;
    r.axis = "Y";
    auto& step = r.test.emplace<StepTest>();
    step.velocityRadS = -7.25;
    step.recordS = 0.3;
    r.traceDivider = 3;
    kinds.push_back(r);
    r = {};
    r.axis = "X";
    auto& jog = r.test.emplace<JogTest>();
    jog.distance = -0.0125;
    jog.velocity = 0.05;
    jog.acceleration = 0.75;
    jog.jerk = 40.0;
    jog.returnToStart = true;
    jog.dwellS = 0.02;
    kinds.push_back(r);
    r = {};
    r.axis = "Z";
    r.test.emplace<HoldTest>().recordS = 1.5;
    kinds.push_back(r);
    r = {};
    r.axis = "X";
    auto& current = r.test.emplace<CurrentStepTest>();
    current.currentA = 2.5;
    current.recordS = 0.004;
    kinds.push_back(r);
    r = {};
    r.axis = "X";
    auto& frf = r.test.emplace<FrfTest>();
    frf.method = FrfMethod::Prbs;
    frf.fminHz = 20.0;
    frf.fmaxHz = 1000.0;
    frf.points = 40;
    frf.amplitudePct = 7.5;
    frf.settleS = 0.125;
    frf.minMeasureS = 0.0625;
    kinds.push_back(r);
    frf.method = FrfMethod::Multisine;
    frf.multisinePeriods = 6;
    frf.multisinePhases = dsp::MultisinePhases::Schroeder;
    frf.multisineBands = {{20.0, 200.0, 2.5}, {200.0, 3900.0, 10.0}};
    kinds.push_back(r);
    r = {};
    r.axis = "X";
    auto& circle = r.test.emplace<CircleTest>();
    circle.secondAxis = "Y";
    circle.radiusM = 0.05;
    circle.feedMPerS = 0.025;
    circle.direction = model::CircleDirection::Cw;
    circle.centerXM = 0.01;
    circle.centerYM = -0.02;
    circle.dataStartDeg = 30.0;
    circle.leadArcDeg = 60.0;
    circle.positioningMPerS = 0.02;
    circle.positioningMPerS2 = 0.5;
    circle.dwellS = 0.25;
    kinds.push_back(r);
    return kinds;
}

} // namespace

TEST(TestRegisters, EveryTestKindComesBackUnchanged)
{
    const auto map = simMap();
    const auto kinds = oneOfEachKind();
    ASSERT_EQ(kinds.size(), 7u);
    for (const auto& want : kinds) {
        const std::string kind = testTypeName(want.type());
        auto got = throughRegisters(want, map);
        ASSERT_TRUE(got.ok()) << kind << ": " << got.error().detail;
        SCOPED_TRACE(kind);
        expectSameRequest(*got, want);
    }
}

// Version 2 had one test.duration: the record length of a step, hold or current step and the dwell of a jog or
// circle. Now a jog's dwell travels in test.dwell_s (register test.dwell) and a record length in test.record_s
// (test.record), each only for its own kinds, and both come back into the field they came from.
TEST(TestRegisters, AJogsDwellAndAStepsRecordLengthTravelInTheirOwnQuantities)
{
    const auto map = simMap();
    const auto j = committedMap();
    auto at = [&](const char* field) { return j["fields"][field]["address"].get<int>(); };

    TestRequest jog;
    jog.axis = "X";
    auto& jogTest = jog.test.emplace<JogTest>();
    jogTest.distance = 0.01;
    jogTest.velocity = 0.02;
    jogTest.acceleration = 0.5;
    jogTest.dwellS = 0.35;
    auto v = testValuesOf(jog, map, indexOf);
    ASSERT_TRUE(v.ok()) << v.error().detail;
    ASSERT_EQ(v->count("test.dwell_s"), 1u);
    EXPECT_EQ(v->at("test.dwell_s"), 0.35);
    EXPECT_EQ(v->count("test.record_s"), 0u);
    auto w = encodeTestRegisters(*v, map);
    ASSERT_TRUE(w.ok()) << w.error().detail;
    EXPECT_EQ(wordsAt(*w, at("test.dwell"), 4), f64Words(0.35));
    EXPECT_EQ(wordsAt(*w, at("test.record"), 4), f64Words(0.0));
    auto back = testRequestOf(*v, map, "X", kAxes);
    ASSERT_TRUE(back.ok()) << back.error().detail;
    ASSERT_TRUE(back->is<JogTest>());
    expectSameRequest(*back, jog);
    auto served = throughRegisters(jog, map);
    ASSERT_TRUE(served.ok()) << served.error().detail;
    expectSameRequest(*served, jog);

    TestRequest step;
    step.axis = "X";
    auto& s = step.test.emplace<StepTest>();
    s.velocityRadS = 4.0;
    s.recordS = 0.45;
    v = testValuesOf(step, map, indexOf);
    ASSERT_TRUE(v.ok()) << v.error().detail;
    ASSERT_EQ(v->count("test.record_s"), 1u);
    EXPECT_EQ(v->at("test.record_s"), 0.45);
    EXPECT_EQ(v->count("test.dwell_s"), 0u);
    w = encodeTestRegisters(*v, map);
    ASSERT_TRUE(w.ok()) << w.error().detail;
    EXPECT_EQ(wordsAt(*w, at("test.record"), 4), f64Words(0.45));
    EXPECT_EQ(wordsAt(*w, at("test.dwell"), 4), f64Words(0.0));
    back = testRequestOf(*v, map, "X", kAxes);
    ASSERT_TRUE(back.ok()) << back.error().detail;
    ASSERT_TRUE(back->is<StepTest>());
    expectSameRequest(*back, step);
    served = throughRegisters(step, map);
    ASSERT_TRUE(served.ok()) << served.error().detail;
    expectSameRequest(*served, step);

    // A hold's and a current step's record length too.
    TestRequest hold;
    hold.axis = "Z";
    hold.test.emplace<HoldTest>().recordS = 2.25;
    v = testValuesOf(hold, map, indexOf);
    ASSERT_TRUE(v.ok()) << v.error().detail;
    EXPECT_EQ(v->at("test.record_s"), 2.25);
    EXPECT_EQ(v->count("test.dwell_s"), 0u);
    back = testRequestOf(*v, map, "Z", kAxes);
    ASSERT_TRUE(back.ok()) << back.error().detail;
    expectSameRequest(*back, hold);
    TestRequest current;
    current.axis = "X";
    auto& c = current.test.emplace<CurrentStepTest>();
    c.currentA = 1.5;
    c.recordS = 0.0125;
    v = testValuesOf(current, map, indexOf);
    ASSERT_TRUE(v.ok()) << v.error().detail;
    EXPECT_EQ(v->at("test.record_s"), 0.0125);
    EXPECT_EQ(v->count("test.dwell_s"), 0u);
    back = testRequestOf(*v, map, "X", kAxes);
    ASSERT_TRUE(back.ok()) << back.error().detail;
    expectSameRequest(*back, current);
}

// Version 2 moved a circle to its start point with the jog's velocity and acceleration (and dwelled test.duration);
// now its positioning speed and acceleration travel in circle.positioning_m_per_s and _m_per_s2 and its dwell in
// test.dwell_s, and no jog quantity is written.
TEST(TestRegisters, ACirclesPositioningTravelsInItsOwnQuantities)
{
    const auto map = simMap();
    const auto j = committedMap();
    auto at = [&](const char* field) { return j["fields"][field]["address"].get<int>(); };
    TestRequest r;
    r.axis = "X";
    auto& circle = r.test.emplace<CircleTest>();
    circle.secondAxis = "Z";
    circle.radiusM = 0.02;
    circle.feedMPerS = 0.01;
    circle.positioningMPerS = 0.03;
    circle.positioningMPerS2 = 0.6;
    circle.dwellS = 0.15;
    auto v = testValuesOf(r, map, indexOf);
    ASSERT_TRUE(v.ok()) << v.error().detail;
    EXPECT_EQ(v->at("circle.positioning_m_per_s"), 0.03);
    EXPECT_EQ(v->at("circle.positioning_m_per_s2"), 0.6);
    EXPECT_EQ(v->at("test.dwell_s"), 0.15);
    EXPECT_EQ(v->at("circle.second_axis"), 2.0); // Z in kAxes
    for (const char* q : {"jog.velocity", "jog.acceleration", "jog.distance", "jog.jerk", "test.record_s"})
        EXPECT_EQ(v->count(q), 0u) << q;
    auto w = encodeTestRegisters(*v, map);
    ASSERT_TRUE(w.ok()) << w.error().detail;
    EXPECT_EQ(wordsAt(*w, at("circle.positioning_speed"), 4), f64Words(0.03));
    EXPECT_EQ(wordsAt(*w, at("circle.positioning_accel"), 4), f64Words(0.6));
    EXPECT_EQ(wordsAt(*w, at("test.velocity"), 4), f64Words(0.0));
    EXPECT_EQ(wordsAt(*w, at("test.acceleration"), 4), f64Words(0.0));
    auto back = testRequestOf(*v, map, "X", kAxes);
    ASSERT_TRUE(back.ok()) << back.error().detail;
    ASSERT_TRUE(back->is<CircleTest>());
    expectSameRequest(*back, r);
    auto served = throughRegisters(r, map);
    ASSERT_TRUE(served.ok()) << served.error().detail;
    expectSameRequest(*served, r);
}

// The codec writes the quantities of the request's own kind only (besides what every test has: its type, flags,
// trace divider and channel mask): a step request carries no FRF quantity, a jog none of the circle's, and so on.
TEST(TestRegisters, ARequestWritesNoQuantityOfAnotherKind)
{
    const auto map = simMap();
    const std::set<std::string> common{"test.type", "test.flags", "test.trace_divider", "trace.channel_mask"};
    auto own = [](TestType t, const std::string& q) {
        auto starts = [&](const char* prefix) { return q.rfind(prefix, 0) == 0; };
        switch (t) {
        case TestType::Step:
            return starts("step.") || q == "test.record_s";
        case TestType::Jog:
            return starts("jog.") || q == "test.dwell_s";
        case TestType::Hold:
            return q == "test.record_s";
        case TestType::CurrentStep:
            return starts("current_step.") || q == "test.record_s";
        case TestType::Frf:
            return starts("frf.") || starts("multisine.");
        case TestType::Circle:
            return starts("circle.") || q == "test.dwell_s";
        }
        return false;
    };
    for (const auto& r : oneOfEachKind()) {
        const std::string kind = testTypeName(r.type());
        auto v = testValuesOf(r, map, indexOf);
        ASSERT_TRUE(v.ok()) << kind << ": " << v.error().detail;
        for (const auto& [q, value] : *v)
            EXPECT_TRUE(common.count(q) || own(r.type(), q)) << kind << " writes " << q << " = " << value;
        if (r.type() != TestType::Frf) {
            for (const auto& [q, value] : *v) {
                EXPECT_NE(q.rfind("frf.", 0), 0u) << kind << " writes " << q;
                EXPECT_NE(q.rfind("multisine.", 0), 0u) << kind << " writes " << q;
            }
        }
    }
    // The example of the issue: a step request's values hold its own quantities and no frf.* one.
    TestRequest step;
    step.axis = "X";
    step.test.emplace<StepTest>().velocityRadS = 3.0;
    auto v = testValuesOf(step, map, indexOf);
    ASSERT_TRUE(v.ok()) << v.error().detail;
    EXPECT_EQ(v->at("step.velocity_rad_s"), 3.0);
    EXPECT_EQ(v->at("test.record_s"), StepTest{}.recordS);
    for (const auto& [q, value] : *v)
        EXPECT_NE(q.rfind("frf.", 0), 0u) << q;
}

// A request the map has no register for is refused before anything is written, naming the quantity: a position
// step never reaches a drive that would take it for rad/s.
TEST(TestRegisters, AQuantityTheMapDoesNotCarryIsRefusedByName)
{
    const auto map = simMap();
    TestRequest step;
    step.axis = "X";
    step.test.emplace<StepTest>().position = 0.002;
    auto v = testValuesOf(step, map, indexOf);
    ASSERT_FALSE(v);
    EXPECT_EQ(v.error().code, ErrorCode::BadInput);
    EXPECT_NE(v.error().detail.find("has no register for step.position"), std::string::npos) << v.error().detail;
    TestRequest frf;
    frf.axis = "X";
    auto& frfTest = frf.test.emplace<FrfTest>();
    frfTest.quantity = FrfQuantity::Plant;
    frfTest.amplitudePeak = 0.5;
    v = testValuesOf(frf, map, indexOf);
    ASSERT_FALSE(v);
    EXPECT_NE(v.error().detail.find("frf.amplitude_peak, frf.quantity"), std::string::npos) << v.error().detail;
    frfTest.quantity = FrfQuantity::Default;
    frfTest.amplitudePeak = 0.0;
    frfTest.method = FrfMethod::Multisine;
    frfTest.multisineShape = {{10.0, 1.0}, {100.0, 2.0}};
    v = testValuesOf(frf, map, indexOf);
    ASSERT_FALSE(v);
    EXPECT_NE(v.error().detail.find("multisine.shape"), std::string::npos) << v.error().detail;
    frfTest.multisineShape.clear();
    // Phases designed through a response (the adaptive FRF's voltage) cannot be sent either.
    frfTest.multisineCrestThrough = {{100.0, {1.0, 2.0}}};
    v = testValuesOf(frf, map, indexOf);
    ASSERT_FALSE(v);
    EXPECT_NE(v.error().detail.find("multisine.crest_response"), std::string::npos) << v.error().detail;
    EXPECT_NE(v.error().detail.find("carries no spectrum"), std::string::npos) << v.error().detail;
    frfTest.multisineCrestThrough.clear();
    frfTest.multisineBands.assign(5, {10.0, 100.0, 5.0});
    v = testValuesOf(frf, map, indexOf);
    ASSERT_FALSE(v);
    EXPECT_NE(v.error().detail.find("at most 4 multisine bands"), std::string::npos) << v.error().detail;
    TestRequest circle;
    circle.axis = "X";
    circle.test.emplace<CircleTest>().secondAxis = "Q";
    v = testValuesOf(circle, map, indexOf);
    ASSERT_FALSE(v);
    EXPECT_NE(v.error().detail.find("second plane axis: no axis Q"), std::string::npos) << v.error().detail;
    TestRequest many;
    many.axis = "X";
    many.test.emplace<FrfTest>().points = 70000;
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
        withField("test.extra", {{"address", 390}, {"type", "f64"}, {"carries", "step.velocity_m_s"}}), "bad.json");
    ASSERT_FALSE(m);
    EXPECT_NE(m.error().detail.find("field 'test.extra': carries unknown quantity 'step.velocity_m_s'"),
              std::string::npos)
        << m.error().detail;
    m = parseRegisterMap(withField("test.extra", {{"address", 390}, {"type", "f64"}, {"carries", "jog.jerk"}}),
                         "bad.json");
    ASSERT_FALSE(m);
    EXPECT_NE(m.error().detail.find("both carry jog.jerk"), std::string::npos) << m.error().detail;
    m = parseRegisterMap(withField("test.extra", {{"address", 390}, {"type", "u16"}, {"carries", "step.position"}}),
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
    m = parseRegisterMap(
        withField("test.position_step", {{"address", 390}, {"type", "f64"}, {"carries", "step.position"}}), "ok.json");
    ASSERT_TRUE(m.ok()) << m.error().detail;
    TestRequest step;
    step.axis = "X";
    step.test.emplace<StepTest>().position = 0.002;
    auto back = throughRegisters(step, *m);
    ASSERT_TRUE(back.ok()) << back.error().detail;
    ASSERT_TRUE(back->is<StepTest>());
    EXPECT_EQ(back->step().position, 0.002);
    EXPECT_EQ(back->step().velocityRadS, 0.0);
}
