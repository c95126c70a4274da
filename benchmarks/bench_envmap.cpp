// What the curved reflector's environment map costs to update: every map type at n = 128, 256 and 512,
// with the direct (vertex-warp) and the resampled fill, in the chrome demo's setting (a ball among
// coloured objects on a floor, a shadow-casting light). The map is forced to update every frame
// (update "always"). An update's cost is the least process CPU time such a frame took less the least a
// frame reusing its map (update "once") took, over frames run in pairs: on llvmpipe the GPU's work is the
// process's rasterizer threads, and CPU time, unlike wall time, moves little when other programs load
// the machine, and then only up (the median of the pairs' differences is printed too). The envmap pass's
// timer-query time (wall time on llvmpipe) is printed beside it. The benchmark's own time per iteration
// covers both frames of a pair. Prints each map's texel solid-angle ratio and checks that the dual-paraboloid
// update with the direct fill costs at most half the cube update at equal n. The resampled fill's ratio is
// printed too, but it renders the very cube it is compared with (at the same n, so that it loses no detail)
// and resamples it: it always costs more. Run: build/release/benchmarks/speculum_bench_envmap
#include "BenchGl.hpp"
#include "render/envmap/SolidAngle.hpp"
#include "render/gl/HeadlessContext.hpp"
#include "render/gl/Objects.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/mesh/Teapot.hpp"
#include "render/renderer/Renderer.hpp"

#include <algorithm>
#include <benchmark/benchmark.h>
#include <cstdio>
#include <ctime>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <memory>
#include <string>
#include <vector>

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
    light.shadows = speculum::render::ShadowParams{1024, 5};
    input.lights = {light};
    Reflector r;
    r.name = "Chrome ball";
    r.mesh = ball;
    r.world = glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0.9, 0)), glm::dvec3(0.9));
    r.map = map;
    r.fill = fill;
    r.resolution = n;
    r.update = ReflectorUpdate::Always;
    input.reflectors = {r};
    return input;
}

std::map<std::string, double> g_updateMs; // process CPU ms of an update, by "map/fill/n"
std::map<std::string, double> g_medianMs; // the median of the pairs' differences, for comparison
std::map<std::string, double> g_timerMs;  // timer-query ms of the envmap pass

// CPU time of the whole process (llvmpipe's rasterizer threads included), in ms.
double processCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t h = v.size() / 2;
    return v.size() % 2 ? v[h] : 0.5 * (v[h - 1] + v[h]);
}

std::string key(ReflectorMap map, ReflectorFill fill, int n) {
    const char* m = map == ReflectorMap::Cube             ? "cube"
                    : map == ReflectorMap::DualParaboloid ? "paraboloid"
                    : map == ReflectorMap::TennisBall     ? "tennis"
                                                          : "octahedral";
    const char* f = !warpable(map) ? "-" : fill == ReflectorFill::Direct ? "direct" : "resampled";
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
    // The same frame reusing the map: everything but the update.
    FrameInput reuse = input;
    reuse.reflectors[0].update = ReflectorUpdate::Once;
    g->renderer->render(input, target); // warm-up: textures, shadow map, subdivided meshes
    g->renderer->render(reuse, target);
    // Other programs on the machine only ever add to a frame's CPU time (shared caches and cores), so the
    // least time each kind of frame took over many is the best estimate of its own work; each update frame
    // is paired with a reuse frame right after it, so both kinds see the same spells of load.
    std::vector<double> updates, reuses;
    double timer = 0.0;
    auto pair = [&] {
        const double t0 = processCpuMs();
        const FrameReport report = g->renderer->render(input, target);
        const double t1 = processCpuMs();
        g->renderer->render(reuse, target);
        updates.push_back(t1 - t0);
        reuses.push_back(processCpuMs() - t1);
        for (const PassRun& run : report.ran)
            if (report.planned(run).kind == PassKind::Envmap)
                timer += run.gpuMs;
    };
    for (auto _ : state)
        pair();
    while (updates.size() < 12) // enough frames for a least time even where a frame takes a second
        pair();
    const double least =
        *std::min_element(updates.begin(), updates.end()) - *std::min_element(reuses.begin(), reuses.end());
    std::vector<double> differences(updates.size());
    for (std::size_t i = 0; i < updates.size(); ++i)
        differences[i] = updates[i] - reuses[i];
    g_updateMs[key(map, fill, n)] = least;
    g_medianMs[key(map, fill, n)] = median(differences);
    g_timerMs[key(map, fill, n)] = timer / double(updates.size());
    state.counters["envmap_process_cpu_ms"] = g_updateMs[key(map, fill, n)];
    state.counters["envmap_timer_ms"] = g_timerMs[key(map, fill, n)];
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
void BM_Octahedral(benchmark::State& s) {
    update(s, ReflectorMap::Octahedral, ReflectorFill::Resampled);
}

#define ENVMAP_BENCHMARK(fn)                                                                                 \
    BENCHMARK(fn)->Arg(128)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond)->MinTime(1.0)->UseRealTime()
