// Frame time of the demo scenes at 1280×720 on whatever GL the machine has (llvmpipe in CI), and the
// share of it each pass takes. Run: build/release/benchmarks/speculum_benchmarks
#include "render/gl/HeadlessContext.hpp"
#include "render/gl/Objects.hpp"
#include "render/renderer/Renderer.hpp"
#include "scene/evaluate/Snapshot.hpp"
#include "scene/project/ProjectFile.hpp"

#include <benchmark/benchmark.h>
#include <map>
#include <memory>

namespace {

using namespace speculum;

struct Fixture {
    std::unique_ptr<render::gl::HeadlessContext> context;
    std::unique_ptr<render::Renderer> renderer;
    speculum::scene::Scene scene;
    speculum::scene::MeshLibrary meshes;
    render::gl::Texture color;
    render::gl::Framebuffer framebuffer;
};

Fixture* fixture(int width, int height) {
    static std::unique_ptr<Fixture> f;
    if (!f) {
        f = std::make_unique<Fixture>();
        auto context = render::gl::HeadlessContext::create();
        if (!context)
            return nullptr;
        f->context = std::move(*context);
        auto renderer = render::Renderer::create();
        if (!renderer)
            return nullptr;
        f->renderer = std::move(*renderer);
        std::vector<std::string> warnings;
        const QString demo = QString(SPECULUM_SOURCE_DIR) + "/resources/scenes/teapot.speculum.json";
        if (!speculum::scene::openProject(f->scene, demo, warnings))
            return nullptr;
    }
    // An 8-bit target like a window's, so the composite pass does what it does on screen.
    f->color = render::gl::makeTexture();
    glBindTexture(GL_TEXTURE_2D, f->color.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    f->framebuffer = render::gl::makeFramebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, f->framebuffer.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, f->color.id(), 0);
    return f.get();
}

// Animated: the light orbits and the teapot bounces, so every frame re-renders the shadow map, as the
// live viewport does while the animation plays. `static` replays t = 0, where the map is reused.
void frame(benchmark::State& state, bool animated) {
    const int width = 1280, height = 720;
    Fixture* f = fixture(width, height);
    if (!f) {
        state.SkipWithError("no OpenGL context or demo scene");
        return;
    }
    std::map<std::string, double> passMs;
    double gpuTotal = 0.0, t = 0.0;
    std::int64_t frames = 0;
    for (auto _ : state) {
        std::vector<speculum::scene::Warning> warnings;
        const render::FrameInput input = speculum::scene::snapshot(f->scene, t, f->meshes, warnings);
        // Timer queries wait for the GPU at the end of the frame, so wall time includes the GPU's work.
        const render::FrameReport report =
            f->renderer->render(input, {f->framebuffer.id(), width, height, true}, {});
        for (const render::PassRun& run : report.ran)
            passMs[std::string(render::toString(report.planned(run).kind))] += std::max(run.gpuMs, 0.0);
        gpuTotal += std::max(report.gpuMs, 0.0);
        ++frames;
        if (animated)
            t += 1.0 / 60.0;
    }
    for (const auto& [kind, ms] : passMs)
        state.counters[kind + "_gpu_ms"] = ms / double(frames);
    state.counters["gpu_ms"] = gpuTotal / double(frames);
    state.counters["shadow_share"] = gpuTotal > 0 ? passMs["shadow"] / gpuTotal : 0.0;
}

void BM_TeapotFrame1280x720Animated(benchmark::State& state) {
    frame(state, true);
}
void BM_TeapotFrame1280x720Static(benchmark::State& state) {
    frame(state, false);
}

BENCHMARK(BM_TeapotFrame1280x720Animated)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();
BENCHMARK(BM_TeapotFrame1280x720Static)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
