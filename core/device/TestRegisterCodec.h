// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A TestRequest and the test registers of a Modbus register map: one table between them (docs/modbus.md
// "Test block"). Every map field that configures a test names in "carries" the one request quantity it holds,
// its unit in the name ("step.velocity_rad_s", "current_step.current_a", "frf.amplitude_pct", "jog.jerk"). The
// client encodes a request by walking the map's fields, and the served drive decodes the registers back into a
// request with the same table: a quantity is named, converted and checked once, and a register never means
// rad/s for one test and A for another.

#include "core/device/Drive.h"
#include "core/device/RegisterMap.h"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace axistune::device {

/// Carried quantities and their values (enumerations as the map's codes, counts and flags as whole numbers).
using TestValues = std::map<std::string, double>;

struct TestQuantity {
    std::string name;      ///< "frf.amplitude_pct"
    std::string enumGroup; ///< the map's enumeration of its codes ("test_type"), empty for numbers
    bool whole = false;    ///< a count, flag set, code or axis index: a whole number ≥ 0
    std::string meaning;   ///< for the map's description and the docs
};

/// Every quantity a map field may carry, in protocol order. "reserved" carries nothing (the client writes 0, the
/// drive ignores it) and may appear on several fields; every other quantity on one field at most.
const std::vector<TestQuantity>& testQuantities();
const TestQuantity* findTestQuantity(const std::string& name);

/// The request as the quantities `map` carries. Refused (BadInput), before anything is written, when the request
/// gives a quantity no field of the map carries ("drive family axistune-sim has no register for step.position")
/// or a value its enumeration lacks. `axisIndex` turns a circle's second axis name into its axis index.
Result<TestValues> testValuesOf(const TestRequest& r, const RegisterMap& map,
                                const std::function<Result<int>(const std::string&)>& axisIndex);

/// The request `values` describe on `axis` (the inverse of testValuesOf); `axisNames` by axis index.
Result<TestRequest> testRequestOf(const TestValues& values, const RegisterMap& map, const std::string& axis,
                                  const std::vector<std::string>& axisNames);

/// One decoded register value against its quantity: finite, a whole number where it must be, a known code.
/// The error names the field ("test.type: unknown test_type code 9").
Status checkTestValue(const RegisterField& field, const RegisterMap& map, double value);

struct RegisterWrite {
    int address = 0;
    std::vector<std::uint16_t> words;
};
/// The map's carrying fields filled from `values` (absent: 0), as writes of contiguous registers, at most
/// `maxPerWrite` each. OutOfRange when a value does not fit its field's type.
Result<std::vector<RegisterWrite>> encodeTestRegisters(const TestValues& values, const RegisterMap& map,
                                                       int maxPerWrite = 123);

/// A carrying field's registers as a number, by its type; and back (the value must fit: checked by the caller).
double decodeCarried(const RegisterField& f, const std::uint16_t* w, WordOrder o);
void encodeCarried(const RegisterField& f, double v, WordOrder o, std::uint16_t* w);

} // namespace axistune::device
