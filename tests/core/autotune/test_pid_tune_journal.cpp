// SPDX-License-Identifier: GPL-3.0-or-later
// The journal of a position-PID tune and of its undo (core/autotune/PidTune.h PidTuneWrite), which the NC PID page
// saves with its session and pid-tune's result JSON lists: every expectation below is written out by hand from the
// rule in docs/storage.md "Journal" (the gains by their keys, AxisTune's notch by HAL's names: axistune-notch 0/1
// for whether it runs, axistune-notch.f0 and .Q). The HAL side (what the undo reads before it writes) runs in
// tests/gui/hal (GuiOnHal.VelocityWizardTunesThePositionPidAndUndoes).
#include "core/autotune/PidTune.h"
#include "core/device/DriveRegistry.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

namespace axistune::autotune {
void PrintTo(const PidTuneWrite& w, std::ostream* os)
{
    *os << w.key << ": " << (w.from ? std::to_string(*w.from) : std::string("none")) << " -> " << w.to;
}
} // namespace axistune::autotune

using namespace axistune;
using namespace axistune::autotune;

namespace {

const tuning::BiquadNotch kOld{150.0, 1.0};
const tuning::BiquadNotch kNew{107.33, 0.7};

PidTuneApplied appliedGains()
{
    PidTuneApplied a;
    a.applied = true;
    a.before = {{"Pgain", 1.0}, {"Igain", 2.0}, {"Dgain", 0.01}, {"FF1", 0.0}, {"FF2", 3e-4}};
    a.written = {{"Pgain", 0.5}, {"Igain", 23.0}, {"Dgain", 0.143}, {"FF1", 0.0}, {"FF2", 3.5e-4}};
    return a;
}

} // namespace

TEST(PidTuneJournal, TheNotchInsertedRetunedRemovedOrKept)
{
    EXPECT_TRUE(pidTuneNotchWrites(std::nullopt, std::nullopt).empty());
    EXPECT_TRUE(pidTuneNotchWrites(kOld, kOld).empty());
    // Inserted: it runs now (0 → 1), its f0 and Q with nothing before.
    EXPECT_EQ(pidTuneNotchWrites(std::nullopt, kNew),
              (std::vector<PidTuneWrite>{{"axistune-notch", 0.0, 1.0},
                                         {"axistune-notch.f0", std::nullopt, 107.33},
                                         {"axistune-notch.Q", std::nullopt, 0.7}}));
    // Retuned: f0 and Q, before → after.
    EXPECT_EQ(pidTuneNotchWrites(kOld, kNew),
              (std::vector<PidTuneWrite>{{"axistune-notch.f0", 150.0, 107.33}, {"axistune-notch.Q", 1.0, 0.7}}));
    // A new Q alone: the component is loaded again with both.
    EXPECT_EQ(pidTuneNotchWrites(kOld, tuning::BiquadNotch{150.0, 0.7}),
              (std::vector<PidTuneWrite>{{"axistune-notch.f0", 150.0, 150.0}, {"axistune-notch.Q", 1.0, 0.7}}));
    // Removed: it runs no more (1 → 0); f0 and Q have no value after it.
    EXPECT_EQ(pidTuneNotchWrites(kOld, std::nullopt), (std::vector<PidTuneWrite>{{"axistune-notch", 1.0, 0.0}}));
}

TEST(PidTuneJournal, AnApplyJournalsTheGainsWrittenThenTheNotch)
{
    PidTuneApplied a = appliedGains();
    a.notchBefore = kOld;
    PidTuneProposal p; // its notch: none, so the running one is removed
    EXPECT_EQ(pidTuneAppliedWrites(a, p), (std::vector<PidTuneWrite>{{"Dgain", 0.01, 0.143},
                                                                     {"FF1", 0.0, 0.0},
                                                                     {"FF2", 3e-4, 3.5e-4},
                                                                     {"Igain", 2.0, 23.0},
                                                                     {"Pgain", 1.0, 0.5},
                                                                     {"axistune-notch", 1.0, 0.0}}));
    // Not kept: what ran before is back, nothing to journal.
    a.applied = false;
    EXPECT_TRUE(pidTuneAppliedWrites(a, p).empty());
    // The notch wizard: no gain written, a notch inserted where none ran.
    PidTuneApplied notchOnly;
    notchOnly.applied = true;
    p.notch = kNew;
    EXPECT_EQ(pidTuneAppliedWrites(notchOnly, p), pidTuneNotchWrites(std::nullopt, kNew));
    EXPECT_EQ(pidTuneAppliedWrites(notchOnly, p).size(), 3u);
}

