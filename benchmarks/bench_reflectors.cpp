// What several curved reflectors cost: a ring of N mirrored balls (N = 1, 2, 4, 8, 16; cube maps of 128²,
// redrawn every frame) around a teapot on a floor, at 1280×720, with reflectorBounces 0, 1 and 2. Each
// frame draws N × (bounces + 1) maps, and each map draws the scene and the N − 1 other balls; the
// benchmark prints the frame's wall time, the envmap passes' timer-query time, that time per map drawn,
// and per thousand triangles a map draws (before each cube face culls what it cannot see). It checks that
// the last stays within 1.5× from 2 reflectors to 16: the cost grows with the maps drawn and what they
// draw, and the planner adds nothing that grows faster. Run:
// build/release/benchmarks/speculum_bench_reflectors
#include "BenchGl.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/mesh/Teapot.hpp"

#include <algorithm>
#include <benchmark/benchmark.h>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <memory>
#include <vector>

namespace {

using namespace speculum::render;

constexpr int kWidth = 1280, kHeight = 720;

Material colored(glm::dvec3 c) {
    Material m;
    m.color = c;
    m.specular = 0.3;
    return m;
}

FrameInput ring(int count, int bounces) {
    static const auto plane = std::make_shared<const MeshData>(makePlane(1));
    static const auto teapot = std::make_shared<const MeshData>(makeTeapot(8));
    static const auto ball = std::make_shared<const MeshData>(makeSphere(48));
    FrameInput input;
    input.settings.background = {0.25, 0.3, 0.4};
    input.settings.reflectorBounces = bounces;
    input.camera.position = {0.0, 3.5, 7.5};
    input.camera.target = {0.0, 0.5, 0.0};
    input.camera.fovY = 55.0;
    input.camera.far = 60.0;
    input.items = {
        {"Floor", glm::scale(glm::dmat4(1.0), glm::dvec3(8, 1, 8)), plane, colored({0.8, 0.8, 0.8}), true},
        {"Teapot", glm::scale(glm::dmat4(1.0), glm::dvec3(0.5)), teapot, colored({0.9, 0.6, 0.1}), true}};
    Light light;
    light.name = "Light";
    light.position = {2.5, 6.0, 3.0};
    light.shadows = ShadowParams{1024, 3};
    input.lights = {light};
    for (int i = 0; i < count; ++i) {
        const double a = 2.0 * M_PI * i / count;
        Reflector r;
        r.name = "Ball " + std::to_string(i);
        r.mesh = ball;
        r.world =
            glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(3.0 * std::cos(a), 0.6, 3.0 * std::sin(a))),
                       glm::dvec3(0.55));
        r.resolution = 128;
        r.update = ReflectorUpdate::Always;
        input.reflectors.push_back(r);
    }
    return input;
}

struct Row {
    double frameMs = 0.0;
    double envmapMs = 0.0;
    int maps = 0;
    std::size_t mapTriangles = 0; // what one map draws: the scene's items and the other balls
};

std::size_t mapTriangles(const FrameInput& input) {
    std::size_t triangles = 0;
    for (const DrawItem& item : input.items)
        triangles += item.mesh->triangleCount();
    for (std::size_t i = 1; i < input.reflectors.size(); ++i)
        triangles += input.reflectors[i].mesh->triangleCount();
    return triangles;
}

double perThousand(const Row& r) {
    return r.maps > 0 && r.mapTriangles > 0 ? r.envmapMs / r.maps / (double(r.mapTriangles) / 1000.0) : 0.0;
}
std::map<std::pair<int, int>, Row> g_rows; // by (reflectors, bounces)

void frames(benchmark::State& state) {
    speculum::bench::BenchGl* g = speculum::bench::benchGl(kWidth, kHeight);
    if (!g) {
        state.SkipWithError("no OpenGL context");
        return;
    }
    const int count = static_cast<int>(state.range(0));
    const int bounces = static_cast<int>(state.range(1));
    const FrameInput input = ring(count, bounces);
    g->renderer->render(input, g->target()); // warm-up: programs, textures, maps allocated
    std::vector<double> wall, envmap;
    int maps = 0;
    for (auto _ : state) {
        const auto t0 = std::chrono::steady_clock::now();
        const FrameReport report = g->renderer->render(input, g->target());
        glFinish();
        wall.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
        double ms = 0.0;
        maps = 0;
        for (const PassRun& run : report.ran)
            if (report.planned(run).kind == PassKind::Envmap) {
                ms += run.gpuMs;
                ++maps;
            }
        envmap.push_back(ms);
    }
    std::sort(wall.begin(), wall.end());
    std::sort(envmap.begin(), envmap.end());
    Row& row = g_rows[{count, bounces}];
    row.frameMs = wall[wall.size() / 2];
    row.envmapMs = envmap[envmap.size() / 2];
    row.maps = maps;
    row.mapTriangles = mapTriangles(input);
    state.counters["maps"] = maps;
    state.counters["envmap_ms"] = row.envmapMs;
    state.counters["ms_per_map"] = maps > 0 ? row.envmapMs / maps : 0.0;
}

BENCHMARK(frames)
    ->ArgsProduct({{1, 2, 4, 8, 16}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3)
    ->UseRealTime();

} // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    std::printf("\n%-11s %-8s %6s %10s %10s %11s %12s %15s\n", "reflectors", "bounces", "maps", "frame ms",
                "envmap ms", "ms per map", "tris per map", "ms per map·kTri");
    for (const auto& [key, row] : g_rows)
        std::printf("%-11d %-8d %6d %10.1f %10.1f %11.2f %12zu %15.3f\n", key.first, key.second, row.maps,
                    row.frameMs, row.envmapMs, row.maps > 0 ? row.envmapMs / row.maps : 0.0, row.mapTriangles,
                    perThousand(row));
    if (g_rows.count({2, 0}) && g_rows.count({16, 0})) {
        const double at2 = perThousand(g_rows[{2, 0}]), at16 = perThousand(g_rows[{16, 0}]);
        const bool ok = at16 <= 1.5 * at2;
        std::printf(
            "time per map and thousand triangles at 16 reflectors: %.3f ms against %.3f ms at 2: %s\n", at16,
            at2,
            ok ? "the cost grows no faster than the maps drawn and what they draw"
               : "FAILS: the cost grows faster than the maps drawn and what they draw");
        return ok ? 0 : 1;
    }
    return 0;
}
