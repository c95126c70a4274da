// Screen-space mirrors (MirrorTechnique::ScreenSpace): the camera's view depth and its pyramid of minima
// (ScreenDepth), and each mirror's reflection traced through the camera's image into its reflection
// texture (its Mirror pass), which its surface pass then reads as a texture mirror's.
#include "base/Printable.hpp"
#include "render/math/Mirror.hpp"
#include "render/math/Projection.hpp"
#include "render/passes/PassExecutors.hpp"

#include <algorithm>
#include <cmath>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>
#include <optional>
#include <string>
#include <vector>

namespace speculum::render::passes {

namespace {

// The view depth of nothing drawn: farther than anything a ray can reach.
constexpr float kNothingDrawn = 3.0e38f;

// What the image shows at a depth the trace can meet: every object, the reflector and the mirrors drawn
// before the screen-space ones (their surfaces, which hold their reflections). The screen-space mirrors
// themselves are left out unless `screenSpaceMirrors` (the reflector's pyramid, drawn after them): a ray
// leaving one passes through the others, whose reflections are not in the image yet when it is traced.
void drawViewDepth(const FrameExecution& frame, const ViewSpace& space, const gl::Program& program,
                   bool screenSpaceMirrors) {
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
    for (const Reflector& reflector : input.reflectors)
        draw(reflector.mesh, reflector.world);
    std::vector<bool> screenSpace(input.mirrors.size(), false);
    for (const MirrorView& view : frame.plan.views)
        if (view.screenSpace && !screenSpaceMirrors)
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

// Where the traced pixels' reflections came from: the image, the reflector's map, the background.
struct SourceCounts {
    long long pixels = 0;
    long long image = 0;
    long long map = 0;
    long long background = 0;
};

// Counts a rectangle of the reflection texture the trace drew its sources into (uShowSources): a drawn
// pixel's alpha is 0, the cleared ones' the background's path length; green is the image, blue the map,
// red the background, blended by the trace's confidence (the larger share names the pixel).
SourceCounts countSources(const math::PixelRect& rect) {
    SourceCounts counts;
    if (rect.empty())
        return counts;
    std::vector<float> texels(static_cast<std::size_t>(rect.width()) *
                              static_cast<std::size_t>(rect.height()) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(rect.x0, rect.y0, rect.width(), rect.height(), GL_RGBA, GL_FLOAT, texels.data());
    for (std::size_t i = 0; i < texels.size(); i += 4) {
        if (texels[i + 3] > 0.5f)
            continue;
        ++counts.pixels;
        const float image = texels[i + 1], map = texels[i + 2], background = texels[i];
        if (image >= std::max(map, background))
            ++counts.image;
        else if (map >= background)
            ++counts.map;
        else
            ++counts.background;
    }
    return counts;
}

std::string percent(long long part, long long whole) {
    return std::to_string(whole > 0 ? (100 * part + whole / 2) / whole : 0) + "%";
}

// The trace's outcome: the share of its pixels that met the image and the shares that fell back.
std::string tracedOutcome(const SourceCounts& c, bool half) {
    std::string outcome = std::string("traced in the camera's image") + (half ? " at half resolution" : "") +
                          ": " + percent(c.image, c.pixels) + " of its " + std::to_string(c.pixels) +
                          " pixels meet what the image shows, ";
    if (c.map > 0)
        outcome += percent(c.map, c.pixels) + " fall back to the reflector's map, ";
    return outcome + percent(c.background, c.pixels) + " show the background";
}

// The uniforms of shaders/screen_trace.glsl: the image, its depth pyramid, the trace's settings and the
// fallback (reflector `probe`'s map, bound here, when the settings ask for it and there is one).
void setImageUniforms(const gl::Program& p, const FrameExecution& frame, const ViewSpace& space,
                      ScreenFallback fallback, int probe) {
    const FrameInput& input = frame.input;
    p.use();
    p.set("uWorldFromView", glm::mat3(glm::transpose(glm::dmat3(space.rotation))));
    p.set("uProjection", glm::mat4(space.projection));
    p.set("uNear", float(input.camera.near));
    p.set("uSize", glm::vec2(float(frame.target.width), float(frame.target.height)));
    p.set("uLevels", frame.resources.screenDepth.levels());
    p.set("uSteps", std::clamp(input.settings.screenSteps, kMinScreenSteps, kMaxScreenSteps));
    p.set("uThickness",
          float(std::clamp(input.settings.screenThickness, kMinScreenThickness, kMaxScreenThickness)));
    p.set("uBackground", glm::vec3(input.settings.background));
    p.set("uFarPath", kFarPathLength);
    p.set("uDepthPyramid", 0);
    p.set("uImage", 1);
    // Units of their own whether or not a map is bound: two samplers of different types on one unit
    // fail every draw.
    p.set("uEnvCube", kEnvCubeUnit);
    p.set("uEnvArray", kEnvArrayUnit);
    p.set("uParallax", 0);
    const bool bound =
        fallback == ScreenFallback::Map && frame.resources.reflector.bindAsProbe(input, probe, p);
    p.set("uFallback", bound ? 1 : 0);
}

// A screen-space mirror's trace: the image's uniforms, and the mirror's rectangle as the camera sees it.
void setTraceUniforms(const gl::Program& p, const FrameExecution& frame, const ViewSpace& space,
                      const Mirror& mirror, const glm::dvec3& normal) {
    setImageUniforms(p, frame, space, frame.input.settings.screenFallback, probeReflector(frame.input));
    const glm::dmat4 toView = space.rotation * math::cameraRelative(frame.input.camera);
    const glm::dmat4 toClip = space.projection * toView;
    const glm::dmat4 rectangle = math::visibleMirrorRectangle(mirrorRectangle(mirror), toClip);
    p.set("uModelClip", glm::mat4(toClip * rectangle));
    p.set("uModelView", glm::mat4(toView * rectangle));
    p.set("uNormal", glm::vec3(glm::normalize(glm::dmat3(space.rotation) * normal)));
}

// Draws the trace (its radiance, or its sources) into the mirror's reflection texture, bound with its
// rectangle scissored. At half resolution it traces into the half-size texture and scales that up
// (bilinear) into the rectangle.
struct TraceDraw {
    bool half = false;    // into the half-size texture, then scaled up
    bool sources = false; // uShowSources
};

void drawTrace(FrameExecution& frame, gl::RenderTexture& reflection, const PlannedPass& pass, TraceDraw how) {
    FrameResources& r = frame.resources;
    r.screenTraceProgram.set("uShowSources", how.sources ? 1 : 0);
    r.screenTraceProgram.use();
    // One flat rectangle, drawn twice when its sources are counted: nothing for a depth test to decide.
    glDisable(GL_DEPTH_TEST);
    const bool half = how.half;
    if (half) {
        // The half texels that cover the rectangle, and one more each side for the bilinear scale-up.
        const math::PixelRect& rect = *pass.writes.scissor;
        const int x0 = std::max(rect.x0 / 2 - 1, 0), y0 = std::max(rect.y0 / 2 - 1, 0);
        glBindFramebuffer(GL_FRAMEBUFFER, r.screenHalf.framebuffer());
        glViewport(0, 0, r.screenHalf.width(), r.screenHalf.height());
        glScissor(x0, y0, (rect.x1 + 1) / 2 + 1 - x0, (rect.y1 + 1) / 2 + 1 - y0);
        const glm::dvec3& background = frame.input.settings.background;
        glClearColor(float(background.r), float(background.g), float(background.b), kFarPathLength);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    frame.context.meshes.get(frame.context.unitPlane).draw();
    if (!half)
        return;
    // Exactly twice the half texture: its texel centres land on the full image's, up to the half-pixel
    // shift bilinear filtering then blends across.
    glBindFramebuffer(GL_READ_FRAMEBUFFER, r.screenHalf.framebuffer());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, reflection.framebuffer());
    const math::PixelRect& rect = *pass.writes.scissor;
    glScissor(rect.x0, rect.y0, rect.width(), rect.height());
    glBlitFramebuffer(0, 0, r.screenHalf.width(), r.screenHalf.height(), 0, 0, 2 * r.screenHalf.width(),
                      2 * r.screenHalf.height(), GL_COLOR_BUFFER_BIT, GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, reflection.framebuffer());
    glViewport(0, 0, reflection.width(), reflection.height());
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
    drawViewDepth(frame, cameraSpace(frame), r.screenDepthProgram, pass.details.screenSpaceMirrorsInDepth);
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
    const base::Result<math::Plane> plane = math::mirrorPlane(mirror.world);
    if (!plane)
        return {true, "no plane: the background"};
    bool half = input.settings.screenResolution == ScreenResolution::Half && pass.writes.scissor;
    if (half) {
        const int width = (frame.target.width + 1) / 2, height = (frame.target.height + 1) / 2;
        if (base::Status made = r.screenHalf.ensure(width, height, GL_RGBA16F, false); !made) {
            frame.warnings.push_back("mirror " + base::quoted(pass.target) +
                                     ": traced at full resolution, no half-size texture: " + made.error());
            half = false;
        }
    }
    setTraceUniforms(r.screenTraceProgram, frame, space, mirror, plane->normal);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, r.screenDepth.color());
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, r.linear.color());
    glDisable(GL_CULL_FACE);
    std::optional<SourceCounts> counts;
    if (frame.countScreenSpace) {
        drawTrace(frame, texture, pass, {.half = half, .sources = true});
        glBindFramebuffer(GL_READ_FRAMEBUFFER, texture.framebuffer());
        glReadBuffer(GL_COLOR_ATTACHMENT0);
        counts = countSources(view.rect);
    }
    drawTrace(frame, texture, pass, {.half = half, .sources = false});
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);
    if (!counts)
        return {true, std::string("traced in the camera's image") + (half ? " at half resolution" : "")};
    return {true, tracedOutcome(*counts, half)};
}

void drawScreenSpaceSources(const PlannedPass& pass, FrameExecution& frame, const ViewSpace& space) {
    if (!frame.screenDepthReady)
        return;
    const MirrorView& view = space.view(pass.view);
    const Mirror& mirror = frame.input.mirrors.at(static_cast<std::size_t>(view.mirror));
    const base::Result<math::Plane> plane = math::mirrorPlane(mirror.world);
    if (!plane)
        return;
    FrameResources& r = frame.resources;
    setTraceUniforms(r.screenTraceProgram, frame, space, mirror, plane->normal);
    r.screenTraceProgram.set("uShowSources", 1);
    r.screenTraceProgram.use();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, r.screenDepth.color());
    // Not the image: it is the target drawn into, and the sources are colours that do not read it.
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, r.screenDepth.color());
    // Over the surface just drawn, where it won the depth test: the same rectangle, pulled forward a
    // little; the target's alpha is left as the surface wrote it.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(-1.0f, -1.0f);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    frame.context.meshes.get(frame.context.unitPlane).draw();
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDepthMask(GL_TRUE);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);
}

