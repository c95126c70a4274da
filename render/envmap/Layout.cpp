#include "render/envmap/Layout.hpp"

#include "render/frame/SceneLimits.hpp"

#include <algorithm>
#include <cassert>

namespace speculum::render::envmap {

int defaultGuard(int resolution) {
    // 4 texels at n = 128, 16 at n = 512: the band survives the first log2(g) mip levels, about as far
    // as a reflector's lookups go before the map is too blurred for a seam to show.
    // Never so wide that the bands (4 of them across a map) leave nothing: at n = 8 one texel.
    return std::min(std::max(2, resolution / 32), (resolution - 1) / 4);
}

MapLayout makeLayout(MapType type, int resolution, int guard) {
    assert(resolution >= kMinEnvironmentMapSize && "envmap::makeLayout(): resolution below the scene limit");
    MapLayout layout;
    layout.type = type;
    layout.resolution = resolution;
    layout.components = componentCount(type);
    layout.width = resolution;
    layout.height = type == MapType::TennisBall ? 3 * resolution : resolution;
    layout.guard = type == MapType::Cube ? 0 : (guard < 0 ? defaultGuard(resolution) : guard);
    assert(4 * layout.guard < resolution && "envmap::makeLayout(): guard band too wide");
    const double g = layout.guard;
    layout.scale = {(layout.width - 2.0 * g) / layout.width, (layout.height - 2.0 * g) / layout.height};
    layout.offset = {g / layout.width, g / layout.height};
    return layout;
}

int mipLevelCount(int width, int height) {
    int levels = 1;
    for (int size = std::max(width, height); size > 1; size /= 2)
        ++levels;
    return levels;
}

int prefilterLevels(const MapLayout& layout) {
    return std::min(kMaxPrefilterLevels, mipLevelCount(layout.width, layout.height));
}

} // namespace speculum::render::envmap
