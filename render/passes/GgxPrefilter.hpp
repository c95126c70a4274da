#pragma once

#include "base/Result.hpp"
#include "render/gl/Objects.hpp"
#include "render/gl/Program.hpp"
#include "render/passes/EnvironmentCapture.hpp"

#include <cstddef>

namespace speculum::render::envmap {

// A rough reflector's GGX pre-filtered chain (prefilterLevels in Layout.hpp): a texture of the map's own
// target, layout and size whose mip level k holds the map convolved with the GGX lobe of roughness
// r_k = k / (levels − 1); level 0 is a copy of the sharp map. Pass 2 reads it like the map, at the
// explicit LOD roughness × (levels − 1), so the sampler interpolates between the two nearest levels.
// Filtered by shaders/envmap_prefilter.glsl, only when the map was rendered again or the sample count
// changed: the planner's Prefilter pass.
class GgxPrefilter {
public:
    GgxPrefilter() = default;
    // Builds the program. Needs a current context.
    static base::Result<GgxPrefilter> create();

    // Convolves `map` (rendered, with its mip chain) into the chain, `samples` GGX samples a texel
    // (clamped to 1..4096), re-creating the chain's texture when the map's size or layout changed. The
    // allocation is checked: an error leaves no chain. Puts back the framebuffer binding and viewport;
    // leaves program, VAO and texture bindings (unit 0) changed.
    base::Status filter(const EnvironmentCapture& map, int samples);

    // For pass 2: bind texture() to target() and look it up as the map (same layout), LOD ≤ levels() − 1.
    GLuint texture() const { return m_chain.id(); }
    GLenum target() const { return m_target; }
    int levels() const { return m_levels; }
    std::size_t bytes() const;

private:
    base::Status allocate(const EnvironmentCapture& map);

    gl::Program m_program;
    gl::Texture m_chain;
    gl::Framebuffer m_draw;
    gl::Framebuffer m_read;
    gl::VertexArray m_emptyVao;
    GLenum m_target = GL_TEXTURE_CUBE_MAP;
    MapLayout m_layout; // of the chain's texture (width 0: none)
    int m_levels = 0;
};

} // namespace speculum::render::envmap
