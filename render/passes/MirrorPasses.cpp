#include "render/passes/MirrorPasses.hpp"

#include "render/frame/Settings.hpp"
#include "render/math/Mirror.hpp"
#include "render/math/Projection.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/trigonometric.hpp>

namespace speculum::render::passes {

ViewSetup viewSetup(const ViewSpace& space, int viewIndex, bool clockwise) {
    ViewSetup setup;
    setup.cullOutside = space.frustum;
    setup.clockwise = clockwise != space.flipsWinding;
    if (viewIndex < 0) {
        setup.viewProjection = space.projection * space.rotation;
        setup.eye = space.input.camera.position;
        setup.coarseDetail = space.ownViewCoarse;
        setup.preWeightedStencil = space.preWeighted;
    } else {
        const MirrorView& view = space.view(viewIndex);
        setup.viewProjection = view.projection * space.rotation;
        setup.reflection = view.reflection;
        setup.eye = view.eye;
        setup.coarseDetail = true;
        setup.pathLengthInAlpha = view.textureSlot >= 0;
        setup.weight = view.weight;
        setup.preWeightedStencil = space.preWeighted && view.textureSlot < 0;
        const glm::dvec2 size = glm::max(glm::dvec2(space.size), glm::dvec2(1.0));
        setup.ndcBounds = glm::dvec4(view.rect.x0 / size.x, view.rect.y0 / size.y, view.rect.x1 / size.x,
                                     view.rect.y1 / size.y) *
                              2.0 -
                          1.0;
    }
    const std::size_t mirrors = space.input.mirrors.size();
    setup.skipMirror.assign(mirrors, false);
    setup.stencilMirror.assign(mirrors, false);
    for (const MirrorView& child : space.views)
        if (child.parent == viewIndex && child.face == space.face) {
            setup.skipMirror[static_cast<std::size_t>(child.mirror)] = true;
            setup.stencilMirror[static_cast<std::size_t>(child.mirror)] = !child.ownTarget;
        }
    return setup;
}

void drawSpaceView(const ViewSpace& space, int viewIndex, bool clockwise) {
    const ViewSetup setup = viewSetup(space, viewIndex, clockwise);
    drawMainPass(space.enter(viewIndex, space.context.program), setup, space.context);
}

void scissorTo(const math::PixelRect& rect) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(rect.x0, rect.y0, rect.width(), rect.height());
}

bool drawMirrorMask(const ViewSpace& space, const MirrorView& view, const ViewSetup& parent, GLuint query,
                    bool waitForQuery) {
    const gl::Program& maskProgram = space.flatProgram;
    const FrameInput& input = space.enter(view.parent, maskProgram);
    const MainPassContext& context = space.context;
    const auto mirror = static_cast<std::size_t>(view.mirror);
    const gl::GpuMesh& mesh = context.meshes.get(context.mirrorMesh(mirror));
    maskProgram.use();
    maskProgram.set("uModelLightClip", mirrorRectangleClip(input, mirror, parent, context));
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_STENCIL_TEST);
    glStencilMask(0xFF);
    glStencilFunc(GL_EQUAL, view.parentStencilLevel, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, view.ownTarget ? GL_KEEP : GL_INCR);
    if (query)
        glBeginQuery(GL_ANY_SAMPLES_PASSED, query);
    mesh.draw();
    GLuint anyPassed = 1; // not tested, or not waited for: maybe
    if (query) {
        glEndQuery(GL_ANY_SAMPLES_PASSED);
        if (waitForQuery)
            glGetQueryObjectuiv(query, GL_QUERY_RESULT, &anyPassed);
    }
    if (anyPassed && !view.ownTarget) {
        // Inside the mask, reset colour to the background and depth to the far plane: the reflected scene
        // (which lies behind the mirror) replaces whatever the parent view drew there.
        glStencilFunc(GL_EQUAL, view.stencilLevel, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        // Alpha: as far as a path can be (material.glsl's outputAlpha), for a rough mirror's blur.
        // Pre-weighted (FramePlan::preWeighted), the background is kept with the view's weight too.
        maskProgram.set("uFlatColor",
                        glm::vec4(glm::vec3(input.settings.background * view.weight), kFarPathLength));
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_ALWAYS);
        glDepthRange(1.0, 1.0);
        mesh.draw();
        glDepthRange(0.0, 1.0);
    }
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    return anyPassed != 0;
}

