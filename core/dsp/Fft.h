// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Real-to-complex FFT over FFTW3. Plans are created once per length under one global mutex
// (FFTW's planner is not thread-safe) and cached; executing a plan is thread-safe, so one RealFft
// per thread may run concurrently. Buffers are FFTW-aligned so the cached plan can run on them.

#include <complex>
#include <cstddef>
#include <memory>
#include <span>

namespace axistune::dsp {

class RealFft {
public:
    /// A transform of length n (n ≥ 1); output has n/2 + 1 bins.
    explicit RealFft(std::size_t n);
    ~RealFft();
    RealFft(const RealFft&) = delete;
    RealFft& operator=(const RealFft&) = delete;

    std::size_t size() const { return m_n; }
    std::size_t bins() const { return m_n / 2 + 1; }
    /// The input buffer (n values) to fill before execute().
    std::span<double> input() { return {m_in, m_n}; }
    /// Transforms input() into output() (unnormalised: X[k] = Σ x[t] e^{-2πikt/n}).
    void execute();
    std::span<const std::complex<double>> output() const { return {m_out, bins()}; }

private:
    std::size_t m_n;
    double* m_in = nullptr;
    std::complex<double>* m_out = nullptr;
    void* m_plan = nullptr;  // fftw_plan, owned by the global cache
};

}  // namespace axistune::dsp
