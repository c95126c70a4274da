#include "render/envmap/Layout.hpp"

#include "render/frame/SceneLimits.hpp"

#include <algorithm>
#include <cassert>

namespace speculum::render::envmap {

namespace {

int largestPowerOfTwoAtMost(int value) {
    int power = 1;
    while (2 * power <= value)
        power *= 2;
    return power;
}

} // namespace

int defaultGuard(MapType type, int resolution) {
    // 4 texels at n = 128, 16 at n = 512: the band survives the first log2(g) mip levels, about as far
    // as a reflector's lookups go before the map is too blurred for a seam to show.
    // Never so wide that the bands (4 of them across a map) leave nothing: at n = 8 one texel.
    const int widest = (resolution - 1) / 4;
    if (type != MapType::Octahedral)
        return std::min(std::max(2, resolution / 32), widest);
    // The octahedral band is the square folded over its own side, not a smooth continuation, so a
    // coarse texel straddling a side would average one side's texels with the other's. A band of 2^k
    // texels keeps the sides on texel boundaries down to level k, where the box-filtered levels then
    // hold the fold exactly (usableMipLevels stops the chain there); at least 4 texels where there is room.
    return largestPowerOfTwoAtMost(std::max(1, std::min(std::max(4, resolution / 32), widest)));
}

MapLayout makeLayout(MapType type, int resolution, int guard) {
    assert(resolution >= kMinEnvironmentMapSize && "envmap::makeLayout(): resolution below the scene limit");
    MapLayout layout;
    layout.type = type;
    layout.resolution = resolution;
    layout.components = componentCount(type);
    layout.width = resolution;
    layout.height = type == MapType::TennisBall ? 3 * resolution : resolution;
    layout.guard = type == MapType::Cube ? 0 : (guard < 0 ? defaultGuard(type, resolution) : guard);
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

int usableMipLevels(const MapLayout& layout) {
    const int full = mipLevelCount(layout.width, layout.height);
    if (layout.type != MapType::Octahedral)
        return full;
    // Level k keeps the sides on texel boundaries while 2^k divides the band and the size (GL rounds odd
    // sizes down, which would move them).
    int levels = 1;
    for (int step = 2; layout.guard % step == 0 && layout.width % step == 0 && layout.height % step == 0;
         step *= 2)
        ++levels;
    return std::min(levels, full);
}

int prefilterLevels(const MapLayout& layout) {
    return std::min(kMaxPrefilterLevels, mipLevelCount(layout.width, layout.height));
}

} // namespace speculum::render::envmap