namespace {

// The reflector's uniforms for its trace: where it is in the camera's view, how much of it reflects, and
// how far off its surface a ray starts (two pixels' width at its distance).
void setReflectorUniforms(const gl::Program& p, FrameExecution& frame, const ViewSpace& space,
                          const Reflector& reflector) {
    const FrameInput& input = frame.input;
    const glm::dmat4 toView = space.rotation * math::cameraRelative(input.camera) * reflector.world;
    p.set("uModelClip", glm::mat4(space.projection * toView));
    p.set("uModelView", glm::mat4(toView));
    p.set("uNormalView", glm::mat3(glm::transpose(glm::inverse(glm::dmat3(toView)))));
    p.set("uReflectivity", float(std::clamp(reflector.reflectivity, 0.0, 1.0)));
    p.set("uFresnel", reflector.fresnel ? 1 : 0);
    const double pixelAngle =
        2.0 * std::tan(glm::radians(input.camera.fovY) / 2.0) / std::max(frame.target.height, 1);
    p.set("uOriginOffset", float(2.0 * pixelAngle));
    p.set("uViewWeight", glm::vec3(viewSetup(space, -1, false).weight));
}

// Draws the reflector into the bound target over what the main pass drew of it: its depth, pulled forward
// a little, decides. A closed mesh's back faces are culled: near its silhouette they pass that test too,
// and the trace's difference would be added twice there. `alpha`: whether the target's alpha is written.
void drawOverReflector(FrameExecution& frame, const Reflector& reflector, bool alpha) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(-1.0f, -1.0f);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, alpha ? GL_TRUE : GL_FALSE);
    if (frame.resources.meshFacts.get(reflector.mesh).closed) {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
        glFrontFace(glm::determinant(glm::dmat3(reflector.world)) < 0.0 ? GL_CW : GL_CCW);
    } else {
        glDisable(GL_CULL_FACE);
    }
    frame.context.meshes.get(reflector.mesh).draw();
    glDisable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDepthMask(GL_TRUE);
}

