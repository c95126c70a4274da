#pragma once

#include "render/frame/FrameInput.hpp"
#include "render/gl/Allocation.hpp"
#include "render/gl/GpuMesh.hpp"
#include "render/gl/Objects.hpp"
#include "render/gl/Program.hpp"
#include "render/gl/TextureCache.hpp"
#include "render/math/Projection.hpp"
#include "render/plan/FramePlan.hpp"

#include <array>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

namespace speculum::render::passes {

// One light's depth map: a 2D texture (spot, directional) or a cube map (point), with hardware depth
// comparison enabled so the main pass filters it with sampler2DShadow / samplerCubeShadow.
// Where it looks from, and its lookup filter width, are the frame's ShadowPlan.
struct ShadowMap {
    bool cube = false;
    int size = 0;
    int filterPcf = 1; // the PCF width the texture's filtering was last set for
    // Per face (2D maps: [0]), the texels that may hold a caster's depth: everything outside holds the
    // cleared depth. A redraw clears only these and the new casters' texels (on llvmpipe a clear writes
    // every texel it covers). Unknown (the whole face) until the map is first drawn.
    std::array<math::PixelRect, 6> drawnTexels{};
    bool drawnTexelsKnown = false;
    // World bounds of everything the map holds (its casters and the reflector, as last drawn): a lookup
    // whose kernel reaches none of it reads only the cleared depth (shaders/lighting.glsl).
    math::Box casterBounds;
    gl::Texture depth;
    gl::Framebuffer framebuffer;
};

class ShadowMaps {
public:
    // Allocates (or keeps) the depth map `shadow` plans (a cube map where its frustum is one) at
    // shadow.mapSize. The planner plans below every size that failed before (failedSizes), so a failure
    // here is of a size never tried: the largest that works is then found by halving and remembered, with
    // a warning naming the light and both sizes, for the next frame to plan; this frame the light has no
    // map (FellBack). The map's filtering is set for shadow.pcf, which may change without the map being
    // drawn again (PCF is a lookup setting).
    gl::PlannedAllocation allocate(const FrameInput& input, const ShadowPlan& shadow,
                                   std::vector<std::string>& warnings);
    // The smallest 2D and cube map sizes that failed to allocate, for the planner.
    void failedSizes(std::map<MapKind, FailedAllocation>& failed) const;
    // Renders the depth map `shadow` plans, through its frustum, from every shadow caster. Casters with an
    // alpha mask (Material::alphaMode) draw with the program's SHADOW_MASK variant, which discards where
    // the material is cut away, so their shadows have the same holes; that needs `textures` (null: they
    // cast whole shadows).
    void render(const FrameInput& input, const ShadowPlan& shadow, gl::MeshCache& meshes,
                const gl::Program& program, gl::TextureCache* textures = nullptr);
    // The map of a light rendered this frame or earlier, or nullptr.
    const ShadowMap* find(int lightIndex) const;
    // The world box the lit shaders test a lookup against (ShadowMap::casterBounds), or, where lookups are
    // not bounded (RenderOptions::boundShadowLookups false), one that holds everything.
    math::Box lookupBounds(const ShadowMap& map) const;
    void boundLookups(bool bounded) { m_boundLookups = bounded; }
    // GPU memory of the light's depth map (six faces for a cube), 0 if it has none.
    std::size_t bytes(int lightIndex) const;
    void clear() { m_maps.clear(); }

private:
    // Allocates a new map of that size, checked; nothing is left behind when it fails.
    base::Status allocateMap(int lightIndex, bool cube, int size, int pcf);
    ShadowMap& prepare(const ShadowPlan& shadow);
    std::unordered_map<int, ShadowMap> m_maps;
    gl::SizeFallback m_fallback2D;   // spot and directional lights' maps
    gl::SizeFallback m_fallbackCube; // point lights' cube maps (six faces)
    bool m_boundLookups = true;
};

} // namespace speculum::render::passes
