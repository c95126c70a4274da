// What the curved reflector's environment map costs to update: every map type at n = 128, 256 and 512,
// with the direct (vertex-warp) and the resampled fill, in the chrome demo's setting (a ball among
// coloured objects on a floor, a shadow-casting light). The map is forced to update every frame
// (update "always") and the envmap pass's own GPU time is taken from the renderer's timer queries.
// Prints each map's texel solid-angle ratio and checks that the dual-paraboloid update (direct fill)
// costs at most half the cube update at equal n.
// Run: build/release/benchmarks/speculum_bench_envmap
#include "BenchGl.hpp"
#include "render/Renderer.hpp"
#include "render/envmap/SolidAngle.hpp"
#include "render/gl/HeadlessContext.hpp"
#include "render/gl/Objects.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/mesh/Teapot.hpp"

#include <benchmark/benchmark.h>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <memory>
#include <string>

namespace {

using namespace speculum::render;

// A small target: the main pass is not what is measured.
constexpr int kWidth = 160, kHeight = 120;

using Gl = speculum::bench::BenchGl;

Gl* gl() {
    return speculum::bench::benchGl(kWidth, kHeight);
}

Material colored(glm::dvec3 c) {
    Material m;
    m.color = c;
    m.specular = 0.3;
    return m;
}

DrawItem item(const char* name, const MeshHandle& mesh, glm::dvec3 at, glm::dvec3 scale, glm::dvec3 color) {
    return {name, glm::scale(glm::translate(glm::dmat4(1.0), at), scale), mesh, colored(color), true};
}

FrameInput chromeScene(ReflectorMap map, ReflectorFill fill, int n) {
    static const auto box = std::make_shared<const MeshData>(makeBox());
    static const auto sphere = std::make_shared<const MeshData>(makeSphere(32));
    static const auto plane = std::make_shared<const MeshData>(makePlane(1));
    static const auto teapot = std::make_shared<const MeshData>(makeTeapot(8));
    static const auto ball = std::make_shared<const MeshData>(makeSphere(64));
    FrameInput input;
    input.settings.background = {0.25, 0.3, 0.4};
    input.camera.position = {0.0, 2.3, 5.5};
    input.camera.target = {0.0, 0.8, 0.0};
    input.camera.fovY = 50.0;
    input.camera.far = 40.0;
    input.items = {item("Floor", plane, {0, 0, 0}, {6, 1, 6}, {0.9, 0.9, 0.9}),
                   item("Red box", box, {-2.2, 0.6, -0.8}, glm::dvec3(0.6), {0.85, 0.1, 0.08}),
                   item("Green ball", sphere, {2.1, 0.7, -1.0}, glm::dvec3(0.7), {0.1, 0.75, 0.15}),
                   item("Blue box", box, {0.3, 0.9, -3.0}, {1.2, 0.9, 0.4}, {0.1, 0.2, 0.9}),
                   item("Teapot", teapot, {-1.6, 0.0, 1.9}, glm::dvec3(0.3), {0.95, 0.8, 0.1}),
                   item("Magenta box", box, {1.9, 0.4, 1.7}, glm::dvec3(0.4), {0.8, 0.1, 0.7})};
    Light light;
    light.name = "Light";
    light.position = {2.5, 5.0, 3.0};
    light.shadows = {true, 1024, 5};
    input.lights = {light};
    Reflector r;
    r.name = "Chrome ball";
    r.mesh = ball;
    r.world = glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0.9, 0)), glm::dvec3(0.9));
    r.map = map;
    r.fill = fill;
    r.resolution = n;
    r.update = ReflectorUpdate::Always;
    input.reflector = r;
    return input;
}

std::map<std::string, double> g_updateMs; // GPU ms of the envmap pass, by "map/fill/n"

std::string key(ReflectorMap map, ReflectorFill fill, int n) {
    const char* m = map == ReflectorMap::Cube             ? "cube"
                    : map == ReflectorMap::DualParaboloid ? "paraboloid"
                                                          : "tennis";
    const char* f = map == ReflectorMap::Cube ? "-" : fill == ReflectorFill::Direct ? "direct" : "resampled";
    return std::string(m) + "/" + f + "/" + std::to_string(n);
}

