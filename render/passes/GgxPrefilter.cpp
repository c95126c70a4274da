#include "render/passes/GgxPrefilter.hpp"

#include "render/gl/Allocation.hpp"
#include "render/gl/Memory.hpp"

#include <algorithm>
#include <cmath>
#include <glm/vec2.hpp>

namespace speculum::render::envmap {

namespace {

constexpr double kPi = 3.14159265358979324;

// The mean solid angle of one level-0 texel, which sets the LOD each sample reads (filtered importance
// sampling). The non-linear maps' texels vary over a component (the paraboloid's by 4× between centre and
// rim): the mean is off by at most a level there, a small change in a blur that wide.
double texelSolidAngle(const MapLayout& l) {
    const double w = l.width - 2.0 * l.guard; // nominal texels
    const double h = l.height - 2.0 * l.guard;
    switch (l.type) {
    case MapType::Cube:
        return 4.0 * kPi / (6.0 * w * h);
    case MapType::DualParaboloid: // a hemisphere on the inscribed disc, π/4 of the nominal square
        return 2.0 * kPi / (0.25 * kPi * w * h);
    case MapType::TennisBall: // a band of ±45° latitude and 270° longitude per component
        return 1.5 * kPi * 2.0 * std::sin(0.25 * kPi) / (w * h);
    case MapType::Octahedral: // the whole sphere on the nominal square
        return 4.0 * kPi / (w * h);
    }
    return 4.0 * kPi / (6.0 * w * h);
}

void allocateLevels(GLenum target, GLuint texture, const MapLayout& l, int levels, GLenum format) {
    glBindTexture(target, texture);
    for (int level = 0; level < levels; ++level) {
        const int w = std::max(1, l.width >> level);
        const int h = std::max(1, l.height >> level);
        if (target == GL_TEXTURE_CUBE_MAP)
            for (int face = 0; face < 6; ++face)
                glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, level, static_cast<GLint>(format), w, h,
                             0, GL_RGBA, GL_FLOAT, nullptr);
        else
            glTexImage3D(GL_TEXTURE_2D_ARRAY, level, static_cast<GLint>(format), w, h, l.components, 0,
                         GL_RGBA, GL_FLOAT, nullptr);
    }
    glTexParameteri(target, GL_TEXTURE_BASE_LEVEL, 0);
    glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, levels - 1);
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    // Clamp: seamless cube filtering, or the guard band, supplies what lies past an edge.
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
        glTexParameteri(target, wrap, GL_CLAMP_TO_EDGE);
    glBindTexture(target, 0);
}

} // namespace

base::Result<GgxPrefilter> GgxPrefilter::create() {
    auto program = gl::Program::build("fullscreen.vert", "envmap_prefilter.glsl");
    if (!program)
        return base::Error{program.error()};
    GgxPrefilter prefilter;
    prefilter.m_program = std::move(*program);
    prefilter.m_draw = gl::makeFramebuffer();
    prefilter.m_read = gl::makeFramebuffer();
    prefilter.m_emptyVao = gl::makeVertexArray();
    return prefilter;
}

std::size_t GgxPrefilter::bytes() const {
    if (!m_chain)
        return 0;
    return static_cast<std::size_t>(m_layout.components) *
           gl::mipChainTexels(m_layout.width, m_layout.height, m_levels) * gl::bytesPerTexel(GL_RGBA16F);
}

