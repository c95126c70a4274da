#include "render/math/GgxAlbedoTable.hpp"

#include "render/math/Ggx.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/vec3.hpp>

namespace speculum::render::math {

namespace {

// The view of the first column: exactly in the plane no microfacet is visible, so a hair above it.
constexpr double kGrazingCosine = 1e-4;

// Van der Corput's radical inverse in base 2: the second coordinate of the Hammersley set.
double radicalInverse(std::uint32_t bits) {
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return double(bits) * 2.3283064365386963e-10; // 2^-32
}

// The mean weight of visible-normal samples: the estimator the tracer's rough bounces use.
double estimatedAlbedo(double mu, double alpha) {
    if (!(alpha > 0.0))
        return 1.0; // a perfect mirror loses nothing
    const glm::dvec3 v(std::sqrt(std::max(0.0, 1.0 - mu * mu)), 0.0, mu);
    double sum = 0.0;
    for (int k = 0; k < GgxAlbedoTable::kSamples; ++k) {
        const double u1 = (k + 0.5) / GgxAlbedoTable::kSamples;
        const double u2 = radicalInverse(static_cast<std::uint32_t>(k));
        const glm::dvec3 h = sampleVisibleNormal(v, alpha, u1, u2);
        sum += visibleNormalWeight(v, reflectAbout(v, h), alpha);
    }
    return sum / GgxAlbedoTable::kSamples;
}

GgxAlbedoTable computed() {
    GgxAlbedoTable table;
    constexpr int n = GgxAlbedoTable::kSize;
    for (int j = 0; j < n; ++j) {
        const double roughness = GgxAlbedoTable::nodeRoughness(j);
        for (int i = 0; i < n; ++i) {
            table.values[std::size_t(j * n + i)] =
                float(estimatedAlbedo(GgxAlbedoTable::nodeCosine(i), roughness * roughness));
        }
    }
    return table;
}

} // namespace

double GgxAlbedoTable::nodeCosine(int i) {
    return i == 0 ? kGrazingCosine : double(i) / (kSize - 1);
}

double GgxAlbedoTable::nodeRoughness(int j) {
    return double(j) / (kSize - 1);
}

double GgxAlbedoTable::at(double cosThetaV, double roughness) const {
    // The nodes are evenly spaced in μ (the first sits at a hair above 0, read as 0, as the shaders do).
    const double x = std::clamp(cosThetaV, 0.0, 1.0) * (kSize - 1);
    const double y = std::clamp(roughness, 0.0, 1.0) * (kSize - 1);
    const int i = std::min(int(x), kSize - 2), j = std::min(int(y), kSize - 2);
    const double fx = x - i, fy = y - j;
    const auto value = [&](int a, int b) { return double(values[std::size_t(b * kSize + a)]); };
    return (1 - fy) * ((1 - fx) * value(i, j) + fx * value(i + 1, j)) +
           fy * ((1 - fx) * value(i, j + 1) + fx * value(i + 1, j + 1));
}

const GgxAlbedoTable& ggxAlbedoTable() {
    static const GgxAlbedoTable table = computed();
    return table;
}

} // namespace speculum::render::math
