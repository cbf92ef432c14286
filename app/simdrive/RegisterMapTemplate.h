// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>

namespace axistune::simdrive {

/// The JSON text of resources/drives/axistune-sim.json, built from the simulator's catalogue.
std::string simRegisterMapJson();

} // namespace axistune::simdrive
