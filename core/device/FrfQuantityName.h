// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One spelling of the FRF quantities (device::FrfQuantity) wherever they are text: the FRF's `quantity` metadata
// (model::meta::kQuantity) that backends, wizards and sessions write and read, the CLI's `--quantity` and the
// `drive` command's list. (The Modbus register map has its own names for its enumeration, TestRegisterCodec.cpp.)

#include "core/device/Drive.h"

#include <optional>
#include <string_view>

namespace axistune::device {

/// "default", "plant", "open-loop".
constexpr std::string_view frfQuantityMetadataName(FrfQuantity q)
{
    switch (q) {
    case FrfQuantity::Plant:
        return "plant";
    case FrfQuantity::OpenLoop:
        return "open-loop";
    case FrfQuantity::Default:
        break;
    }
    return "default";
}

/// The inverse of frfQuantityMetadataName; nullopt for any other text.
constexpr std::optional<FrfQuantity> frfQuantityFromMetadataName(std::string_view name)
{
    for (const auto q : {FrfQuantity::Default, FrfQuantity::Plant, FrfQuantity::OpenLoop})
        if (frfQuantityMetadataName(q) == name)
            return q;
    return std::nullopt;
}

} // namespace axistune::device