namespace {

// Reflectivity 1 leaves nothing of the surface's own material (Fresnel cannot raise it further): the
// reflection, already in place, is only scaled by the tint. Same stencil and depth steps as the lit path.
void tintPerfectMirror(const ViewSpace& space, const MirrorView& view, const ViewSetup& parent) {
    const gl::Program& flatProgram = space.flatProgram;
    const FrameInput& input = space.enter(view.parent, flatProgram);
    const MainPassContext& context = space.context;
    const auto index = static_cast<std::size_t>(view.mirror);
    flatProgram.use();
    flatProgram.set("uModelLightClip", mirrorRectangleClip(input, index, parent, context));
    flatProgram.set("uFlatColor", glm::vec4(0.0f));
    glEnable(GL_STENCIL_TEST);
    glStencilMask(0xFF);
    glStencilFunc(GL_EQUAL, view.stencilLevel, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_DECR);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ZERO, GL_CONSTANT_COLOR);
    // Pre-weighted, the reflection already has its tint.
    const glm::vec3 tint = parent.preWeightedStencil ? glm::vec3(1.0f) : glm::vec3(input.mirrors[index].tint);
    glBlendColor(tint.r, tint.g, tint.b, 1.0f);
    context.meshes.get(context.mirrorMesh(index)).draw();
    glDisable(GL_BLEND);
    glDepthFunc(GL_LESS);
}

// A rough mirror filtered over its lobe's footprint (GlossyFilter::Footprint), not one mip level.
bool usesFootprint(const MirrorView& view, const Mirror& mirror) {
    return mirror.roughness > 0.0 && view.glossyFilter == GlossyFilter::Footprint;
}

// A rough mirror read from its convolved chain at the footprint's level (GlossyFilter::Chain).
bool usesChain(const MirrorView& view, const Mirror& mirror) {
    return mirror.roughness > 0.0 && view.glossyFilter == GlossyFilter::Chain;
}

// The Chain filter's stand-in for the GGX lobe, which has a sharp core and long tails: two Gaussians in
// tan 2θh, a core of deviation 0.6 α and a tail 3.5 times as wide weighing 0.4. Tuned against the tracer
// on the glossy agreement scene (GlossyAgreementGLTest): a single Gaussian matched to the lobe's median
// turn (2α) blurs the core away, 4.5 dB worse at roughness 0.3.
constexpr double kChainCoreSigmaPerAlpha = 0.6;
constexpr double kChainTailRatio = 3.5;
constexpr double kChainTailWeight = 0.4;
// Rougher than 0.4 the two Gaussians spill what is on screen over the lobe's off-screen share (21.5 dB
// against the 16-tap footprint's 27.3 at roughness 0.6, whatever their widths); 12 taps read from the
// convolved chain give 27.3 there (8 taps 26.2, 16 taps 27.8), so the Chain filter blends from its
// Gaussians to 12 taps between roughness 0.4 and 0.5.
constexpr glm::vec2 kChainTapsAbove{0.4f, 0.5f};
constexpr int kChainTaps = 12;

// A rough mirror's filter (shaders/mirror.frag). Mip: a level of the reflection texture set by the
// roughness alone, up to 1/64 of its resolution at roughness 1 (the blur of old). Footprint: the GGX
// lobe's taps, spread by the distance to what the mirror reflects. Chain: four lookups in the convolved
// chain at the footprint's levels, or, rougher, taps read from it.
void setGlossyUniforms(const FrameInput& input, const MirrorView& view, const Mirror& mirror,
                       const gl::Program& program, int reflectionLevels, glm::ivec2 targetSize) {
    const double roughness = std::clamp(mirror.roughness, 0.0, 1.0);
    const bool footprint = usesFootprint(view, mirror);
    const double maxLod = std::max(reflectionLevels - 1, 0);
    const bool chain = usesChain(view, mirror);
    program.set("uBlurLod", footprint || chain ? 0.0f : float(std::min(6.0, maxLod) * roughness));
    program.set("uGlossyTaps", footprint ? glossyTapCount(input.settings) : 0);
    program.set("uChainSigma", chain ? float(kChainCoreSigmaPerAlpha) : 0.0f);
    program.set("uChainTail", glm::vec2(float(kChainTailRatio), float(kChainTailWeight)));
    program.set("uChainTapsAbove", kChainTapsAbove);
    program.set("uChainTaps", kChainTaps);
    program.set("uGgxAlpha", float(roughness * roughness));
    program.set("uRoughness", float(roughness));
    program.set("uGgxAlbedo", kGgxAlbedoUnit);
    const double tanHalfFov = std::tan(glm::radians(std::clamp(input.camera.fovY, 1.0, 179.0)) * 0.5);
    program.set("uFocalPx", float(targetSize.y / (2.0 * tanHalfFov)));
    program.set("uMaxLod", float(maxLod));
}

} // namespace

