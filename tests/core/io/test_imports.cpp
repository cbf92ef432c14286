// SPDX-License-Identifier: GPL-3.0-or-later
// Open imports (core/io/TableImport, Uff58, SampleTime, the FRF units key).
#include "core/io/FrfCsv.h"
#include "core/io/SampleTime.h"
#include "core/io/TableImport.h"
#include "core/io/Uff58.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

using namespace axistune;

namespace {

std::string realData(const std::string& name)
{
    return std::string(AXISTUNE_REAL_DATA_DIR) + "/" + name;
}

double num(const std::string& s)
{
    double v = 0.0;
    std::from_chars(s.data(), s.data() + s.size(), v);
    return v;
}

} // namespace

TEST(FrfUnits, MicrometrePerNewtonIsConvertedAndUnknownUnitRefused)
{
    std::istringstream um("# units=um/N\nf_Hz,re,im\n100,2.5,-1.25\n200,0.5,0\n");
    auto frf = io::readFrfCsv(um, "tool_um.csv");
    ASSERT_TRUE(frf) << frf.error().detail;
    EXPECT_DOUBLE_EQ(frf->h[0].real(), 2.5e-6);
    EXPECT_DOUBLE_EQ(frf->h[0].imag(), -1.25e-6);
    EXPECT_EQ(frf->metadata.text("units"), "m/N");
    EXPECT_EQ(frf->metadata.text("units_in_file"), "um/N");
    std::istringstream bad("# units=inch/lbf\nf_Hz,re,im\n100,2.5,-1.25\n");
    auto r = io::readFrfCsv(bad, "tool_in.csv");
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().detail.find("tool_in.csv"), std::string::npos);
    EXPECT_NE(r.error().detail.find("inch/lbf"), std::string::npos);
    std::istringstream accel("# units=g/N\nf_Hz,re,im\n100,1,0\n");
    auto a = io::readFrfCsv(accel, "a.csv");
    ASSERT_TRUE(a);
    EXPECT_DOUBLE_EQ(a->h[0].real(), 9.80665); // standard gravity, by definition
    EXPECT_EQ(a->metadata.text("units"), "m/s2/N");
}

TEST(TableImport, SemicolonWithDecimalComma)
{
    std::istringstream in("# exported by a logger\nZeit;Kraft;Beschl\n0,000;1,5;-2,25\n0,001;3,0;4,5\n");
    auto t = io::readTable(in, "de.csv", {});
    ASSERT_TRUE(t) << t.error().detail;
    ASSERT_EQ(t->channels.size(), 3u);
    EXPECT_EQ(t->channels[1].name, "Kraft");
    EXPECT_EQ(t->channels[1].data[0], 1.5);
    EXPECT_EQ(t->channels[2].data[0], -2.25);
    EXPECT_EQ(t->channels[0].data[1], 0.001);
    EXPECT_EQ(t->metadata.text("separator"), "semicolon");
    EXPECT_EQ(t->metadata.text("decimal"), "comma");
    std::istringstream bad("a;b\n1,5;2.5\n");
    auto r = io::readTable(bad, "mixed.csv", {});
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().detail.find("mixed.csv line 2, column 'a'"), std::string::npos) << r.error().detail;
}

