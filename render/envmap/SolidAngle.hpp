#pragma once

#include "render/envmap/Layout.hpp"

#include <cstdint>
#include <string>

namespace speculum::render::envmap {

// How evenly a map spends its texels over the sphere. A texel is *used* when some direction of the
// component's nominal square that the component rule sends to that component falls inside it (guard-band
// texels and the corners outside a paraboloid's disc are not); its solid angle is that of its whole
// footprint, integrated numerically.
struct SolidAngleStats {
    MapType type = MapType::Cube;
    int resolution = 0;
    double minTexel = 0.0; // steradians, over used texels
    double maxTexel = 0.0;
    double ratio = 0.0; // maxTexel / minTexel: 1 would be a perfectly even map
    std::int64_t usedTexels = 0;
    std::int64_t totalTexels = 0; // every texel allocated, guard bands included
    double usedFraction = 0.0;
    double usedSolidAngle = 0.0; // Σ over used texels; ≥ 4π (boundary texels straddle components)
};

// Solid angle of texel (x, y) of a component, by 3×3-point Gauss–Legendre quadrature of
// solidAngleDensity over the texel's nominal-uv footprint.
double texelSolidAngle(const MapLayout& layout, int x, int y);

// Whether some direction inside texel (x, y) of `component` is looked up in that component; decided
// on a 5×5 grid of points of the texel including its corners.
bool texelUsed(const MapLayout& layout, int component, int x, int y);

// The statistics of a map in the project's layout at resolution n (about a second at n = 512).
SolidAngleStats solidAngleStats(MapType type, int resolution);

// One line for the benchmark: "tennis-ball n=256: solid angle ratio 1.43, 94.1% of texels used".
std::string describe(const SolidAngleStats& stats);

} // namespace speculum::render::envmap
