// What a big imported model costs a still, end to end, as a user runs it: `speculum render` at 64×64 of a
// small scene with a generated 4 M-triangle binary PLY (a bumpy height field without normals, so import
// has to build them), against the same scene without the model. The check of the import issue: within
// 12× (the ratio was about 60× when every import ran Assimp's own normal, weld and degenerate steps).
// Run: build/release/benchmarks/speculum_bench_big_model [--triangles N] [--runs N]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// A square grid of side×side vertices, two triangles per cell: 2·(side − 1)² triangles.
void writeHeightField(const fs::path& path, int side) {
    std::ofstream out(path, std::ios::binary);
    const long long vertices = 1LL * side * side;
    const long long triangles = 2LL * (side - 1) * (side - 1);
    out << "ply\nformat binary_little_endian 1.0\nelement vertex " << vertices
        << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << triangles
        << "\nproperty list uchar int vertex_indices\nend_header\n";
    std::vector<float> row(static_cast<std::size_t>(side) * 3);
    for (int j = 0; j < side; ++j) {
        for (int i = 0; i < side; ++i) {
            const float x = 2.0f * i / (side - 1) - 1.0f, z = 2.0f * j / (side - 1) - 1.0f;
            row[i * 3 + 0] = x;
            row[i * 3 + 1] = 0.05f * std::sin(25.0f * x) * std::cos(19.0f * z);
            row[i * 3 + 2] = z;
        }
        out.write(reinterpret_cast<const char*>(row.data()), static_cast<std::streamsize>(row.size() * 4));
    }
    std::vector<char> faces;
    faces.reserve(static_cast<std::size_t>(side - 1) * 26);
    const auto face = [&](std::int32_t a, std::int32_t b, std::int32_t c) {
        faces.push_back(3);
        for (std::int32_t v : {a, b, c})
            faces.insert(faces.end(), reinterpret_cast<const char*>(&v),
                         reinterpret_cast<const char*>(&v) + 4);
    };
    for (int j = 0; j + 1 < side; ++j) {
        faces.clear();
        for (int i = 0; i + 1 < side; ++i) {
            const std::int32_t a = j * side + i, b = a + 1, c = a + side, d = c + 1;
            face(a, c, b); // counter-clockwise seen from +Y
            face(b, c, d);
        }
        out.write(faces.data(), static_cast<std::streamsize>(faces.size()));
    }
}

void writeScene(const fs::path& path, bool withModel) {
    std::ofstream out(path);
    out << R"({"format": "speculum-scene", "version": 1,
  "camera": {"position": [0, 2, 3], "target": [0, 0, 0], "fovY": 50, "near": 0.1, "far": 20},
  "nodes": [
    {"name": "Floor", "transform": {"scale": [3, 1, 3]}, "mesh": {"builtin": "plane", "tessellation": 1}},
    {"name": "Light", "transform": {"translate": [1, 3, 2]}, "light": {"type": "point"}})";
    if (withModel)
        out << R"(,
    {"name": "Terrain", "transform": {"translate": [0, 0.3, 0]}, "mesh": {"file": "terrain.ply"}})";
    out << "\n  ]\n}\n";
}

// Wall-clock seconds of one `speculum render` at 64×64; exits on failure.
double renderSeconds(const fs::path& scene, const fs::path& image) {
    const std::string command = std::string(SPECULUM_BINARY) + " render '" + scene.string() + "' -o '" +
                                image.string() + "' --size 64x64 >/dev/null";
    const auto start = Clock::now();
    const int status = std::system(command.c_str());
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (status != 0) {
        std::fprintf(stderr, "bench_big_model: '%s' failed\n", command.c_str());
        std::exit(1);
    }
    return seconds;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

} // namespace

int main(int argc, char** argv) {
    long long triangles = 4'000'000;
    int runs = 3;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        if (flag == "--triangles")
            triangles = std::atoll(argv[i + 1]);
        else if (flag == "--runs")
            runs = std::max(1, std::atoi(argv[i + 1]));
    }
    const int side = static_cast<int>(std::ceil(std::sqrt(triangles / 2.0))) + 1;
    const fs::path dir =
        fs::temp_directory_path() / ("speculum-bench-big-model-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::printf("writing a %lld-triangle PLY ...\n", 2LL * (side - 1) * (side - 1));
    writeHeightField(dir / "terrain.ply", side);
    writeScene(dir / "with.speculum.json", true);
    writeScene(dir / "without.speculum.json", false);

    std::vector<double> with, without;
    for (int r = 0; r < runs; ++r) {
        without.push_back(renderSeconds(dir / "without.speculum.json", dir / "without.png"));
        with.push_back(renderSeconds(dir / "with.speculum.json", dir / "with.png"));
    }
    const double a = median(with), b = median(without);
    std::printf("render 64x64 without the model: %.3f s (median of %d)\n", b, runs);
    std::printf("render 64x64 with the model:    %.3f s (median of %d)\n", a, runs);
    std::printf("check: import + render within 12x the scene without it: %.1fx %s\n", a / b,
                a <= 12.0 * b ? "MET" : "NOT MET");
    fs::remove_all(dir);
    return 0;
}