TEST(TableImport, TabHeaderlessNamesAndUnits)
{
    std::istringstream tab("t\tforce\taccel\n0\t1\t2\n0.5\t3\t4\n");
    auto t = io::readTable(tab, "tab.txt", {});
    ASSERT_TRUE(t) << t.error().detail;
    EXPECT_EQ(t->metadata.text("separator"), "tab");
    EXPECT_EQ(t->channels[2].data[1], 4.0);

    std::istringstream noHeader("0.0,10,1\n0.001,20,2\n");
    io::TableImportOptions o;
    o.names = {"t", "force", "accel"};
    o.units = {{"force", "kN"}, {"accel", "g"}, {"t", "ms"}};
    auto h = io::readTable(noHeader, "raw.csv", o);
    ASSERT_TRUE(h) << h.error().detail;
    EXPECT_DOUBLE_EQ(h->channel("force")->data[1], 20e3);
    EXPECT_DOUBLE_EQ(h->channel("accel")->data[1], 2 * 9.80665);
    EXPECT_DOUBLE_EQ(h->channel("t")->data[1], 1e-6);
    EXPECT_EQ(h->metadata.text("unit.accel"), "m/s2");

    std::istringstream plain("1 2\n3 4\n");
    auto p = io::readTable(plain, "p.txt", {});
    ASSERT_TRUE(p);
    EXPECT_EQ(p->channels[1].name, "col2");
    std::istringstream wrong("1,2\n3,4\n");
    o.units = {{"x", "furlong"}};
    o.names = {"x", "y"};
    auto w = io::readTable(wrong, "u.csv", o);
    ASSERT_FALSE(w);
    EXPECT_NE(w.error().detail.find("furlong"), std::string::npos);
}

TEST(TableImport, FrfColumnsPickedByName)
{
    std::istringstream in("f_Hz,H11_re,H11_im,H12_re,H12_im\n0,1,0,2,0\n1,3,4,5,6\n");
    auto t = io::readTable(in, "h.csv", {});
    ASSERT_TRUE(t);
    auto none = io::frfFromTable(*t, "h.csv", {});
    ASSERT_FALSE(none);
    EXPECT_NE(none.error().detail.find("--column"), std::string::npos);
    io::FrfColumnOptions c;
    c.name = "H12";
    c.units = "mm/N";
    auto h12 = io::frfFromTable(*t, "h.csv", c);
    ASSERT_TRUE(h12) << h12.error().detail;
    EXPECT_DOUBLE_EQ(h12->h[1].imag(), 6e-3);
    EXPECT_EQ(h12->metadata.text("units"), "m/N");
}

TEST(SampleTime, JitteredColumnsAcceptedGapsRefused)
{
    // ±24 ns of jitter at 1 ms (EMPS) is accepted, the rate from the whole span
    std::vector<double> t;
    for (int i = 0; i < 1000; ++i)
        t.push_back(i * 1e-3 + ((i * 7919) % 3 - 1) * 24e-9);
    auto s = io::sampleTiming(t, "j.csv, column 't_s'", 5);
    ASSERT_TRUE(s) << s.error().detail;
    EXPECT_NEAR(s->fsHz, 1000.0, 1e-4);
    t.erase(t.begin() + 500); // a lost sample
    auto g = io::sampleTiming(t, "g.csv, column 't_s'", 5);
    ASSERT_FALSE(g);
    EXPECT_NE(g.error().detail.find("g.csv, column 't_s', line"), std::string::npos) << g.error().detail;
}

TEST(SampleTime, RealImpactAndEmpsTimeColumns)
{
    for (const auto& [file, fs] :
         {std::pair{"impact_test_raw_time.csv", 51200.0}, std::pair{"emps_DATA_EMPS.csv", 1000.0}}) {
        auto t = io::readTableFile(realData(file), {});
        ASSERT_TRUE(t) << t.error().detail;
        auto s = io::sampleTiming(t->channel("t_s")->data, file);
        ASSERT_TRUE(s) << s.error().detail;
        // the README's rates; the span of 7-digit stamps is exact to 1e-7 s over ≥ 1 s
        EXPECT_NEAR(s->fsHz, fs, 1e-5 * fs) << file;
    }
}

TEST(Halscope, SavedLogRead)
{
    std::istringstream in("Sampling period is 1000000 ns \n\nx-vel +0.10000000000000 ferror -0.00000100000000 \n"
                          "x-vel +0.20000000000000 ferror +0.00000250000000 \n");
    ASSERT_TRUE(io::looksLikeHalscope("Sampling period is 1000000 ns "));
    auto c = io::readHalscope(in, "scope.log");
    ASSERT_TRUE(c) << c.error().detail;
    ASSERT_EQ(c->channels.size(), 2u);
    EXPECT_EQ(c->channels[1].name, "ferror");
    EXPECT_EQ(c->channels[1].data[1], 2.5e-6);
    EXPECT_EQ(c->metadata.number("fs_Hz").value(), 1000.0);
    std::istringstream bad("Sampling period is 1000000 ns \nx-vel +0.1 ferror\n");
    auto b = io::readHalscope(bad, "bad.log");
    ASSERT_FALSE(b);
    EXPECT_NE(b.error().detail.find("bad.log line 2"), std::string::npos);
}

