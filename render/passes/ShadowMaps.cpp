#include "render/passes/ShadowMaps.hpp"

#include "render/gl/Memory.hpp"
#include "render/math/Projection.hpp"
#include "render/passes/MainPass.hpp"
#include "render/plan/GpuLimits.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_inverse.hpp>

namespace speculum::render::passes {

namespace {

GLenum textureTarget(const ShadowMap& map) {
    return map.cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
}

void setDepthSampling(GLenum target, int pcf) {
    // PCF kernels > 1 also get the hardware's bilinear 2×2 comparison per tap; a kernel of 1 is a
    // single unfiltered comparison, i.e. a hard shadow.
    const GLint filter = pcf > 1 ? GL_LINEAR : GL_NEAREST;
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, filter);
}

// Sets the map's filtering for a lookup filter width, unless it has it already.
void useFilter(ShadowMap& map, int pcf) {
    if (map.filterPcf == pcf || !map.depth)
        return;
    map.filterPcf = pcf;
    glBindTexture(textureTarget(map), map.depth.id());
    setDepthSampling(textureTarget(map), pcf);
    glBindTexture(textureTarget(map), 0);
}

} // namespace

base::Status ShadowMaps::allocateMap(int lightIndex, bool cube, int size, int pcf) {
    m_maps.erase(lightIndex); // the old map's memory first: it may be what the new one needs
    ShadowMap map;
    map.cube = cube;
    map.size = size;
    map.filterPcf = pcf;
    const std::size_t bytes = (cube ? 6u : 1u) * static_cast<std::size_t>(size) *
                              static_cast<std::size_t>(size) * gl::bytesPerTexel(GL_DEPTH_COMPONENT24);
    if (base::Status fits = gl::beginAllocation(bytes); !fits)
        return fits;
    map.depth = gl::makeTexture();
    map.framebuffer = gl::makeFramebuffer();
    const GLenum target = cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
    glBindTexture(target, map.depth.id());
    // One level, said before the upload: with the default mipmapped minification filter a driver may
    // reserve a whole mip chain with level 0, a third more memory than the map needs.
    glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, 0);
    setDepthSampling(target, map.filterPcf);
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
    setDepthSampling(target, map.filterPcf);
    glBindTexture(target, 0);
    if (base::Status allocated = gl::finishAllocation(); !allocated)
        return allocated;
    // Drivers may allocate only when the texture is first used: a target that cannot be drawn into is
    // as failed as an out-of-memory error.
    gl::FramebufferBinding keepBinding;
    glBindFramebuffer(GL_FRAMEBUFFER, map.framebuffer.id());
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    for (int face = 0; face < (cube ? 6 : 1); ++face) {
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                               cube ? GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face) : GLenum(GL_TEXTURE_2D),
                               map.depth.id(), 0);
        if (base::Status complete = gl::checkFramebuffer(); !complete)
            return complete;
    }
    m_maps.emplace(lightIndex, std::move(map));
    return base::Done{};
}

gl::PlannedAllocation ShadowMaps::allocate(const FrameInput& input, const ShadowPlan& shadow,
                                           std::vector<std::string>& warnings) {
    const int lightIndex = shadow.light;
    const Light& light = input.lights.at(static_cast<std::size_t>(lightIndex));
    const int planned = shadow.mapSize;
    const bool cube = shadow.frustum.cube;
    gl::SizeFallback& fallback = cube ? m_fallbackCube : m_fallback2D;
    const gl::SizeFallback::Fitted fitted =
        fallback.fit(planned, kMinShadowMapSize, [&](int size) -> base::Status {
            if (const ShadowMap* map = find(lightIndex);
                map && map->depth && map->cube == cube && map->size == size)
                return base::Done{};
            return allocateMap(lightIndex, cube, size, shadow.pcf);
        });
    if (fitted.size != planned) {
        // A map of another size would not match the plan's frustum: the light goes without this frame.
        m_maps.erase(lightIndex);
        warnings.push_back(shadowFallbackWarning(light, lightIndex, planned, fitted.reason, fitted.size));
        return gl::PlannedAllocation::FellBack;
    }
    if (auto it = m_maps.find(lightIndex); it != m_maps.end())
        useFilter(it->second, shadow.pcf);
    return gl::PlannedAllocation::Done;
}

void ShadowMaps::failedSizes(std::map<MapKind, FailedAllocation>& failed) const {
    if (m_fallback2D.failedAt() != kNoFailedSize)
        failed[MapKind::Shadow2D] = m_fallback2D.failed();
    if (m_fallbackCube.failedAt() != kNoFailedSize)
        failed[MapKind::ShadowCube] = m_fallbackCube.failed();
}

