// Screen-space mirrors (MirrorTechnique::ScreenSpace): the camera's view depth and its pyramid of minima
// (ScreenDepth), and each mirror's reflection traced through the camera's image into its reflection
// texture (its Mirror pass), which its surface pass then reads as a texture mirror's.
#include "render/math/Mirror.hpp"
#include "render/math/Projection.hpp"
#include "render/passes/PassExecutors.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace speculum::render::passes {

namespace {

// The view depth of nothing drawn: farther than anything a ray can reach.
constexpr float kNothingDrawn = 3.0e38f;

// What the image shows at a depth the trace can meet: every object, the reflector and the mirrors drawn
// before the screen-space ones (their surfaces, which hold their reflections). The screen-space mirrors
// themselves are left out: a ray leaving one passes through the others, whose reflections are not in the
// image yet when it is traced.
void drawViewDepth(const FrameExecution& frame, const ViewSpace& space, const gl::Program& program) {
    const FrameInput& input = frame.input;
    const glm::dmat4 toView = space.rotation * math::cameraRelative(input.camera);
    const glm::dmat4 toClip = space.projection * toView;
    auto draw = [&](const MeshHandle& mesh, const glm::dmat4& world) {
        if (!mesh)
            return;
        program.set("uModelClip", glm::mat4(toClip * world));
        program.set("uModelView", glm::mat4(toView * world));
        frame.context.meshes.get(mesh).draw();
    };
    for (const DrawItem& item : input.items)
        draw(item.mesh, item.world);
    if (input.reflector)
        draw(input.reflector->mesh, input.reflector->world);
    std::vector<bool> screenSpace(input.mirrors.size(), false);
    for (const MirrorView& view : frame.plan.views)
        if (view.screenSpace)
            screenSpace[static_cast<std::size_t>(view.mirror)] = true;
    for (std::size_t m = 0; m < input.mirrors.size(); ++m)
        if (!screenSpace[m])
            draw(frame.context.unitPlane,
                 math::visibleMirrorRectangle(mirrorRectangle(input.mirrors[m]), toClip));
}

// Each level of the pyramid from the one below: the nearest of the texels it covers.
void reduceToMinima(gl::RenderTexture& pyramid, const FrameResources& r) {
    r.depthMinProgram.use();
    r.depthMinProgram.set("uSource", 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, pyramid.color());
    glBindFramebuffer(GL_FRAMEBUFFER, r.convolveFramebuffer.id());
    glBindVertexArray(r.emptyVao.id());
    glDisable(GL_DEPTH_TEST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    for (int level = 1; level < pyramid.levels(); ++level) {
        // Only the level below is visible to the lookups: no loop through the level being written. Its size
        // is given: llvmpipe's textureSize misreports levels of a chain whose base level moves.
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, level - 1);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, level - 1);
        r.depthMinProgram.set("uSourceSize", glm::vec2(float(std::max(pyramid.width() >> (level - 1), 1)),
                                                       float(std::max(pyramid.height() >> (level - 1), 1))));
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, pyramid.color(), level);
        glViewport(0, 0, std::max(pyramid.width() >> level, 1), std::max(pyramid.height() >> level, 1));
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, pyramid.levels() - 1);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindVertexArray(0);
}

// How many of the traced pixels met what the image shows: the rest hold the background's path length
// (shaders/screen_trace.frag), as every pixel the trace did not draw does. Reads the mirror's rectangle
// of the reflection texture back.
long long pixelsThatMetTheImage(const math::PixelRect& rect) {
    if (rect.empty())
        return 0;
    std::vector<float> texels(static_cast<std::size_t>(rect.width()) *
                              static_cast<std::size_t>(rect.height()) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(rect.x0, rect.y0, rect.width(), rect.height(), GL_RGBA, GL_FLOAT, texels.data());
    long long met = 0;
    for (std::size_t i = 3; i < texels.size(); i += 4)
        met += texels[i] < 0.5f * kFarPathLength ? 1 : 0;
    return met;
}

std::string percent(long long part, long long whole) {
    return std::to_string(whole > 0 ? (100 * part + whole / 2) / whole : 0) + "%";
}

// The trace's outcome: the share of its pixels that met the image and the share that show the background.
std::string tracedOutcome(long long pixels, long long met) {
    return "traced in the camera's image: " + percent(met, pixels) + " of its " + std::to_string(pixels) +
           " pixels meet what the image shows, " + percent(pixels - met, pixels) + " show the background";
}

} // namespace

