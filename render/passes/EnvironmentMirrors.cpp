#include "render/passes/EnvironmentMirrors.hpp"

#include "render/envmap/CaptureMath.hpp"
#include "render/math/Mirror.hpp"
#include "render/math/Projection.hpp"
#include "render/plan/Planner.hpp"

#include <glm/gtc/matrix_inverse.hpp>
#include <optional>

namespace speculum::render::passes {

namespace {

struct MirrorInFace {
    int index = -1;
    ViewSetup reflected;
};

// The reflected view of mirror `m` from the capture point in one face, or nothing when the capture point is
// not in front of it, it is outside the face, or no oblique projection exists.
std::optional<MirrorInFace> reflectedView(const FrameInput& env, int m, const glm::dmat4& projection,
                                          const glm::dmat4& reflectedProjection, const glm::dmat4& view,
                                          int size) {
    const Mirror& mirror = env.mirrors[static_cast<std::size_t>(m)];
    const auto plane = math::mirrorPlane(mirror.world);
    if (!plane || plane->distance(env.camera.position) <= 1e-9)
        return std::nullopt;
    std::vector<glm::dvec3> corners;
    for (const glm::dvec3& c : math::mirrorCorners(mirror))
        corners.push_back(c - env.camera.position);
    const math::PixelRect whole{0, 0, size, size};
    const math::ScreenCoverage coverage =
        math::screenCoverage(corners, projection * view, size, size, whole, nullptr);
    if (coverage.rect.empty() || coverage.pixelArea < 1.0)
        return std::nullopt;
    const auto reflection = math::reflectionMatrix(*plane);
    if (!reflection)
        return std::nullopt;
    const glm::dmat4 toRelative = math::cameraRelative(env.camera);
    const glm::dvec4 kept(plane->normal, plane->d - kMirrorClipOffset);
    const glm::dvec4 inView =
        math::transformPlane(math::transformPlane(kept, *reflection), view * toRelative);
    const auto oblique = math::obliqueProjection(reflectedProjection, inView);
    if (!oblique)
        return std::nullopt;
    MirrorInFace result;
    result.index = m;
    result.reflected.viewProjection = *oblique * view;
    result.reflected.reflection = *reflection;
    result.reflected.eye = glm::dvec3(glm::inverse(*reflection) * glm::dvec4(env.camera.position, 1.0));
    return result;
}

} // namespace

void drawEnvironmentFace(const FrameInput& env, double near, double far, const glm::dmat4& view, int size,
                         int mirrorDepth, const EnvironmentMirrorPrograms& programs, MainPassContext& ctx) {
    const glm::dmat4 projection = envmap::cubeFaceProjection(near, far);
    // A reflected point is at most far + 2·(the mirror's distance) ≤ 3·far from the capture point.
    const glm::dmat4 reflectedProjection = envmap::cubeFaceProjection(near, 3.0 * far);
    ViewSetup direct;
    direct.viewProjection = projection * view;
    direct.eye = env.camera.position;
    direct.skipMirror.assign(env.mirrors.size(), false);
    std::vector<MirrorInFace> seen;
    if (mirrorDepth >= 1 && programs.flat && programs.mirror)
        for (int m = 0; m < static_cast<int>(env.mirrors.size()); ++m)
            if (auto r = reflectedView(env, m, projection, reflectedProjection, view, size))
                seen.push_back(std::move(*r));
    if (seen.empty()) {
        drawMainPass(env, direct, ctx);
        return;
    }
    const glm::dmat4 toRelative = math::cameraRelative(env.camera);
    for (const MirrorInFace& mirror : seen) {
        const Mirror& m = env.mirrors[static_cast<std::size_t>(mirror.index)];
        // Depth 0 everywhere but on the mirror, where it is 1: the reflection can only land there.
        glClearDepth(0.0);
        glClear(GL_DEPTH_BUFFER_BIT);
        glClearDepth(1.0);
        programs.flat->use();
        programs.flat->set("uModelLightClip",
                           glm::mat4(direct.viewProjection * toRelative * mirrorRectangle(m)));
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glDepthFunc(GL_ALWAYS);
        glDepthRange(1.0, 1.0);
        ctx.meshes.get(ctx.unitPlane).draw();
        glDepthRange(0.0, 1.0);
        glDepthFunc(GL_LESS);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        ViewSetup reflected = mirror.reflected;
        reflected.skipMirror.assign(env.mirrors.size(), false); // deeper mirrors: their own material
        drawMainPass(env, reflected, ctx);
        glFrontFace(GL_CCW);
    }
    glClear(GL_DEPTH_BUFFER_BIT);
    // The mirror surfaces first, over their reflections: what lies behind a mirror then fails the depth test.
    const gl::Program& p = *programs.mirror;
    for (const MirrorInFace& mirror : seen) {
        const Mirror& m = env.mirrors[static_cast<std::size_t>(mirror.index)];
        beginLitView(env, direct, p, ctx);
        setMaterial(m.hasMaterial ? m.material : Material{}, p, ctx);
        p.set("uReflectivity", float(m.reflectivity));
        p.set("uTint", glm::vec3(m.tint));
        p.set("uFresnel", m.fresnel ? 1 : 0);
        p.set("uFromTexture", 0);
        p.set("uReflectionTexture", kReflectionTextureUnit);
        p.set("uTargetSize", glm::vec2(float(size)));
        p.set("uBlurLod", 0.0f);
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_SRC1_COLOR);
        drawLitMesh(ctx.unitPlane, mirrorRectangle(m), env, p, ctx);
        glDisable(GL_BLEND);
        direct.skipMirror[static_cast<std::size_t>(mirror.index)] = true;
    }
    drawMainPass(env, direct, ctx);
}

} // namespace speculum::render::passes
