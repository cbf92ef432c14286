// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Universal File Format (UFF/UNV) dataset 58 "Function at Nodal DOF", ASCII form (docs/formats.md
// "UFF58"), written from the dataset's specification (SDRC/I-DEAS universal file, records 1–12):
//   records 1–5 ID lines; 6 DOF identification Format(2(I5,I10),2(1X,10A1,I10,I4));
//   7 data form Format(3I10,3E13.5): ordinate type (2/4 real single/double, 5/6 complex single/double),
//     points, abscissa spacing (0 uneven, 1 even), minimum, increment, z value;
//   8–11 abscissa / ordinate numerator / ordinate denominator / z axis Format(I10,3I5,2(1X,20A1)):
//     data type (8 displacement, 11 velocity, 12 acceleration, 13 excitation force, 17 time,
//     18 frequency, ...), length, force and temperature unit exponents, axis label, units label;
//   12 the values (x only when uneven; complex values as re, im).
// Datasets are framed by lines "    -1"; other datasets are skipped, except 164 (units), whose length and
// force factors convert the values to SI. The binary form (58b) is refused with its line.

#include "core/dsp/FrequencyResponse.h"
#include "core/model/Capture.h"
#include "core/model/Result.h"

#include <complex>
#include <istream>
#include <string>
#include <vector>

namespace axistune::io {

struct UffAxis {
    int dataType = 0;
    int lengthExp = 0, forceExp = 0, temperatureExp = 0;
    std::string label, unitsLabel;
};

struct Uff58Record {
    std::size_t line = 0; ///< file line of the "58" line
    std::vector<std::string> idLines;
    int functionType = 0; ///< 1 time response, 4 FRF, ...
    int functionId = 0, version = 0, loadCase = 0;
    std::string responseName, referenceName;
    int responseNode = 0, responseDirection = 0, referenceNode = 0, referenceDirection = 0;
    int ordinateType = 0; ///< 2, 4 real; 5, 6 complex
    bool evenSpacing = true;
    double xMin = 0.0, xStep = 0.0, zValue = 0.0;
    UffAxis abscissa, numerator, denominator, zAxis;
    std::vector<double> x;                        ///< abscissa of every point (filled for even spacing too)
    std::vector<std::complex<double>> y;          ///< ordinate (imaginary part 0 for real data)
    double lengthFactor = 1.0, forceFactor = 1.0; ///< dataset 164 in force before this record (1 without)
    bool isComplex() const { return ordinateType == 5 || ordinateType == 6; }
};

/// All dataset-58 records of a universal file, in file order.
Result<std::vector<Uff58Record>> readUff58(std::istream& in, const std::string& sourceName);
Result<std::vector<Uff58Record>> readUff58File(const std::string& path);

/// An FRF (function type 4, or any complex function against frequency) as an AxisTune FRF in SI:
/// units from dataset 164, else from the units labels (m, mm, um, m/s, m/s^2, g, N, ...), else SI by the
/// data types (noted in metadata units_assumed=SI); an unknown label is refused.
Result<dsp::FrequencyResponse> frfFromUff(const Uff58Record& record, const std::string& sourceName);

/// Time-response records (function type 1, real, even spacing) as one capture: equal length and step
/// required; channels named by ID line 1 (else "node<N>_dir<D>"), converted to SI as for FRFs; t_s added.
Result<model::Capture> captureFromUff(const std::vector<Uff58Record>& records, const std::string& sourceName);

} // namespace axistune::io
