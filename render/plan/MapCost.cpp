#include "render/plan/MapCost.hpp"

#include "render/envmap/Layout.hpp"
#include "render/plan/Planner.hpp"

#include <cmath>
#include <cstdio>

namespace speculum::render {

namespace {

// Rates of Mesa llvmpipe on two cores, measured with `speculum time` at 160x90 on the chrome demo with
// its reflector's map redrawn every frame, so that the map is the frame: cube maps of 1024² and 2048² at
// roughness 0 drew 3.6e7 texels a second, and at roughness 0.5 with 256 samples (512², 1024²) the
// pre-filter took 6.6e7-6.9e7 lobe samples a second, both with a compile running beside them (the
// editor's first frame of a 256² chain with 1024 samples: 6.4e7). A GPU is some hundred times faster
// (kGpuOverSoftware).
constexpr double kSoftwareTexelsPerSecond = 4.0e7;
constexpr double kSoftwarePrefilterSamplesPerSecond = 7.0e7;

} // namespace

double MapCost::softwareSeconds() const {
    return texels / kSoftwareTexelsPerSecond + prefilterSamples / kSoftwarePrefilterSamplesPerSecond;
}

MapCost mapCost(const Reflector& reflector, int resolution, const Settings& settings, int samples) {
    MapCost cost;
    if (resolution <= 0) {
        return cost;
    }
    const envmap::MapLayout layout = envmap::makeLayout(mapTypeOf(reflector.map), resolution);
    const double mapTexels = double(layout.components) * layout.width * layout.height;
    // A resampled map (the octahedral map's only fill) draws a cube of its resolution first, then
    // resamples it into its own texels.
    const bool resampled = reflector.map != ReflectorMap::Cube &&
                           (!warpable(reflector.map) || reflector.fill == ReflectorFill::Resampled);
    cost.texels = resampled ? 6.0 * resolution * resolution + mapTexels : mapTexels;
    if (reflector.roughness > 0.0 && settings.glossyFilter != GlossyFilter::Mip) {
        cost.prefilterSamples = mapTexels / 3.0 * std::max(samples, 1);
    }
    return cost;
}

std::string costText(const MapCost& cost) {
    const double seconds = cost.softwareSeconds();
    char text[96];
    if (seconds < 90.0) {
        std::snprintf(text, sizeof text, "roughly %.0f s", seconds);
    } else if (seconds < 5400.0) {
        std::snprintf(text, sizeof text, "roughly %.0f min", seconds / 60.0);
    } else {
        std::snprintf(text, sizeof text, "roughly %.1f h", seconds / 3600.0);
    }
    char samples[64];
    std::snprintf(samples, sizeof samples, "%.1e", cost.texels + cost.prefilterSamples);
    return std::string("about ") + samples + " texels and samples, " + text + " on a software renderer";
}

} // namespace speculum::render