// A still's counts: the trace's sources drawn into the copy of the image (no longer read), over the
// camera's depth, and read back.
SourceCounts countReflectorSources(FrameExecution& frame, const Reflector& reflector) {
    FrameResources& r = frame.resources;
    const int width = frame.target.width, height = frame.target.height;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, r.linear.framebuffer());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, r.screenImage.framebuffer());
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, r.screenImage.framebuffer());
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f); // alpha 1: not drawn (countSources)
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_BLEND);
    r.reflectorTraceProgram.set("uShowSources", 1);
    r.reflectorTraceProgram.use();
    drawOverReflector(frame, reflector, true); // a drawn pixel's alpha 0 is what countSources counts
    glBindFramebuffer(GL_READ_FRAMEBUFFER, r.screenImage.framebuffer());
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    return countSources({0, 0, width, height});
}

} // namespace

// Copies the camera's image into FrameResources::screenImage, with its mip chain when `blurred`; the
// error, if the copy could not be made.
base::Status copyImage(FrameExecution& frame, bool blurred) {
    FrameResources& r = frame.resources;
    const int width = frame.target.width, height = frame.target.height;
    if (base::Status made = r.screenImage.ensure(width, height, GL_RGBA16F, blurred); !made)
        return made;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, r.linear.framebuffer());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, r.screenImage.framebuffer());
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    if (blurred) {
        glBindTexture(GL_TEXTURE_2D, r.screenImage.color());
        glGenerateMipmap(GL_TEXTURE_2D); // trilinear lookups (RenderTexture's filters when mipmapped)
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    return base::Done{};
}

