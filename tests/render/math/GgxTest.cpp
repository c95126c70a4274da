// The GGX lobe's math (render/math/Ggx.hpp) against independent quadratures (tests/render/GgxReference.hpp):
// D and the visible normals are normalised, the albedo is right, and the visible-normal sampler draws
// with the density it claims, so that the tracer's estimator is unbiased.
#include "render/math/Ggx.hpp"

#include "support/GgxReference.hpp"

#include <cmath>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <random>

namespace speculum::test {
namespace {

namespace math = render::math;

const double kAlphas[] = {0.04, 0.25, 1.0}; // roughness 0.2, 0.5, 1
const double kViewAngles[] = {0.0, 60.0, 85.0};

glm::dvec3 view(double degrees) {
    const double t = degrees * ggx::kPi / 180.0;
    return {std::sin(t), 0.0, std::cos(t)};
}

glm::dvec3 direction(double theta, double phi) {
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

TEST(Ggx, DistributionIsNormalisedAndMatchesTheAngularForm) {
    for (double alpha : kAlphas) {
        const double projected = ggx::hemisphereIntegral(
            [&](double theta, double phi) {
                return math::ggxD(direction(theta, phi), alpha) * std::cos(theta);
            },
            1024, 16);
        EXPECT_NEAR(projected, 1.0, 1e-6) << "alpha " << alpha;
        for (double theta : {0.0, 0.1, 0.7, 1.4})
            EXPECT_NEAR(math::ggxD(direction(theta, 0.3), alpha), ggx::distribution(std::cos(theta), alpha),
                        1e-9 * ggx::distribution(std::cos(theta), alpha));
    }
}

// ∫ G1(v) max(0, v·h) D(h) dω_h = n·v: Λ belongs to this D (the visible normals' density integrates to 1).
TEST(Ggx, VisibleNormalsAreNormalised) {
    for (double alpha : kAlphas)
        for (double angle : kViewAngles) {
            const glm::dvec3 v = view(angle);
            const double g1 = math::smithG1(v, alpha);
            EXPECT_NEAR(g1, 1.0 / (1.0 + ggx::lambda(v.z, alpha)), 1e-12);
            const double projected = ggx::hemisphereIntegral(
                [&](double theta, double phi) {
                    const glm::dvec3 h = direction(theta, phi);
                    return g1 * std::max(0.0, glm::dot(v, h)) * math::ggxD(h, alpha);
                },
                1024, 1024);
            EXPECT_NEAR(projected, v.z, 1e-5 * v.z + 1e-7) << "alpha " << alpha << ", view " << angle;
        }
}

TEST(Ggx, HeightCorrelatedMaskingLiesBetweenTheProductAndTheMinimum) {
    const glm::dvec3 l = glm::normalize(glm::dvec3(-0.5, 0.2, 0.4));
    for (double alpha : kAlphas)
        for (double angle : kViewAngles) {
            const glm::dvec3 v = view(angle);
            const double g2 = math::smithG2(v, l, alpha);
            EXPECT_DOUBLE_EQ(g2, math::smithG2(l, v, alpha));
            EXPECT_GE(g2, math::smithG1(v, alpha) * math::smithG1(l, alpha));
            EXPECT_LE(g2, std::min(math::smithG1(v, alpha), math::smithG1(l, alpha)));
            EXPECT_NEAR(math::visibleNormalWeight(v, l, alpha), g2 / math::smithG1(v, alpha), 1e-12);
        }
    EXPECT_EQ(math::smithG2(view(0.0), glm::dvec3(1, 0, -0.1), 0.5), 0.0);
    EXPECT_EQ(math::visibleNormalWeight(view(0.0), glm::dvec3(1, 0, -0.1), 0.5), 0.0);
}

TEST(Ggx, AlbedoQuadratureMatchesTheIndependentOne) {
    for (double alpha : kAlphas)
        for (double angle : kViewAngles) {
            const double expected = ggx::albedo(angle * ggx::kPi / 180.0, alpha);
            EXPECT_NEAR(math::ggxDirectionalAlbedo(std::cos(angle * ggx::kPi / 180.0), alpha), expected, 1e-7)
                << "alpha " << alpha << ", view " << angle;
        }
    // A rougher lobe loses more to masking (at normal incidence).
    EXPECT_GT(math::ggxDirectionalAlbedo(1.0, 0.04), math::ggxDirectionalAlbedo(1.0, 0.25));
    // A closed form: at α = 1, D = 1/π and, seen along the normal, G2 = 2μ_l/(1 + μ_l), so
    // E = ∫ D·G2/4 dω_l = ½∫₀¹ 2μ/(1 + μ) dμ = 1 − ln 2.
    EXPECT_NEAR(math::ggxDirectionalAlbedo(1.0, 1.0), 1.0 - std::log(2.0), 1e-9);
}

// The sampler's density: the mean of a function of h over a fine grid of (u1, u2) equals its integral
// against D_v(h) = G1(v) max(0, v·h) D(h) / (n·v). h.x tells the lobe's lean towards the viewer.
TEST(Ggx, SamplerDrawsTheVisibleNormals) {
    const int n = 1024;
    for (double alpha : kAlphas)
        for (double angle : kViewAngles) {
            const glm::dvec3 v = view(angle);
            glm::dvec3 mean(0.0);
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j)
                    mean += math::sampleVisibleNormal(v, alpha, (i + 0.5) / n, (j + 0.5) / n);
            mean /= double(n) * n;
            const double g1 = math::smithG1(v, alpha);
            for (int axis : {0, 2}) {
                const double expected = ggx::hemisphereIntegral(
                    [&](double theta, double phi) {
                        const glm::dvec3 h = direction(theta, phi);
                        return h[axis] * g1 * std::max(0.0, glm::dot(v, h)) * math::ggxD(h, alpha) / v.z;
                    },
                    1024, 1024);
                EXPECT_NEAR(mean[axis], expected, 2e-4) << "alpha " << alpha << ", view " << angle;
            }
            EXPECT_NEAR(mean.y, 0.0, 1e-9);
        }
}

// The estimator: the average weight G2/G1 of random samples is the albedo, within 4 standard errors.
TEST(Ggx, SampleWeightsAverageToTheAlbedo) {
    std::mt19937_64 random(19);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (double alpha : kAlphas)
        for (double angle : kViewAngles) {
            const glm::dvec3 v = view(angle);
            const int count = 1 << 18;
            double sum = 0.0, squares = 0.0;
            for (int i = 0; i < count; ++i) {
                const glm::dvec3 h = math::sampleVisibleNormal(v, alpha, uniform(random), uniform(random));
                const double w = math::visibleNormalWeight(v, math::reflectAbout(v, h), alpha);
                sum += w;
                squares += w * w;
            }
            const double mean = sum / count;
            const double standardError = std::sqrt((squares / count - mean * mean) / (count - 1));
            const double expected = ggx::albedo(angle * ggx::kPi / 180.0, alpha);
            EXPECT_NEAR(mean, expected, 4.0 * standardError + 1e-9)
                << "alpha " << alpha << ", view " << angle;
        }
}

TEST(Ggx, SamplesStayValidAtGrazingViewsAndTinyRoughness) {
    const glm::dvec3 views[] = {view(0.0), view(89.999), glm::dvec3(1.0, 0.0, 0.0),
                                glm::normalize(glm::dvec3(1.0, 1.0, -1e-12))};
    for (double alpha : {1e-8, 1e-3, 0.5, 1.0})
        for (const glm::dvec3& v : views)
            for (double u1 : {0.0, 0.25, 0.999999})
                for (double u2 : {0.0, 0.5, 0.999999}) {
                    const glm::dvec3 h = math::sampleVisibleNormal(v, alpha, u1, u2);
                    ASSERT_TRUE(std::isfinite(h.x) && std::isfinite(h.y) && std::isfinite(h.z));
                    EXPECT_NEAR(glm::length(h), 1.0, 1e-12);
                    EXPECT_GE(h.z, 0.0);
                    const double w = math::visibleNormalWeight(v, math::reflectAbout(v, h), alpha);
                    EXPECT_TRUE(std::isfinite(w) && w >= 0.0 && w <= 1.0) << w;
                }
}

} // namespace
} // namespace speculum::test
