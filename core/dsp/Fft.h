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
    void* m_plan = nullptr; // fftw_plan, owned by the global cache
};

/// The inverse: n/2 + 1 bins of a Hermitian spectrum to n real values (unnormalised: x[t] = Σ_k X[k] e^{+2πikt/n} over
/// the full spectrum, so x = n × the mean; divide by n for the inverse of RealFft). FFTW's c2r overwrites its input.
class InverseRealFft {
public:
    explicit InverseRealFft(std::size_t n);
    ~InverseRealFft();
    InverseRealFft(const InverseRealFft&) = delete;
    InverseRealFft& operator=(const InverseRealFft&) = delete;

    std::size_t size() const { return m_n; }
    std::size_t bins() const { return m_n / 2 + 1; }
    std::span<std::complex<double>> input() { return {m_in, bins()}; }
    void execute();
    std::span<const double> output() const { return {m_out, m_n}; }

private:
    std::size_t m_n;
    std::complex<double>* m_in = nullptr;
    double* m_out = nullptr;
    void* m_plan = nullptr; // fftw_plan, owned by the global cache
};

} // namespace axistune::dsp
