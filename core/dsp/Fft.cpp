// SPDX-License-Identifier: GPL-3.0-or-later
// FFTW3 r2c wrapper: plans cached per length, created under one global mutex (DESIGN.md / STYLE.md).
#include "core/dsp/Fft.h"

#include <fftw3.h>
#include <map>
#include <mutex>
#include <new>
#include <utility>

namespace axistune::dsp {

namespace {

std::mutex& planMutex()
{
    static std::mutex m;
    return m;
}

/// The plan cache; the plans are destroyed at exit (LeakSanitizer in the sanitizer tree reports them
/// otherwise).
struct PlanCache : std::map<std::pair<std::size_t, bool>, fftw_plan> {
    ~PlanCache()
    {
        for (auto& [n, p] : *this)
            fftw_destroy_plan(p);
    }
};

// Plans live for the whole program; FFTW plans may be executed concurrently on other aligned
// arrays through the new-array execute interface.
fftw_plan cachedPlan(std::size_t n, bool inverse = false)
{
    std::lock_guard<std::mutex> lock(planMutex());
    static PlanCache plans;
    auto it = plans.find({n, inverse});
    if (it != plans.end())
        return it->second;
    double* real = fftw_alloc_real(n);
    fftw_complex* spectrum = fftw_alloc_complex(n / 2 + 1);
    fftw_plan p = inverse ? fftw_plan_dft_c2r_1d(static_cast<int>(n), spectrum, real, FFTW_ESTIMATE)
                          : fftw_plan_dft_r2c_1d(static_cast<int>(n), real, spectrum, FFTW_ESTIMATE);
    fftw_free(real);
    fftw_free(spectrum);
    plans.emplace(std::make_pair(n, inverse), p);
    return p;
}

} // namespace

RealFft::RealFft(std::size_t n) : m_n(n)
{
    m_plan = cachedPlan(n);
    m_in = fftw_alloc_real(n);
    m_out = reinterpret_cast<std::complex<double>*>(fftw_alloc_complex(n / 2 + 1));
    if (m_in == nullptr || m_out == nullptr || m_plan == nullptr)
        throw std::bad_alloc();
}

RealFft::~RealFft()
{
    fftw_free(m_in);
    fftw_free(reinterpret_cast<fftw_complex*>(m_out));
}

InverseRealFft::InverseRealFft(std::size_t n) : m_n(n)
{
    m_plan = cachedPlan(n, true);
    m_in = reinterpret_cast<std::complex<double>*>(fftw_alloc_complex(n / 2 + 1));
    m_out = fftw_alloc_real(n);
    if (m_in == nullptr || m_out == nullptr || m_plan == nullptr)
        throw std::bad_alloc();
}

InverseRealFft::~InverseRealFft()
{
    fftw_free(reinterpret_cast<fftw_complex*>(m_in));
    fftw_free(m_out);
}

void InverseRealFft::execute()
{
    fftw_execute_dft_c2r(static_cast<fftw_plan>(m_plan), reinterpret_cast<fftw_complex*>(m_in), m_out);
}

void RealFft::execute()
{
    fftw_execute_dft_r2c(static_cast<fftw_plan>(m_plan), m_in, reinterpret_cast<fftw_complex*>(m_out));
}

} // namespace axistune::dsp
