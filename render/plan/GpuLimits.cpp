#include "render/plan/GpuLimits.hpp"

#include "base/Printable.hpp"

#include <algorithm>

namespace speculum::render {

namespace {

// The names the GPU-limit warnings have always used ("light \"Lamp\""); the fallback warnings quote as
// allocation errors do ("light 'Lamp'").
std::string lightName(const Light& light, int index) {
    return light.name.empty() ? "light " + std::to_string(index) : "light \"" + light.name + "\"";
}

std::string quotedLightName(const Light& light, int index) {
    return light.name.empty() ? "light " + std::to_string(index) : "light " + base::quoted(light.name);
}

std::string mapName(const Reflector& reflector) {
    return std::string(names::fileName(names::kReflectorMaps, reflector.map));
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
    case ReflectorMap::TennisBall:
    case ReflectorMap::Octahedral: {
        const int height = reflector.map == ReflectorMap::TennisBall ? 3 : 1;
        int n = std::min(limits.maxTextureSize, target) / height;
        if (reflector.fill == ReflectorFill::Resampled || !warpable(reflector.map))
            n = std::min({n, limits.maxCubeMapSize, target});
        return n;
    }
    }
    return target;
}

int shadowMapWithinGpu(const Light& light, int index, int size, const GpuLimits& limits,
                       std::vector<std::string>& warnings) {
    const int most = std::max(kMinShadowMapSize, maxShadowMapSize(light, limits));
    if (size > most) {
        warnings.push_back(lightName(light, index) + ": a " + std::to_string(size) +
                           "² shadow map is more than this GPU can hold (at most " + std::to_string(most) +
                           "²); using " + std::to_string(most) + "²");
        return most;
    }
    if (size < kMinShadowMapSize) {
        warnings.push_back(lightName(light, index) + ": shadow map size " + std::to_string(size) +
                           " is too small; using " + std::to_string(kMinShadowMapSize) + "²");
        return kMinShadowMapSize;
    }
    return size;
}

int envmapWithinGpu(const Reflector& reflector, const GpuLimits& limits, std::vector<std::string>& warnings) {
    const int most = std::max(kMinEnvmapResolution, maxEnvmapResolution(reflector, limits));
    const int n = reflector.resolution;
    const std::string name = "reflector \"" + reflector.name + "\"";
    if (n > most) {
        warnings.push_back(name + ": resolution " + std::to_string(n) +
                           " is more than this GPU can hold for a " + mapName(reflector) + " map (at most " +
                           std::to_string(most) + "); using " + std::to_string(most));
        return most;
    }
    if (n < kMinEnvmapResolution) {
        warnings.push_back(name + ": resolution " + std::to_string(n) + " is too small; using " +
                           std::to_string(kMinEnvmapResolution));
        return kMinEnvmapResolution;
    }
    return n;
}

} // namespace

MapKind shadowMapKind(const Light& light) {
    return light.type == LightType::Point ? MapKind::ShadowCube : MapKind::Shadow2D;
}

MapKind envmapKind(const Reflector& reflector) {
    const bool resampled = reflector.fill == ReflectorFill::Resampled;
    switch (reflector.map) {
    case ReflectorMap::Cube:
        return MapKind::EnvmapCube;
    case ReflectorMap::DualParaboloid:
        return resampled ? MapKind::EnvmapParaboloidResampled : MapKind::EnvmapParaboloid;
    case ReflectorMap::TennisBall:
        return resampled ? MapKind::EnvmapTennisBallResampled : MapKind::EnvmapTennisBall;
    case ReflectorMap::Octahedral:
        return MapKind::EnvmapOctahedral;
    }
    return MapKind::EnvmapCube;
}

const FailedAllocation& MapLimits::failure(MapKind kind) const {
    static const FailedAllocation none;
    const auto it = failed.find(kind);
    return it == failed.end() ? none : it->second;
}

int belowFailure(int size, int minimum, const FailedAllocation& failed) {
    size = std::max(size, minimum);
    while (size >= failed.size && size > minimum)
        size = std::max(minimum, size / 2);
    return size >= failed.size ? 0 : size;
}

int fitShadowMapSize(const Light& light, int lightIndex, int asked, const MapLimits& limits,
                     std::vector<std::string>& warnings) {
    const int fitted = shadowMapWithinGpu(light, lightIndex, asked, limits.gpu, warnings);
    const FailedAllocation& failed = limits.failure(shadowMapKind(light));
    const int size = belowFailure(fitted, kMinShadowMapSize, failed);
    if (size != fitted)
        warnings.push_back(shadowFallbackWarning(light, lightIndex, fitted, failed.reason, size));
    return size;
}

int fitEnvmapResolution(const Reflector& reflector, const MapLimits& limits,
                        std::vector<std::string>& warnings) {
    const int fitted = envmapWithinGpu(reflector, limits.gpu, warnings);
    const FailedAllocation& failed = limits.failure(envmapKind(reflector));
    const int n = belowFailure(fitted, kMinEnvmapResolution, failed);
    if (n != fitted)
        warnings.push_back(envmapFallbackWarning(reflector, fitted, failed.reason, n));
    return n;
}

std::string shadowFallbackWarning(const Light& light, int lightIndex, int asked, const std::string& reason,
                                  int used) {
    const std::string map = "the " + std::to_string(asked) + "²" +
                            (shadowMapKind(light) == MapKind::ShadowCube ? " cube" : "") + " shadow map " +
                            reason;
    if (used == 0)
        return quotedLightName(light, lightIndex) + ": " + map + ", nor did any down to " +
               std::to_string(kMinShadowMapSize) + "²; the light casts no shadows";
    return quotedLightName(light, lightIndex) + ": " + map + "; using " + std::to_string(used) + "²";
}

std::string envmapFallbackWarning(const Reflector& reflector, int asked, const std::string& reason,
                                  int used) {
    const std::string map = "reflector " + base::quoted(reflector.name) + ": the " + std::to_string(asked) +
                            " " + mapName(reflector) + " environment map " + reason;
    if (used == 0)
        return map + ", nor did any down to " + std::to_string(kMinEnvmapResolution) +
               "; the reflector is drawn without it";
    return map + "; using " + std::to_string(used);
}

} // namespace speculum::render
