// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Correlation-based chatter detection (spec/cutting-force-observer-and-chatter-detection.md §2.2–§2.4, §3.6
// CD-2/CD-3): zero-lag normalised correlations of force with position (r_Fx) and with acceleration (r_Fa) over a
// moving window; chatter ⇔ r_Fx < r_Fa. O(1) per sample with moving sums, re-summed every window.

#include <cstddef>
#include <vector>

namespace axistune::machining {

struct CorrelationSample {
    double rFx = 0.0;
    double rFa = 0.0;
    bool valid = false;    ///< window full and every energy above its floor
    bool chatter = false;  ///< valid && rFx < rFa
};

class CorrelationChatterDetector {
public:
    /// windowSamples ≥ 2; energyFloor: minimum mean square of each signal for a valid index.
    explicit CorrelationChatterDetector(std::size_t windowSamples, double energyFloor = 0.0);
    void reset();
    CorrelationSample step(double force, double position, double acceleration);

private:
    void resum();
    std::size_t m_n;
    double m_floor;
    std::vector<double> m_ring;  // 5 products per sample: FF, XX, AA, FX, FA
    std::size_t m_head = 0, m_count = 0, m_sinceResum = 0;
    double m_s[5] = {0, 0, 0, 0, 0};
    std::size_t m_zeros[3] = {0, 0, 0};  // slots of the window whose FF, XX, AA product is exactly 0
};

}  // namespace axistune::machining
