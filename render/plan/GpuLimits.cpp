#include "render/plan/GpuLimits.hpp"

#include <algorithm>

namespace speculum::render {

namespace {

std::string lightName(const Light& light, std::size_t index) {
    return light.name.empty() ? "light " + std::to_string(index) : "light \"" + light.name + "\"";
}

// The largest shadow map side: cube maps for point lights, 2D maps otherwise, drawn with a viewport of
// the map's size.
int maxShadowMapSize(const Light& light, const GpuLimits& limits) {
    const int texture = light.type == LightType::Point ? limits.maxCubeMapSize : limits.maxTextureSize;
    return std::min(texture, limits.maxViewportSize);
}

// The largest resolution n of the reflector's map (see envmap::MapLayout): the map itself (n × n cube
// faces or paraboloids, n × 3n tennis-ball components) with its depth renderbuffer, and for the resampled
// fill the n × n cube it is resampled from.
int maxEnvmapResolution(const Reflector& reflector, const GpuLimits& limits) {
    const int target = std::min(limits.maxRenderbufferSize, limits.maxViewportSize);
    switch (reflector.map) {
    case ReflectorMap::Cube:
        return std::min(limits.maxCubeMapSize, target);
    case ReflectorMap::DualParaboloid:
    case ReflectorMap::TennisBall: {
        const int height = reflector.map == ReflectorMap::TennisBall ? 3 : 1;
        int n = std::min(limits.maxTextureSize, target) / height;
        if (reflector.fill == ReflectorFill::Resampled)
            n = std::min({n, limits.maxCubeMapSize, target});
        return n;
    }
    }
    return target;
}

} // namespace

std::optional<FrameInput> fitToGpuLimits(const FrameInput& input, const GpuLimits& limits,
                                         std::vector<std::string>& warnings) {
    std::optional<FrameInput> fitted;
    auto copy = [&]() -> FrameInput& {
        if (!fitted)
            fitted = input;
        return *fitted;
    };
    for (std::size_t i = 0; i < input.lights.size(); ++i) {
        const Light& light = input.lights[i];
        if (!light.shadows.has_value())
            continue;
        const int most = std::max(kMinShadowMapSize, maxShadowMapSize(light, limits));
        const int size = light.shadows->mapSize;
        if (size > most) {
            warnings.push_back(lightName(light, i) + ": a " + std::to_string(size) +
                               "² shadow map is more than this GPU can hold (at most " +
                               std::to_string(most) + "²); using " + std::to_string(most) + "²");
            copy().lights[i].shadows->mapSize = most;
        } else if (size < kMinShadowMapSize) {
            warnings.push_back(lightName(light, i) + ": shadow map size " + std::to_string(size) +
                               " is too small; using " + std::to_string(kMinShadowMapSize) + "²");
            copy().lights[i].shadows->mapSize = kMinShadowMapSize;
        }
    }
    if (input.reflector) {
        const Reflector& reflector = *input.reflector;
        const int most = std::max(kMinEnvmapResolution, maxEnvmapResolution(reflector, limits));
        const int n = reflector.resolution;
        const std::string name = "reflector \"" + reflector.name + "\"";
        if (n > most) {
            warnings.push_back(name + ": resolution " + std::to_string(n) +
                               " is more than this GPU can hold for a " +
                               std::string(names::fileName(names::kReflectorMaps, reflector.map)) +
                               " map (at most " + std::to_string(most) + "); using " + std::to_string(most));
            copy().reflector->resolution = most;
        } else if (n < kMinEnvmapResolution) {
            warnings.push_back(name + ": resolution " + std::to_string(n) + " is too small; using " +
                               std::to_string(kMinEnvmapResolution));
            copy().reflector->resolution = kMinEnvmapResolution;
        }
    }
    return fitted;
}

} // namespace speculum::render
