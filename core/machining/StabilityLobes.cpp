// SPDX-License-Identifier: GPL-3.0-or-later
// Stability lobes of 2-DOF milling by the (first-order, zero-order-hold) semi-discretization method,
// spec/chatter-stability-and-spindle-speed.md §2.1–§2.5 and §2.8, with the implementer's corrections of
// §2.3 (shift-register delay rows, spectral radius rather than the maximum singular value).
//
// Structure used: the lifted step matrix D_i is [P_i, ½R_i·(last two delay blocks); C; shift]. Applying
// it to the running monodromy product only multiplies the n tool-state rows (O(n·N) per row), copies
// C·(state rows) into a ring of 2×N delay blocks and moves the ring's head — the shift costs nothing.
// P_i and R_i come from one exponential of the block matrix [[A_1i, B_c],[0, 0]]·Δt (§6.1 "numerical
// hygiene"), so A_1i is never inverted. Positions are scaled by a reference frequency ω0 (a diagonal
// similarity, which leaves the multipliers unchanged) so that ‖A Δt‖ stays near 1.
#include "core/machining/StabilityLobes.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <unsupported/Eigen/MatrixFunctions>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <thread>

namespace axistune::machining {

namespace {

struct StateSpace {
    Eigen::MatrixXd a;  // ns × ns
    Eigen::MatrixXd b;  // ns × 2 (force → state derivative)
    Eigen::MatrixXd c;  // 2 × ns (state → scaled tool displacement ω0·q)
    int ns = 0;
};

// States: [ω0·x_1 … ω0·x_n, v_1 … v_n]; output ω0·q with q_x = Σ x-modes, q_y = Σ y-modes.
StateSpace buildStateSpace(const ToolModes& tool, double omega0)
{
    std::vector<std::pair<ModalParameters, int>> modes;
    for (const auto& m : tool.modesX)
        modes.emplace_back(m, 0);
    for (const auto& m : tool.modesY)
        modes.emplace_back(m, 1);
    const int n = static_cast<int>(modes.size());
    StateSpace ss;
    ss.ns = 2 * n;
    ss.a = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    ss.b = Eigen::MatrixXd::Zero(2 * n, 2);
    ss.c = Eigen::MatrixXd::Zero(2, 2 * n);
    for (int i = 0; i < n; ++i) {
        const auto& [m, dir] = modes[static_cast<std::size_t>(i)];
        ss.a(i, n + i) = omega0;
        ss.a(n + i, i) = -m.stiffnessNPerM / m.massKg / omega0;
        ss.a(n + i, n + i) = -m.dampingNsPerM / m.massKg;
        ss.b(n + i, dir) = 1.0 / m.massKg;
        ss.c(dir, i) = 1.0;
    }
    return ss;
}

double referenceOmega(const ToolModes& tool)
{
    double w = 0.0;
    for (const auto* list : {&tool.modesX, &tool.modesY})
        for (const auto& m : *list)
            w = std::max(w, std::sqrt(m.stiffnessNPerM / m.massKg));
    return w;
}

// Everything about one spindle speed that does not depend on the depth.
struct SpeedSetup {
    double dt = 0.0;
    std::vector<Eigen::Matrix2d> kf;  // interval means of K_f, one per step
};

SpeedSetup setupSpeed(const CuttingConditions& cut, double rpm, int k)
{
    SpeedSetup s;
    const double tau = 60.0 / (rpm * cut.teeth);
    s.dt = tau / k;
    const double dTheta = 2.0 * std::numbers::pi / (cut.teeth * static_cast<double>(k));
    s.kf.reserve(static_cast<std::size_t>(k));
    for (int i = 0; i < k; ++i)
        s.kf.push_back(averageCuttingMatrix(cut, i * dTheta, (i + 1) * dTheta));
    return s;
}

// Small matrices (tool state plus the two force inputs) live on the stack when they fit.
template <typename Small>
Eigen::MatrixXd monodromyImpl(const StateSpace& ss, double omega0, const SpeedSetup& sp, double depthM,
                              Eigen::MatrixXd* feedInput)
{
    const int k = static_cast<int>(sp.kf.size());
    const int ns = ss.ns;
    const int n = ns + 2 * k;
    Eigen::MatrixXd top = Eigen::MatrixXd::Zero(ns, n);
    top.leftCols(ns).setIdentity();
    Eigen::MatrixXd ring = Eigen::MatrixXd::Zero(2 * k, n);  // slot r = rows 2r, 2r+1
    for (int j = 0; j < k; ++j)
        ring.block(2 * j, ns + 2 * j, 2, 2).setIdentity();  // slot j holds q[i−1−j]
    int head = 0;
    const Small a = ss.a, b = ss.b, c = ss.c;
    Small aug = Small::Zero(ns + 2, ns + 2);
    Small bc(ns, 2), e(ns + 2, ns + 2), p(ns, ns), r(ns, 2);
    Eigen::MatrixXd delayed(2, n), newQ(2, n), nextTop(ns, n);
    // Optional lifted input matrix G (spec (3-25)), tracked with the same structure: N × k.
    Eigen::MatrixXd gTop, gRing, gDelayed, gNewQ, gNextTop;
    if (feedInput) {
        gTop = Eigen::MatrixXd::Zero(ns, k);
        gRing = Eigen::MatrixXd::Zero(2 * k, k);
    }
    for (int i = 0; i < k; ++i) {
        // ω0 scaling: the force from scaled displacement is K_f·(ω0 q)/ω0.
        bc.noalias() = (depthM / omega0) * b * sp.kf[static_cast<std::size_t>(i)];
        aug.topLeftCorner(ns, ns) = a * sp.dt;
        aug.topLeftCorner(ns, ns).noalias() -= (bc * sp.dt) * c;
        aug.topRightCorner(ns, 2) = bc * sp.dt;
        e = aug.exp();
        p = e.topLeftCorner(ns, ns);
        r = e.block(0, ns, ns, 2);
        const int slotK = (head + k - 1) % k;   // q[i−k]
        const int slotK1 = (head + k - 2) % k;  // q[i−k+1] (k ≥ 2)
        delayed = 0.5 * (ring.middleRows(2 * slotK, 2) + ring.middleRows(2 * slotK1, 2));
        newQ.noalias() = c * top;
        nextTop.noalias() = p * top;
        nextTop.noalias() += r * delayed;
        top.swap(nextTop);
        if (feedInput) {
            // The static chip enters like the delayed position with weight 1 (h0 = [u_f, 0]): E_i = R_i[:, 0].
            gDelayed = 0.5 * (gRing.middleRows(2 * slotK, 2) + gRing.middleRows(2 * slotK1, 2));
            gNewQ.noalias() = c * gTop;
            gNextTop.noalias() = p * gTop;
            gNextTop.noalias() += r * gDelayed;
            gNextTop.col(i) += r.col(0);
            gTop.swap(gNextTop);
            gRing.middleRows(2 * ((head + k - 1) % k), 2) = gNewQ;
        }
        head = (head + k - 1) % k;
        ring.middleRows(2 * head, 2) = newQ;  // the shift: only the ring head moves
    }
    if (feedInput) {
        feedInput->resize(n, k);
        feedInput->topRows(ns) = gTop;
        for (int j = 0; j < k; ++j)
            feedInput->middleRows(ns + 2 * j, 2) = gRing.middleRows(2 * ((head + j) % k), 2);
    }
    Eigen::MatrixXd f(n, n);
    f.topRows(ns) = top;
    for (int j = 0; j < k; ++j)
        f.middleRows(ns + 2 * j, 2) = ring.middleRows(2 * ((head + j) % k), 2);
    return f;
}

Eigen::MatrixXd monodromy(const StateSpace& ss, double omega0, const SpeedSetup& sp, double depthM,
                          Eigen::MatrixXd* feedInput = nullptr)
{
    using Small = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 16, 16>;
    if (ss.ns + 2 <= 16)
        return monodromyImpl<Small>(ss, omega0, sp, depthM, feedInput);
    return monodromyImpl<Eigen::MatrixXd>(ss, omega0, sp, depthM, feedInput);
}

double denseSpectralRadius(const Eigen::MatrixXd& f)
{
    Eigen::EigenSolver<Eigen::MatrixXd> es(f, false);
    return es.eigenvalues().cwiseAbs().maxCoeff();
}

// Arnoldi (modified Gram–Schmidt, one re-orthogonalisation) on F. The multipliers of a damped tool fall off
// quickly (a dominant pair per mode, the rest well below), so a Krylov space of ~24 vectors gives the
// largest ones far below the root-search tolerance. Convergence test: the largest Ritz modulus of the
// m-dimensional space must agree with that of its (m−6)-dimensional leading part; otherwise a negative value
// is returned and the caller solves the dense problem.
double arnoldiSpectralRadius(const Eigen::MatrixXd& f, int m)
{
    const Eigen::Index n = f.rows();
    Eigen::MatrixXd v(n, m + 1);
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero(m + 1, m);
    for (Eigen::Index i = 0; i < n; ++i)
        v(i, 0) = 1.0 + 0.5 * std::sin(1.7 * static_cast<double>(i) + 0.3);  // generic, deterministic
    v.col(0).normalize();
    Eigen::VectorXd w(n);
    for (int j = 0; j < m; ++j) {
        w.noalias() = f * v.col(j);
        for (int pass = 0; pass < 2; ++pass) {
            const Eigen::VectorXd c = v.leftCols(j + 1).transpose() * w;
            h.col(j).head(j + 1) += c;
            w.noalias() -= v.leftCols(j + 1) * c;
        }
        h(j + 1, j) = w.norm();
        if (h(j + 1, j) < 1e-14 * h.col(j).norm()) {  // invariant subspace: its Ritz values are exact
            Eigen::EigenSolver<Eigen::MatrixXd> es(h.topLeftCorner(j + 1, j + 1), false);
            return es.eigenvalues().cwiseAbs().maxCoeff();
        }
        v.col(j + 1) = w / h(j + 1, j);
    }
    Eigen::EigenSolver<Eigen::MatrixXd> full(h.topLeftCorner(m, m), false);
    Eigen::EigenSolver<Eigen::MatrixXd> part(h.topLeftCorner(m - 6, m - 6), false);
    const double rho = full.eigenvalues().cwiseAbs().maxCoeff();
    const double rhoPart = part.eigenvalues().cwiseAbs().maxCoeff();
    return std::abs(rho - rhoPart) <= 1e-9 * std::max(rho, 1e-3) ? rho : -1.0;
}

double spectralRadius(const Eigen::MatrixXd& f)
{
    constexpr int kKrylov = 24;
    if (f.rows() > 2 * kKrylov) {
        const double rho = arnoldiSpectralRadius(f, kKrylov);
        if (rho >= 0.0)
            return rho;
    }
    return denseSpectralRadius(f);
}

Status checkInputs(const ToolModes& tool, const CuttingConditions& cut, int k)
{
    if (auto s = validateTool(tool); !s)
        return s;
    if (auto s = validateCut(cut); !s)
        return s;
    if (k < 4 || k > 2000)
        return makeError(ErrorCode::OutOfRange, "steps per period must be between 4 and 2000 (got " + std::to_string(k) + ")");
    return Status::success();
}

// The search itself, on validated inputs. Returns +inf when stable up to depthMaxM.
double searchLimit(const StateSpace& ss, double omega0, const SpeedSetup& sp, const LobeOptions& opt, double guess)
{
    auto logRho = [&](double a) { return std::log(spectralRadius(monodromy(ss, omega0, sp, a))); };
    double a = std::clamp(guess, 1e-7, opt.depthMaxM);
    double g = logRho(a);
    double lo = 0.0, glo = 0.0, hi = 0.0, ghi = 0.0;
    if (g < 0.0) {
        lo = a, glo = g;
        for (;;) {
            if (a >= opt.depthMaxM)
                return std::numeric_limits<double>::infinity();
            a = std::min(2.0 * a, opt.depthMaxM);
            g = logRho(a);
            if (g >= 0.0) {
                hi = a, ghi = g;
                break;
            }
            lo = a, glo = g;
        }
    } else {
        hi = a, ghi = g;
        for (;;) {
            a *= 0.5;
            if (a < 1e-9)
                return a;  // unstable at any practical depth: report the floor
            g = logRho(a);
            if (g < 0.0) {
                lo = a, glo = g;
                break;
            }
            hi = a, ghi = g;
        }
    }
    // Safeguarded secant (regula falsi in log a), bisection in log a when the step is poor.
    bool lastWasLo = false;
    int sameSide = 0;
    for (int it = 0; it < 100 && (hi - lo) > opt.relTolerance * hi; ++it) {
        const double la = std::log(lo), lb = std::log(hi);
        double x = la - glo * (lb - la) / (ghi - glo);
        const double margin = 0.02 * (lb - la);
        if (!(x > la + margin && x < lb - margin) || sameSide >= 2) {
            x = 0.5 * (la + lb);
            sameSide = 0;
        }
        const double am = std::exp(x);
        const double gm = logRho(am);
        if (gm < 0.0) {
            sameSide = lastWasLo ? sameSide + 1 : 0;
            lastWasLo = true;
            lo = am, glo = gm;
        } else {
            sameSide = !lastWasLo ? sameSide + 1 : 0;
            lastWasLo = false;
            hi = am, ghi = gm;
        }
    }
    return 0.5 * (lo + hi);
}

}  // namespace

Result<double> monodromySpectralRadius(const ToolModes& tool, const CuttingConditions& cut, double rpm, double depthM,
                                       int stepsPerPeriod)
{
    if (auto s = checkInputs(tool, cut, stepsPerPeriod); !s)
        return s.error();
    if (!(rpm > 0.0) || !std::isfinite(rpm))
        return makeError(ErrorCode::OutOfRange, "spindle speed must be > 0 rpm");
    if (!(depthM >= 0.0) || !std::isfinite(depthM))
        return makeError(ErrorCode::OutOfRange, "depth must be >= 0 m");
    const double w0 = referenceOmega(tool);
    const auto ss = buildStateSpace(tool, w0);
    return denseSpectralRadius(monodromy(ss, w0, setupSpeed(cut, rpm, stepsPerPeriod), depthM));
}

Result<ChatterIndices> chatterIndices(const ToolModes& tool, const CuttingConditions& cut, double rpm, double depthM,
                                      int stepsPerPeriod)
{
    if (auto s = checkInputs(tool, cut, stepsPerPeriod); !s)
        return s.error();
    if (!(rpm > 0.0) || !std::isfinite(rpm) || !(depthM >= 0.0) || !std::isfinite(depthM))
        return makeError(ErrorCode::OutOfRange, "spindle speed must be > 0 rpm and depth >= 0 m");
    const double w0 = referenceOmega(tool);
    const auto ss = buildStateSpace(tool, w0);
    Eigen::MatrixXd g;
    const Eigen::MatrixXd f = monodromy(ss, w0, setupSpeed(cut, rpm, stepsPerPeriod), depthM, &g);
    ChatterIndices out;
    out.lambda = denseSpectralRadius(f);
    if (out.lambda >= 1.0) {
        out.sigma = std::numeric_limits<double>::infinity();
        return out;
    }
    // H selects the y position now and in the delay line: y[ki], y[ki−1], …, y[ki−k] (spec (3-27)).
    // In scaled coordinates H̃(I−F)⁻¹G̃ equals the physical ratio (the ω0 factors cancel).
    const Eigen::Index n = f.rows();
    const int k = stepsPerPeriod;
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero(k + 1, n);
    h.row(0).head(ss.ns) = ss.c.row(1);
    for (int j = 0; j < k; ++j)
        h(j + 1, ss.ns + 2 * j + 1) = 1.0;
    const Eigen::MatrixXd x = (Eigen::MatrixXd::Identity(n, n) - f).partialPivLu().solve(g);
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(h * x);
    out.sigma = svd.singularValues()(0);
    return out;
}

Result<double> limitDepth(const ToolModes& tool, const CuttingConditions& cut, double rpm, const LobeOptions& opt)
{
    auto r = stabilityLobes(tool, cut, {rpm}, opt);
    if (!r)
        return r.error();
    return r->front().limitDepthM;
}

Result<std::vector<LobePoint>> stabilityLobes(const ToolModes& tool, const CuttingConditions& cut,
                                              const std::vector<double>& rpms, const LobeOptions& opt)
{
    if (auto s = checkInputs(tool, cut, opt.stepsPerPeriod); !s)
        return s.error();
    if (!(opt.depthMaxM > 0.0) || !(opt.relTolerance > 0.0) || !(opt.depthGuessM > 0.0))
        return makeError(ErrorCode::OutOfRange, "depth search limits must be > 0");
    for (double r : rpms)
        if (!(r > 0.0) || !std::isfinite(r))
            return makeError(ErrorCode::OutOfRange, "spindle speeds must be > 0 rpm");
    const double w0 = referenceOmega(tool);
    const auto ss = buildStateSpace(tool, w0);
    std::vector<LobePoint> out(rpms.size());
    std::atomic<std::size_t> next{0};
    auto worker = [&]() {
        double guess = opt.depthGuessM;
        for (std::size_t i = next++; i < rpms.size(); i = next++) {
            const auto sp = setupSpeed(cut, rpms[i], opt.stepsPerPeriod);
            const double lim = searchLimit(ss, w0, sp, opt, guess);
            out[i] = {rpms[i], lim};
            if (std::isfinite(lim))
                guess = lim;  // neighbouring speeds have similar limits: a cheap bracket
        }
    };
    const int nThreads = std::max(1, std::min<int>(opt.threads, static_cast<int>(rpms.size())));
    std::vector<std::thread> pool;
    for (int t = 1; t < nThreads; ++t)
        pool.emplace_back(worker);
    worker();
    for (auto& t : pool)
        t.join();
    return out;
}

Result<std::vector<double>> rpmGrid(double rpmMin, double rpmMax, double rpmStep)
{
    if (!(rpmMin > 0.0) || !std::isfinite(rpmMin))
        return makeError(ErrorCode::OutOfRange, "rpm-min must be > 0");
    if (!(rpmMax >= rpmMin) || !std::isfinite(rpmMax))
        return makeError(ErrorCode::OutOfRange, "rpm-max must be >= rpm-min");
    if (!(rpmStep > 0.0) || !std::isfinite(rpmStep))
        return makeError(ErrorCode::OutOfRange, "rpm-step must be > 0");
    const double count = std::floor((rpmMax - rpmMin) / rpmStep + 0.5 + 1e-9) + 1.0;
    if (count > 100000.0)
        return makeError(ErrorCode::OutOfRange, "more than 100000 spindle speeds requested");
    std::vector<double> g;
    for (int i = 0; i < static_cast<int>(count); ++i) {
        const double r = rpmMin + i * rpmStep;
        if (r > rpmMax + 0.5 * rpmStep)
            break;
        g.push_back(r);
    }
    return g;
}

}  // namespace axistune::machining
