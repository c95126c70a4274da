#include "render/Renderer.hpp"

#include "render/gl/GpuMesh.hpp"
#include "render/gl/GpuTimer.hpp"
#include "render/gl/Objects.hpp"
#include "render/gl/Program.hpp"
#include "render/gl/TextureCache.hpp"
#include "render/math/Projection.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/passes/MainPass.hpp"
#include "render/passes/ShadowMaps.hpp"
#include "render/plan/Planner.hpp"

#include <chrono>
#include <glm/gtc/matrix_transform.hpp>

namespace speculum::render {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// The linear (half-float) colour buffer every frame is drawn into before the composite pass, with a
// depth-stencil buffer for the main and (later) mirror passes.
struct LinearTarget {
    int width = 0;
    int height = 0;
    gl::Texture color;
    gl::Renderbuffer depthStencil;
    gl::Framebuffer framebuffer;

    void ensure(int w, int h) {
        if (framebuffer && w == width && h == height)
            return;
        width = w;
        height = h;
        color = gl::makeTexture();
        glBindTexture(GL_TEXTURE_2D, color.id());
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, w, h, 0, GL_RGBA, GL_FLOAT, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
        glBindTexture(GL_TEXTURE_2D, 0);
        depthStencil = gl::makeRenderbuffer();
        glBindRenderbuffer(GL_RENDERBUFFER, depthStencil.id());
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, w, h);
        glBindRenderbuffer(GL_RENDERBUFFER, 0);
        framebuffer = gl::makeFramebuffer();
        gl::FramebufferBinding keep;
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color.id(), 0);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                                  depthStencil.id());
    }
};

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
    gl::Program shadowProgram;
    gl::Program compositeProgram;
    gl::MeshCache meshes;
    gl::TextureCache textures;
    passes::ShadowMaps shadows;
    LinearTarget linear;
    gl::VertexArray emptyVao; // core profile needs a VAO bound even for attribute-less draws
    gl::Texture dummyShadow2D;
    gl::Texture dummyShadowCube;
    gl::GpuTimer timer;
    PlannerState plannerState;
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
    auto composite = gl::Program::build("fullscreen.vert", "composite.frag");
    if (!composite)
        return Error{composite.error()};
    s.meshProgram = std::move(*mesh);
    s.shadowProgram = std::move(*shadow);
    s.compositeProgram = std::move(*composite);
    s.emptyVao = gl::makeVertexArray();
    s.dummyShadow2D = makeDummyDepth(GL_TEXTURE_2D);
    s.dummyShadowCube = makeDummyDepth(GL_TEXTURE_CUBE_MAP);
    s.unitPlane = std::make_shared<const MeshData>(makePlane(1));
    return renderer;
}

void Renderer::releaseGlResources() {
    // Destroying the state deletes every GL object while the caller's context is current.
    m_state = std::make_unique<State>();
    m_state->released = true;
}

FrameReport Renderer::render(const FrameInput& input, const RenderTarget& target,
                             const RenderOptions& options) {
    const auto frameStart = Clock::now();
    State& s = *m_state;
    FrameReport report;
    if (s.released || target.width <= 0 || target.height <= 0)
        return report;
    report.plan = planFrame(input, s.plannerState);

    // A seamless cube map filters across face edges, so PCF near a face border reads the neighbouring
    // face instead of clamping (which would leak light or shadow along the seams).
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    s.linear.ensure(target.width, target.height);

    const double aspect = double(target.width) / double(target.height);
    glm::dmat4 projection = math::perspective(input.camera.fovY, aspect, input.camera.near, input.camera.far);
    projection =
        math::jitter(projection, options.jitterPixels.x, options.jitterPixels.y, target.width, target.height);
    const glm::dmat4 viewProjection = projection * math::viewRotation(input.camera);

    gl::FramebufferBinding keepCallerBinding;
    for (std::size_t i = 0; i < report.plan.passes.size(); ++i) {
        PlannedPass& pass = report.plan.passes[i];
        const auto passStart = Clock::now();
        if (options.gpuTimings)
            s.timer.begin(i);
        switch (pass.kind) {
        case PassKind::Shadow:
            s.shadows.render(input, pass.lightIndex, s.meshes, s.shadowProgram);
            s.plannerState.shadowSignatures[pass.lightIndex] = shadowSignature(input, pass.lightIndex);
            break;
        case PassKind::Main: {
            for (int lightIndex : report.plan.shadowedLights)
                s.shadows.setPcf(lightIndex, input.lights[static_cast<std::size_t>(lightIndex)].shadows.pcf);
            glBindFramebuffer(GL_FRAMEBUFFER, s.linear.framebuffer.id());
            glViewport(0, 0, target.width, target.height);
            glDisable(GL_SCISSOR_TEST);
            glDisable(GL_BLEND);
            glDisable(GL_CULL_FACE);
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_LESS);
            glDepthMask(GL_TRUE);
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            glStencilMask(0xFF);
            glClearColor(float(input.settings.background.r), float(input.settings.background.g),
                         float(input.settings.background.b), 1.0f);
            glClearStencil(0);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
            passes::MainPassContext ctx{s.meshProgram,
                                        s.meshes,
                                        s.textures,
                                        s.shadows,
                                        report.plan.shadowedLights,
                                        s.dummyShadow2D.id(),
                                        s.dummyShadowCube.id(),
                                        s.unitPlane};
            passes::drawMainPass(input, viewProjection, ctx);
            break;
        }
        case PassKind::Composite:
            glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
            glViewport(0, 0, target.width, target.height);
            glDisable(GL_DEPTH_TEST);
            glDisable(GL_BLEND);
            glDisable(GL_STENCIL_TEST);
            glDisable(GL_CULL_FACE);
            s.compositeProgram.use();
            glActiveTexture(GL_TEXTURE0);
            glBindTexture(GL_TEXTURE_2D, s.linear.color.id());
            s.compositeProgram.set("uColor", 0);
            s.compositeProgram.set("uEncodeSrgb", target.encodeSrgb ? 1 : 0);
            glBindVertexArray(s.emptyVao.id());
            glDrawArrays(GL_TRIANGLES, 0, 3);
            break;
        default:
            break;
        }
        if (options.gpuTimings)
            s.timer.end();
        pass.cpuMs = msSince(passStart);
    }
    glBindVertexArray(0);
    glUseProgram(0);

    if (options.gpuTimings) {
        const std::vector<double> gpu = s.timer.collect(report.plan.passes.size());
        report.gpuMs = 0.0;
        for (std::size_t i = 0; i < gpu.size(); ++i) {
            report.plan.passes[i].gpuMs = gpu[i];
            if (gpu[i] > 0)
                report.gpuMs += gpu[i];
        }
    }
    s.meshes.purge();
    report.warnings = s.textures.takeWarnings();
    report.cpuMs = msSince(frameStart);
    return report;
}

} // namespace speculum::render
