// SPDX-License-Identifier: GPL-3.0-or-later
// FFTW3 r2c wrapper: plans cached per length, created under one global mutex (DESIGN.md / STYLE.md).
#include "core/dsp/Fft.h"

#include <fftw3.h>

#include <map>
#include <mutex>
#include <new>

namespace axistune::dsp {

namespace {

std::mutex& planMutex()
{
    static std::mutex m;
    return m;
}

/// The plan cache; the plans are destroyed at exit (LeakSanitizer in the sanitizer tree reports them
/// otherwise).
struct PlanCache : std::map<std::size_t, fftw_plan> {
    ~PlanCache()
    {
        for (auto& [n, p] : *this)
            fftw_destroy_plan(p);
    }
};

// Plans live for the whole program; FFTW plans may be executed concurrently on other aligned
// arrays through the new-array execute interface.
fftw_plan cachedPlan(std::size_t n)
{
    std::lock_guard<std::mutex> lock(planMutex());
    static PlanCache plans;
    auto it = plans.find(n);
    if (it != plans.end())
        return it->second;
    double* in = fftw_alloc_real(n);
    fftw_complex* out = fftw_alloc_complex(n / 2 + 1);
    fftw_plan p = fftw_plan_dft_r2c_1d(static_cast<int>(n), in, out, FFTW_ESTIMATE);
    fftw_free(in);
    fftw_free(out);
    plans.emplace(n, p);
    return p;
}

}  // namespace

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

void RealFft::execute()
{
    fftw_execute_dft_r2c(static_cast<fftw_plan>(m_plan), m_in, reinterpret_cast<fftw_complex*>(m_out));
}

}  // namespace axistune::dsp
