#include "render/renderer/Renderer.hpp"

#include "render/gl/GpuTimer.hpp"
#include "render/gl/Objects.hpp"
#include "render/math/GgxAlbedoTable.hpp"
#include "render/math/Projection.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/mesh/Simplify.hpp"
#include "render/passes/LightingVariant.hpp"
#include "render/passes/PassExecutors.hpp"
#include "render/plan/Planner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

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

// The GGX albedo table (math::ggxAlbedoTable) as a float texture the glossy shaders read bilinearly.
gl::Texture makeGgxAlbedoTexture() {
    const math::GgxAlbedoTable& table = math::ggxAlbedoTable();
    constexpr int size = math::GgxAlbedoTable::kSize;
    gl::Texture t = gl::makeTexture();
    glBindTexture(GL_TEXTURE_2D, t.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, size, size, 0, GL_RED, GL_FLOAT, table.values.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glBindTexture(GL_TEXTURE_2D, 0);
    return t;
}

} // namespace

struct Renderer::State {
    passes::FrameResources resources;
    gl::GpuTimer timer;
    PlannerState plannerState;
    GpuLimits limits;
    CoarseLevelRequest coarseLevelRequest;
    PlanObserver planObserver;
    bool released = false;
};

Renderer::Renderer()
    : m_state(std::make_unique<State>()) {}

Renderer::~Renderer() = default;

