// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A LinuxCNC configuration as the HAL backend needs it (docs/linuxcnc.md "Configurations"): the INI, the HAL
// files it names, the pid instances they load, which INI key feeds each gain of each pid (or that a gain is a
// literal in a HAL file), the joints and their axis letters; and Persist: new gains written into exactly the
// INI keys that feed them, every other byte of the file unchanged, with a backup next to it.

#include "core/model/Result.h"

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace axistune::device::hal {

/// One `KEY = VALUE` line of an INI file.
struct IniEntry {
    std::string section;
    std::string key;
    std::string value;
    std::size_t line = 0;       ///< 1-based
    std::size_t valueBegin = 0; ///< byte offset of the value in the file text
    std::size_t valueEnd = 0;   ///< one past its last byte (before trailing blanks and the line end)
};

struct IniFile {
    std::string path;
    std::string text;
    std::vector<IniEntry> entries;
    /// The first value of [section]key (LinuxCNC reads the first); nullptr when absent.
    const IniEntry* find(std::string_view section, std::string_view key) const;
    std::vector<const IniEntry*> findAll(std::string_view section, std::string_view key) const;
};

/// Parses INI text: sections `[NAME]`, `KEY = VALUE` lines, `#` and `;` comment lines. A line that is none of
/// these is an error naming the file and line.
Result<IniFile> parseIni(std::string path, std::string text);
Result<IniFile> readIni(const std::string& path);

/// Where one gain of one pid comes from.
struct GainSource {
    std::string pin;     ///< e.g. pid_x.Pgain
    std::string section; ///< INI section when fed by [SECTION]KEY
    std::string key;     ///< INI key
    std::string literal; ///< the value when written as a literal in the HAL file
    std::string halFile; ///< the HAL file with the setp
    std::size_t halLine = 0;
};

struct PidInstance {
    std::string name;       ///< pid_x, pid.0 …
    int joint = -1;         ///< the [JOINT_n] its gains come from; -1 when none
    std::string axisLetter; ///< from [TRAJ]COORDINATES for trivial kinematics; empty when unknown
    std::map<std::string, GainSource>
        gains; ///< by pin suffix: Pgain, Igain, Dgain, FF0, FF1, FF2, bias, deadband, maxoutput, maxerror …
};

struct LinuxCncConfig {
    IniFile ini;
    std::vector<std::string> halFiles; ///< resolved paths, in load order
    std::vector<std::string> notes;    ///< what was not read and why (e.g. a .tcl HAL file)
    std::vector<PidInstance> pids;
    const PidInstance* findPid(std::string_view name) const;
};

/// Reads the INI and the HAL files of its [HAL]HALFILE (and POSTGUI_HALFILE) lines: a name is looked for next to
/// the INI first, then in `hallibDir` (LinuxCNC's own library; `LIB:name` only there).
Result<LinuxCncConfig> readLinuxCncConfig(const std::string& iniPath,
                                          const std::string& hallibDir = "/usr/share/linuxcnc/hallib");

/// Reads one HAL file's text into `cfg`: `loadrt pid` lines add pid instances (names= or count=/num_chan=,
/// 1 to 64), `setp <pid>.<gain> VALUE` lines record where each gain comes from ([SECTION]KEY or a literal);
/// `letters` are the coordinate letters of trivial kinematics (joint n is letters[n]). Every other line is left
/// alone (HAL files hold much else). A malformed pid line is refused naming `halPath` and the line.
Status addHalText(LinuxCncConfig& cfg, const std::string& halPath, std::string_view text, std::string_view letters);

/// A gain to persist: pid pin suffix (Pgain …) and its new value.
struct GainChange {
    std::string pid;
    std::string gain;
    double value = 0.0;
};

struct IniEdit {
    std::string section;
    std::string key;
    std::size_t line = 0;
    std::string oldValue;
    std::string newValue;
};

/// The INI text with the given gains written into the keys that feed them; every other byte unchanged. Refused
/// (nothing written) when a gain is unknown, fed by no INI key, or written as a literal in a HAL file (the
/// message names the HAL file and line: AxisTune does not edit HAL files), or when a value is not finite.
Result<std::pair<std::string, std::vector<IniEdit>>> planPersist(const LinuxCncConfig& config,
                                                                 const std::vector<GainChange>& changes);

/// Applies planPersist to the file: a backup of the original next to it (`<ini>.axistune-backup`, replaced each
/// time), then the new text written atomically. Returns the edits.
Result<std::vector<IniEdit>> persistGains(const LinuxCncConfig& config, const std::vector<GainChange>& changes);

} // namespace axistune::device::hal