namespace {

// World bounds of what the shadow pass draws: the casters and the reflectors.
std::vector<math::Box> casterBoxes(const FrameInput& input) {
    std::vector<math::Box> boxes;
    for (const DrawItem& item : input.items)
        if (item.castsShadows && item.mesh)
            boxes.push_back(math::worldBounds(computeBounds(*item.mesh), item.world));
    for (const Reflector& reflector : input.reflectors)
        if (reflector.mesh)
            boxes.push_back(math::worldBounds(computeBounds(*reflector.mesh), reflector.world));
    return boxes;
}

// The texels of a size² map face that the casters can cover: the bounds of their boxes' projected corners,
// a texel wider on each side; the whole face where a corner lies behind the light's plane (or is not
// finite), empty where every box lies off the face.
math::PixelRect casterTexels(const std::vector<math::Box>& boxes, const glm::dmat4& viewProjection,
                             int size) {
    const math::PixelRect whole{0, 0, size, size};
    glm::dvec2 low(1e300), high(-1e300);
    for (const math::Box& box : boxes) {
        if (box.empty())
            continue;
        for (const glm::dvec3& corner : box.corners()) {
            const glm::dvec4 clip = viewProjection * glm::dvec4(corner, 1.0);
            if (!(clip.w > 1e-9) || !std::isfinite(clip.x) || !std::isfinite(clip.y))
                return whole;
            const glm::dvec2 texel = (glm::dvec2(clip) / clip.w * 0.5 + 0.5) * double(size);
            low = glm::min(low, texel);
            high = glm::max(high, texel);
        }
    }
    if (low.x > high.x)
        return {};
    const math::PixelRect rect{static_cast<int>(std::clamp(std::floor(low.x) - 1.0, 0.0, double(size))),
                               static_cast<int>(std::clamp(std::floor(low.y) - 1.0, 0.0, double(size))),
                               static_cast<int>(std::clamp(std::ceil(high.x) + 1.0, 0.0, double(size))),
                               static_cast<int>(std::clamp(std::ceil(high.y) + 1.0, 0.0, double(size)))};
    return rect.empty() ? math::PixelRect{} : rect;
}

math::PixelRect unite(const math::PixelRect& a, const math::PixelRect& b) {
    if (a.empty())
        return b;
    if (b.empty())
        return a;
    return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

} // namespace

ShadowMap& ShadowMaps::prepare(const ShadowPlan& shadow) {
    const bool cube = shadow.frustum.cube;
    if (auto it = m_maps.find(shadow.light); it != m_maps.end() && it->second.depth &&
                                             it->second.cube == cube && it->second.size == shadow.mapSize) {
        useFilter(it->second, shadow.pcf);
        return it->second;
    }
    // allocate() normally made it already; a caller that did not still gets a checked allocation (an empty
    // map when it fails), only without the fallback.
    (void)allocateMap(shadow.light, cube, shadow.mapSize, shadow.pcf);
    return m_maps[shadow.light];
}

std::size_t ShadowMaps::bytes(int lightIndex) const {
    const ShadowMap* map = find(lightIndex);
    if (!map || !map->depth)
        return 0;
    return (map->cube ? 6u : 1u) * static_cast<std::size_t>(map->size) * static_cast<std::size_t>(map->size) *
           gl::bytesPerTexel(GL_DEPTH_COMPONENT24);
}

math::Box ShadowMaps::lookupBounds(const ShadowMap& map) const {
    if (m_boundLookups)
        return map.casterBounds;
    math::Box everything;
    everything.min = glm::dvec3(-1e30);
    everything.max = glm::dvec3(1e30);
    return everything;
}

const ShadowMap* ShadowMaps::find(int lightIndex) const {
    auto it = m_maps.find(lightIndex);
    return it == m_maps.end() ? nullptr : &it->second;
}

void ShadowMaps::render(const FrameInput& input, const ShadowPlan& shadow, gl::MeshCache& meshes,
                        const gl::Program& program, gl::TextureCache* textures) {
    // The planner fitted the size to the GPU's limits and to the sizes that failed (fitShadowMapSize).
    const int size = shadow.mapSize;
    const math::ShadowFrustum& frustum = shadow.frustum;
    ShadowMap& map = prepare(shadow);
    if (!map.depth) { // it did not fit: the main pass samples no map for the light
        m_maps.erase(shadow.light);
        return;
    }

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

    const int faces = frustum.cube ? 6 : 1;
    const std::vector<math::Box> casters = casterBoxes(input);
    map.casterBounds = {};
    for (const math::Box& box : casters)
        if (!box.empty())
            map.casterBounds.add(box);
    const math::PixelRect whole{0, 0, size, size};
    if (!map.drawnTexelsKnown)
        map.drawnTexels.fill(whole);
    map.drawnTexelsKnown = true;
    glEnable(GL_SCISSOR_TEST);
    for (int face = 0; face < faces; ++face) {
        // Faces that hold no caster stay cleared: everything seen through them is lit.
        const bool holdsCasters = !frustum.cube || (frustum.faceMask & (1u << face)) != 0;
        const glm::dmat4& viewProjection = frustum.viewProjection[face];
        const math::PixelRect drawn =
            holdsCasters ? casterTexels(casters, viewProjection, size) : math::PixelRect{};
        const math::PixelRect cleared = unite(map.drawnTexels[static_cast<std::size_t>(face)], drawn);
        map.drawnTexels[static_cast<std::size_t>(face)] = drawn;
        if (cleared.empty())
            continue; // holds only the cleared depth already, and nothing is drawn into it
        if (frustum.cube)
            glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_CUBE_MAP_POSITIVE_X + face,
                                   map.depth.id(), 0);
        else
            glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, map.depth.id(), 0);
        glScissor(cleared.x0, cleared.y0, cleared.width(), cleared.height());
        glClear(GL_DEPTH_BUFFER_BIT);
        if (drawn.empty())
            continue;
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
                    textures->bind(m.texture, m.wrap, TextureUse::Color, 0);
            }
            program.set("uModelLightClip", glm::mat4(viewProjection * item.world));
            meshes.get(item.mesh).draw();
            if (masked)
                program.useWith({}); // back to the plain depth variant
        }
        for (const Reflector& reflector : input.reflectors) {
            if (!reflector.mesh)
                continue;
            program.set("uModelLightClip", glm::mat4(viewProjection * reflector.world));
            meshes.get(reflector.mesh).draw();
        }
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_SCISSOR_TEST);
}

} // namespace speculum::render::passes