TEST(Uff58, IndependentFileReadBackExactly)
{
    // tests/data/uff/make_uff.py wrote frf.unv and expected.csv (the decimal strings it wrote)
    const std::string dir = std::string(AXISTUNE_TEST_DATA_DIR) + "/uff/";
    auto recs = io::readUff58File(dir + "frf.unv");
    ASSERT_TRUE(recs) << recs.error().detail;
    ASSERT_EQ(recs->size(), 3u);
    std::ifstream ex(dir + "expected.csv");
    ASSERT_TRUE(ex);
    std::string line;
    std::getline(ex, line);
    std::vector<std::size_t> seen(4, 0);
    while (std::getline(ex, line)) {
        std::vector<std::string> c;
        std::stringstream ss(line);
        for (std::string cell; std::getline(ss, cell, ',');)
            c.push_back(cell);
        ASSERT_EQ(c.size(), 4u);
        const auto r = static_cast<std::size_t>(std::stoi(c[0]));
        const auto& rec = (*recs)[r - 1];
        const std::size_t i = seen[r]++;
        ASSERT_LT(i, rec.x.size());
        std::string re = c[2], im = c[3];
        EXPECT_EQ(rec.x[i], num(c[1])) << "record " << r << " point " << i;
        EXPECT_EQ(rec.y[i].real(), num(re)) << "record " << r << " point " << i;
        EXPECT_EQ(rec.y[i].imag(), num(im)) << "record " << r << " point " << i;
    }
    EXPECT_EQ(seen[1], 7u);
    EXPECT_EQ(seen[2], 5u);
    EXPECT_EQ(seen[3], 9u);
    // record 1: accelerance in mm/s^2 per N (units labels) → m/s2/N
    auto f1 = io::frfFromUff((*recs)[0], "frf.unv");
    ASSERT_TRUE(f1) << f1.error().detail;
    EXPECT_EQ(f1->metadata.text("units"), "m/s2/N");
    EXPECT_DOUBLE_EQ(f1->h[0].real(), (*recs)[0].y[0].real() * 1e-3);
    // record 2: no labels, SI by data type (noted)
    auto f2 = io::frfFromUff((*recs)[1], "frf.unv");
    ASSERT_TRUE(f2);
    EXPECT_EQ(f2->metadata.text("units"), "m/N");
    EXPECT_EQ(f2->metadata.text("units_assumed"), "SI");
    // record 3: time response
    auto cap = io::captureFromUff(*recs, "frf.unv");
    ASSERT_TRUE(cap) << cap.error().detail;
    EXPECT_NEAR(cap->metadata.number("fs_Hz").value(), 1.0 / 4.88281e-4, 1e-9); // the increment as written (E13.5)
    EXPECT_FALSE(io::frfFromUff((*recs)[2], "frf.unv"));
}

TEST(Uff58, TruncatedFileNamesTheLine)
{
    std::istringstream in("    -1\n    58\nid1\nid2\nid3\nid4\nid5\n    4         1    1         0 NONE               "
                          "1   1 NONE               1   1\n"
                          "         6         3         1  1.00000E+01  5.00000E-01  0.00000E+00\n");
    auto r = io::readUff58(in, "cut.unv");
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().detail.find("cut.unv"), std::string::npos) << r.error().detail;
    std::istringstream bin("    -1\n    58b     2         2\n");
    auto b = io::readUff58(bin, "b.unv");
    ASSERT_FALSE(b);
    EXPECT_NE(b.error().detail.find("58b"), std::string::npos);
}