base::Status GgxPrefilter::allocate(const EnvironmentCapture& map) {
    const MapLayout& l = map.layout();
    if (m_chain && m_target == map.target() && m_layout.type == l.type && m_layout.width == l.width &&
        m_layout.height == l.height && m_layout.guard == l.guard)
        return base::Done{};
    m_chain.reset();
    m_levels = 0;
    m_layout = MapLayout{};
    const int levels = prefilterLevels(l);
    const GLenum format = map.settings().colorFormat;
    const std::size_t bytes = static_cast<std::size_t>(l.components) *
                              gl::mipChainTexels(l.width, l.height, levels) * gl::bytesPerTexel(format);
    if (base::Status fits = gl::beginAllocation(bytes); !fits)
        return base::Error{fits.error() + " (the GGX pre-filtered chain)"};
    gl::Texture chain = gl::makeTexture();
    allocateLevels(map.target(), chain.id(), l, levels, format);
    if (base::Status done = gl::finishAllocation(); !done)
        return base::Error{done.error() + " (the GGX pre-filtered chain)"};
    m_chain = std::move(chain);
    m_target = map.target();
    m_layout = l;
    m_levels = levels;
    return base::Done{};
}

base::Status GgxPrefilter::filter(const EnvironmentCapture& map, int samples) {
    if (base::Status allocated = allocate(map); !allocated)
        return allocated;
    samples = std::clamp(samples, 1, 4096);
    const MapLayout& l = m_layout;
    const bool cube = m_target == GL_TEXTURE_CUBE_MAP;
    const int components = l.components; // 6 faces, or the layers of a 2D array (one, octahedral)
    gl::FramebufferBinding keepBinding;
    const gl::PlainDrawState plain;

    // Level 0 is the sharp map itself, copied texel for texel: roughness between 0 and r_1 reads between
    // them.
    glBindFramebuffer(GL_READ_FRAMEBUFFER, m_read.id());
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(m_target, m_chain.id());
    for (int c = 0; c < components; ++c) {
        if (cube) {
            glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                   GL_TEXTURE_CUBE_MAP_POSITIVE_X + c, map.texture(), 0);
            glCopyTexSubImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + c, 0, 0, 0, 0, 0, l.width, l.height);
        } else {
            glFramebufferTextureLayer(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, map.texture(), 0, c);
            glCopyTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, c, 0, 0, l.width, l.height);
        }
    }
    glBindTexture(m_target, 0);

    // Levels 1.. from the source's own mip chain (never from the chain being written: no feedback).
    const gl::Program& p = m_program;
    p.use();
    glBindTexture(map.target(), map.texture());
    p.set("uSourceCube", 0);
    p.set("uSourceArray", 0);
    const bool sourceCube = map.target() == GL_TEXTURE_CUBE_MAP;
    if (!sourceCube) { // the unused sampler type still needs a unit of its own type: a different one
        p.set("uSourceCube", 1);
    } else {
        p.set("uSourceArray", 1);
    }
    p.set("uEnvType", static_cast<int>(l.type));
    p.set("uEnvLayout", l.packed());
    p.set("uSamples", samples);
    p.set("uSourceTexelSolidAngle", static_cast<float>(texelSolidAngle(l)));
    const int sourceLevels = map.settings().mipmaps ? usableMipLevels(l) : 1;
    p.set("uSourceMaxLod", static_cast<float>(sourceLevels - 1));
    glBindVertexArray(m_emptyVao.id());
    glBindFramebuffer(GL_FRAMEBUFFER, m_draw.id());
    for (int level = 1; level < m_levels; ++level) {
        const int w = std::max(1, l.width >> level);
        const int h = std::max(1, l.height >> level);
        glViewport(0, 0, w, h);
        p.set("uLevelSize", glm::vec2(w, h));
        p.set("uRoughness", static_cast<float>(level) / static_cast<float>(m_levels - 1));
        for (int c = 0; c < components; ++c) {
            if (cube)
                glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                       GL_TEXTURE_CUBE_MAP_POSITIVE_X + c, m_chain.id(), level);
            else
                glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, m_chain.id(), level, c);
            p.set("uEnvComponent", c);
            glDrawArrays(GL_TRIANGLES, 0, 3);
        }
    }
    glBindVertexArray(0);
    glBindTexture(map.target(), 0);
    return base::Done{};
}

} // namespace speculum::render::envmap
