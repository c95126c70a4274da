#include "render/Renderer.hpp"

#include "render/gl/Allocation.hpp"
#include "render/gl/GpuMesh.hpp"
#include "render/gl/GpuTimer.hpp"
#include "render/gl/Objects.hpp"
#include "render/gl/Program.hpp"
#include "render/gl/RenderTexture.hpp"
#include "render/gl/TextureCache.hpp"
#include "render/io/Printable.hpp"
#include "render/math/Projection.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/passes/LightingVariant.hpp"
#include "render/passes/MainPass.hpp"
#include "render/passes/MirrorOcclusion.hpp"
#include "render/passes/MirrorPasses.hpp"
#include "render/passes/ReflectorPass.hpp"
#include "render/passes/ShadowMaps.hpp"
#include "render/plan/Planner.hpp"

#include <algorithm>
#include <chrono>
#include <glm/gtc/matrix_transform.hpp>

namespace speculum::render {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

gl::Texture makeDummyDepth(GLenum target) {
    gl::Texture t = gl::makeTexture();
    glBindTexture(target, t.id());
    const float one = 1.0f;
    if (target == GL_TEXTURE_CUBE_MAP) {
        for (int face = 0; face < 6; ++face)
            glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_DEPTH_COMPONENT24, 1, 1, 0,
                         GL_DEPTH_COMPONENT, GL_FLOAT, &one);
    } else {
        glTexImage2D(target, 0, GL_DEPTH_COMPONENT24, 1, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &one);
    }
    glTexParameteri(target, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(target, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, 0);
    glBindTexture(target, 0);
    return t;
}

} // namespace

struct Renderer::State {
    gl::Program meshProgram;
    gl::Program shadowProgram; // depth only
    gl::Program flatProgram;   // mirror masks and background resets
    gl::Program mirrorProgram;
    gl::Program compositeProgram;
    gl::MeshCache meshes;
    gl::TextureCache textures;
    passes::ShadowMaps shadows;
    passes::ReflectorPass reflector; // the curved reflector's environment map and surface
    // The linear (half-float) colour buffer every frame is drawn into before the composite pass, with
    // the depth-stencil buffer the mirror passes nest in.
    gl::RenderTexture linear;
    std::vector<gl::RenderTexture> reflectionTextures; // texture-technique mirrors, one per nesting
    passes::MirrorOcclusion occlusion;                 // the mirror masks' occlusion tests
    gl::VertexArray emptyVao; // core profile needs a VAO bound even for attribute-less draws
    gl::Texture dummyShadow2D;
    gl::Texture dummyShadowCube;
    gl::GpuTimer timer;
    PlannerState plannerState;
    GpuLimits limits;
    MeshHandle unitPlane;
    bool released = false;
};

Renderer::Renderer()
    : m_state(std::make_unique<State>()) {}

Renderer::~Renderer() = default;

Result<std::unique_ptr<Renderer>> Renderer::create() {
    std::unique_ptr<Renderer> renderer(new Renderer);
    State& s = *renderer->m_state;
    auto mesh = gl::Program::build("mesh.vert", "mesh.frag");
    if (!mesh)
        return Error{mesh.error()};
    auto shadow = gl::Program::build("shadow.vert", "shadow.frag");
    if (!shadow)
        return Error{shadow.error()};
    auto flat = gl::Program::build("shadow.vert", "flat.frag");
    if (!flat)
        return Error{flat.error()};
    auto mirror = gl::Program::build("mesh.vert", "mirror.frag");
    if (!mirror)
        return Error{mirror.error()};
    auto composite = gl::Program::build("fullscreen.vert", "composite.frag");
    if (!composite)
        return Error{composite.error()};
    s.meshProgram = std::move(*mesh);
    s.shadowProgram = std::move(*shadow);
    s.mirrorProgram = std::move(*mirror);
    s.flatProgram = std::move(*flat);
    s.compositeProgram = std::move(*composite);
    s.emptyVao = gl::makeVertexArray();
    s.dummyShadow2D = makeDummyDepth(GL_TEXTURE_2D);
    s.dummyShadowCube = makeDummyDepth(GL_TEXTURE_CUBE_MAP);
    s.unitPlane = std::make_shared<const MeshData>(makePlane(1));
    s.limits = queryGpuLimits();
    if (Status reflector = s.reflector.init(); !reflector)
        return Error{reflector.error()};
    return renderer;
}