PassResult runScreenColour(const PlannedPass& pass, FrameExecution& frame) {
    if (base::Status copied = copyImage(frame, true); !copied) {
        frame.warnings.push_back(
            "reflector " + base::quoted(pass.details.node) +
            ": no blurred copy of the image, its trace reads it sharp: " + copied.error());
        return {true, "no copy of the image: " + copied.error()};
    }
    frame.screenColourReady = true;
    const gl::RenderTexture& image = frame.resources.screenImage;
    return {true, std::to_string(image.levels()) + " levels from " + std::to_string(image.width()) + "×" +
                      std::to_string(image.height())};
}

PassResult runReflectorTrace(const PlannedPass& pass, FrameExecution& frame) {
    FrameResources& r = frame.resources;
    const FrameInput& input = frame.input;
    const auto index = static_cast<std::size_t>(pass.reflector);
    if (index >= input.reflectors.size() || !input.reflectors[index].mesh || !frame.screenDepthReady)
        return {true, "no depth pyramid: the map alone"};
    const Reflector& reflector = input.reflectors[index];
    if (!r.reflector.hasMap(pass.reflector, reflector))
        return {true, "no map: the reflector is drawn without one, and nothing is traced over it"};
    // The image the rays read, copied (the trace draws into the camera's buffer), unless the ScreenColour
    // pass has just copied and blurred it.
    if (!frame.screenColourReady) {
        if (base::Status copied = copyImage(frame, false); !copied) {
            frame.warnings.push_back("reflector " + base::quoted(pass.target) +
                                     ": not traced in screen space, no copy of the image: " + copied.error());
            return {true, "no copy of the image: the map alone"};
        }
    }
    const ViewSpace space = cameraSpace(frame);
    bindWrites(pass.writes, frame, space);
    const gl::Program& p = r.reflectorTraceProgram;
    setImageUniforms(p, frame, space, ScreenFallback::Map, pass.reflector);
    setReflectorUniforms(p, frame, space, reflector);
    // What the surface drew, looked up alike; a rough reflector without the blurred image traces sharp.
    r.reflector.bindLookup(input, pass.reflector, p);
    p.set("uImageLevels", frame.screenColourReady ? r.screenImage.levels() : 1);
    p.set("uShowSources", 0);
    p.use();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, r.screenDepth.color());
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, r.screenImage.color());
    // The difference to the map's reflection, added.
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    drawOverReflector(frame, reflector, false);
    glDisable(GL_BLEND);
    if (frame.showScreenSpaceSources) {
        p.set("uShowSources", 1);
        p.use();
        drawOverReflector(frame, reflector, false);
    }
    std::optional<SourceCounts> counts;
    if (frame.countScreenSpace) {
        glActiveTexture(GL_TEXTURE1);
        glBindTexture(GL_TEXTURE_2D, r.screenDepth.color()); // not the copy, which is drawn into now
        counts = countReflectorSources(frame, reflector);
    }
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);
    resetPassState();
    frame.screenColourReady = false; // the next reflector's trace copies the image it drew into
    if (!counts)
        return {true, "traced in the camera's image"};
    return {true, tracedOutcome(*counts, false)};
}

} // namespace speculum::render::passes
