#include "render/math/Ggx.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>

namespace speculum::render::math {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The smallest cosine a view keeps: a view exactly in the plane (or a hair below it, from rounding) has
// no visible microfacets to sample, so it is nudged just above the horizon instead.
constexpr double kMinViewCosine = 1e-9;

} // namespace

double ggxD(const glm::dvec3& h, double alpha) {
    if (h.z <= 0.0)
        return 0.0;
    const double a2 = alpha * alpha;
    const double c2 = h.z * h.z / glm::dot(h, h);
    const double t = c2 * (a2 - 1.0) + 1.0;
    return a2 / (kPi * t * t);
}

double smithLambda(const glm::dvec3& w, double alpha) {
    if (w.z <= 0.0)
        return kInfinity;
    // α² tan²θ from the components, without forming tan θ (finite for any w.z > 0).
    const double a2t2 = alpha * alpha * (w.x * w.x + w.y * w.y) / (w.z * w.z);
    return 0.5 * (std::sqrt(1.0 + a2t2) - 1.0);
}

double smithG1(const glm::dvec3& w, double alpha) {
    return w.z <= 0.0 ? 0.0 : 1.0 / (1.0 + smithLambda(w, alpha));
}

double smithG2(const glm::dvec3& v, const glm::dvec3& l, double alpha) {
    if (v.z <= 0.0 || l.z <= 0.0)
        return 0.0;
    return 1.0 / (1.0 + smithLambda(v, alpha) + smithLambda(l, alpha));
}

double visibleNormalWeight(const glm::dvec3& v, const glm::dvec3& l, double alpha) {
    if (l.z <= 0.0)
        return 0.0;
    const double lv = smithLambda(glm::dvec3(v.x, v.y, std::max(v.z, kMinViewCosine)), alpha);
    const double ll = smithLambda(l, alpha);
    if (std::isinf(ll))
        return 0.0;
    // (1 + Λv)/(1 + Λv + Λl) = 1 / (1 + Λl/(1 + Λv)): finite even where Λv overflows.
    return 1.0 / (1.0 + ll / (1.0 + lv));
}

glm::dvec3 sampleVisibleNormal(const glm::dvec3& v, double alpha, double u1, double u2) {
    // Section 3 of the paper, isotropic (αx = αy = α). 1: the view in the hemisphere configuration,
    // where the stretched GGX lobe is the unit hemisphere.
    const glm::dvec3 vh = glm::normalize(glm::dvec3(alpha * v.x, alpha * v.y, std::max(v.z, kMinViewCosine)));
    // 2: an orthonormal basis around it (any tangent when the view is along the normal).
    const double lensq = vh.x * vh.x + vh.y * vh.y;
    const glm::dvec3 t1 = lensq > 0.0 ? glm::dvec3(-vh.y, vh.x, 0.0) / std::sqrt(lensq) : glm::dvec3(1, 0, 0);
    const glm::dvec3 t2 = glm::cross(vh, t1);
    // 3: a point of the projected area: a uniform disk whose lower half is squashed by the part of the
    // hemisphere the view cannot see.
    const double r = std::sqrt(u1);
    const double phi = 2.0 * kPi * u2;
    const double p1 = r * std::cos(phi);
    double p2 = r * std::sin(phi);
    const double s = 0.5 * (1.0 + vh.z);
    p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * p2;
    // 4: back onto the hemisphere, 5: unstretched to the ellipsoid's normal.
    const glm::dvec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
    const glm::dvec3 ne(alpha * nh.x, alpha * nh.y, std::max(0.0, nh.z));
    const double length = glm::length(ne);
    // Only a sample on the very rim with a vanishing α has no direction left: the macro normal it tends to.
    return length > 0.0 ? ne / length : glm::dvec3(0.0, 0.0, 1.0);
}

glm::dvec3 reflectAbout(const glm::dvec3& v, const glm::dvec3& h) {
    return 2.0 * glm::dot(v, h) * h - v;
}

double ggxDirectionalAlbedo(double cosThetaV, double alpha, int thetaPanels, int phiSteps) {
    // E = ∫ D(h) G2(v, l) / (4 (n·v)) dω_l: f·(n·l) with f = D G2 / (4 (n·v)(n·l)).
    const double mu = std::clamp(cosThetaV, kMinViewCosine, 1.0);
    const glm::dvec3 v(std::sqrt(std::max(0.0, 1.0 - mu * mu)), 0.0, mu);
    // 5-point Gauss–Legendre on [−1, 1].
    static constexpr std::array<double, 5> node = {0.0, -0.5384693101056831, 0.5384693101056831,
                                                   -0.9061798459386640, 0.9061798459386640};
    static constexpr std::array<double, 5> weight = {
        0.5688888888888889, 0.4786286704993665, 0.4786286704993665, 0.2369268850561891, 0.2369268850561891};
    const int panels = std::max(thetaPanels, 1);
    const int steps = std::max(phiSteps, 1);
    const double panel = 0.5 * kPi / panels;
    // The lobe lies around the mirror direction, at φ = π (v is at φ = 0), and is symmetric about the
    // plane of v and n: φ runs over [π, 2π] only, doubled. At grazing views the lobe is far narrower in φ
    // than in θ (a tilt of h across the plane of incidence moves l by 2(v·h) times as much), so the nodes
    // crowd towards φ = π: φ = π + ψ − c·sin ψ with ψ uniform keeps the rule periodic (so still spectrally
    // accurate) with nodes 1/(1 − c) times denser there.
    constexpr double c = 0.9;
    const double dpsi = kPi / steps;
    double sum = 0.0;
    for (int p = 0; p < panels; ++p) {
        for (std::size_t k = 0; k < node.size(); ++k) {
            const double theta = (p + 0.5 + 0.5 * node[k]) * panel;
            const double sinT = std::sin(theta), cosT = std::cos(theta);
            double ring = 0.0;
            for (int j = 0; j < steps; ++j) {
                const double psi = (j + 0.5) * dpsi;
                const double phi = kPi + psi - c * std::sin(psi);
                const glm::dvec3 l(sinT * std::cos(phi), sinT * std::sin(phi), cosT);
                const glm::dvec3 h = v + l;
                if (glm::dot(h, h) <= 0.0)
                    continue;
                ring += ggxD(glm::normalize(h), alpha) * smithG2(v, l, alpha) * (1.0 - c * std::cos(psi));
            }
            sum += 0.5 * weight[k] * panel * sinT * 2.0 * dpsi * ring;
        }
    }
    return sum / (4.0 * mu);
}

} // namespace speculum::render::math
