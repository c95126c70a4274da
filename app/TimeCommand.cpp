// `speculum time`: wall-clock frame times of a project drawn as the editor draws it (an 8-bit target like
// a window's, shadow and environment maps reused while nothing they show changes), each frame timed until
// its pixels can be read back, and the share of each pass kind.
#include "app/TimeCommand.hpp"

#include "app/Interrupt.hpp"
#include "app/ProjectInput.hpp"
#include "render/gl/HeadlessContext.hpp"
#include "render/gl/Objects.hpp"
#include "render/plan/FrameReport.hpp"
#include "render/plan/Planner.hpp"
#include "render/renderer/Renderer.hpp"
#include "scene/evaluate/Snapshot.hpp"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <numeric>
#include <optional>

namespace speculum::app {

namespace {

using Clock = std::chrono::steady_clock;

// Frames drawn before timing starts: shaders compiled, buffers allocated, maps drawn once.
constexpr int kWarmUpFrames = 5;
// Frames drawn again with a timer query per pass, for the shares: queries make llvmpipe flush between
// passes, so the timed frames run without them.
constexpr int kProfiledFrames = 20;

struct KindTime {
    double gpuMs = 0.0;
    double cpuMs = 0.0;
    int runs = 0;
};

// An 8-bit colour target of the given size, as the editor's viewport has: an sRGB colour texture with a
// depth-stencil buffer (Viewport), which the renderer draws straight into when it can.
struct WindowLikeTarget {
    render::gl::Texture color = render::gl::makeTexture();
    render::gl::Renderbuffer depthStencil = render::gl::makeRenderbuffer();
    render::gl::Framebuffer framebuffer = render::gl::makeFramebuffer();

    bool create(int width, int height) {
        glBindTexture(GL_TEXTURE_2D, color.id());
        glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        glBindTexture(GL_TEXTURE_2D, 0);
        glBindRenderbuffer(GL_RENDERBUFFER, depthStencil.id());
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
        glBindRenderbuffer(GL_RENDERBUFFER, 0);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color.id(), 0);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                                  depthStencil.id());
        return glGetError() == GL_NO_ERROR &&
               glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    }
};

// The pixels are there once one of them can be read: the read waits for every pass of the frame.
void waitForPixels(GLuint framebuffer) {
    unsigned char pixel[4];
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
}

double percentile(std::vector<double> sorted, double q) {
    std::sort(sorted.begin(), sorted.end());
    const double at = q * double(sorted.size() - 1);
    const auto low = static_cast<std::size_t>(at);
    const std::size_t high = std::min(low + 1, sorted.size() - 1);
    return sorted[low] + (sorted[high] - sorted[low]) * (at - double(low));
}

std::string kindName(render::PassKind kind) {
    return std::string(render::toString(kind));
}

// Draws the project's frames one after another into the window-like target, each timed until its pixels
// can be read back. Frame k shows the scene at options.time + k/60 s when animated (a fresh snapshot each
// frame, as the playing editor takes one), at options.time otherwise.
class FrameDrawer {
public:
    FrameDrawer(const CliOptions& options, ProjectFrame& project, render::Renderer& renderer,
                const render::RenderTarget& target)
        : m_options(options)
        , m_project(project)
        , m_renderer(renderer)
        , m_target(target) {
        m_renderOptions.halfFloatCameraBuffer = options.halfFloat;
        m_renderOptions.gpuTimings = false;
    }

    // The next frame, with a timer query per pass when `profiled`: its wall time in milliseconds, or
    // nothing when the renderer failed (last().error).
    std::optional<double> draw(bool profiled) {
        const auto start = Clock::now();
        m_renderOptions.gpuTimings = profiled;
        m_last = m_renderer.render(nextInput(), m_target, m_renderOptions);
        waitForPixels(m_target.framebuffer);
        if (!m_last.error.empty())
            return std::nullopt;
        return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    }
    const render::FrameReport& last() const { return m_last; }

private:
    const render::FrameInput& nextInput() {
        if (m_options.animated) {
            m_project.input =
                scene::snapshot(*m_project.scene, m_options.time + m_frameNumber * kAnimationFrameStep,
                                *m_project.meshes, m_snapshotWarnings);
            useCheckedTextures(m_project.input, m_project.textures);
            m_snapshotWarnings.clear();
        }
        ++m_frameNumber;
        return m_project.input;
    }