void update(benchmark::State& state, ReflectorMap map, ReflectorFill fill) {
    Gl* g = gl();
    if (!g) {
        state.SkipWithError("no OpenGL context");
        return;
    }
    const int n = static_cast<int>(state.range(0));
    const FrameInput input = chromeScene(map, fill, n);
    const RenderTarget target{g->framebuffer.id(), kWidth, kHeight, true};
    g->renderer->render(input, target); // warm-up: textures, shadow map, subdivided meshes
    double gpu = 0.0, cpu = 0.0;
    std::int64_t frames = 0;
    for (auto _ : state) {
        const FrameReport report = g->renderer->render(input, target);
        for (const PlannedPass& p : report.plan.passes)
            if (p.kind == PassKind::Envmap) {
                gpu += p.gpuMs;
                cpu += p.cpuMs;
            }
        ++frames;
    }
    g_updateMs[key(map, fill, n)] = gpu / double(frames);
    state.counters["envmap_gpu_ms"] = gpu / double(frames);
    state.counters["envmap_cpu_ms"] = cpu / double(frames);
}

void BM_Cube(benchmark::State& s) {
    update(s, ReflectorMap::Cube, ReflectorFill::Resampled);
}
void BM_ParaboloidDirect(benchmark::State& s) {
    update(s, ReflectorMap::DualParaboloid, ReflectorFill::Direct);
}
void BM_ParaboloidResampled(benchmark::State& s) {
    update(s, ReflectorMap::DualParaboloid, ReflectorFill::Resampled);
}
void BM_TennisBallDirect(benchmark::State& s) {
    update(s, ReflectorMap::TennisBall, ReflectorFill::Direct);
}
void BM_TennisBallResampled(benchmark::State& s) {
    update(s, ReflectorMap::TennisBall, ReflectorFill::Resampled);
}

#define ENVMAP_BENCHMARK(fn)                                                                                 \
    BENCHMARK(fn)->Arg(128)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond)->MinTime(1.0)->UseRealTime()
ENVMAP_BENCHMARK(BM_Cube);
ENVMAP_BENCHMARK(BM_ParaboloidDirect);
ENVMAP_BENCHMARK(BM_ParaboloidResampled);
ENVMAP_BENCHMARK(BM_TennisBallDirect);
ENVMAP_BENCHMARK(BM_TennisBallResampled);

} // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();

    std::printf("\nEnvironment-map update, GPU ms of the envmap pass (timer queries):\n");
    std::printf("  %-22s %10s %10s %10s\n", "map / fill", "n=128", "n=256", "n=512");
    const std::pair<ReflectorMap, ReflectorFill> rows[] = {
        {ReflectorMap::Cube, ReflectorFill::Resampled},
        {ReflectorMap::DualParaboloid, ReflectorFill::Direct},
        {ReflectorMap::DualParaboloid, ReflectorFill::Resampled},
        {ReflectorMap::TennisBall, ReflectorFill::Direct},
        {ReflectorMap::TennisBall, ReflectorFill::Resampled}};
    for (const auto& [map, fill] : rows) {
        std::string name = key(map, fill, 0);
        name.resize(name.size() - 2);
        std::printf("  %-22s", name.c_str());
        for (int n : {128, 256, 512}) {
            const auto it = g_updateMs.find(key(map, fill, n));
            if (it == g_updateMs.end())
                std::printf(" %10s", "-");
            else
                std::printf(" %10.2f", it->second);
        }
        std::printf("\n");
    }

    std::printf("\nTexel solid angle, largest / smallest (used texels):\n");
    for (auto type : {envmap::MapType::Cube, envmap::MapType::DualParaboloid, envmap::MapType::TennisBall})
        for (int n : {128, 256, 512})
            std::printf("  %s\n", envmap::describe(envmap::solidAngleStats(type, n)).c_str());

    std::printf("\nDual-paraboloid (direct fill) update at most half the cube update at equal n:\n");
    bool allHalf = true;
    for (int n : {128, 256, 512}) {
        const auto cube = g_updateMs.find(key(ReflectorMap::Cube, ReflectorFill::Resampled, n));
        const auto dp = g_updateMs.find(key(ReflectorMap::DualParaboloid, ReflectorFill::Direct, n));
        if (cube == g_updateMs.end() || dp == g_updateMs.end())
            continue;
        const bool half = dp->second <= 0.5 * cube->second;
        allHalf = allHalf && half;
        std::printf("  n=%d: paraboloid %.2f ms, cube %.2f ms, ratio %.2f %s\n", n, dp->second, cube->second,
                    dp->second / cube->second, half ? "ok" : "NOT at most half");
    }
    std::printf("  %s\n", allHalf ? "check passed" : "check FAILED");
    return 0;
}