PassResult runScreenDepth(const PlannedPass& pass, FrameExecution& frame) {
    FrameResources& r = frame.resources;
    gl::RenderTexture& pyramid = r.screenDepth;
    frame.screenDepthReady = false;
    if (base::Status made = pyramid.ensure(frame.target.width, frame.target.height, GL_R32F, true); !made) {
        // Nothing to trace against: every screen-space mirror shows the background, and says why.
        frame.warnings.push_back("screen-space mirrors " + pass.details.node.substr(4) +
                                 ": no depth pyramid, so they show the background: " + made.error());
        return {false, {}};
    }
    resetPassState();
    glBindFramebuffer(GL_FRAMEBUFFER, pyramid.framebuffer());
    glViewport(0, 0, pyramid.width(), pyramid.height());
    glClearColor(kNothingDrawn, 0.0f, 0.0f, 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    r.screenDepthProgram.use();
    drawViewDepth(frame, cameraSpace(frame), r.screenDepthProgram);
    reduceToMinima(pyramid, r);
    resetPassState();
    frame.screenDepthReady = true;
    return {true, std::to_string(pyramid.levels()) + " levels"};
}

PassResult runScreenTrace(const PlannedPass& pass, FrameExecution& frame, const ViewSpace& space) {
    FrameResources& r = frame.resources;
    const MirrorView& view = space.view(pass.view);
    if (!ensureReflectionTexture(pass, frame, GL_RGBA16F))
        return {false, {}};
    gl::RenderTexture& texture = r.reflectionTextures.at(static_cast<std::size_t>(pass.writes.slot));
    bindWrites(pass.writes, frame, space); // cleared to the background, as far as can be
    if (!frame.screenDepthReady)
        return {true, "no depth pyramid: the background"};
    const FrameInput& input = frame.input;
    const Mirror& mirror = input.mirrors.at(static_cast<std::size_t>(view.mirror));
    const glm::dmat4 toView = space.rotation * math::cameraRelative(input.camera);
    const glm::dmat4 toClip = space.projection * toView;
    const glm::dmat4 rectangle = math::visibleMirrorRectangle(mirrorRectangle(mirror), toClip);
    const base::Result<math::Plane> plane = math::mirrorPlane(mirror.world);
    if (!plane)
        return {true, "no plane: the background"};
    const gl::Program& p = r.screenTraceProgram;
    p.use();
    p.set("uModelClip", glm::mat4(toClip * rectangle));
    p.set("uModelView", glm::mat4(toView * rectangle));
    p.set("uNormal", glm::vec3(glm::normalize(glm::dmat3(space.rotation) * plane->normal)));
    p.set("uProjection", glm::mat4(space.projection));
    p.set("uNear", float(input.camera.near));
    p.set("uSize", glm::vec2(float(frame.target.width), float(frame.target.height)));
    p.set("uLevels", r.screenDepth.levels());
    p.set("uSteps", std::clamp(input.settings.screenSteps, kMinScreenSteps, kMaxScreenSteps));
    p.set("uThickness",
          float(std::clamp(input.settings.screenThickness, kMinScreenThickness, kMaxScreenThickness)));
    p.set("uBackground", glm::vec3(input.settings.background));
    p.set("uFarPath", kFarPathLength);
    p.set("uDepthPyramid", 0);
    p.set("uImage", 1);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, r.screenDepth.color());
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, r.linear.color());
    glDisable(GL_CULL_FACE);
    gl::Query pixels;
    if (frame.countScreenSpace) {
        pixels = gl::makeQuery();
        glBeginQuery(GL_SAMPLES_PASSED, pixels.id());
    }
    frame.context.meshes.get(frame.context.unitPlane).draw();
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);
    if (!frame.countScreenSpace)
        return {true, "traced in the camera's image"};
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint drawn = 0;
    glGetQueryObjectuiv(pixels.id(), GL_QUERY_RESULT, &drawn);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, texture.framebuffer());
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    const long long met = pixelsThatMetTheImage(view.rect);
    return {true, tracedOutcome(drawn, std::min<long long>(met, drawn))};
}

} // namespace speculum::render::passes
