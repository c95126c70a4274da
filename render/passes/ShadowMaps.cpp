#include "render/passes/ShadowMaps.hpp"

#include "render/GpuLimits.hpp"
#include "render/gl/Memory.hpp"
#include "render/passes/MainPass.hpp"

#include <algorithm>
#include <glm/gtc/matrix_inverse.hpp>

namespace speculum::render::passes {

namespace {

void setDepthSampling(GLenum target, int pcf) {
    // PCF kernels > 1 also get the hardware's bilinear 2×2 comparison per tap; a kernel of 1 is a
    // single unfiltered comparison, i.e. a hard shadow.
    const GLint filter = pcf > 1 ? GL_LINEAR : GL_NEAREST;
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, filter);
}

} // namespace

ShadowMap& ShadowMaps::prepare(int lightIndex, bool cube, int size) {
    ShadowMap& map = m_maps[lightIndex];
    if (map.depth && map.cube == cube && map.size == size)
        return map;
    map = ShadowMap{};
    map.cube = cube;
    map.size = size;
    map.depth = gl::makeTexture();
    map.framebuffer = gl::makeFramebuffer();
    const GLenum target = cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
    glBindTexture(target, map.depth.id());
    if (cube) {
        for (int face = 0; face < 6; ++face)
            glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_DEPTH_COMPONENT24, size, size, 0,
                         GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
        glTexParameteri(target, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    } else {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, size, size, 0, GL_DEPTH_COMPONENT,
                     GL_UNSIGNED_INT, nullptr);
    }
    glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(target, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, 0);
    setDepthSampling(target, map.pcf);
    glBindTexture(target, 0);
    return map;
}

std::size_t ShadowMaps::bytes(int lightIndex) const {
    const ShadowMap* map = find(lightIndex);
    if (!map || !map->depth)
        return 0;
    return (map->cube ? 6u : 1u) * static_cast<std::size_t>(map->size) * static_cast<std::size_t>(map->size) *
           gl::bytesPerTexel(GL_DEPTH_COMPONENT24);
}

void ShadowMaps::setPcf(int lightIndex, int pcf) {
    auto it = m_maps.find(lightIndex);
    if (it == m_maps.end() || it->second.pcf == pcf)
        return;
    it->second.pcf = pcf;
    const GLenum target = it->second.cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
    glBindTexture(target, it->second.depth.id());
    setDepthSampling(target, pcf);
    glBindTexture(target, 0);
}

const ShadowMap* ShadowMaps::find(int lightIndex) const {
    auto it = m_maps.find(lightIndex);
    return it == m_maps.end() ? nullptr : &it->second;
}

void ShadowMaps::render(const FrameInput& input, int lightIndex, gl::MeshCache& meshes,
                        const gl::Program& program, gl::TextureCache* textures) {
    const Light& light = input.lights.at(static_cast<std::size_t>(lightIndex));
    // The renderer already fitted the size to the GPU's limits (fitToGpuLimits).
    const int size = std::max(light.shadows.mapSize, kMinShadowMapSize);
    auto frustum = math::shadowFrustum(input, light, size);
    if (!frustum)
        return;
    ShadowMap& map = prepare(lightIndex, frustum->cube, size);
    setPcf(lightIndex, light.shadows.pcf);
    map.frustum = *frustum;

    gl::FramebufferBinding keepBinding;
    glBindFramebuffer(GL_FRAMEBUFFER, map.framebuffer.id());
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    glViewport(0, 0, size, size);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE); // open meshes (planes, the teapot's lid gap) must cast from both sides
    // Slope-scaled bias: surfaces at grazing angles to the light need more offset than facing ones.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(2.0f, 4.0f);
    program.use();

    const int faces = frustum->cube ? 6 : 1;
    for (int face = 0; face < faces; ++face) {
        if (frustum->cube)
            glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_CUBE_MAP_POSITIVE_X + face,
                                   map.depth.id(), 0);
        else
            glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, map.depth.id(), 0);
        glClear(GL_DEPTH_BUFFER_BIT);
        // Faces that hold no caster stay cleared: everything seen through them is lit.
        if (frustum->cube && !(frustum->faceMask & (1u << face)))
            continue;
        const glm::dmat4& viewProjection = frustum->viewProjection[face];
        for (const DrawItem& item : input.items) {
            if (!item.castsShadows || !item.mesh)
                continue;
            const Material& m = item.material;
            const bool masked = textures && m.alphaMode != AlphaMode::Opaque;
            if (masked) {
                // The material's alpha, as mesh.frag computes it: opacity · texture alpha · vertex alpha.
                program.useWith("#define SHADOW_MASK 1\n");
                program.set("uOpacity", float(m.opacity));
                program.set("uAlphaCutoff", float(alphaCutoff(m)));
                program.set("uHasTexture", m.texture.empty() ? 0 : 1);
                program.set("uTexture", 0);
                if (!m.texture.empty())
                    textures->bind(m.texture, gl::TextureUse::Color, 0);
            }
            program.set("uModelLightClip", glm::mat4(viewProjection * item.world));
            meshes.get(item.mesh).draw();
            if (masked)
                program.useWith({}); // back to the plain depth variant
        }
        if (input.reflector && input.reflector->mesh) {
            program.set("uModelLightClip", glm::mat4(viewProjection * input.reflector->world));
            meshes.get(input.reflector->mesh).draw();
        }
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
}

} // namespace speculum::render::passes