void Renderer::releaseGlResources() {
    // Destroying the state deletes every GL object while the caller's context is current.
    m_state = std::make_unique<State>();
    m_state->released = true;
}

const GpuLimits& Renderer::gpuLimits() const {
    return m_state->limits;
}

void Renderer::lowerGpuLimits(const GpuLimits& limits) {
    GpuLimits& l = m_state->limits;
    l.maxTextureSize = std::min(l.maxTextureSize, limits.maxTextureSize);
    l.maxCubeMapSize = std::min(l.maxCubeMapSize, limits.maxCubeMapSize);
    l.maxRenderbufferSize = std::min(l.maxRenderbufferSize, limits.maxRenderbufferSize);
    l.maxViewportSize = std::min(l.maxViewportSize, limits.maxViewportSize);
}

namespace {

// Marks pass i and every later pass of the same view or its descendants as not run.
bool descendsFrom(const FramePlan& plan, int view, int ancestor) {
    for (int v = view; v >= 0; v = plan.views[static_cast<std::size_t>(v)].parent)
        if (v == ancestor)
            return true;
    return false;
}

void resetState() {
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDisable(GL_STENCIL_TEST);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilMask(0xFF);
    glFrontFace(GL_CCW);
}

} // namespace

FrameReport Renderer::render(const FrameInput& requested, const RenderTarget& target,
                             const RenderOptions& options) {
    const auto frameStart = Clock::now();
    State& s = *m_state;
    FrameReport report;
    if (s.released || target.width <= 0 || target.height <= 0)
        return report;
    // Map sizes beyond the GPU's limits would fail to allocate: the frame is planned and drawn with sizes
    // it can hold, and says so.
    std::optional<FrameInput> fitted = fitToGpuLimits(requested, s.limits, report.warnings);
    // A tile is planned as the whole image, then restricted to its pixels: it draws them exactly as an
    // untiled frame would, with the same sub-pixel sample positions.
    const PlanViewport viewport{options.tile ? options.tile->imageWidth : target.width,
                                options.tile ? options.tile->imageHeight : target.height,
                                options.jitterPixels};
    const PlannerState freshState;
    const PlannerState& plannerState = options.reuseMaps ? s.plannerState : freshState;
    FramePlan& plan = report.plan;
    plan = planFrame(fitted ? *fitted : requested, plannerState, viewport);
    // Maps that do not fit in GPU memory (or that the driver cannot draw into) are allocated smaller, with
    // a warning, and the frame is planned, explained and drawn with the sizes that worked. Failed sizes
    // are remembered by the passes, so later frames go straight to the size that works.
    {
        auto edit = [&]() -> FrameInput& {
            if (!fitted)
                fitted = requested;
            return *fitted;
        };
        bool changed = false;
        for (int lightIndex : plan.shadowedLights) {
            const auto i = static_cast<std::size_t>(lightIndex);
            const FrameInput& current = fitted ? *fitted : requested;
            const int asked = std::max(current.lights[i].shadows.mapSize, kMinShadowMapSize);
            const int size = s.shadows.allocate(current, lightIndex, report.warnings);
            if (size == asked)
                continue;
            changed = true;
            if (size == 0)
                edit().lights[i].shadows.enabled = false;
            else
                edit().lights[i].shadows.mapSize = size;
        }
        bool reflectorDropped = false;
        const bool capturing = std::any_of(plan.passes.begin(), plan.passes.end(),
                                           [](const PlannedPass& p) { return p.kind == PassKind::Envmap; });
        if (capturing) {
            const FrameInput& current = fitted ? *fitted : requested;
            const int asked = current.reflector->resolution;
            const int n = s.reflector.allocate(*current.reflector, report.warnings);
            if (n == 0)
                reflectorDropped = true;
            else if (n != asked) {
                edit().reflector->resolution = n;
                changed = true;
            }
        }
        if (changed)
            plan = planFrame(*fitted, plannerState, viewport);
        if (reflectorDropped) {
            const FrameInput& current = fitted ? *fitted : requested;
            std::erase_if(plan.passes, [](const PlannedPass& p) { return p.kind == PassKind::Envmap; });
            plan.envmap.reset();
            plan.skipped.push_back(
                {current.reflector->name, "no environment map: none could be allocated (see the warnings)"});
        }
    }
    const FrameInput& input = fitted ? *fitted : requested;
    glm::dmat4 projection = cameraProjection(input, viewport);
    if (options.tile) {
        const math::PixelRect tile{options.tile->x, options.tile->y, options.tile->x + target.width,
                                   options.tile->y + target.height};
        restrictToTile(plan, tile, viewport);
        projection = math::tileProjection(projection, tile.x0, tile.y0, target.width, target.height,
                                          viewport.width, viewport.height);
    }

    // The lit shaders, built for this frame's lights. A variant that fails to build leaves the shaders that
    // read the lights from uniforms: the same image, slower.
    {
        const bool variants = options.lightingVariants;
        const std::string lighting = variants ? passes::lightingVariant(input, plan.shadowedLights) : "";
        Status selected = s.meshProgram.select(lighting, variants);
        if (selected)
            selected = s.mirrorProgram.select(lighting, variants);
        if (selected && input.reflector) // the reflector's programs build their variants only when needed
            selected = s.reflector.selectLighting(lighting, variants);
        if (!selected) {
            report.warnings.push_back("lit shaders for this frame's lights did not build; drawn with the "
                                      "general ones: " +
                                      selected.error());
            (void)s.meshProgram.select({}, variants);
            (void)s.mirrorProgram.select({}, variants);
            (void)s.reflector.selectLighting({}, variants);
        }
    }

    // A seamless cube map filters across face edges, so PCF near a face border reads the neighbouring
    // face instead of clamping (which would leak light or shadow along the seams).
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    if (Status linear = s.linear.ensure(target.width, target.height, GL_RGBA16F, false); !linear) {
        // Without its colour buffer the frame cannot be drawn at all: say so instead of an empty image.
        report.error = "the frame could not be drawn: " + linear.error();
        report.warnings.push_back(report.error);
        plan.passes.clear();
        report.cpuMs = msSince(frameStart);
        return report;
    }
    passes::MainPassContext ctx{
        s.meshProgram,          s.meshes,   s.textures, s.shadows, plan.shadowedLights, s.dummyShadow2D.id(),
        s.dummyShadowCube.id(), s.unitPlane};
    ctx.depthOnlyProgram = &s.flatProgram;
    // Every view the main pass draws (the camera's and each mirror's) draws the reflector with its map.
    ctx.drawReflector = [&s](const FrameInput& in, const passes::ViewSetup& view,
                             passes::MainPassContext& c) { return s.reflector.drawSurface(in, view, c); };

    // The framebuffer a view's scene is drawn into: its own texture, or its parent's target.
    auto targetOf = [&](int viewIndex) -> GLuint {
        if (viewIndex < 0)
            return s.linear.framebuffer();
        const MirrorView& v = plan.views[static_cast<std::size_t>(viewIndex)];
        return v.textureSlot < 0
                   ? s.linear.framebuffer()
                   : s.reflectionTextures[static_cast<std::size_t>(v.textureSlot)].framebuffer();
    };
    s.occlusion.beginFrame(plan);
    std::vector<bool> ran(plan.passes.size(), true);
    std::vector<std::string> hidden; // reasons for views found fully occluded, by view
    hidden.resize(plan.views.size());
    int deepestSlot = -1;
    for (const MirrorView& v : plan.views)
        deepestSlot = std::max(deepestSlot, v.textureSlot);
    if (static_cast<int>(s.reflectionTextures.size()) <= deepestSlot)
        s.reflectionTextures.resize(static_cast<std::size_t>(deepestSlot + 1));

    gl::FramebufferBinding keepCallerBinding;
    for (std::size_t i = 0; i < plan.passes.size(); ++i) {
        PlannedPass& pass = plan.passes[i];
        if (pass.view >= 0) {
            // A view inside a mirror found hidden runs nothing.
            for (std::size_t v = 0; v < plan.views.size(); ++v)
                if (!hidden[v].empty() && descendsFrom(plan, pass.view, static_cast<int>(v)))
                    ran[i] = false;
            if (!ran[i])
                continue;
        }
        const auto passStart = Clock::now();
        if (options.gpuTimings)
            s.timer.begin(i);
        switch (pass.kind) {
        case PassKind::Shadow:
            s.shadows.render(input, pass.lightIndex, s.meshes, s.shadowProgram, &s.textures);
            s.plannerState.shadowSignatures[pass.lightIndex] = pass.signature;
            break;
        case PassKind::Envmap: {
            for (int lightIndex : plan.shadowedLights)
                s.shadows.setPcf(lightIndex, input.lights[static_cast<std::size_t>(lightIndex)].shadows.pcf);
            resetState();
            passes::MainPassContext envCtx{s.meshProgram,
                                           s.meshes,
                                           s.textures,
                                           s.shadows,
                                           plan.shadowedLights,
                                           s.dummyShadow2D.id(),
                                           s.dummyShadowCube.id(),
                                           s.unitPlane};
            if (Status captured =
                    s.reflector.capture(input, *plan.envmap, envCtx, {&s.flatProgram, &s.mirrorProgram});
                captured) {
                s.plannerState.envmapSignature = plan.envmap->signature;
                s.plannerState.envmapSettings = plan.envmap->settingsKey;
            } else {
                report.warnings.push_back(captured.error());
            }
            break;
        }
        case PassKind::Main: {
            for (int lightIndex : plan.shadowedLights)
                s.shadows.setPcf(lightIndex, input.lights[static_cast<std::size_t>(lightIndex)].shadows.pcf);
            glBindFramebuffer(GL_FRAMEBUFFER, s.linear.framebuffer());
            glViewport(0, 0, target.width, target.height);
            resetState();
            glClearColor(float(input.settings.background.r), float(input.settings.background.g),
                         float(input.settings.background.b), 1.0f);
            glClearStencil(0);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
            passes::drawMainPass(
                input, passes::viewSetup(input, plan, -1, projection, {target.width, target.height}), ctx);
            break;
        }
        case PassKind::MirrorMask: {
            const MirrorView& view = plan.views[static_cast<std::size_t>(pass.view)];
            glBindFramebuffer(GL_FRAMEBUFFER, targetOf(view.parent));
            glViewport(0, 0, target.width, target.height);
            resetState();
            passes::scissorTo(view.rect);
            const passes::ViewSetup parent =
                passes::viewSetup(input, plan, view.parent, projection, {target.width, target.height});
            const bool wait = s.occlusion.mustWait(pass.view);
            const bool marked = passes::drawMirrorMask(input, view, parent, s.flatProgram, ctx,
                                                       s.occlusion.query(pass.view), wait);
            if (wait) {
                s.occlusion.waited(pass.view, marked);
                pass.reason += "; waited for its occlusion test";
            } else {
                s.occlusion.leftForLater(pass.view);
                pass.reason += "; visible last frame, so not waiting for its occlusion test";
            }
            if (!marked)
                hidden[static_cast<std::size_t>(pass.view)] =
                    options.tile ? "fully occluded in this tile: no pixel of it passed the depth test"
                                 : "fully occluded: no pixel of it passed the depth test";
            break;
        }
        case PassKind::Mirror: {
            const MirrorView& view = plan.views[static_cast<std::size_t>(pass.view)];
            resetState();
            if (view.ownTarget) {
                gl::RenderTexture& texture = s.reflectionTextures[static_cast<std::size_t>(view.textureSlot)];
                const bool blurred = input.mirrors[static_cast<std::size_t>(view.mirror)].blur > 0.0;
                if (Status made = texture.ensure(target.width, target.height, GL_RGBA16F, true); !made) {
                    // No texture to draw the reflection into: the mirror's passes (and those of views
                    // inside it) are skipped and reported, with the reason.
                    const std::string why = "its reflection texture: " + made.error();
                    report.warnings.push_back("mirror " + quoted(pass.target) + ": no reflection, " + why);
                    hidden[static_cast<std::size_t>(pass.view)] = why;
                    ran[i] = false;
                    break;
                }
                glBindFramebuffer(GL_FRAMEBUFFER, texture.framebuffer());
                glViewport(0, 0, target.width, target.height);
                // Blurred lookups read around the mirror's pixels too: clear the whole texture for them.
                if (!blurred)
                    passes::scissorTo(view.rect);
                glClearColor(float(input.settings.background.r), float(input.settings.background.g),
                             float(input.settings.background.b), 1.0f);
                glClearStencil(0);
                glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
            } else {
                glBindFramebuffer(GL_FRAMEBUFFER, targetOf(pass.view));
                glViewport(0, 0, target.width, target.height);
                glEnable(GL_STENCIL_TEST);
                glStencilFunc(GL_EQUAL, view.stencilLevel, 0xFF);
                glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
            }
            passes::scissorTo(view.rect);
            // An odd number of reflections turns counter-clockwise triangles clockwise.
            glFrontFace(glm::determinant(glm::dmat3(view.reflection)) < 0.0 ? GL_CW : GL_CCW);
            passes::drawMainPass(
                input, passes::viewSetup(input, plan, pass.view, projection, {target.width, target.height}),
                ctx);
            glFrontFace(GL_CCW);
            break;
        }
        case PassKind::MirrorSurface: {
            const MirrorView& view = plan.views[static_cast<std::size_t>(pass.view)];
            GLuint reflection = 0;
            int levels = 1;
            if (view.ownTarget) {
                gl::RenderTexture& texture = s.reflectionTextures[static_cast<std::size_t>(view.textureSlot)];
                if (input.mirrors[static_cast<std::size_t>(view.mirror)].blur > 0.0)
                    texture.generateMipmaps();
                reflection = texture.color();
                levels = texture.levels();
            }
            glBindFramebuffer(GL_FRAMEBUFFER, targetOf(view.parent));
            glViewport(0, 0, target.width, target.height);
            resetState();
            passes::scissorTo(view.rect);
            if (view.parent >= 0) // drawn in the parent's (reflected) view
                glFrontFace(glm::determinant(glm::dmat3(
                                plan.views[static_cast<std::size_t>(view.parent)].reflection)) < 0.0
                                ? GL_CW
                                : GL_CCW);
            passes::drawMirrorSurface(
                input, view,
                passes::viewSetup(input, plan, view.parent, projection, {target.width, target.height}),
                s.mirrorProgram, s.flatProgram, ctx, reflection, levels, {target.width, target.height});
            glFrontFace(GL_CCW);
            break;
        }
        case PassKind::Composite:
            glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
            glViewport(0, 0, target.width, target.height);
            resetState();
            glDisable(GL_DEPTH_TEST);
            s.compositeProgram.use();
            glActiveTexture(GL_TEXTURE0);
            glBindTexture(GL_TEXTURE_2D, s.linear.color());
            s.compositeProgram.set("uColor", 0);
            s.compositeProgram.set("uEncodeSrgb", target.encodeSrgb ? 1 : 0);
            glBindVertexArray(s.emptyVao.id());
            glDrawArrays(GL_TRIANGLES, 0, 3);
            break;
        }
        if (options.gpuTimings)
            s.timer.end();
        pass.cpuMs = msSince(passStart);
    }
    glBindVertexArray(0);
    glUseProgram(0);
    resetState();

    if (options.gpuTimings) {
        const std::vector<double> gpu = s.timer.collect(plan.passes.size());
        report.gpuMs = 0.0;
        for (std::size_t i = 0; i < gpu.size(); ++i) {
            plan.passes[i].gpuMs = ran[i] ? gpu[i] : -1.0;
            if (ran[i] && gpu[i] > 0)
                report.gpuMs += gpu[i];
        }
    }
    // Passes of hidden mirrors did not run: report them as skipped, with the reason.
    std::vector<PlannedPass> executed;
    for (std::size_t i = 0; i < plan.passes.size(); ++i) {
        if (ran[i]) {
            executed.push_back(std::move(plan.passes[i]));
        } else if (plan.passes[i].kind == PassKind::Mirror) {
            for (std::size_t v = 0; v < plan.views.size(); ++v)
                if (!hidden[v].empty() && descendsFrom(plan, plan.passes[i].view, static_cast<int>(v))) {
                    plan.skipped.push_back({plan.passes[i].target, "no reflection: " + hidden[v]});
                    break;
                }
        }
    }
    plan.passes = std::move(executed);

    report.memory.main = s.linear.bytes();
    for (int slot = 0; slot <= deepestSlot; ++slot)
        report.memory.mirrors += s.reflectionTextures[static_cast<std::size_t>(slot)].bytes();
    for (int lightIndex : plan.shadowedLights)
        report.memory.shadows += s.shadows.bytes(lightIndex);
    if (input.reflector)
        report.memory.envmap = s.reflector.mapBytes(*input.reflector);
    s.meshes.purge();
    s.reflector.purge();
    for (std::string& warning : s.meshes.takeWarnings())
        report.warnings.push_back(std::move(warning));
    for (std::string& warning : s.textures.takeWarnings())
        report.warnings.push_back(std::move(warning));
    report.occlusionWaits = s.occlusion.waits();
    report.cpuMs = msSince(frameStart);
    return report;
}

} // namespace speculum::render