bool surfaceCopiesReflection(const Mirror& mirror, const glm::dvec3& viewWeight) {
    return !(mirror.roughness > 0.0) && !mirror.fresnel && mirror.reflectivity == 1.0 &&
           mirror.tint == glm::dvec3(1.0) && viewWeight == glm::dvec3(1.0);
}

namespace {

// The draw variant of shaders/mirror.frag for this mirror: what it does not use is compiled out.
std::string mirrorDefines(const MirrorView& view, const Mirror& mirror, bool fromTexture,
                          const glm::dvec3& viewWeight, bool encoded) {
    const bool footprint = fromTexture && usesFootprint(view, mirror);
    const bool chain = fromTexture && usesChain(view, mirror);
    // Which of the chain's two reads its roughness takes (mirror.frag's chainReflection): the Gaussians up
    // to kChainTapsAbove.y, the taps from kChainTapsAbove.x; both between.
    const double roughness = std::clamp(mirror.roughness, 0.0, 1.0);
    const bool chainGaussians = chain && roughness < kChainTapsAbove.y;
    const bool chainTaps = chain && roughness > kChainTapsAbove.x;
    const bool sharp = fromTexture && !(mirror.roughness > 0.0);
    // Weight exactly 1 everywhere: the texel is the pixel.
    const bool copy = fromTexture && surfaceCopiesReflection(mirror, viewWeight);
    auto define = [](const char* name, bool on) {
        return std::string("#define ") + name + (on ? " 1\n" : " 0\n");
    };
    return define("MIRROR_FROM_TEXTURE", fromTexture) + define("MIRROR_GLOSSY_TAPS", footprint) +
           define("MIRROR_CHAIN", chain) + define("MIRROR_CHAIN_GAUSSIANS", chainGaussians) +
           define("MIRROR_CHAIN_TAPS", chainTaps) + define("MIRROR_FRESNEL", mirror.fresnel) +
           define("MIRROR_SHARP", sharp) + define("MIRROR_COPY", copy) +
           define("MIRROR_COPY_ENCODED", copy && encoded) +
           define("MIRROR_SURFACE", !(mirror.reflectivity >= 1.0));
}

} // namespace

void drawMirrorSurface(const ViewSpace& space, const MirrorView& view, const ViewSetup& parent,
                       GLuint reflectionTexture, int reflectionLevels, bool reflectionEncoded) {
    const auto index = static_cast<std::size_t>(view.mirror);
    if (!view.ownTarget && space.input.mirrors[index].reflectivity >= 1.0) {
        tintPerfectMirror(space, view, parent);
        return;
    }
    const gl::Program& surfaceProgram = space.mirrorProgram;
    MainPassContext& context = space.context;
    const FrameInput& input = space.enter(view.parent, surfaceProgram);
    const Mirror& mirror = input.mirrors[index];
    beginLitView(input, parent, surfaceProgram, context);
    setMaterial(mirror.hasMaterial ? mirror.material : Material{}, surfaceProgram, context,
                mirrorDefines(view, mirror, view.ownTarget, parent.weight, reflectionEncoded));
    surfaceProgram.set("uReflectivity", float(mirror.reflectivity));
    surfaceProgram.set("uTint", glm::vec3(mirror.tint));
    surfaceProgram.set("uFresnel", mirror.fresnel ? 1 : 0);
    surfaceProgram.set("uFromTexture", view.ownTarget ? 1 : 0);
    surfaceProgram.set("uReflectionPreWeighted", parent.preWeightedStencil && !view.ownTarget ? 1 : 0);
    surfaceProgram.set("uReflectionTexture", kReflectionTextureUnit);
    surfaceProgram.set("uTargetSize", glm::vec2(space.size));
    setGlossyUniforms(input, view, mirror, surfaceProgram, reflectionLevels, space.size);
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
    // The same mesh, and the same part of the rectangle, as the mask drew.
    drawLitMesh(context.mirrorMesh(index), drawnMirrorWorld(input, index, parent, context), input,
                surfaceProgram, context);
    glDisable(GL_BLEND);
    glDepthFunc(GL_LESS);
}

} // namespace speculum::render::passes