base::Result<std::unique_ptr<Renderer>> Renderer::create() {
    std::unique_ptr<Renderer> renderer(new Renderer);
    State& state = *renderer->m_state;
    passes::FrameResources& s = state.resources;
    auto mesh = gl::Program::build("mesh.vert", "mesh.frag");
    if (!mesh)
        return base::Error{mesh.error()};
    auto shadow = gl::Program::build("shadow.vert", "shadow.frag");
    if (!shadow)
        return base::Error{shadow.error()};
    auto flat = gl::Program::build("shadow.vert", "flat.frag");
    if (!flat)
        return base::Error{flat.error()};
    auto mirror = gl::Program::build("mesh.vert", "mirror.frag");
    if (!mirror)
        return base::Error{mirror.error()};
    auto composite = gl::Program::build("fullscreen.vert", "composite.frag");
    if (!composite)
        return base::Error{composite.error()};
    auto convolve = gl::Program::build("fullscreen.vert", "mip_convolve.frag");
    if (!convolve)
        return base::Error{convolve.error()};
    s.meshProgram = std::move(*mesh);
    s.shadowProgram = std::move(*shadow);
    s.mirrorProgram = std::move(*mirror);
    s.flatProgram = std::move(*flat);
    s.compositeProgram = std::move(*composite);
    s.mipConvolveProgram = std::move(*convolve);
    for (auto [program, vertex, fragment] :
         {std::tuple{&s.screenDepthProgram, "screen_depth.vert", "screen_depth.frag"},
          std::tuple{&s.depthMinProgram, "fullscreen.vert", "depth_min.frag"},
          std::tuple{&s.screenTraceProgram, "screen_trace.vert", "screen_trace.frag"},
          std::tuple{&s.reflectorTraceProgram, "reflector_trace.vert", "reflector_trace.frag"}}) {
        auto built = gl::Program::build(vertex, fragment);
        if (!built)
            return base::Error{built.error()};
        *program = std::move(*built);
    }
    s.convolveFramebuffer = gl::makeFramebuffer();
    s.emptyVao = gl::makeVertexArray();
    s.dummyShadow2D = makeDummyDepth(GL_TEXTURE_2D);
    s.dummyShadowCube = makeDummyDepth(GL_TEXTURE_CUBE_MAP);
    s.ggxAlbedo = makeGgxAlbedoTexture();
    s.unitPlane = std::make_shared<const MeshData>(makePlane(1));
    state.limits = queryGpuLimits();
    if (base::Status reflector = s.reflector.init(); !reflector)
        return base::Error{reflector.error()};
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

void Renderer::setCoarseLevelRequest(CoarseLevelRequest request) {
    m_state->coarseLevelRequest = std::move(request);
}

void Renderer::setPlanObserver(PlanObserver observer) {
    m_state->planObserver = std::move(observer);
}

void Renderer::lowerGpuLimits(const GpuLimits& limits) {
    GpuLimits& l = m_state->limits;
    l.maxTextureSize = std::min(l.maxTextureSize, limits.maxTextureSize);
    l.maxCubeMapSize = std::min(l.maxCubeMapSize, limits.maxCubeMapSize);
    l.maxRenderbufferSize = std::min(l.maxRenderbufferSize, limits.maxRenderbufferSize);
    l.maxViewportSize = std::min(l.maxViewportSize, limits.maxViewportSize);
}

namespace {

// What allocating the frame's maps found.
struct AllocatedMaps {
    std::vector<int> shadowsMissing; // lights whose planned map could not be allocated: no shadow this frame
    std::vector<bool> envmapAllocated; // per reflector; false: its Envmap passes do not run
    bool fellBack = false;             // a planned size failed: the next frame plans the one that works
};

// Allocates the maps the plan sizes: each planned shadow map, and each reflector's map where the frame
// captures it. The plan is below every size that failed before; a size that fails now (one never tried)
// leaves its map out of this frame, with a warning, and is remembered, so the next frame is planned with a
// size that works. The plan is never made again for this frame.
AllocatedMaps allocateMaps(const FrameInput& input, const FramePlan& plan, passes::FrameResources& r,
                           std::vector<std::string>& warnings) {
    AllocatedMaps allocated;
    auto note = [&](gl::PlannedAllocation outcome) {
        allocated.fellBack = allocated.fellBack || outcome == gl::PlannedAllocation::FellBack;
        return outcome == gl::PlannedAllocation::Done;
    };
    for (const ShadowPlan& shadow : plan.shadows)
        if (!note(r.shadows.allocate(input, shadow, warnings)))
            allocated.shadowsMissing.push_back(shadow.light);
    allocated.envmapAllocated.assign(input.reflectors.size(), true);
    r.reflector.keepMaps(input.reflectors.size());
    std::vector<bool> tried(input.reflectors.size(), false);
    for (const EnvmapPlan& map : plan.envmaps) { // each reflector once, whatever its bounces
        const auto i = static_cast<std::size_t>(map.reflector);
        if (tried[i])
            continue;
        tried[i] = true;
        allocated.envmapAllocated[i] =
            note(r.reflector.allocate(map.reflector, input.reflectors[i], warnings));
    }
    return allocated;
}

// What the planner plans the frame's maps within: the context's limits and every size the passes found
// failing in earlier frames.
MapLimits mapLimits(const GpuLimits& gpu, const passes::FrameResources& r) {
    MapLimits limits{gpu, {}};
    r.shadows.failedSizes(limits.failed);
    r.reflector.failedSizes(limits.failed);
    return limits;
}

// The lit shaders, built for this frame's lights. A variant that fails to build leaves the shaders that
// read the lights from uniforms: the same image, slower.
void selectLighting(passes::FrameResources& r, const FrameInput& input, const FramePlan& plan,
                    const RenderOptions& options, std::vector<std::string>& warnings) {
    const bool variants = options.lightingVariants;
    const std::string lighting = variants ? passes::lightingVariant(input, plan.shadowedLights) : "";
    base::Status selected = r.meshProgram.select(lighting, variants);
    if (selected)
        selected = r.mirrorProgram.select(lighting, variants);
    if (selected && !input.reflectors.empty()) // the reflector's programs build variants only when needed
        selected = r.reflector.selectLighting(lighting, variants);
    if (!selected) {
        warnings.push_back(
            "lit shaders for this frame's lights did not build; drawn with the general ones: " +
            selected.error());
        (void)r.meshProgram.select({}, variants);
        (void)r.mirrorProgram.select({}, variants);
        (void)r.reflector.selectLighting({}, variants);
    }
}

// The target the passes draw at: the caller's, or a fraction of its size for a preview (scaled up by the
// composite). A tile is a part of an exact image: always drawn whole.
RenderTarget drawnTarget(const RenderTarget& target, const RenderOptions& options) {
    const double scale = std::min(options.resolutionScale, options.preview.scale);
    if (options.tile || !(scale < 1.0)) { // NaN draws every pixel too
        return target;
    }
    const double clamped = std::max(scale, kMinResolutionScale);
    RenderTarget drawn = target;
    drawn.width = std::max(1, static_cast<int>(std::lround(target.width * clamped)));
    drawn.height = std::max(1, static_cast<int>(std::lround(target.height * clamped)));
    return drawn;
}

// Why a view draws nothing: the skip of the first view found hidden that it is, or lies inside; null if
// it draws (and for passes of no view).
const SkippedEffect* hiddenReason(const passes::FrameExecution& frame, int view) {
    if (view < 0)
        return nullptr;
    for (std::size_t v = 0; v < frame.hidden.size(); ++v) {
        if (!frame.hidden[v])
            continue;
        for (int u = view; u >= 0; u = frame.plan.views[static_cast<std::size_t>(u)].parent)
            if (u == static_cast<int>(v))
                return &*frame.hidden[v];
    }
    return nullptr;
}

// The frame as it will be drawn (its plan is the report's): the scene with the sizes the plan chose, the
// camera's projection, and what allocating its maps found.
struct DrawnFrame {
    std::optional<FrameInput> planned; // empty: the scene as requested
    glm::dmat4 projection{1.0};        // restricted to the tile for a tile
    AllocatedMaps maps;
};

// Planning, once, into report.plan and report.skipped, with the map sizes fitted to the GPU (the plan's
// warnings open the report's), then the maps' allocation.
DrawnFrame planDrawnFrame(const FrameInput& requested, const RenderTarget& target, const RenderTarget& drawn,
                          const RenderOptions& options, const GpuLimits& limits,
                          const PlannerState& committed,
                          const Renderer::CoarseLevelRequest& coarseLevelRequest,
                          const Renderer::PlanObserver& planObserver, passes::FrameResources& r,
                          FrameReport& report) {
    DrawnFrame frame;
    // A tile is planned as the whole image, then restricted to its pixels: it draws them exactly as an
    // untiled frame would, with the same sub-pixel sample positions. It is part of an exact still: never a
    // preview.
    const bool eightBitOutput = target.encodeSrgb && !options.halfFloatCameraBuffer;
    const bool drawnWhole = !options.tile && drawn.width == target.width && drawn.height == target.height;
    const PlanViewport viewport{options.tile ? options.tile->imageWidth : drawn.width,
                                options.tile ? options.tile->imageHeight : drawn.height, options.jitterPixels,
                                eightBitOutput, eightBitOutput && drawnWhole && target.srgbDepthStencil};
    const PlannerState freshState;
    const PlannerState& plannerState = options.reuseMaps ? committed : freshState;
    const PlanOptions planOptions{mapLimits(limits, r), options.tile ? PreviewPolicy{} : options.preview,
                                  options.tile ? 0 : options.guides.size(),
                                  options.maxMapSeconds * (limits.software ? 1.0 : kGpuOverSoftware)};
    FramePlan& plan = report.plan;
    plan = planFrame(requested, plannerState, viewport, planOptions);
    if (!plan.coarseLevelsWanted.empty() && coarseLevelRequest) {
        coarseLevelRequest(plan.coarseLevelsWanted);
    } else if (!plan.coarseLevelsWanted.empty()) {
        for (const MeshHandle& mesh : plan.coarseLevelsWanted)
            coarseLevel(*mesh);
        plan = planFrame(requested, plannerState, viewport, planOptions);
    }
    report.warnings = plan.warnings;
    if (planObserver)
        planObserver(plan);
    frame.planned = plannedInput(requested, plan);
    const FrameInput& input = frame.planned ? *frame.planned : requested;
    frame.maps = allocateMaps(input, plan, r, report.warnings);
    report.drawAgain = frame.maps.fellBack;
    frame.projection = cameraProjection(input, viewport);
    if (options.tile) {
        const math::PixelRect tile{options.tile->x, options.tile->y, options.tile->x + target.width,
                                   options.tile->y + target.height};
        restrictToTile(plan, tile, viewport);
        frame.projection = math::tileProjection(frame.projection, tile.x0, tile.y0, target.width,
                                                target.height, viewport.width, viewport.height);
    }
    report.skipped = plan.skipped;
    return frame;
}

// The camera's colour buffer, at the drawn size. Drawn straight into the output, the frame needs no buffer
// of its own.
base::Status ensureCameraBuffer(passes::FrameResources& r, const FramePlan& plan, const RenderTarget& drawn) {
    if (plan.cameraBufferIsOutput)
        return base::Status{base::Done{}};
    const bool srgbBuffer = plan.cameraBuffer == CameraBuffer::Srgb8;
    return r.linear.ensure(drawn.width, drawn.height, srgbBuffer ? GL_SRGB8_ALPHA8 : GL_RGBA16F, false);
}

// What the main pass of every view draws with: the renderer's programs, caches and maps.
passes::MainPassContext mainPassContext(passes::FrameResources& r, const FramePlan& plan,
                                        const RenderOptions& options) {
    passes::MainPassContext context{
        r.meshProgram,          r.meshes,   r.textures, r.shadows, plan.shadows, r.dummyShadow2D.id(),
        r.dummyShadowCube.id(), r.unitPlane};
    context.depthOnlyProgram = &r.flatProgram;
    context.coarseItems = plan.coarseItems;
    r.meshFacts.purge();
    context.meshFacts = options.cullHiddenBackFaces ? &r.meshFacts : nullptr;
    // Every view the main pass draws (the camera's and each mirror's) draws the reflectors with their maps.
    context.drawReflector = [&r](const FrameInput& in, int index, const passes::ViewSetup& view,
                                 passes::MainPassContext& c) {
        return r.reflector.drawSurface(in, index, view, c);
    };
    return context;
}

// A reflection texture for each texture slot the mirror views use; returns the deepest slot (-1: none).
int ensureReflectionTextures(passes::FrameResources& r, const FramePlan& plan) {
    int deepestSlot = -1;
    for (const MirrorView& v : plan.views)
        deepestSlot = std::max(deepestSlot, v.textureSlot);
    if (static_cast<int>(r.reflectionTextures.size()) <= deepestSlot)
        r.reflectionTextures.resize(static_cast<std::size_t>(deepestSlot + 1));
    return deepestSlot;
}

// Execution: the plan as it is, pass by pass, each one that ran reported with its CPU time (and timed on
// the GPU when asked); then the GL state is left as the caller expects it.
void runPasses(passes::FrameExecution& frame, bool srgbBuffer, const RenderOptions& options,
               gl::GpuTimer& timer, FrameReport& report) {
    const FramePlan& plan = frame.plan;
    // Only sRGB attachments are affected: the camera's buffer when it is one. Maps, reflection textures and
    // float outputs store what the shaders write.
    (srgbBuffer ? glEnable : glDisable)(GL_FRAMEBUFFER_SRGB);
    glActiveTexture(GL_TEXTURE0 + passes::kGgxAlbedoUnit);
    glBindTexture(GL_TEXTURE_2D, frame.resources.ggxAlbedo.id());
    glActiveTexture(GL_TEXTURE0);
    for (std::size_t i = 0; i < plan.passes.size(); ++i) {
        const PlannedPass& pass = plan.passes[i];
        // A view inside a mirror found hidden runs nothing; its reflection is reported skipped.
        if (const SkippedEffect* why = hiddenReason(frame, pass.view)) {
            if (pass.kind == PassKind::Mirror)
                frame.skipped.push_back({pass.target, why->code, why->details});
            continue;
        }
        const auto passStart = Clock::now();
        if (options.gpuTimings)
            timer.begin(i);
        passes::PassResult result = passes::runPass(pass, frame);
        if (options.gpuTimings)
            timer.end();
        if (!result.ran)
            continue;
        report.ran.push_back({static_cast<int>(i), std::move(result.outcome), -1.0, msSince(passStart)});
        if (options.probePixel) {
            report.probes.push_back(passes::probePixel(pass.writes, frame, *options.probePixel));
            report.probes.back().run = int(report.ran.size()) - 1;
        }
    }
    glBindVertexArray(0);
    glUseProgram(0);
    passes::resetPassState();
    glDisable(GL_FRAMEBUFFER_SRGB); // the caller's drawing after ours (the editor's overlays) is not ours
}

// Each pass's GPU time, and the frame's: the sum of those measured.
void collectGpuTimes(gl::GpuTimer& timer, const FramePlan& plan, FrameReport& report) {
    const std::vector<double> gpu = timer.collect(plan.passes.size());
    report.gpuMs = 0.0;
    for (PassRun& run : report.ran) {
        const auto i = static_cast<std::size_t>(run.pass);
        run.gpuMs = i < gpu.size() ? gpu[i] : -1.0;
        if (run.gpuMs > 0)
            report.gpuMs += run.gpuMs;
    }
}

// The rest of the report: what execution found it could not draw, the memory the frame's buffers and maps
// hold, and the caches' warnings, once the caches have dropped what the frame no longer uses.
void finishReport(passes::FrameResources& r, passes::FrameExecution& frame, int deepestSlot,
                  FrameReport& report) {
    const FramePlan& plan = frame.plan;
    for (SkippedEffect& skip : frame.skipped)
        report.skipped.push_back(std::move(skip));
    report.memory.main = plan.cameraBufferIsOutput ? 0 : r.linear.bytes();
    for (int slot = 0; slot <= deepestSlot; ++slot)
        report.memory.mirrors += r.reflectionTextures[static_cast<std::size_t>(slot)].bytes();
    for (int lightIndex : plan.shadowedLights)
        report.memory.shadows += r.shadows.bytes(lightIndex);
    for (std::size_t i = 0; i < frame.input.reflectors.size(); ++i)
        report.memory.envmap += r.reflector.mapBytes(static_cast<int>(i), frame.input.reflectors[i]);
    r.meshes.purge();
    r.reflector.purge();
    for (std::string& warning : r.meshes.takeWarnings())
        report.warnings.push_back(std::move(warning));
    for (std::string& warning : r.textures.takeWarnings())
        report.warnings.push_back(std::move(warning));
    report.occlusionWaits = r.occlusion.waits();
}

// Forgets in the planner state the maps that could not be made at the planned size: their signatures,
// their faces and their GGX chains.
void forgetEnvmaps(PlannerState& state, const std::vector<bool>& allocated) {
    for (std::size_t i = 0; i < allocated.size(); ++i)
        if (!allocated[i] && i < state.reflectorMaps.size())
            state.reflectorMaps[i] = ReflectorMapState{};
}

// Map updates recorded so far, all reflectors together.
std::uint64_t mapUpdates(const PlannerState& state) {
    std::uint64_t updates = 0;
    for (const ReflectorMapState& map : state.reflectorMaps)
        updates += map.updates;
    return updates;
}

// Whether the frame's time-sliced map update (if any) left faces showing an older scene.
bool timeSliceLeftFacesBehind(const FramePlan& plan) {
    return std::any_of(plan.passes.begin(), plan.passes.end(), [](const PlannedPass& pass) {
        return pass.code == PlanReason::EnvmapTimeSliced && pass.details.staleFaces > 0;
    });
}

} // namespace

FrameReport Renderer::render(const FrameInput& requested, const RenderTarget& target,
                             const RenderOptions& options) {
    const auto frameStart = Clock::now();
    State& s = *m_state;
    passes::FrameResources& r = s.resources;
    FrameReport report;
    if (s.released || target.width <= 0 || target.height <= 0)
        return report;

    // Every pass but the composite draws at `drawn` (the target's size, or less for a preview); the
    // composite writes the target.
    const RenderTarget drawn = drawnTarget(target, options);
    report.drawnWidth = drawn.width;
    report.drawnHeight = drawn.height;

    const DrawnFrame planned = planDrawnFrame(requested, target, drawn, options, s.limits, s.plannerState,
                                              s.coarseLevelRequest, s.planObserver, r, report);
    const FramePlan& plan = report.plan;
    const FrameInput& input = planned.planned ? *planned.planned : requested;
    // A reflector's map could not be made at the planned size: whatever the planner state says it holds is
    // gone, so the next frame draws a new map whole. The state keeps no reflector the scene has no more.
    forgetEnvmaps(s.plannerState, planned.maps.envmapAllocated);
    if (s.plannerState.reflectorMaps.size() > input.reflectors.size())
        s.plannerState.reflectorMaps.resize(input.reflectors.size());
    const std::uint64_t mapUpdatesBefore = mapUpdates(s.plannerState);

    selectLighting(r, input, plan, options, report.warnings);
    // A seamless cube map filters across face edges, so PCF near a face border reads the neighbouring
    // face instead of clamping (which would leak light or shadow along the seams).
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    if (base::Status linear = ensureCameraBuffer(r, plan, drawn); !linear) {
        // Without its colour buffer the frame cannot be drawn at all: say so instead of an empty image.
        report.error = "the frame could not be drawn: " + linear.error();
        report.warnings.push_back(report.error);
        report.cpuMs = msSince(frameStart);
        return report;
    }
    r.shadows.boundLookups(options.boundShadowLookups);
    passes::MainPassContext context = mainPassContext(r, plan, options);
    r.occlusion.beginFrame(plan);
    const int deepestSlot = ensureReflectionTextures(r, plan);

    passes::FrameExecution frame{input, plan,    drawn,          planned.projection, options.tile.has_value(),
                                 r,     context, s.plannerState, report.warnings};
    frame.output = &target;
    frame.guides = &options.guides;
    frame.envmapAllocated = planned.maps.envmapAllocated;
    frame.shadowsMissing = planned.maps.shadowsMissing;
    frame.hidden.resize(plan.views.size());
    frame.countScreenSpace = options.countScreenSpace;
    frame.showScreenSpaceSources = options.showScreenSpaceSources;
    gl::FramebufferBinding keepCallerBinding;
    r.reflector.beginFrame();
    runPasses(frame, plan.cameraBuffer == CameraBuffer::Srgb8, options, s.timer, report);
    r.reflector.endFrame();
    report.mapSettling = mapUpdates(s.plannerState) != mapUpdatesBefore && timeSliceLeftFacesBehind(plan);

    // The report: what ran, what it cost, and what execution found it could not draw.
    if (options.gpuTimings)
        collectGpuTimes(s.timer, plan, report);
    finishReport(r, frame, deepestSlot, report);
    report.cpuMs = msSince(frameStart);
    return report;
}

bool composeSrgbTextureAsStored(unsigned framebuffer) {
    gl::FramebufferBinding keep;
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    GLint type = GL_NONE;
    GLint name = 0;
    GLint encoding = GL_LINEAR;
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                          GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    if (type != GL_TEXTURE)
        return false;
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                          GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                          GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING, &encoding);
    if (encoding != GL_SRGB || name == 0)
        return false;
    GLint bound = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(name));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SRGB_DECODE_EXT, GL_SKIP_DECODE_EXT);
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(bound));
    return glGetError() == GL_NO_ERROR;
}

} // namespace speculum::render
