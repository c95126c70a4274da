#include "render/envmap/SolidAngle.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

namespace speculum::render::envmap {

namespace {

// Gauss–Legendre nodes and weights on [0, 1].
constexpr std::array<double, 3> kNodes{0.5 - 0.38729833462074168852, 0.5, 0.5 + 0.38729833462074168852};
constexpr std::array<double, 3> kWeights{5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};

} // namespace

double texelSolidAngle(const MapLayout& layout, int x, int y) {
    const glm::dvec2 lo = layout.toNominal(glm::dvec2(double(x) / layout.width, double(y) / layout.height));
    const glm::dvec2 hi =
        layout.toNominal(glm::dvec2(double(x + 1) / layout.width, double(y + 1) / layout.height));
    const glm::dvec2 size = hi - lo;
    double sum = 0.0;
    for (std::size_t i = 0; i < kNodes.size(); ++i)
        for (std::size_t j = 0; j < kNodes.size(); ++j)
            sum += kWeights[i] * kWeights[j] *
                   solidAngleDensity(layout.type, lo + size * glm::dvec2(kNodes[i], kNodes[j]));
    return sum * size.x * size.y;
}

bool texelUsed(const MapLayout& layout, int component, int x, int y) {
    if (layout.type == MapType::Cube)
        return true; // every direction in a face's square belongs to that face
    constexpr int kSteps = 4;
    for (int i = 0; i <= kSteps; ++i)
        for (int j = 0; j <= kSteps; ++j) {
            const glm::dvec2 t((x + double(i) / kSteps) / layout.width,
                               (y + double(j) / kSteps) / layout.height);
            // A point of the guard band is not used: it repeats a direction the component holds elsewhere
            // (an octahedral map's band its own square folded) or that another component holds.
            const glm::dvec2 nominal = layout.toNominal(t);
            const double rounding = 1e-12;
            if (nominal.x < -rounding || nominal.y < -rounding || nominal.x > 1.0 + rounding ||
                nominal.y > 1.0 + rounding)
                continue;
            const glm::dvec3 d = fromMap(layout.type, component, nominal);
            if (mapComponent(layout.type, d) == component)
                return true;
        }
    return false;
}

SolidAngleStats solidAngleStats(MapType type, int resolution) {
    const MapLayout layout = makeLayout(type, resolution);
    SolidAngleStats stats;
    stats.type = type;
    stats.resolution = resolution;
    stats.minTexel = std::numeric_limits<double>::max();
    stats.totalTexels = std::int64_t(layout.components) * layout.width * layout.height;
    for (int c = 0; c < layout.components; ++c)
        for (int y = 0; y < layout.height; ++y)
            for (int x = 0; x < layout.width; ++x) {
                if (!texelUsed(layout, c, x, y))
                    continue;
                const double omega = texelSolidAngle(layout, x, y);
                stats.minTexel = std::min(stats.minTexel, omega);
                stats.maxTexel = std::max(stats.maxTexel, omega);
                stats.usedSolidAngle += omega;
                ++stats.usedTexels;
            }
    stats.ratio = stats.maxTexel / stats.minTexel;
    stats.usedFraction = double(stats.usedTexels) / double(stats.totalTexels);
    return stats;
}

std::string describe(const SolidAngleStats& stats) {
    char line[160];
    std::snprintf(line, sizeof line,
                  "%s n=%d: texel solid angle ratio %.3f (max/min), %.1f%% of %lld texels used",
                  std::string(mapTypeName(stats.type)).c_str(), stats.resolution, stats.ratio,
                  100.0 * stats.usedFraction, static_cast<long long>(stats.totalTexels));
    return line;
}

} // namespace speculum::render::envmap
