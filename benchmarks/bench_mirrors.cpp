// What planar mirrors cost at 1280×720: a mirror that is present but hidden, one visible mirror covering
// a fraction f of the screen, and two facing mirrors at depth 1 and 8. Prints the checks of the mirror
// issue after the timings. Run: build/release/benchmarks/speculum_bench_mirrors
#include "BenchGl.hpp"
#include "render/Renderer.hpp"
#include "render/gl/HeadlessContext.hpp"
#include "render/gl/Objects.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/mesh/Teapot.hpp"

#include <benchmark/benchmark.h>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <memory>
#include <sys/resource.h>

namespace {

using namespace speculum::render;

constexpr int kWidth = 1280, kHeight = 720;

using Gl = speculum::bench::BenchGl;

Gl* gl() {
    return speculum::bench::benchGl(kWidth, kHeight);
}

Mirror wall(const std::string& name, glm::dvec3 at, glm::dvec3 axis, double degrees, glm::dvec2 size) {
    Mirror m;
    m.name = name;
    m.world = glm::rotate(glm::translate(glm::dmat4(1.0), at), glm::radians(degrees), axis);
    m.size = size;
    m.reflectivity = 0.9;
    return m;
}

// The teapot demo's content: a teapot on a marble-sized floor under a shadow-casting point light.
FrameInput baseScene() {
    FrameInput input;
    input.camera.position = {0.0, 0.0, 1.0};
    input.camera.target = {0.0, -0.6, -3.0};
    input.camera.fovY = 65.0;
    input.camera.far = 30.0;
    static const auto teapot = std::make_shared<const MeshData>(makeTeapot(8));
    static const auto plane = std::make_shared<const MeshData>(makePlane(1));
    DrawItem pot{"Teapot",
                 glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0, -1, -3)), glm::dvec3(0.25)),
                 teapot,
                 {},
                 true};
    pot.material.specular = 0.5;
    DrawItem floor{"Floor",
                   glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0, -1, -3)), glm::dvec3(2, 1, 2)),
                   plane,
                   {},
                   true};
    input.items = {pot, floor};
    Light light;
    light.name = "Light";
    light.position = {1.5, 2.0, -3.0};
    light.shadows = {true, 1024, 5};
    input.lights = {light};
    return input;
}

// CPU time of the whole process (llvmpipe's rasterizer threads included), in ms. On llvmpipe this is the
// GPU's work, and unlike wall time it hardly moves when other programs load the machine.
double processCpuMs() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return (usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) * 1e3 +
           (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) * 1e-3;
}

std::map<std::string, double> g_gpuMs;
std::map<std::string, double> g_processMs;
std::map<std::string, double> g_coverage;

void frame(benchmark::State& state, const std::string& name, const FrameInput& input) {
    Gl* g = gl();
    if (!g) {
        state.SkipWithError("no OpenGL context");
        return;
    }
    const RenderTarget target{g->framebuffer.id(), kWidth, kHeight, true};
    g->renderer->render(input, target); // warm-up: shadow map, shader variants
    double gpu = 0.0;
    std::int64_t frames = 0;
    double coverage = 0.0;
    const double cpuStart = processCpuMs();
    for (auto _ : state) {
        const FrameReport report = g->renderer->render(input, target);
        gpu += report.gpuMs;
        ++frames;
        coverage = 0.0;
        for (const MirrorView& v : report.plan.views)
            if (v.depth == 1)
                coverage += v.pixelArea / double(kWidth * kHeight);
    }
    g_gpuMs[name] = gpu / double(frames);
    g_processMs[name] = (processCpuMs() - cpuStart) / double(frames);
    state.counters["process_cpu_ms"] = g_processMs[name];
    g_coverage[name] = coverage;
    state.counters["gpu_ms"] = g_gpuMs[name];
    state.counters["mirror_coverage"] = coverage;
}

void BM_Base(benchmark::State& state) {
    frame(state, "base", baseScene());
}

void BM_HiddenMirror(benchmark::State& state) {
    FrameInput input = baseScene();
    input.mirrors = {wall("Behind camera", {0, 0, 3}, {1, 0, 0}, -90.0, {3, 2})};
    frame(state, "hidden", input);
}

void BM_VisibleMirror(benchmark::State& state) {
    FrameInput input = baseScene();
    input.mirrors = {wall("Back wall", {0, -0.2, -4.5}, {1, 0, 0}, 90.0, {2.4, 1.6})};
    frame(state, "visible", input);
}

// A corridor: the camera stands between two facing mirrors and looks into one at a slant, so each
// level sees the other mirror again, smaller, until the depth limit.
FrameInput facing(int depth) {
    FrameInput input = baseScene();
    input.settings.mirrorDepth = depth;
    input.mirrors = {wall("Left", {-1.6, -0.2, -3}, {0, 0, 1}, -90.0, {1.6, 4}),
                     wall("Right", {1.6, -0.2, -3}, {0, 0, 1}, 90.0, {1.6, 4})};
    input.camera.position = {0.9, -0.3, -2.2};
    input.camera.target = {-1.6, -0.5, -3.1};
    return input;
}

void BM_FacingDepth1(benchmark::State& state) {
    frame(state, "facing1", facing(1));
}
void BM_FacingDepth8(benchmark::State& state) {
    frame(state, "facing8", facing(8));
}

BENCHMARK(BM_Base)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();
BENCHMARK(BM_HiddenMirror)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();
BENCHMARK(BM_VisibleMirror)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();
BENCHMARK(BM_FacingDepth1)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();
BENCHMARK(BM_FacingDepth8)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();

} // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    if (!g_gpuMs.count("base") || !g_gpuMs.count("hidden") || !g_gpuMs.count("visible") ||
        !g_gpuMs.count("facing1") || !g_gpuMs.count("facing8"))
        return 0; // a filtered run: no checks
    const double f = g_coverage["visible"];
    for (const auto* costs : {&g_gpuMs, &g_processMs}) {
        auto c = *costs;
        const double base = c["base"];
        std::printf("\nMirror costs (%s per frame at %dx%d):\n",
                    costs == &g_gpuMs ? "GPU ms from timer queries"
                                      : "process CPU ms, llvmpipe threads included",
                    kWidth, kHeight);
        std::printf("  hidden mirror: %.2f vs base %.2f = %+.1f%% (target within 3%%)\n", c["hidden"], base,
                    100.0 * (c["hidden"] / base - 1.0));
        std::printf("  visible mirror covering f = %.3f: %.2f vs limit base×(1+f)+1 = %.2f\n", f,
                    c["visible"], base * (1.0 + f) + 1.0);
        std::printf("  facing mirrors: depth 8 %.2f vs depth 1 %.2f = %.2f× (target at most 3×)\n",
                    c["facing8"], c["facing1"], c["facing8"] / c["facing1"]);
    }
    return 0;
}
