// Import time of a big binary PLY: a 1415×1415-quad grid (about 4 M triangles, 2 M vertices) written to a
// temporary folder on first use. BM_ImportModel is speculum's import (Assimp read without the
// smoothing/joining/degenerate steps, meshoptimizer weld, repairMesh, flatten); BM_ImportModelFile stops
// before flattening; each on the indexed grid (argument 0) and on the same grid with every triangle's
// vertices written separately (argument 1, what welding is for); BM_AssimpOldSteps is Assimp alone with the
// steps the import used to run (GenSmoothNormals, JoinIdenticalVertices, FindDegenerates), for comparison.
// Run: build/release/benchmarks/speculum_bench_import
#include "scene/import/ModelImport.hpp"

#include <QDir>
#include <QTemporaryDir>
#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <benchmark/benchmark.h>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace speculum;

constexpr int kQuads = 1415; // per side: 2 · 1415² = 4 004 450 triangles

// A gently curved height field, so normals vary and nothing is degenerate. `unshared`: every triangle has
// its own three vertices (as STL-converted or "flat" exports do), which is what welding is for.
std::string writeGridPly(const std::string& path, int quads, bool unshared = false) {
    std::ofstream out(path, std::ios::binary);
    const int side = quads + 1;
    out << "ply\nformat binary_little_endian 1.0\n"
        << "element vertex " << (unshared ? 6 * quads * quads : side * side)
        << "\nproperty float x\nproperty float y\nproperty float z\n"
        << "element face " << 2 * quads * quads << "\nproperty list uchar int vertex_indices\nend_header\n";
    std::vector<float> vertices;
    vertices.reserve(static_cast<std::size_t>(side) * side * 3);
    for (int j = 0; j < side; ++j) {
        for (int i = 0; i < side; ++i) {
            // 100 units across: Assimp's FindDegenerates (the old import) drops every triangle under 1e-6
            // square units, which on a unit-sized grid this fine would be all of them.
            const float x = static_cast<float>(i) / quads, z = static_cast<float>(j) / quads;
            vertices.insert(vertices.end(),
                            {100.0f * x, 5.0f * std::sin(12.0f * x) * std::cos(9.0f * z), 100.0f * z});
        }
    }
    std::vector<char> faces;
    faces.reserve(static_cast<std::size_t>(quads) * quads * 2 * 13);
    std::vector<float> corners;
    const auto face = [&](std::int32_t a, std::int32_t b, std::int32_t c) {
        if (unshared) {
            for (std::int32_t index : {a, b, c}) {
                corners.insert(corners.end(), vertices.begin() + 3 * index, vertices.begin() + 3 * index + 3);
            }
            const auto first = static_cast<std::int32_t>(corners.size() / 3 - 3);
            a = first, b = first + 1, c = first + 2;
        }
        faces.push_back(3);
        for (std::int32_t index : {a, b, c}) {
            const char* bytes = reinterpret_cast<const char*>(&index);
            faces.insert(faces.end(), bytes, bytes + 4);
        }
    };
    for (int j = 0; j < quads; ++j) {
        for (int i = 0; i < quads; ++i) {
            const std::int32_t v = j * side + i;
            face(v, v + side, v + 1); // counter-clockwise seen from +y
            face(v + 1, v + side, v + side + 1);
        }
    }
    const std::vector<float>& written = unshared ? corners : vertices;
    out.write(reinterpret_cast<const char*>(written.data()),
              static_cast<std::streamsize>(written.size() * sizeof(float)));
    out.write(faces.data(), static_cast<std::streamsize>(faces.size()));
    return path;
}

QTemporaryDir& folder() {
    static QTemporaryDir dir;
    return dir;
}

const std::string& plyFile(bool unshared) {
    static const std::string shared =
        writeGridPly(QDir(folder().path()).filePath("grid4m.ply").toStdString(), kQuads);
    static const std::string separate =
        writeGridPly(QDir(folder().path()).filePath("grid4m-unshared.ply").toStdString(), kQuads, true);
    return unshared ? separate : shared;
}

void BM_ImportModel(benchmark::State& state) {
    const std::string& path = plyFile(state.range(0) != 0);
    for (auto _ : state) {
        std::vector<std::string> warnings;
        auto mesh = speculum::scene::importModel(path, warnings);
        if (!mesh) {
            state.SkipWithError(mesh.error().c_str());
            return;
        }
        state.counters["triangles"] = static_cast<double>(mesh->triangleCount());
        benchmark::DoNotOptimize(mesh->positions.data());
    }
}

void BM_ImportModelFile(benchmark::State& state) {
    const std::string& path = plyFile(state.range(0) != 0);
    for (auto _ : state) {
        std::vector<std::string> warnings;
        auto model = speculum::scene::importModelFile(path, warnings);
        if (!model) {
            state.SkipWithError(model.error().c_str());
            return;
        }
        benchmark::DoNotOptimize(model->parts.data());
    }
}

void BM_AssimpOldSteps(benchmark::State& state) {
    const std::string& path = plyFile(state.range(0) != 0);
    for (auto _ : state) {
        Assimp::Importer importer;
        importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
        importer.SetPropertyBool(AI_CONFIG_PP_FD_REMOVE, true);
        const aiScene* scene = importer.ReadFile(
            path, aiProcess_Triangulate | aiProcess_GenSmoothNormals | aiProcess_JoinIdenticalVertices |
                      aiProcess_SortByPType | aiProcess_FindDegenerates | aiProcess_ValidateDataStructure);
        if (scene == nullptr || scene->mNumMeshes == 0) {
            state.SkipWithError(scene == nullptr ? importer.GetErrorString() : "no meshes left");
            return;
        }
        state.counters["triangles"] = static_cast<double>(scene->mMeshes[0]->mNumFaces);
        benchmark::DoNotOptimize(scene->mMeshes);
    }
}

// Argument: 0 = indexed grid, 1 = every triangle with its own vertices.
BENCHMARK(BM_ImportModel)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(BM_ImportModelFile)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(BM_AssimpOldSteps)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(1);

} // namespace

BENCHMARK_MAIN();
