// SPDX-License-Identifier: GPL-3.0-or-later
// Registration of the Modbus TCP drive, "modbus://HOST:PORT[?timeout_ms=N&map=FAMILY]"
// (DriveRegistry.h, docs/drive-seam.md, docs/modbus.md).
#include "core/device/DriveRegistry.h"
#include "core/device/ModbusDrive.h"
#include <nlohmann/json.hpp>

namespace axistune::device {

DriveBackend modbusBackend()
{
    DriveBackend b;
    b.scheme = "modbus://";
    b.label = AXISTUNE_TRANSLATE_NOOP("DriveRegistry", "Drive over Modbus TCP");
    b.uriForm = "modbus://HOST:PORT[?timeout_ms=N&map=FAMILY]";
    b.description = AXISTUNE_TRANSLATE_NOOP(
        "DriveRegistry", "A drive speaking a register map of resources/drives/ over Modbus TCP (docs/modbus.md); "
                         "axis i answers on unit id base + i of the map.");
    BackendSetting host =
        makeSetting("host", AXISTUNE_TRANSLATE_NOOP("DriveRegistry", "Host"), BackendSetting::Type::Text, "127.0.0.1");
    host.required = true;
    host.hint = AXISTUNE_TRANSLATE_NOOP("DriveRegistry", "host name or address of the drive");
    BackendSetting port =
        makeSetting("port", AXISTUNE_TRANSLATE_NOOP("DriveRegistry", "Port"), BackendSetting::Type::Integer, "502");
    port.minimum = 1;
    port.maximum = 65535;
    port.required = true;
    BackendSetting timeout = makeSetting("timeout_ms", AXISTUNE_TRANSLATE_NOOP("DriveRegistry", "Response timeout"),
                                         BackendSetting::Type::Integer, "1000", "ms");
    timeout.minimum = 10;
    timeout.maximum = 60000;
    BackendSetting map = makeSetting("map", AXISTUNE_TRANSLATE_NOOP("DriveRegistry", "Register map"),
                                     BackendSetting::Type::Text, "axistune-sim");
    map.hint = AXISTUNE_TRANSLATE_NOOP("DriveRegistry", "family of resources/drives/FAMILY.json");
    b.settings = {host, port, timeout, map};
    b.uriFromSettings = [b](const SettingValues& v) -> Result<std::string> {
        if (auto st = checkSettings(b, v); !st)
            return st.error();
        auto get = [&](const char* k) { return v.count(k) ? v.at(k) : std::string(); };
        std::string u = "modbus://" + get("host") + ":" + get("port"), query;
        if (!get("timeout_ms").empty() && get("timeout_ms") != "1000")
            query += "timeout_ms=" + get("timeout_ms");
        if (!get("map").empty() && get("map") != "axistune-sim")
            query += (query.empty() ? "" : "&") + std::string("map=") + get("map");
        return query.empty() ? u : u + "?" + query;
    };
    b.open = connectModbus;
    return b;
}

} // namespace axistune::device
