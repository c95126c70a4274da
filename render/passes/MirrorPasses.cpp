#include "render/passes/MirrorPasses.hpp"

#include "render/math/Projection.hpp"

#include <glm/gtc/matrix_inverse.hpp>

namespace speculum::render::passes {

ViewSetup viewSetup(const FrameInput& input, const FramePlan& plan, int viewIndex,
                    const glm::dmat4& cameraProjection) {
    ViewSetup setup;
    const glm::dmat4 rotation = math::viewRotation(input.camera);
    if (viewIndex < 0) {
        setup.viewProjection = cameraProjection * rotation;
        setup.eye = input.camera.position;
    } else {
        const MirrorView& view = plan.views[static_cast<std::size_t>(viewIndex)];
        setup.viewProjection = view.projection * rotation;
        setup.reflection = view.reflection;
        setup.eye = view.eye;
    }
    setup.skipMirror.assign(input.mirrors.size(), false);
    for (const MirrorView& child : plan.views)
        if (child.parent == viewIndex)
            setup.skipMirror[static_cast<std::size_t>(child.mirror)] = true;
    return setup;
}

void scissorTo(const math::PixelRect& rect) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(rect.x0, rect.y0, rect.width(), rect.height());
}

namespace {

// Object → clip for the mirror rectangle drawn in the parent's view, composed in double.
glm::mat4 rectangleClip(const FrameInput& input, const Mirror& mirror, const ViewSetup& parent) {
    const glm::dmat4 toCameraRelative = math::cameraRelative(input.camera);
    return glm::mat4(parent.viewProjection * toCameraRelative * parent.reflection * mirrorRectangle(mirror));
}

} // namespace

bool drawMirrorMask(const FrameInput& input, const MirrorView& view, const ViewSetup& parent,
                    const gl::Program& maskProgram, const MainPassContext& context, GLuint query) {
    const Mirror& mirror = input.mirrors[static_cast<std::size_t>(view.mirror)];
    maskProgram.use();
    maskProgram.set("uModelLightClip", rectangleClip(input, mirror, parent));
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_STENCIL_TEST);
    glStencilMask(0xFF);
    glStencilFunc(GL_EQUAL, view.parentStencilLevel, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, view.ownTarget ? GL_KEEP : GL_INCR);
    glBeginQuery(GL_ANY_SAMPLES_PASSED, query);
    context.meshes.get(context.unitPlane).draw();
    glEndQuery(GL_ANY_SAMPLES_PASSED);
    GLuint anyPassed = 0;
    glGetQueryObjectuiv(query, GL_QUERY_RESULT, &anyPassed);
    if (anyPassed && !view.ownTarget) {
        // Inside the mask, reset colour to the background and depth to the far plane: the reflected scene
        // (which lies behind the mirror) replaces whatever the parent view drew there.
        glStencilFunc(GL_EQUAL, view.stencilLevel, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        maskProgram.set("uFlatColor", glm::vec4(glm::vec3(input.settings.background), 1.0f));
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_ALWAYS);
        glDepthRange(1.0, 1.0);
        context.meshes.get(context.unitPlane).draw();
        glDepthRange(0.0, 1.0);
    }
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    return anyPassed != 0;
}

void drawMirrorSurface(const FrameInput& input, const MirrorView& view, const ViewSetup& parent,
                       const gl::Program& surfaceProgram, MainPassContext& context, GLuint reflectionTexture,
                       int reflectionLevels, glm::ivec2 targetSize) {
    const Mirror& mirror = input.mirrors[static_cast<std::size_t>(view.mirror)];
    beginLitView(input, parent, surfaceProgram, context);
    setMaterial(mirror.hasMaterial ? mirror.material : Material{}, surfaceProgram, context);
    surfaceProgram.set("uReflectivity", float(mirror.reflectivity));
    surfaceProgram.set("uTint", glm::vec3(mirror.tint));
    surfaceProgram.set("uFresnel", mirror.fresnel ? 1 : 0);
    surfaceProgram.set("uFromTexture", view.ownTarget ? 1 : 0);
    surfaceProgram.set("uReflectionTexture", kReflectionTextureUnit);
    surfaceProgram.set("uTargetSize", glm::vec2(targetSize));
    // Blur: a mip level of the reflection texture, up to 1/64 of its resolution at blur 1.
    surfaceProgram.set("uBlurLod", float(std::min(6.0, double(reflectionLevels - 1)) * mirror.blur));
    glEnable(GL_STENCIL_TEST);
    glStencilMask(0xFF);
    if (view.ownTarget) {
        glActiveTexture(GL_TEXTURE0 + kReflectionTextureUnit);
        glBindTexture(GL_TEXTURE_2D, reflectionTexture);
        glActiveTexture(GL_TEXTURE0);
        // An ordinary surface of the parent's view, depth-tested like any other.
        glStencilFunc(GL_EQUAL, view.parentStencilLevel, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        glDepthFunc(GL_LESS);
        glDisable(GL_BLEND);
    } else {
        // Exactly the marked pixels: the mask already did the depth test. Restores the mirror's depth and
        // steps the stencil back to the parent's level.
        glStencilFunc(GL_EQUAL, view.stencilLevel, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_DECR);
        glDepthFunc(GL_ALWAYS);
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_SRC1_COLOR);
    }
    glDepthMask(GL_TRUE);
    drawLitMesh(context.unitPlane, mirrorRectangle(mirror), input, surfaceProgram, context);
    glDisable(GL_BLEND);
    glDepthFunc(GL_LESS);
}

} // namespace speculum::render::passes