    const CliOptions& m_options;
    ProjectFrame& m_project;
    render::Renderer& m_renderer;
    const render::RenderTarget m_target;
    render::RenderOptions m_renderOptions;
    std::vector<scene::Warning> m_snapshotWarnings;
    int m_frameNumber = 0;
    render::FrameReport m_last;
};

// The warm-up frames, then options.frames timed ones: their wall times in milliseconds.
base::Result<std::vector<double>> timeFrames(FrameDrawer& drawer, int frames) {
    for (int i = 0; i < kWarmUpFrames && !StopOnSignal::requested(); ++i)
        if (!drawer.draw(false))
            return base::Error{drawer.last().error};
    std::vector<double> frameMs;
    frameMs.reserve(static_cast<std::size_t>(frames));
    for (int i = 0; i < frames && !StopOnSignal::requested(); ++i) {
        const auto ms = drawer.draw(false);
        if (!ms)
            return base::Error{drawer.last().error};
        frameMs.push_back(*ms);
    }
    return frameMs;
}

// Why the frame has the camera buffer it has: the composite pass's reason, or, when the frame was drawn
// straight into the output, the reason the composite was skipped.
std::string compositeReasonOf(const render::FrameReport& report) {
    std::string compositeReason;
    for (const render::PlannedPass& pass : report.plan.passes)
        if (pass.kind == render::PassKind::Composite)
            compositeReason = pass.reason();
    for (const render::SkippedEffect& skip : report.plan.skipped)
        if (report.plan.cameraBufferIsOutput && skip.target == "output")
            compositeReason = skip.reason();
    return compositeReason;
}

// The share of each pass kind: per frame, averaged over the profiled frames.
struct PassProfile {
    int frames = 0;
    std::map<std::string, KindTime> kinds;
    double gpuMs = 0.0; // the whole frame's GPU time
};

base::Result<PassProfile> profilePasses(FrameDrawer& drawer, int frames) {
    PassProfile profile;
    profile.frames = frames;
    for (int i = 0; i < frames && !StopOnSignal::requested(); ++i) {
        if (!drawer.draw(true))
            return base::Error{drawer.last().error};
        const render::FrameReport& last = drawer.last();
        for (const render::PassRun& run : last.ran) {
            KindTime& k = profile.kinds[kindName(last.planned(run).kind)];
            k.gpuMs += std::max(run.gpuMs, 0.0) / frames;
            k.cpuMs += run.cpuMs / frames;
            ++k.runs;
        }
        profile.gpuMs += std::max(last.gpuMs, 0.0) / frames;
    }
    return profile;
}

// Everything `speculum time` prints.
struct TimeFigures {
    std::vector<double> frameMs;
    double median = 0.0;
    double fastest = 0.0;
    double slowest = 0.0;
    double mean = 0.0;
    std::string bufferName; // the camera buffer: "srgb8" or "half-float"
    std::string compositeReason;
    bool drawnIntoOutput = false;
    PassProfile profile;
    std::string renderer; // the GL context's description
};

std::string sizeText(const CliOptions& options) {
    return std::to_string(options.width) + "x" + std::to_string(options.height);
}

void printTimeJson(const CliOptions& options, const TimeFigures& f) {
    const PassProfile& profile = f.profile;
    QJsonArray passes;
    for (const auto& [kind, k] : profile.kinds)
        passes.append(QJsonObject{{"kind", QString::fromStdString(kind)},
                                  {"gpuMs", k.gpuMs},
                                  {"cpuMs", k.cpuMs},
                                  {"share", profile.gpuMs > 0.0 ? k.gpuMs / profile.gpuMs : 0.0},
                                  {"runsPerFrame", double(k.runs) / profile.frames}});
    QJsonArray times;
    for (double ms : f.frameMs)
        times.append(ms);
    const QJsonObject root{{"project", QString::fromStdString(options.project)},
                           {"size", QString::fromStdString(sizeText(options))},
                           {"frames", options.frames},
                           {"warmUpFrames", kWarmUpFrames},
                           {"profiledFrames", profile.frames},
                           {"animated", options.animated},
                           {"medianMs", f.median},
                           {"minMs", f.fastest},
                           {"maxMs", f.slowest},
                           {"meanMs", f.mean},
                           {"fps", f.median > 0.0 ? 1000.0 / f.median : 0.0},
                           {"cameraBuffer", QString::fromStdString(f.bufferName)},
                           {"compositeReason", QString::fromStdString(f.compositeReason)},
                           {"drawnIntoOutput", f.drawnIntoOutput},
                           {"gpuMsPerFrame", profile.gpuMs},
                           {"passes", passes},
                           {"frameMs", times},
                           {"renderer", QString::fromStdString(f.renderer)}};
    std::cout << QJsonDocument(root).toJson(QJsonDocument::Indented).toStdString();
}