ENVMAP_BENCHMARK(BM_Cube);
ENVMAP_BENCHMARK(BM_ParaboloidDirect);
ENVMAP_BENCHMARK(BM_ParaboloidResampled);
ENVMAP_BENCHMARK(BM_TennisBallDirect);
ENVMAP_BENCHMARK(BM_TennisBallResampled);
ENVMAP_BENCHMARK(BM_Octahedral);

} // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();

    const std::pair<ReflectorMap, ReflectorFill> rows[] = {
        {ReflectorMap::Cube, ReflectorFill::Resampled},
        {ReflectorMap::DualParaboloid, ReflectorFill::Direct},
        {ReflectorMap::DualParaboloid, ReflectorFill::Resampled},
        {ReflectorMap::TennisBall, ReflectorFill::Direct},
        {ReflectorMap::TennisBall, ReflectorFill::Resampled},
        {ReflectorMap::Octahedral, ReflectorFill::Resampled}};
    auto table = [&](const char* title, const std::map<std::string, double>& ms) {
        std::printf("\n%s\n", title);
        std::printf("  %-22s %10s %10s %10s\n", "map / fill", "n=128", "n=256", "n=512");
        for (const auto& [map, fill] : rows) {
            std::string name = key(map, fill, 0);
            name.resize(name.size() - 2);
            std::printf("  %-22s", name.c_str());
            for (int n : {128, 256, 512}) {
                const auto it = ms.find(key(map, fill, n));
                if (it == ms.end())
                    std::printf(" %10s", "-");
                else
                    std::printf(" %10.2f", it->second);
            }
            std::printf("\n");
        }
    };
    table("Environment-map update, process CPU ms (least time of a frame with the update less that of a "
          "frame reusing the map):",
          g_updateMs);
    table("The same, median of the paired frames' differences:", g_medianMs);
    table("Envmap pass, timer-query ms (wall time on llvmpipe: moves with the machine's load):", g_timerMs);

    std::printf("\nTexel solid angle, largest / smallest (used texels):\n");
    for (auto type : {envmap::MapType::Cube, envmap::MapType::DualParaboloid, envmap::MapType::TennisBall,
                      envmap::MapType::Octahedral})
        for (int n : {128, 256, 512})
            std::printf("  %s\n", envmap::describe(envmap::solidAngleStats(type, n)).c_str());

    std::printf("\nDual-paraboloid update (direct fill) at most half the cube update at equal n, process CPU "
                "time:\n");
    bool allHalf = true;
    for (ReflectorFill fill : {ReflectorFill::Direct, ReflectorFill::Resampled})
        for (int n : {128, 256, 512}) {
            const auto cube = g_updateMs.find(key(ReflectorMap::Cube, ReflectorFill::Resampled, n));
            const auto dp = g_updateMs.find(key(ReflectorMap::DualParaboloid, fill, n));
            if (cube == g_updateMs.end() || dp == g_updateMs.end())
                continue;
            const bool half = dp->second <= 0.5 * cube->second;
            if (fill == ReflectorFill::Direct)
                allHalf = allHalf && half;
            const auto timerCube = g_timerMs.find(key(ReflectorMap::Cube, ReflectorFill::Resampled, n));
            const auto timerDp = g_timerMs.find(key(ReflectorMap::DualParaboloid, fill, n));
            std::printf(
                "  %-9s n=%d: paraboloid %.2f ms, cube %.2f ms, ratio %.2f %s (timer queries: %.2f)\n",
                fill == ReflectorFill::Direct ? "direct" : "resampled", n, dp->second, cube->second,
                dp->second / cube->second,
                fill == ReflectorFill::Resampled ? "(not checked)"
                : half                           ? "ok"
                                                 : "NOT at most half",
                timerDp->second / timerCube->second);
        }
    std::printf("  %s\n", allHalf ? "check passed" : "check FAILED");
    return 0;
}
