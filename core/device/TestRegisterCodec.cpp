// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/device/TestRegisterCodec.h"

#include "core/device/MultisineTest.h"
#include "core/model/CircleDirectionName.h"
#include "core/model/Units.h"

#include <algorithm>
#include <cmath>

namespace axistune::device {
namespace {

/// Where a quantity lives in a request: the member of its kind, or nullptr when the request is of another kind.
template <class T> using MemberOf = T* (*)(TestRequest&);

template <class K, class T, T K::*M> T* member(TestRequest& r)
{
    auto* k = std::get_if<K>(&r.test);
    return k ? &(k->*M) : nullptr;
}

double* recordLength(TestRequest& r)
{
    if (auto* s = std::get_if<StepTest>(&r.test))
        return &s->recordS;
    if (auto* h = std::get_if<HoldTest>(&r.test))
        return &h->recordS;
    if (auto* c = std::get_if<CurrentStepTest>(&r.test))
        return &c->recordS;
    return nullptr;
}

double* dwell(TestRequest& r)
{
    if (auto* j = std::get_if<JogTest>(&r.test))
        return &j->dwellS;
    if (auto* c = std::get_if<CircleTest>(&r.test))
        return &c->dwellS;
    return nullptr;
}

/// The real quantities: one member of one or more kinds each.
const std::vector<std::pair<std::string, MemberOf<double>>>& realMembers()
{
    static const std::vector<std::pair<std::string, MemberOf<double>>> k{
        {"test.record_s", &recordLength},
        {"test.dwell_s", &dwell},
        {"step.velocity_rad_s", &member<StepTest, double, &StepTest::velocityRadS>},
        {"step.position", &member<StepTest, double, &StepTest::position>},
        {"current_step.current_a", &member<CurrentStepTest, double, &CurrentStepTest::currentA>},
        {"jog.distance", &member<JogTest, double, &JogTest::distance>},
        {"jog.velocity", &member<JogTest, double, &JogTest::velocity>},
        {"jog.acceleration", &member<JogTest, double, &JogTest::acceleration>},
        {"jog.jerk", &member<JogTest, double, &JogTest::jerk>},
        {"frf.fmin_hz", &member<FrfTest, double, &FrfTest::fminHz>},
        {"frf.fmax_hz", &member<FrfTest, double, &FrfTest::fmaxHz>},
        {"frf.amplitude_pct", &member<FrfTest, double, &FrfTest::amplitudePct>},
        {"frf.amplitude_peak", &member<FrfTest, double, &FrfTest::amplitudePeak>},
        {"frf.settle_s", &member<FrfTest, double, &FrfTest::settleS>},
        {"frf.min_measure_s", &member<FrfTest, double, &FrfTest::minMeasureS>},
        {"circle.radius_m", &member<CircleTest, double, &CircleTest::radiusM>},
        {"circle.feed_m_per_s", &member<CircleTest, double, &CircleTest::feedMPerS>},
        {"circle.center_x_m", &member<CircleTest, double, &CircleTest::centerXM>},
        {"circle.center_y_m", &member<CircleTest, double, &CircleTest::centerYM>},
        {"circle.data_start_deg", &member<CircleTest, double, &CircleTest::dataStartDeg>},
        {"circle.lead_arc_deg", &member<CircleTest, double, &CircleTest::leadArcDeg>},
        {"circle.positioning_m_per_s", &member<CircleTest, double, &CircleTest::positioningMPerS>},
        {"circle.positioning_m_per_s2", &member<CircleTest, double, &CircleTest::positioningMPerS2>}};
    return k;
}

int* traceDivider(TestRequest& r)
{
    return &r.traceDivider;
}

const std::vector<std::pair<std::string, MemberOf<int>>>& wholeMembers()
{
    static const std::vector<std::pair<std::string, MemberOf<int>>> k{
        {"test.trace_divider", &traceDivider},
        {"frf.points", &member<FrfTest, int, &FrfTest::points>},
        {"multisine.periods", &member<FrfTest, int, &FrfTest::multisinePeriods>}};
    return k;
}

/// A request of the same kind on the same axis with every field at its default: what "not given" means.
TestRequest unsetLike(const TestRequest& r)
{
    TestRequest u;
    u.axis = r.axis;
    u.test = testKindOf(r.type());
    return u;
}

constexpr int kBandSlots = 4; ///< multisine.band1 .. band4 (a map may carry fewer)
const char* const kBandParts[] = {"fmin_hz", "fmax_hz", "spacing_hz"};

std::string bandQuantity(int band, int part)
{
    return "multisine.band" + std::to_string(band + 1) + "." + kBandParts[part];
}

const char* frfQuantityName(FrfQuantity q)
{
    return q == FrfQuantity::Plant ? "plant" : q == FrfQuantity::OpenLoop ? "open_loop" : "default";
}

const RegisterField* carrier(const RegisterMap& map, const std::string& quantity)
{
    for (const auto& [n, f] : map.fields) {
        if (f.carries == quantity)
            return &f;
    }
    return nullptr;
}

int bandSlots(const RegisterMap& map)
{
    int n = 0;
    while (n < kBandSlots && carrier(map, bandQuantity(n, 0)) && carrier(map, bandQuantity(n, 1)) &&
           carrier(map, bandQuantity(n, 2)))
        ++n;
    return n;
}

template <class E, std::size_t N>
Result<E> enumOf(const RegisterMap& map, const std::string& group, double code, const E (&all)[N],
                 const char* (*nameOf)(E))
{
    const std::string name = map.name(group, static_cast<int>(code));
    for (const E e : all) {
        if (name == nameOf(e))
            return e;
    }
    return makeError(ErrorCode::BadInput, "drive family " + map.family + ": unknown " + group + " code " +
                                              model::formatNumber(code, 6) + (name.empty() ? "" : " ('" + name + "')"));
}

Status frfEnumsOf(const TestValues& values, const RegisterMap& map, FrfTest& r)
{
    auto has = [&](const std::string& q) { return values.find(q) != values.end(); };
    auto at = [&](const std::string& q) { return values.at(q); };
    if (has("frf.method")) {
        static const FrfMethod methods[] = {FrfMethod::MultiSweep, FrfMethod::Conventional, FrfMethod::Prbs,
                                            FrfMethod::Multisine};
        auto m = enumOf(map, "frf_method", at("frf.method"), methods, frfMethodName);
        if (!m)
            return m.error();
        r.method = *m;
    }
    if (has("frf.quantity")) {
        static const FrfQuantity qs[] = {FrfQuantity::Default, FrfQuantity::Plant, FrfQuantity::OpenLoop};
        auto q = enumOf(map, "frf_quantity", at("frf.quantity"), qs, frfQuantityName);
        if (!q)
            return q.error();
        r.quantity = *q;
    }
    if (has("multisine.phases")) {
        static const dsp::MultisinePhases ps[] = {dsp::MultisinePhases::Clipping, dsp::MultisinePhases::Schroeder};
        auto p = enumOf(map, "multisine_phases", at("multisine.phases"), ps, dsp::multisinePhasesName);
        if (!p)
            return p.error();
        r.multisinePhases = *p;
    }
    if (r.method == FrfMethod::Multisine && has("multisine.band_count")) {
        const int count = static_cast<int>(at("multisine.band_count"));
        if (count > bandSlots(map))
            return makeError(ErrorCode::OutOfRange, "multisine.band_count " + std::to_string(count) + " above the " +
                                                        std::to_string(bandSlots(map)) + " bands of the map");
        for (int b = 0; b < count; ++b)
            r.multisineBands.push_back({at(bandQuantity(b, 0)), at(bandQuantity(b, 1)), at(bandQuantity(b, 2))});
    }
    return Status::success();
}

} // namespace

const std::vector<TestQuantity>& testQuantities()
{
    static const std::vector<TestQuantity> k = [] {
        std::vector<TestQuantity> q{
            {"reserved", "", true, "reserved, reads 0 (written 0 so that the test block is one write)"},
            {"test.type", "test_type", true, "enum test_type"},
            {"test.flags", "", true, "bit set of enum test_flag"},
            {"test.trace_divider", "", true, "trace every N velocity periods (0: parameter trace.divider)"},
            {"test.record_s", "", false, "step/hold/current_step: recording length [s]"},
            {"test.dwell_s", "", false, "jog: dwell before and after the move; circle: dwell at the start point [s]"},
            {"trace.channel_mask", "", true, "bit i: keep trace channel i (0: all)"},
            {"step.velocity_rad_s", "", false, "step: motor velocity step [rad/s]"},
            {"step.position", "", false, "step: position step of the command [its units]"},
            {"current_step.current_a", "", false, "current_step: q-axis current step [A]"},
            {"jog.distance", "", false, "jog: distance [m or rad]"},
            {"jog.velocity", "", false, "jog: velocity [m/s or rad/s]"},
            {"jog.acceleration", "", false, "jog: acceleration [m/s^2 or rad/s^2]"},
            {"jog.jerk", "", false, "jog: jerk limit [m/s^3 or rad/s^3] (0: trapezoid)"},
            {"frf.method", "frf_method", true, "frf: enum frf_method"},
            {"frf.quantity", "frf_quantity", true, "frf: enum frf_quantity"},
            {"frf.points", "", true, "frf: number of frequencies"},
            {"frf.fmin_hz", "", false, "frf: lowest frequency [Hz]"},
            {"frf.fmax_hz", "", false, "frf: highest frequency [Hz]"},
            {"frf.amplitude_pct", "", false, "frf: excitation amplitude (multisine: its peak) [% of rated torque]"},
            {"frf.amplitude_peak", "", false, "frf: excitation peak in the injection point's units"},
            {"frf.settle_s", "", false, "frf: settle time per frequency [s] (0: from the loop dynamics)"},
            {"frf.min_measure_s", "", false,
             "frf: minimum measured time per frequency [s] (0: from the loop dynamics)"},
            {"multisine.periods", "", true, "frf multisine: averaged periods (0: from the loop dynamics)"},
            {"multisine.phases", "multisine_phases", true, "frf multisine: enum multisine_phases"},
            {"multisine.band_count", "", true, "frf multisine: bands in use"}};
        for (int b = 0; b < kBandSlots; ++b) {
            const std::string band = "frf multisine: band " + std::to_string(b + 1);
            q.push_back({bandQuantity(b, 0), "", false, band + ", lowest line [Hz]"});
            q.push_back({bandQuantity(b, 1), "", false, band + ", highest line [Hz]"});
            q.push_back({bandQuantity(b, 2), "", false, band + ", line spacing [Hz]"});
        }
        for (TestQuantity c : std::vector<TestQuantity>{
                 {"circle.second_axis", "", true, "circle: axis index of the second plane axis"},
                 {"circle.direction", "circle_direction", true, "circle: enum circle_direction"},
                 {"circle.radius_m", "", false, "circle: radius [m]"},
                 {"circle.feed_m_per_s", "", false, "circle: feed along the path [m/s]"},
                 {"circle.center_x_m", "", false, "circle: centre, position of the first axis [m]"},
                 {"circle.center_y_m", "", false, "circle: centre, position of the second axis [m]"},
                 {"circle.data_start_deg", "", false, "circle: angle at which the 360 deg data arc begins [deg]"},
                 {"circle.lead_arc_deg", "", false, "circle: lead-in and lead-out arc [deg]"},
                 {"circle.positioning_m_per_s", "", false,
                  "circle: speed of the move to the start point [m/s] (0: default)"},
                 {"circle.positioning_m_per_s2", "", false,
                  "circle: acceleration of the move to the start point [m/s^2] (0: default)"}})
            q.push_back(c);
        return q;
    }();
    return k;
}

const TestQuantity* findTestQuantity(const std::string& name)
{
    const auto& all = testQuantities();
    auto it = std::find_if(all.begin(), all.end(), [&](const TestQuantity& q) { return q.name == name; });
    return it == all.end() ? nullptr : &*it;
}

Result<TestValues> testValuesOf(const TestRequest& r, const RegisterMap& map,
                                const std::function<Result<int>(const std::string&)>& axisIndex)
{
    TestRequest unset = unsetLike(r);
    TestRequest req = r; // the member tables hand out pointers into a request they may write
    TestValues v;
    std::vector<std::string> missing;
    auto put = [&](const std::string& q, double value, bool given) {
        if (carrier(map, q))
            v[q] = value;
        else if (given)
            missing.push_back(q);
    };
    Status bad = Status::success();
    auto putEnum = [&](const std::string& q, const std::string& group, const std::string& name, bool given) {
        const int code = map.code(group, name);
        if (carrier(map, q) && code < 0 && bad)
            bad = makeError(ErrorCode::BadInput, "drive family " + map.family + " has no " + group + " '" + name + "'");
        put(q, code, given);
    };
    putEnum("test.type", "test_type", testTypeName(r.type()), true);
    const bool back = r.is<JogTest>() && r.jog().returnToStart;
    const int backBit = map.code("test_flag", "return_to_start");
    if (back && backBit <= 0 && bad)
        bad = makeError(ErrorCode::BadInput, "drive family " + map.family + " has no test_flag 'return_to_start'");
    put("test.flags", back ? std::max(backBit, 0) : 0, back);
    put("trace.channel_mask", 0, false);
    for (const auto& [q, m] : realMembers()) {
        if (const double* value = m(req))
            put(q, *value, !(*value == *m(unset)));
    }
    for (const auto& [q, m] : wholeMembers()) {
        if (const int* value = m(req))
            put(q, *value, *value != *m(unset));
    }
    std::vector<dsp::MultisineBand> bands;
    if (const auto* f = std::get_if<FrfTest>(&r.test)) {
        const FrfTest plain;
        putEnum("frf.method", "frf_method", frfMethodName(f->method), f->method != plain.method);
        putEnum("frf.quantity", "frf_quantity", frfQuantityName(f->quantity), f->quantity != plain.quantity);
        putEnum("multisine.phases", "multisine_phases", dsp::multisinePhasesName(f->multisinePhases),
                f->multisinePhases != plain.multisinePhases);
        if (!f->multisineShape.empty())
            missing.push_back("multisine.shape");
        if (!f->multisineCrestThrough.empty())
            missing.push_back("multisine.crest_response");
        if (f->method == FrfMethod::Multisine)
            bands = multisineBandsOf(*f);
    }
    const int slots = bandSlots(map);
    if (static_cast<int>(bands.size()) > slots && bad)
        bad = makeError(ErrorCode::OutOfRange, "drive family " + map.family + ": at most " + std::to_string(slots) +
                                                   " multisine bands over Modbus (got " +
                                                   std::to_string(bands.size()) + ")");
    if (r.is<FrfTest>()) {
        put("multisine.band_count", static_cast<double>(bands.size()), !bands.empty());
        for (int b = 0; b < slots; ++b) {
            const auto i = static_cast<std::size_t>(b);
            const bool used = i < bands.size();
            put(bandQuantity(b, 0), used ? bands[i].fminHz : 0.0, false);
            put(bandQuantity(b, 1), used ? bands[i].fmaxHz : 0.0, false);
            put(bandQuantity(b, 2), used ? bands[i].spacingHz : 0.0, false);
        }
    }
    if (const auto* c = std::get_if<CircleTest>(&r.test)) {
        auto i = axisIndex(c->secondAxis);
        if (!i)
            return makeError(i.error().code, "circle test: second plane axis: " + i.error().detail);
        put("circle.second_axis", *i, true);
        putEnum("circle.direction", "circle_direction", model::circleDirectionName(c->direction),
                c->direction != CircleTest{}.direction);
    }
    if (!bad)
        return bad.error();
    if (!missing.empty()) {
        std::string list;
        for (const auto& q : missing)
            list += (list.empty() ? "" : ", ") + q;
        const bool shape = std::find(missing.begin(), missing.end(), "multisine.shape") != missing.end() ||
                           std::find(missing.begin(), missing.end(), "multisine.crest_response") != missing.end();
        return makeError(ErrorCode::BadInput,
                         "drive family " + map.family + " has no register for " + list +
                             ": this drive cannot take the request as given" +
                             (shape ? " (a shaped multisine, or one with phases for a response, cannot "
                                      "be sent over Modbus: the test block carries no spectrum)"
                                    : ""));
    }
    return v;
}

Result<TestRequest> testRequestOf(const TestValues& values, const RegisterMap& map, const std::string& axis,
                                  const std::vector<std::string>& axisNames)
{
    TestRequest r;
    r.axis = axis;
    auto has = [&](const std::string& q) { return values.find(q) != values.end(); };
    auto at = [&](const std::string& q) { return values.at(q); };
    if (!has("test.type"))
        return makeError(ErrorCode::BadInput, "drive family " + map.family + ": no field carries test.type");
    static const TestType types[] = {TestType::Step, TestType::Jog,    TestType::Hold,
                                     TestType::Frf,  TestType::Circle, TestType::CurrentStep};
    auto type = enumOf(map, "test_type", at("test.type"), types, testTypeName);
    if (!type)
        return type.error();
    r.test = testKindOf(*type);
    if (has("test.flags") && r.is<JogTest>())
        r.jog().returnToStart =
            (static_cast<long long>(at("test.flags")) & std::max(0, map.code("test_flag", "return_to_start"))) != 0;
    for (const auto& [q, m] : realMembers()) {
        if (double* value = m(r); value && has(q))
            *value = at(q);
    }
    for (const auto& [q, m] : wholeMembers()) {
        if (int* value = m(r); value && has(q))
            *value = static_cast<int>(at(q));
    }
    if (auto* f = std::get_if<FrfTest>(&r.test))
        if (auto st = frfEnumsOf(values, map, *f); !st)
            return st.error();
    if (auto* c = std::get_if<CircleTest>(&r.test)) {
        if (has("circle.direction")) {
            static const model::CircleDirection ds[] = {model::CircleDirection::Ccw, model::CircleDirection::Cw};
            auto d = enumOf(map, "circle_direction", at("circle.direction"), ds, model::circleDirectionName);
            if (!d)
                return d.error();
            c->direction = *d;
        }
        const double i = has("circle.second_axis") ? at("circle.second_axis") : -1.0;
        if (!(i >= 0.0 && i < static_cast<double>(axisNames.size())))
            return makeError(ErrorCode::BadInput, "circle.second_axis: no axis with index " + model::formatNumber(i, 6));
        c->secondAxis = axisNames[static_cast<std::size_t>(i)];
    }
    return r;
}

Status checkTestValue(const RegisterField& field, const RegisterMap& map, double value)
{
    const TestQuantity* q = findTestQuantity(field.carries);
    if (!q)
        return Status::success();
    if (!std::isfinite(value))
        return makeError(ErrorCode::BadInput, field.name + " must be finite");
    if (q->whole && (value < 0.0 || value != std::floor(value) || value > 2147483647.0))
        return makeError(ErrorCode::BadInput, field.name + " must be a whole number in 0..2147483647");
    if (!q->enumGroup.empty() && map.name(q->enumGroup, static_cast<int>(value)).empty())
        return makeError(ErrorCode::BadInput,
                         field.name + ": unknown " + q->enumGroup + " code " + model::formatNumber(value, 6));
    if (q->name == "multisine.band_count" && value > bandSlots(map))
        return makeError(ErrorCode::BadInput, field.name + " " + model::formatNumber(value, 6) + " outside 0.." +
                                                  std::to_string(bandSlots(map)));
    return Status::success();
}

double decodeCarried(const RegisterField& f, const std::uint16_t* w, WordOrder o)
{
    switch (f.type) {
    case RegisterType::U16:
        return w[0];
    case RegisterType::U32:
        return decodeU32(w, o);
    case RegisterType::F32:
        return decodeF32(w, o);
    default:
        return decodeF64(w, o);
    }
}

void encodeCarried(const RegisterField& f, double v, WordOrder o, std::uint16_t* w)
{
    switch (f.type) {
    case RegisterType::U16:
        w[0] = static_cast<std::uint16_t>(v);
        break;
    case RegisterType::U32:
        encodeU32(static_cast<std::uint32_t>(v), o, w);
        break;
    case RegisterType::F32:
        encodeF32(static_cast<float>(v), o, w);
        break;
    default:
        encodeF64(v, o, w);
        break;
    }
}

Result<std::vector<RegisterWrite>> encodeTestRegisters(const TestValues& values, const RegisterMap& map,
                                                       int maxPerWrite)
{
    std::vector<const RegisterField*> fields;
    for (const auto& [n, f] : map.fields) {
        if (!f.carries.empty())
            fields.push_back(&f);
    }
    std::sort(fields.begin(), fields.end(),
              [](const RegisterField* a, const RegisterField* b) { return a->address < b->address; });
    std::vector<RegisterWrite> out;
    for (const RegisterField* f : fields) {
        auto it = values.find(f->carries);
        const double v = it == values.end() ? 0.0 : it->second;
        const double top = f->type == RegisterType::U16 ? 65535.0 : f->type == RegisterType::U32 ? 4294967295.0 : 0.0;
        if (top > 0.0 && !(v >= 0.0 && v <= top && v == std::floor(v)))
            return makeError(ErrorCode::OutOfRange, f->carries + " must be a whole number in 0.." +
                                                        model::formatNumber(top, 10) + " (" + f->name + ", got " +
                                                        model::formatNumber(v, 6) + ")");
        if (out.empty() || out.back().address + static_cast<int>(out.back().words.size()) != f->address ||
            static_cast<int>(out.back().words.size()) + f->count > maxPerWrite)
            out.push_back({f->address, {}});
        auto& words = out.back().words;
        words.resize(words.size() + static_cast<std::size_t>(f->count));
        encodeCarried(*f, v, map.wordOrder, &words[words.size() - static_cast<std::size_t>(f->count)]);
    }
    return out;
}

} // namespace axistune::device
