// `speculum time`: wall-clock frame times of a project drawn as the editor draws it (an 8-bit target like
// a window's, shadow and environment maps reused while nothing they show changes), each frame timed until
// its pixels can be read back, and the share of each pass kind.
#include "app/TimeCommand.hpp"

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

namespace speculum::app {

namespace {

using Clock = std::chrono::steady_clock;

// Frames drawn before timing starts: shaders compiled, buffers allocated, maps drawn once.
constexpr int kWarmUpFrames = 5;
// Frames drawn again with a timer query per pass, for the shares: queries make llvmpipe flush between
// passes, so the timed frames run without them.
constexpr int kProfiledFrames = 20;
constexpr double kFrameStep = 1.0 / 60.0; // --animated: seconds of scene time per frame

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
    WindowLikeTarget window;
    if (!window.create(options.width, options.height))
        return fail("this GPU cannot hold a " + std::to_string(options.width) + "x" +
                    std::to_string(options.height) + " colour buffer");
    const render::RenderTarget target{window.framebuffer.id(), options.width, options.height, true, true};

    // Frame k shows the scene at options.time + k/60 s when animated (a fresh snapshot each frame, as the
    // playing editor takes one), at options.time otherwise.
    std::vector<std::string> snapshotWarnings;
    int frameNumber = 0;
    auto frameInput = [&]() -> const render::FrameInput& {
        if (options.animated) {
            project->input = scene::snapshot(*project->scene, options.time + frameNumber * kFrameStep,
                                             *project->meshes, snapshotWarnings);
            snapshotWarnings.clear();
        }
        ++frameNumber;
        return project->input;
    };
    render::RenderOptions renderOptions;
    renderOptions.halfFloatCameraBuffer = options.halfFloat;
    renderOptions.gpuTimings = false;

    render::FrameReport last;
    auto drawOne = [&](bool profiled) -> std::optional<double> {
        const auto start = Clock::now();
        renderOptions.gpuTimings = profiled;
        last = (*renderer)->render(frameInput(), target, renderOptions);
        waitForPixels(window.framebuffer.id());
        if (!last.error.empty())
            return std::nullopt;
        return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    };
    for (int i = 0; i < kWarmUpFrames; ++i)
        if (!drawOne(false))
            return fail(last.error);
    std::vector<double> frameMs;
    frameMs.reserve(static_cast<std::size_t>(options.frames));
    for (int i = 0; i < options.frames; ++i) {
        const auto ms = drawOne(false);
        if (!ms)
            return fail(last.error);
        frameMs.push_back(*ms);
    }
    const render::CameraBuffer cameraBuffer = last.plan.cameraBuffer;
    std::string compositeReason;
    for (const render::PlannedPass& pass : last.plan.passes)
        if (pass.kind == render::PassKind::Composite)
            compositeReason = pass.reason;
    for (const render::SkippedEffect& skip : last.plan.skipped)
        if (last.plan.cameraBufferIsOutput && skip.target == "output")
            compositeReason = skip.reason;

    std::map<std::string, KindTime> kinds;
    const int profiled = std::min(options.frames, kProfiledFrames);
    double profiledGpu = 0.0;
    for (int i = 0; i < profiled; ++i) {
        if (!drawOne(true))
            return fail(last.error);
        for (const render::PassRun& run : last.ran) {
            KindTime& k = kinds[kindName(last.planned(run).kind)];
            k.gpuMs += std::max(run.gpuMs, 0.0) / profiled;
            k.cpuMs += run.cpuMs / profiled;
            ++k.runs;
        }
        profiledGpu += std::max(last.gpuMs, 0.0) / profiled;
    }
    printWarnings(last.warnings);

    const double median = percentile(frameMs, 0.5);
    const double fastest = *std::min_element(frameMs.begin(), frameMs.end());
    const double slowest = *std::max_element(frameMs.begin(), frameMs.end());
    const double mean = std::accumulate(frameMs.begin(), frameMs.end(), 0.0) / double(frameMs.size());
    const std::string size = std::to_string(options.width) + "x" + std::to_string(options.height);
    const std::string bufferName = cameraBuffer == render::CameraBuffer::Srgb8 ? "srgb8" : "half-float";
    if (options.json) {
        QJsonArray passes;
        for (const auto& [kind, k] : kinds)
            passes.append(QJsonObject{{"kind", QString::fromStdString(kind)},
                                      {"gpuMs", k.gpuMs},
                                      {"cpuMs", k.cpuMs},
                                      {"share", profiledGpu > 0.0 ? k.gpuMs / profiledGpu : 0.0},
                                      {"runsPerFrame", double(k.runs) / profiled}});
        QJsonArray times;
        for (double ms : frameMs)
            times.append(ms);
        const QJsonObject root{{"project", QString::fromStdString(options.project)},
                               {"size", QString::fromStdString(size)},
                               {"frames", options.frames},
                               {"warmUpFrames", kWarmUpFrames},
                               {"profiledFrames", profiled},
                               {"animated", options.animated},
                               {"medianMs", median},
                               {"minMs", fastest},
                               {"maxMs", slowest},
                               {"meanMs", mean},
                               {"fps", median > 0.0 ? 1000.0 / median : 0.0},
                               {"cameraBuffer", QString::fromStdString(bufferName)},
                               {"compositeReason", QString::fromStdString(compositeReason)},
                               {"drawnIntoOutput", last.plan.cameraBufferIsOutput},
                               {"gpuMsPerFrame", profiledGpu},
                               {"passes", passes},
                               {"frameMs", times},
                               {"renderer", QString::fromStdString((*context)->description())}};
        std::cout << QJsonDocument(root).toJson(QJsonDocument::Indented).toStdString();
        return 0;
    }
    std::printf("%s at %s, %s, %d frames after %d warm-up frames, on %s\n",
                std::filesystem::path(options.project).filename().string().c_str(), size.c_str(),
                options.animated ? "animated" : "static", options.frames, kWarmUpFrames,
                (*context)->description().c_str());
    std::printf("frame: median %.2f ms (%.1f fps), min %.2f ms, max %.2f ms\n", median,
                median > 0.0 ? 1000.0 / median : 0.0, fastest, slowest);
    std::printf("camera buffer: %s (%s)\n", bufferName.c_str(), compositeReason.c_str());
    std::printf("passes, per frame, over %d frames with a timer query per pass:\n", profiled);
    for (const auto& [kind, k] : kinds)
        std::printf("  %-15s gpu %7.2f ms %5.1f%%   cpu %7.2f ms   %.1f per frame\n", kind.c_str(), k.gpuMs,
                    profiledGpu > 0.0 ? 100.0 * k.gpuMs / profiledGpu : 0.0, k.cpuMs,
                    double(k.runs) / profiled);
    return 0;
}

} // namespace speculum::app
