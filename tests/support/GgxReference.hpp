#pragma once

// Test-side GGX formulas, written from the papers in angles rather than taken from render/math/Ggx.hpp,
// so that the sampler and the tracer are checked against an independent statement of the lobe. Shared by
// the pure-math tests (tests/render/math) and the tracer's glossy tests (tests/render/reference).
#include <cmath>
#include <numbers>

namespace speculum::test::ggx {

inline constexpr double kPi = std::numbers::pi;

// Trowbridge–Reitz: D(θ_h) = α² / (π cos⁴θ_h (α² + tan²θ_h)²).
inline double distribution(double cosThetaH, double alpha) {
    if (cosThetaH <= 0.0)
        return 0.0;
    const double c2 = cosThetaH * cosThetaH;
    const double tan2 = (1.0 - c2) / c2;
    const double s = alpha * alpha + tan2;
    return alpha * alpha / (kPi * c2 * c2 * s * s);
}

// Smith Λ for GGX from the direction's polar angle.
inline double lambda(double cosTheta, double alpha) {
    const double tan2 = (1.0 - cosTheta * cosTheta) / (cosTheta * cosTheta);
    return (std::sqrt(1.0 + alpha * alpha * tan2) - 1.0) / 2.0;
}

// Integrates g(θ, φ)·sinθ over θ in [0, π/2], φ in [0, 2π] on a fine grid: composite 3-point
// Gauss–Legendre in θ (no sample on the pole or the horizon), the midpoint rule in φ, with the nodes
// crowded `crowd` times denser around φ = π (φ = π + ψ − c·sin ψ, c = 1 − 1/crowd, ψ uniform: still
// periodic, so still spectrally accurate), where a lobe seen from φ = 0 reflects to.
template <typename G>
double hemisphereIntegral(G&& g, int thetaPanels = 1024, int phiSteps = 2048, double crowd = 1.0) {
    const double x = std::sqrt(0.6);
    const double nodes[3] = {-x, 0.0, x};
    const double weights[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
    const double panel = kPi / 2.0 / thetaPanels, dpsi = 2.0 * kPi / phiSteps, c = 1.0 - 1.0 / crowd;
    double sum = 0.0;
    for (int i = 0; i < thetaPanels; ++i)
        for (int k = 0; k < 3; ++k) {
            const double theta = (i + 0.5 + 0.5 * nodes[k]) * panel;
            double ring = 0.0;
            for (int j = 0; j < phiSteps; ++j) {
                const double psi = (j + 0.5) * dpsi - kPi;
                ring += g(theta, kPi + psi - c * std::sin(psi)) * (1.0 - c * std::cos(psi));
            }
            sum += 0.5 * weights[k] * panel * std::sin(theta) * ring * dpsi;
        }
    return sum;
}

// The directional albedo E(θ_v, α) = ∫ f(v, l) cosθ_l dω_l with F = 1 and the height-correlated Smith
// G2 = 1 / (1 + Λ(v) + Λ(l)): what a rough perfect mirror shows of a uniform white surround.
inline double albedo(double thetaV, double alpha) {
    const double sv = std::sin(thetaV), cv = std::cos(thetaV);
    return hemisphereIntegral(
        [&](double theta, double phi) {
            const double sl = std::sin(theta), cl = std::cos(theta);
            // h ∝ v + l with v = (sin θv, 0, cos θv).
            const double hx = sv + sl * std::cos(phi), hy = sl * std::sin(phi), hz = cv + cl;
            const double cosH = hz / std::sqrt(hx * hx + hy * hy + hz * hz);
            const double g2 = 1.0 / (1.0 + lambda(cv, alpha) + lambda(cl, alpha));
            return distribution(cosH, alpha) * g2 / (4.0 * cv * cl) * cl;
        },
        512, 1024, 20.0);
}

} // namespace speculum::test::ggx