void printTimeText(const CliOptions& options, const TimeFigures& f) {
    const PassProfile& profile = f.profile;
    std::printf("%s at %s, %s, %d frames after %d warm-up frames, on %s\n",
                std::filesystem::path(options.project).filename().string().c_str(), sizeText(options).c_str(),
                options.animated ? "animated" : "static", options.frames, kWarmUpFrames, f.renderer.c_str());
    std::printf("frame: median %.2f ms (%.1f fps), min %.2f ms, max %.2f ms\n", f.median,
                f.median > 0.0 ? 1000.0 / f.median : 0.0, f.fastest, f.slowest);
    std::printf("camera buffer: %s (%s)\n", f.bufferName.c_str(), f.compositeReason.c_str());
    std::printf("passes, per frame, over %d frames with a timer query per pass:\n", profile.frames);
    for (const auto& [kind, k] : profile.kinds)
        std::printf("  %-15s gpu %7.2f ms %5.1f%%   cpu %7.2f ms   %.1f per frame\n", kind.c_str(), k.gpuMs,
                    profile.gpuMs > 0.0 ? 100.0 * k.gpuMs / profile.gpuMs : 0.0, k.cpuMs,
                    double(k.runs) / profile.frames);
}

} // namespace

int runTime(const CliOptions& options) {
    auto fail = [](const std::string& message) {
        printError("time: " + message);
        return 1;
    };
    auto project = loadProjectFrame(options.project, options.time,
                                    options.keepGoing ? MissingFiles::KeepGoing : MissingFiles::Fail);
    if (!project)
        return fail(project.error());
    auto context = render::gl::HeadlessContext::create();
    if (!context)
        return fail("no OpenGL: " + context.error());
    auto renderer = render::Renderer::create();
    if (!renderer)
        return fail(renderer.error());
    warnAsPlanned(**renderer);
    WindowLikeTarget window;
    if (!window.create(options.width, options.height))
        return fail("this GPU cannot hold a " + std::to_string(options.width) + "x" +
                    std::to_string(options.height) + " colour buffer");
    const render::RenderTarget target{window.framebuffer.id(), options.width, options.height, true, true};
    FrameDrawer drawer(options, *project, **renderer, target);

    TimeFigures figures;
    auto frameMs = timeFrames(drawer, options.frames);
    if (StopOnSignal::requested())
        return interrupted("time", "nothing was printed");
    if (!frameMs)
        return fail(frameMs.error());
    figures.frameMs = std::move(*frameMs);
    // Of the last timed frame: the profiled ones below draw with timer queries.
    const render::CameraBuffer cameraBuffer = drawer.last().plan.cameraBuffer;
    figures.compositeReason = compositeReasonOf(drawer.last());
    auto profile = profilePasses(drawer, std::min(options.frames, kProfiledFrames));
    if (StopOnSignal::requested())
        return interrupted("time", "nothing was printed");
    if (!profile)
        return fail(profile.error());
    figures.profile = std::move(*profile);
    printWarnings(drawer.last().warnings);

    const std::vector<double>& ms = figures.frameMs;
    figures.median = percentile(ms, 0.5);
    figures.fastest = *std::min_element(ms.begin(), ms.end());
    figures.slowest = *std::max_element(ms.begin(), ms.end());
    figures.mean = std::accumulate(ms.begin(), ms.end(), 0.0) / double(ms.size());
    figures.bufferName = cameraBuffer == render::CameraBuffer::Srgb8 ? "srgb8" : "half-float";
    figures.drawnIntoOutput = drawer.last().plan.cameraBufferIsOutput;
    figures.renderer = (*context)->description();
    if (options.json)
        printTimeJson(options, figures);
    else
        printTimeText(options, figures);
    return 0;
}

} // namespace speculum::app
