// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Connections as a registry (docs/drive-seam.md): every backend describes its URI scheme, a label,
// the form of its URI and its settings (fields a GUI builds a form from), and opens a Drive from a
// URI. device::connect() dispatches through the registry; the GUI's Connect dialog and the CLI's
// --connect help list what is registered. A backend is one folder with one line in Backends.def.

#include "core/device/Drive.h"
#include "core/model/Result.h"

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

/// Marks a backend's English label for translation (context "DriveRegistry"): lupdate treats it as
/// QT_TRANSLATE_NOOP (-tr-function-alias in app/gui/CMakeLists.txt), the GUI translates the text with
/// QCoreApplication::translate("DriveRegistry", text). Core stays free of Qt.
#define AXISTUNE_TRANSLATE_NOOP(context, text) text

namespace axistune::device {

/// One field of a backend's settings form. Labels and hints are English; a GUI translates them by their
/// text in the translation context "DriveRegistry" (docs/drive-seam.md "Translations").
struct BackendSetting {
    enum class Type { Text, Integer, Choice, File };
    std::string name;  ///< key in the values given to DriveBackend::uriFromSettings
    std::string label; ///< "Machine preset"
    Type type = Type::Text;
    std::string defaultValue;           ///< as text ("vmc", "502")
    std::string unit;                   ///< "ms", or empty
    std::vector<std::string> choices;   ///< Type::Choice
    long long minimum = 0, maximum = 0; ///< Type::Integer
    bool required = false;              ///< an empty value is refused
    std::string hint;                   ///< placeholder text or tool tip
};

/// A setting with its name, label, type, default and unit (the other members as they are).
BackendSetting makeSetting(std::string name, std::string label, BackendSetting::Type type,
                           std::string defaultValue = {}, std::string unit = {});

using SettingValues = std::map<std::string, std::string>;

struct DriveBackend {
    std::string scheme;      ///< URI prefix: "sim:", "modbus://", "replay:"
    std::string label;       ///< "Built-in simulated machine"
    std::string uriForm;     ///< "sim:PRESET[?model=PATH&axis=NAME]"
    std::string description; ///< one or two sentences for help texts
    std::vector<BackendSetting> settings;
    bool usesSeed = false; ///< ConnectionSettings::seed means something (the simulator's noise)
    /// The URI of a settings form (every setting present, defaults filled in); errors name the setting.
    std::function<Result<std::string>(const SettingValues&)> uriFromSettings;
    /// Opens the connection; errors name the URI and what is wrong with it.
    std::function<Result<std::unique_ptr<Drive>>(const ConnectionSettings&)> open;
};

/// The registered backends in registration order (Backends.def).
const std::vector<DriveBackend>& registeredBackends();
/// The backend whose scheme starts `uri`, or nullptr.
const DriveBackend* findBackend(const std::string& uri);
/// "sim:PRESET[...], modbus://HOST:PORT[...] or replay:FILE" for messages and help texts.
std::string registeredUriForms();
/// Gives a backend whose URI is its scheme followed by a file path (replay:, linuxcnc:) its one required File setting
/// "file" (label and hint as given, English, translated by the GUI) and the uriFromSettings that builds that URI.
void setFileSetting(DriveBackend& backend, std::string label, std::string hint);

/// Settings of a backend with their default values.
SettingValues defaultSettings(const DriveBackend& backend);
/// Checks the values of a settings form against their descriptions (required, integer range, choice);
/// the error names the setting by its label.
Status checkSettings(const DriveBackend& backend, const SettingValues& values);

/// The query of a URI ("a=1&b=2") as key → value; errors name the item that is not key=value.
Result<SettingValues> parseUriQuery(const std::string& query);

} // namespace axistune::device
