// SPDX-License-Identifier: GPL-3.0-or-later
// Correlation chatter detection, spec/cutting-force-observer-and-chatter-detection.md §2.2 eqs. (1)–(2) (causal
// window [t−T, t]), §2.3 (O(1) moving sums), §3.6 CD-2 (periodic re-summation, energy gate), CD-3 (rule).
#include "core/machining/CorrelationChatterDetector.h"

#include <algorithm>
#include <cmath>

namespace axistune::machining {

CorrelationChatterDetector::CorrelationChatterDetector(std::size_t windowSamples, double energyFloor)
    : m_n(std::max<std::size_t>(windowSamples, 2)), m_floor(energyFloor), m_ring(5 * m_n, 0.0)
{
    std::fill(std::begin(m_zeros), std::end(m_zeros), m_n);
}

void CorrelationChatterDetector::reset()
{
    std::fill(m_ring.begin(), m_ring.end(), 0.0);
    m_head = m_count = m_sinceResum = 0;
    std::fill(std::begin(m_s), std::end(m_s), 0.0);
    std::fill(std::begin(m_zeros), std::end(m_zeros), m_n);
}

void CorrelationChatterDetector::resum()
{
    std::fill(std::begin(m_s), std::end(m_s), 0.0);
    for (std::size_t i = 0; i < m_n; ++i)
        for (int c = 0; c < 5; ++c)
            m_s[c] += m_ring[5 * i + static_cast<std::size_t>(c)];
}

CorrelationSample CorrelationChatterDetector::step(double f, double x, double a)
{
    const double p[5] = {f * f, x * x, a * a, f * x, f * a};
    double* slot = &m_ring[5 * m_head];
    for (int c = 0; c < 3; ++c)
        m_zeros[c] += static_cast<std::size_t>(p[c] == 0.0) - static_cast<std::size_t>(slot[c] == 0.0);
    for (int c = 0; c < 5; ++c) {
        m_s[c] += p[c] - slot[c];
        slot[c] = p[c];
    }
    m_head = (m_head + 1) % m_n;
    m_count = std::min(m_count + 1, m_n);
    if (++m_sinceResum >= m_n) {  // cancel floating-point drift of the running sums
        resum();
        m_sinceResum = 0;
    }
    CorrelationSample s;
    const double nf = static_cast<double>(m_n);
    const double floorSum = m_floor * nf;
    // A window of exact zeros is invalid even while the running sums still hold a rounding residue of data
    // that has left the window (until the next re-summation), spec §3.9 V-004-03.
    const bool zeroEnergy = m_zeros[0] == m_n || m_zeros[1] == m_n || m_zeros[2] == m_n;
    if (m_count < m_n || zeroEnergy || !(m_s[0] > floorSum) || !(m_s[1] > floorSum) || !(m_s[2] > floorSum) || m_s[0] <= 0.0 ||
        m_s[1] <= 0.0 || m_s[2] <= 0.0)
        return s;
    s.rFx = std::clamp(m_s[3] / std::sqrt(m_s[0] * m_s[1]), -1.0, 1.0);
    s.rFa = std::clamp(m_s[4] / std::sqrt(m_s[0] * m_s[2]), -1.0, 1.0);
    s.valid = std::isfinite(s.rFx) && std::isfinite(s.rFa);
    s.chatter = s.valid && s.rFx < s.rFa;
    return s;
}

}  // namespace axistune::machining