// Undo anyway over a later change: the journal starts from what HAL held just before the undo (Pgain 0.3 set by
// hand, a notch at 120 Hz, Q 2 put there by hand), not from what the tune applied.
TEST(PidTuneJournal, AForcedUndoStartsFromWhatHalHeldJustBefore)
{
    const std::vector<UndoneParameter> gains{{"Dgain", 0.143, 0.01}, {"Pgain", 0.3, 1.0}};
    PidTuneNotchUndone notch;
    notch.changed = true;
    notch.held = tuning::BiquadNotch{120.0, 2.0};
    notch.restored = kOld;
    EXPECT_EQ(pidTuneUndoWrites(gains, notch), (std::vector<PidTuneWrite>{{"Dgain", 0.143, 0.01},
                                                                          {"Pgain", 0.3, 1.0},
                                                                          {"axistune-notch.f0", 120.0, 150.0},
                                                                          {"axistune-notch.Q", 2.0, 1.0}}));
    // The tune's notch removed by the undo (none ran before it).
    notch.held = kNew;
    notch.restored = std::nullopt;
    EXPECT_EQ(pidTuneUndoWrites({}, notch), (std::vector<PidTuneWrite>{{"axistune-notch", 1.0, 0.0}}));
    // Someone removed the notch already: the undo's removal changes nothing.
    notch.held = std::nullopt;
    EXPECT_TRUE(pidTuneUndoWrites({}, notch).empty());
    // The tune left the notch as it was: the undo did not touch it.
    PidTuneNotchUndone untouched;
    untouched.held = kNew;
    EXPECT_EQ(pidTuneUndoWrites(gains, untouched).size(), 2u);
}

TEST(PidTuneJournal, TheResultJsonListsTheWritesOfAKeptTune)
{
    EXPECT_EQ(pidTuneWritesJson({{"axistune-notch.f0", std::nullopt, 107.33}, {"Pgain", 1.0, 0.5}}),
              nlohmann::json::parse(R"([{"key": "axistune-notch.f0", "new": 107.33},
                                        {"key": "Pgain", "old": 1.0, "new": 0.5}])"));
    PidTuneRequest r;
    r.axis = "pid.x";
    PidLoopMeasurement m;
    m.servoRateHz = 1000.0;
    PidTuneProposal p;
    p.notch = kNew;
    PidTuneApplied a = appliedGains();
    const auto kept = pidTuneJson(r, m, p, &a);
    ASSERT_TRUE(kept.contains("journal"));
    ASSERT_EQ(kept["journal"].size(), 8u); // five gains, the notch inserted (runs, f0, Q)
    EXPECT_EQ(kept["journal"][5], nlohmann::json::parse(R"({"key": "axistune-notch", "old": 0.0, "new": 1.0})"));
    a.applied = false;
    a.refusal = "the measured loop misses the margins asked";
    EXPECT_FALSE(pidTuneJson(r, m, p, &a).contains("journal"));
    EXPECT_FALSE(pidTuneJson(r, m, p).contains("journal"));
}

// Without a change of the notch the undo neither reads nor writes it; with one, a drive that is no HAL session is
// refused (nothing of AxisTune's notch can run there), not reported as undone.
TEST(PidTuneJournal, TheNotchUndoOnADriveWithoutHal)
{
    auto drive = device::connect({"sim:vmc", 1});
    ASSERT_TRUE(drive) << drive.error().detail;
    auto same = undoPidTuneNotch(**drive, {"X", kOld, kOld});
    ASSERT_TRUE(same) << same.error().detail;
    EXPECT_FALSE(same->changed);
    auto other = undoPidTuneNotch(**drive, {"X", std::nullopt, kNew});
    ASSERT_FALSE(other);
    EXPECT_NE(other.error().detail.find("HAL"), std::string::npos) << other.error().detail;
}
