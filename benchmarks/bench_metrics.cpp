// What the error metrics cost per comparison, at the bench's quick size (480×270) and its full size
// (1280×720): RMSE/PSNR/MAE, SSIM, LDR-FLIP, HDR-FLIP (as many LDR-FLIPs as the reference's exposure range
// asks for) and the reference-noise interval. The images are a generated gradient with structure and a
// perturbed copy, so the work is that of a real comparison. Run:
// build/release/benchmarks/speculum_bench_metrics
#include "render/metrics/ErrorMetrics.hpp"
#include "render/metrics/Flip.hpp"
#include "render/metrics/ReferenceNoise.hpp"
#include "render/metrics/Ssim.hpp"

#include <benchmark/benchmark.h>
#include <cmath>
#include <map>

namespace {

using namespace speculum::render;

struct Pair {
    Image reference, test, noise;
};

// A scene-like HDR image: a gradient sky, a bright highlight well above 1 and some edges.
const Pair& pairOf(int width, int height) {
    static std::map<int, Pair> pairs;
    auto [it, made] = pairs.try_emplace(width);
    if (!made)
        return it->second;
    Pair& p = it->second;
    for (Image* image : {&p.reference, &p.test, &p.noise}) {
        image->width = width;
        image->height = height;
        image->rgba.assign(std::size_t(width) * height * 4, 1.0f);
    }
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::size_t i = (std::size_t(y) * width + x) * 4;
            const float u = float(x) / width, v = float(y) / height;
            const float d = std::hypot(u - 0.6f, v - 0.4f);
            const float highlight = d < 0.05f ? 8.0f : 0.0f;
            const float stripes = (x / 16 + y / 16) % 2 == 0 ? 0.15f : 0.0f;
            for (int c = 0; c < 3; ++c) {
                const float value = 0.1f + 0.6f * v * (c + 1) / 3.0f + stripes + highlight;
                p.reference.rgba[i + c] = value;
                p.test.rgba[i + c] =
                    value * (1.0f + 0.05f * std::sin(0.1f * x + c)) + (x % 7 == 0 ? 0.02f : 0.0f);
                p.noise.rgba[i + c] = 1e-5f;
            }
        }
    return p;
}

void setSize(benchmark::State& state, const Pair& p) {
    state.counters["pixels"] = double(p.reference.width) * p.reference.height;
}

void BM_RmsePsnrMae(benchmark::State& state) {
    const Pair& p = pairOf(int(state.range(0)), int(state.range(1)));
    for (auto _ : state)
        benchmark::DoNotOptimize(metrics::compare(p.test, p.reference));
    setSize(state, p);
}

void BM_Ssim(benchmark::State& state) {
    const Pair& p = pairOf(int(state.range(0)), int(state.range(1)));
    for (auto _ : state)
        benchmark::DoNotOptimize(metrics::ssim(p.test, p.reference));
    setSize(state, p);
}

void BM_LdrFlip(benchmark::State& state) {
    const Pair& p = pairOf(int(state.range(0)), int(state.range(1)));
    for (auto _ : state)
        benchmark::DoNotOptimize(metrics::ldrFlip(p.test, p.reference));
    setSize(state, p);
}

void BM_HdrFlip(benchmark::State& state) {
    const Pair& p = pairOf(int(state.range(0)), int(state.range(1)));
    int exposures = 0;
    for (auto _ : state) {
        auto flip = metrics::hdrFlip(p.test, p.reference);
        exposures = flip.ok() ? flip->exposures : 0;
        benchmark::DoNotOptimize(flip);
    }
    setSize(state, p);
    state.counters["exposures"] = exposures;
}

void BM_NoiseInterval(benchmark::State& state) {
    const Pair& p = pairOf(int(state.range(0)), int(state.range(1)));
    for (auto _ : state)
        benchmark::DoNotOptimize(metrics::noiseInterval(p.test, p.reference, p.noise));
    setSize(state, p);
}

void sizes(benchmark::internal::Benchmark* b) {
    b->Args({480, 270})->Args({1280, 720})->Unit(benchmark::kMillisecond);
}

BENCHMARK(BM_RmsePsnrMae)->Apply(sizes);
BENCHMARK(BM_Ssim)->Apply(sizes);
BENCHMARK(BM_LdrFlip)->Apply(sizes);
BENCHMARK(BM_HdrFlip)->Apply(sizes);
BENCHMARK(BM_NoiseInterval)->Apply(sizes);

} // namespace

BENCHMARK_MAIN();
