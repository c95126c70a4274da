#pragma once

#include "render/envmap/Mapping.hpp"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace speculum::render::envmap {

// Where the nominal [0,1]² square of each component lies in its texture.
//
// "Resolution n" is the texture size, so maps compare at equal memory: cube faces n×n, paraboloid
// components n×n, tennis-ball components n wide × 3n tall. The two non-linear maps keep a guard band of
// `guard` texels on every side *inside* that size: the nominal square covers the inner
// (n − 2g)×(m − 2g) texels and the band holds the smooth continuation of the same mapping (the other
// hemisphere past a paraboloid's rim, latitudes past ±45° and longitudes past ±135° on a tennis ball).
// Bilinear and mipmapped lookups near a component's edge then read real environment, never the clamp
// of an edge texel, which is what makes the seams invisible. The cube needs no band: GL's seamless
// cube filtering (GL_TEXTURE_CUBE_MAP_SEAMLESS) reads across faces.
struct MapLayout {
    MapType type = MapType::Cube;
    int resolution = 0; // n
    int width = 0;      // texels per component
    int height = 0;
    int components = 0;    // 6 faces, or 2 layers of a 2D array texture
    int guard = 0;         // texels on each side
    glm::dvec2 scale{1.0}; // texture coordinate = offset + scale · nominal uv
    glm::dvec2 offset{0.0};

    glm::dvec2 toTexture(const glm::dvec2& nominalUv) const { return offset + scale * nominalUv; }
    glm::dvec2 toNominal(const glm::dvec2& textureUv) const { return (textureUv - offset) / scale; }
    // (scale.x, scale.y, offset.x, offset.y): the uEnvLayout uniform of envmap_lookup.glsl.
    glm::vec4 packed() const { return glm::vec4(scale.x, scale.y, offset.x, offset.y); }
    // Nominal uv of the centre of texel (x, y).
    glm::dvec2 texelCentre(int x, int y) const {
        return toNominal(glm::dvec2((x + 0.5) / width, (y + 0.5) / height));
    }
};

// The guard band this project uses: wide enough for bilinear filtering at mip level log2(g). The
// octahedral map's is a power of two, so the square's sides stay on texel boundaries to level log2(g).
int defaultGuard(MapType type, int resolution);

// guard < 0 picks defaultGuard(type, n); the cube ignores it. n ≥ 8 and 4·guard < n, else an assertion.
MapLayout makeLayout(MapType type, int resolution, int guard = -1);

// Levels of a full mip chain of a width × height component (down to 1×1).
int mipLevelCount(int width, int height);

// Levels of a map's own mip chain that lookups may read: the full chain, except for the octahedral map,
// whose box-filtered levels are right only while its square's sides lie on texel boundaries: to level
// log2(guard), 32×32 texels for n ≥ 128. Blurrier lookups of it take the GGX pre-filtered chain, whose
// texels are each convolved from their own direction.
int usableMipLevels(const MapLayout& layout);

// The GGX pre-filtered chain of a rough reflector: a texture of the map's own layout and size whose mip
// level k holds the map convolved with the GGX lobe of roughness r_k = k / (levels − 1), level 0 the sharp
// map. Mip levels keep the layout's texture coordinates (the guard band scales with the level), so one
// explicit-LOD lookup at roughness × (levels − 1) reads between the two nearest levels. Six levels (r in
// steps of 0.2), fewer for maps too small for them.
inline constexpr int kMaxPrefilterLevels = 6;
int prefilterLevels(const MapLayout& layout);

} // namespace speculum::render::envmap
