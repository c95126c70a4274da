#include "scene/import/ModelImport.hpp"

#include "support/MeshChecks.hpp"
#include "support/TestPaths.hpp"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <random>
#include <sstream>

namespace speculum::document {
namespace {

namespace fs = std::filesystem;
using render::Bounds;
using render::MeshData;
using render::test::expectWellFormed;
using render::test::faceNormal;
using render::test::signedVolume;

// Debian's assimp-testmodels package: Assimp's own regression corpus, valid and invalid files.
const fs::path kModels = "/usr/share/assimp/models";

#define REQUIRE_TEST_MODELS()                                                                                \
    if (!fs::is_directory(kModels)) {                                                                        \
        GTEST_SKIP() << kModels << " is missing; install the assimp-testmodels package";                     \
    }

fs::path freshFolder() {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const fs::path folder = fs::path(speculum::testDataPath()) / "editor_import" /
                            (std::string(info->test_suite_name()) + "." + info->name());
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

fs::path writeFile(const fs::path& path, const std::string& content) {
    std::ofstream(path, std::ios::binary) << content;
    return path;
}

struct Imported {
    base::Result<MeshData> mesh;
    std::vector<std::string> warnings;
};

Imported import(const fs::path& path) {
    std::vector<std::string> warnings;
    auto mesh = scene::importModel(path.string(), warnings);
    return {std::move(mesh), std::move(warnings)};
}

void expectBounds(const MeshData& mesh, glm::vec3 min, glm::vec3 max, float tolerance = 1e-5f) {
    const Bounds b = computeBounds(mesh);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(b.min[k], min[k], tolerance) << "axis " << k;
        EXPECT_NEAR(b.max[k], max[k], tolerance) << "axis " << k;
    }
}

// Every triangle's winding agrees with its vertex normals (as after a correct transform of both).
void expectWindingMatchesNormals(const MeshData& mesh) {
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const glm::dvec3 face = faceNormal(mesh, t);
        for (int k = 0; k < 3; ++k) {
            ASSERT_GT(glm::dot(face, glm::dvec3(mesh.normals[mesh.indices[t * 3 + k]])), 0.0) << t;
        }
    }
}

// --- real files -------------------------------------------------------------------------------------------

TEST(ModelImport, ObjCube) {
    REQUIRE_TEST_MODELS();
    const Imported result = import(kModels / "OBJ/box.obj");
    ASSERT_TRUE(result.mesh.ok()) << result.mesh.error();
    const MeshData& mesh = *result.mesh;
    expectWellFormed(mesh);
    EXPECT_EQ(mesh.triangleCount(), 12u); // six quads, triangulated
    expectBounds(mesh, glm::vec3(-0.5f), glm::vec3(0.5f));
    EXPECT_NEAR(signedVolume(mesh), 1.0, 1e-6); // wound outward, closed
    EXPECT_TRUE(mesh.uvs.empty());
}

TEST(ModelImport, ObjWithTexturesAndGroups) {
    REQUIRE_TEST_MODELS();
    const Imported result = import(kModels / "OBJ/spider.obj");
    ASSERT_TRUE(result.mesh.ok()) << result.mesh.error();
    expectWellFormed(*result.mesh);
    EXPECT_EQ(result.mesh->uvs.size(), result.mesh->vertexCount());
    EXPECT_GT(result.mesh->triangleCount(), 1000u);
}

TEST(ModelImport, GltfTextFileAndBinaryAgree) {
    REQUIRE_TEST_MODELS();
    const Imported text = import(kModels / "glTF2/BoxTextured-glTF/BoxTextured.gltf");
    const Imported binary = import(kModels / "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb");
    for (const Imported* result : {&text, &binary}) {
        ASSERT_TRUE(result->mesh.ok()) << result->mesh.error();
        const MeshData& mesh = *result->mesh;
        expectWellFormed(mesh);
        EXPECT_EQ(mesh.triangleCount(), 12u);
        EXPECT_EQ(mesh.uvs.size(), mesh.vertexCount()); // first uv channel kept
        expectBounds(mesh, glm::vec3(-0.5f), glm::vec3(0.5f));
        EXPECT_NEAR(signedVolume(mesh), 1.0, 1e-5);
        expectWindingMatchesNormals(mesh); // the file's node rotates the box; normals follow it
    }
    EXPECT_EQ(text.mesh->positions, binary.mesh->positions);
}

TEST(ModelImport, PlyAsciiAndBinary) {
    REQUIRE_TEST_MODELS();
    for (const char* name : {"PLY/cube.ply", "PLY/cube_binary.ply"}) {
        const Imported result = import(kModels / name);
        ASSERT_TRUE(result.mesh.ok()) << name << ": " << result.mesh.error();
        expectWellFormed(*result.mesh);
        EXPECT_EQ(result.mesh->triangleCount(), 12u) << name;
        expectBounds(*result.mesh, glm::vec3(0.0f), glm::vec3(1.0f));
    }
}

TEST(ModelImport, StlAsciiAndBinary) {
    REQUIRE_TEST_MODELS();
    const Imported triangle = import(kModels / "STL/triangle.stl");
    ASSERT_TRUE(triangle.mesh.ok()) << triangle.mesh.error();
    EXPECT_EQ(triangle.mesh->triangleCount(), 1u);
    expectBounds(*triangle.mesh, {-1, -1, 0}, {1, 1, 0});
    EXPECT_GT(faceNormal(*triangle.mesh, 0).z, 0.0); // the file's facet normal is +Z

    const Imported ascii = import(kModels / "STL/Spider_ascii.stl");
    const Imported binary = import(kModels / "STL/Spider_binary.stl");
    ASSERT_TRUE(ascii.mesh.ok()) << ascii.mesh.error();
    ASSERT_TRUE(binary.mesh.ok()) << binary.mesh.error();
    expectWellFormed(*binary.mesh);
    EXPECT_EQ(ascii.mesh->triangleCount(), binary.mesh->triangleCount());
    const Bounds a = computeBounds(*ascii.mesh), b = computeBounds(*binary.mesh);
    EXPECT_NEAR(glm::distance(a.min, b.min), 0.0f, 1e-3f);
    EXPECT_NEAR(glm::distance(a.max, b.max), 0.0f, 1e-3f);
}

TEST(ModelImport, FbxAndCollada) {
    REQUIRE_TEST_MODELS();
    for (const char* name : {"FBX/box.fbx", "FBX/spider.fbx", "FBX/cubes_with_mirroring_and_pivot.fbx",
                             "Collada/duck.dae", "Collada/teapots.DAE", "Collada/teapot_instancenodes.DAE"}) {
        SCOPED_TRACE(name);
        const Imported result = import(kModels / name);
        ASSERT_TRUE(result.mesh.ok()) << result.mesh.error();
        expectWellFormed(*result.mesh);
    }
}

// The node hierarchy is flattened exactly as Assimp's own PreTransformVertices step would do it.
TEST(ModelImport, HierarchyFlattenedLikeAssimpPreTransform) {
    REQUIRE_TEST_MODELS();
    for (const char* name :
         {"Collada/teapot_instancenodes.DAE", "Collada/duck.dae", "FBX/cubes_with_mirroring_and_pivot.fbx",
          "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"}) {
        SCOPED_TRACE(name);
        const Imported result = import(kModels / name);
        ASSERT_TRUE(result.mesh.ok()) << result.mesh.error();

        Assimp::Importer importer;
        importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
        importer.SetPropertyBool(AI_CONFIG_PP_FD_REMOVE, true);
        const aiScene* scene = importer.ReadFile((kModels / name).string(),
                                                 aiProcess_Triangulate | aiProcess_FindDegenerates |
                                                     aiProcess_SortByPType | aiProcess_PreTransformVertices);
        ASSERT_NE(scene, nullptr) << importer.GetErrorString();
        glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
        std::size_t triangles = 0;
        for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
            const aiMesh* mesh = scene->mMeshes[m];
            triangles += mesh->mNumFaces;
            for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
                const glm::vec3 p(mesh->mVertices[v].x, mesh->mVertices[v].y, mesh->mVertices[v].z);
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
        }
        // Our repair also drops zero-area triangles Assimp keeps, so it can only have a few fewer.
        EXPECT_LE(result.mesh->triangleCount(), triangles);
        EXPECT_GE(result.mesh->triangleCount(), triangles * 99 / 100);
        const float tolerance = 1e-4f * glm::length(hi - lo);
        expectBounds(*result.mesh, lo, hi, tolerance);
    }
}

// --- node transforms on a file we write, so the expected numbers are known ---------------------------------

std::string base64(const std::string& bytes) {
    static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
        std::uint32_t chunk = 0;
        for (std::size_t k = 0; k < 3; ++k) {
            chunk = (chunk << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
        }
        for (std::size_t k = 0; k < 4; ++k) {
            out += k <= n ? kAlphabet[(chunk >> (18 - 6 * k)) & 63u] : '=';
        }
    }
    return out;
}

// A glTF file holding one triangle with one normal, placed by the given node list (node 0 is the root).
fs::path writeTriangleGltf(const fs::path& path, const std::array<glm::vec3, 3>& corners, glm::vec3 normal,
                           const std::string& nodes) {
    std::string buffer;
    const auto append = [&](const void* data, std::size_t size) {
        buffer.append(static_cast<const char*>(data), size);
    };
    for (const glm::vec3& p : corners) {
        append(&p, sizeof p);
    }
    for (int k = 0; k < 3; ++k) {
        append(&normal, sizeof normal);
    }
    const std::uint16_t indices[4] = {0, 1, 2, 0};
    append(indices, sizeof indices);
    const glm::vec3 lo = glm::min(corners[0], glm::min(corners[1], corners[2]));
    const glm::vec3 hi = glm::max(corners[0], glm::max(corners[1], corners[2]));
    std::ostringstream json;
    json << R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":)" << nodes
         << R"(,"meshes":[{"primitives":[{"attributes":{"POSITION":0,"NORMAL":1},"indices":2}]}],)"
         << R"("buffers":[{"byteLength":80,"uri":"data:application/octet-stream;base64,)" << base64(buffer)
         << R"("}],"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},)"
         << R"({"buffer":0,"byteOffset":36,"byteLength":36},{"buffer":0,"byteOffset":72,"byteLength":6}],)"
         << R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[)" << lo.x
         << ',' << lo.y << ',' << lo.z << "],\"max\":[" << hi.x << ',' << hi.y << ',' << hi.z << "]},"
         << R"({"bufferView":1,"componentType":5126,"count":3,"type":"VEC3"},)"
         << R"({"bufferView":2,"componentType":5123,"count":3,"type":"SCALAR"}]})";
    return writeFile(path, json.str());
}

bool near(glm::vec3 a, glm::vec3 b) {
    return glm::distance(a, b) < 1e-5f;
}

bool containsPosition(const MeshData& mesh, glm::vec3 p) {
    return std::any_of(mesh.positions.begin(), mesh.positions.end(), [&](glm::vec3 q) { return near(p, q); });
}

TEST(ModelImport, NestedNodeTransformsAreApplied) {
    const fs::path folder = freshFolder();
    // Root moves by +10 in x; its child turns 90 degrees about +X, taking +Y to +Z and +Z to -Y.
    const fs::path file =
        writeTriangleGltf(folder / "nested.gltf", {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}, {0, 0, 1},
                          R"([{"translation":[10,0,0],"children":[1]},)"
                          R"({"rotation":[0.70710678,0,0,0.70710678],"mesh":0}])");
    const Imported result = import(file);
    ASSERT_TRUE(result.mesh.ok()) << result.mesh.error();
    const MeshData& mesh = *result.mesh;
    expectWellFormed(mesh);
    ASSERT_EQ(mesh.triangleCount(), 1u);
    EXPECT_TRUE(containsPosition(mesh, {10, 0, 0}));
    EXPECT_TRUE(containsPosition(mesh, {11, 0, 0}));
    EXPECT_TRUE(containsPosition(mesh, {10, 0, 1}));
    for (const glm::vec3& n : mesh.normals) {
        EXPECT_TRUE(near(n, {0, -1, 0})) << n.x << ' ' << n.y << ' ' << n.z;
    }
    expectWindingMatchesNormals(mesh);
}

TEST(ModelImport, NormalsUseTheInverseTranspose) {
    const fs::path folder = freshFolder();
    // A slanted triangle stretched 4x along z: transforming its normal like a position would tilt it the
    // wrong way; the inverse transpose keeps it perpendicular to the stretched triangle.
    const fs::path file =
        writeTriangleGltf(folder / "stretched.gltf", {{{0, 0, 0}, {1, 0, 0}, {0, 1, 1}}},
                          glm::normalize(glm::vec3(0, -1, 1)), R"([{"scale":[1,1,4],"mesh":0}])");
    const Imported result = import(file);
    ASSERT_TRUE(result.mesh.ok()) << result.mesh.error();
    const MeshData& mesh = *result.mesh;
    ASSERT_EQ(mesh.triangleCount(), 1u);
    EXPECT_TRUE(containsPosition(mesh, {0, 1, 4}));
    const glm::vec3 expected = glm::normalize(glm::vec3(0, -4, 1));
    for (const glm::vec3& n : mesh.normals) {
        EXPECT_TRUE(near(n, expected)) << n.x << ' ' << n.y << ' ' << n.z;
    }
    EXPECT_NEAR(glm::dot(glm::normalize(faceNormal(mesh, 0)), glm::dvec3(expected)), 1.0, 1e-6);
}

TEST(ModelImport, MirroringTransformKeepsTrianglesFrontFacing) {
    const fs::path folder = freshFolder();
    const fs::path file = writeTriangleGltf(folder / "mirrored.gltf", {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}},
                                            {0, 0, 1}, R"([{"scale":[-1,1,1],"mesh":0}])");
    const Imported result = import(file);
    ASSERT_TRUE(result.mesh.ok()) << result.mesh.error();
    const MeshData& mesh = *result.mesh;
    EXPECT_TRUE(containsPosition(mesh, {-1, 0, 0}));
    for (const glm::vec3& n : mesh.normals) {
        EXPECT_TRUE(near(n, {0, 0, 1}));
    }
    // The mirror turned the triangle clockwise; the import swaps two corners so it still faces its normal.
    EXPECT_GT(faceNormal(mesh, 0).z, 0.0);
}

// --- broken input --------------------------------------------------------------------------------------

void expectErrorNaming(const Imported& result, const std::string& file, const std::string& reason = "") {
    ASSERT_FALSE(result.mesh.ok()) << file << " imported unexpectedly";
    EXPECT_EQ(result.mesh.error().rfind(file + ": ", 0), 0u) << result.mesh.error();
    if (!reason.empty()) {
        EXPECT_NE(result.mesh.error().find(reason), std::string::npos) << result.mesh.error();
    }
}

// Broken files either fail with a message that names them, or import as a well-formed mesh.
void expectFailsOrWellFormed(const fs::path& path) {
    SCOPED_TRACE(path.string());
    const Imported result = import(path);
    if (result.mesh.ok()) {
        expectWellFormed(*result.mesh);
    } else {
        EXPECT_EQ(result.mesh.error().rfind(path.filename().string() + ": ", 0), 0u) << result.mesh.error();
    }
}

TEST(ModelImport, MissingFileDirectoryAndEmptyFile) {
    const fs::path folder = freshFolder();
    expectErrorNaming(import(folder / "nothing.obj"), "nothing.obj", "file not found");
    fs::create_directories(folder / "folder.obj");
    expectErrorNaming(import(folder / "folder.obj"), "folder.obj", "not a regular file");
    expectErrorNaming(import(writeFile(folder / "empty.obj", "")), "empty.obj", "file is empty");
}

TEST(ModelImport, GarbageAndUnknownFormats) {
    const fs::path folder = freshFolder();
    std::mt19937 random(7);
    std::string garbage(4096, '\0');
    for (char& c : garbage) {
        c = static_cast<char>(random());
    }
    expectErrorNaming(import(writeFile(folder / "garbage.xyz", garbage)), "garbage.xyz",
                      "unknown model format");
    expectErrorNaming(import(writeFile(folder / "notes.txt", "just some text\n")), "notes.txt");
    for (const char* name :
         {"garbage.obj", "garbage.fbx", "garbage.glb", "garbage.ply", "garbage.stl", "garbage.dae"}) {
        expectFailsOrWellFormed(writeFile(folder / name, garbage));
    }
}

TEST(ModelImport, TruncatedObj) {
    const fs::path folder = freshFolder();
    const std::string head = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\n";
    // Cut in the middle of a face, of a vertex, and a face that refers past the end of the vertex list.
    expectFailsOrWellFormed(writeFile(folder / "cut_face.obj", head + "f 2 4 3\nf 3 4 "));
    expectFailsOrWellFormed(writeFile(folder / "cut_vertex.obj", head + "f 2 4 3\nv 0.5 0."));
    expectFailsOrWellFormed(writeFile(folder / "dangling.obj", head + "f 2 4 7\n"));
    // Points only: nothing to render.
    expectErrorNaming(import(writeFile(folder / "points.obj", "v 0 0 0\nv 1 0 0\np 1\np 2\n")), "points.obj",
                      "no triangles");
}

TEST(ModelImport, ObjWithNanKeepsTheGoodTriangles) {
    const fs::path folder = freshFolder();
    const fs::path file = writeFile(folder / "nan.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan 0 0\nv 1 1 0\n"
                                                        "f 1 2 3\nf 2 4 3\nf 2 5 3\n");
    const Imported result = import(file);
    ASSERT_TRUE(result.mesh.ok()) << result.mesh.error();
    expectWellFormed(*result.mesh);
    EXPECT_EQ(result.mesh->triangleCount(), 2u);
    expectBounds(*result.mesh, {0, 0, 0}, {1, 1, 0});
    ASSERT_FALSE(result.warnings.empty());
    EXPECT_EQ(result.warnings[0].rfind("nan.obj: ", 0), 0u) << result.warnings[0];
    EXPECT_NE(result.warnings[0].find("non-finite"), std::string::npos) << result.warnings[0];

    // Only NaN triangles: an error, not an empty mesh.
    expectErrorNaming(import(writeFile(folder / "allnan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")),
                      "allnan.obj", "no usable triangles");
}

TEST(ModelImport, AbsurdDeclaredCountsAreRefusedQuickly) {
    const fs::path folder = freshFolder();
    expectErrorNaming(
        import(writeFile(folder / "huge.off", "OFF\n3 2000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")),
        "huge.off", "declares");
    expectErrorNaming(
        import(writeFile(folder / "huge.ply", "ply\nformat ascii 1.0\nelement vertex 3\n"
                                              "property float x\nproperty float y\nproperty float z\n"
                                              "element face 3000000000\n"
                                              "property list uchar int vertex_indices\nend_header\n"
                                              "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")),
        "huge.ply", "declares");
}

TEST(ModelImport, AssimpInvalidCorpus) {
    REQUIRE_TEST_MODELS();
    std::size_t checked = 0;
    for (const fs::directory_entry& entry : fs::directory_iterator(kModels / "invalid")) {
        if (entry.path().extension() == ".txt") {
            continue;
        }
        expectFailsOrWellFormed(entry.path());
        ++checked;
        if (entry.file_size() == 0) {
            expectErrorNaming(import(entry.path()), entry.path().filename().string(), "file is empty");
        }
    }
    EXPECT_GE(checked, 10u);
    // Declares 353535235358 faces in 309 bytes.
    expectErrorNaming(import(kModels / "invalid/OutOfMemory.off"), "OutOfMemory.off", "declares");
    expectErrorNaming(import(kModels / "invalid/malformed.obj"), "malformed.obj");
}

TEST(ModelImport, AssimpBrokenGltfCorpus) {
    REQUIRE_TEST_MODELS();
    for (const char* name :
         {"glTF2/IndexOutOfRange/IndexOutOfRange.gltf", "glTF2/IndexOutOfRange/AllIndicesOutOfRange.gltf",
          "glTF2/MissingBin/BoxTextured.gltf", "glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb",
          "glTF2/RecursiveNodes/RecursiveNodes.gltf", "glTF2/BoxBadNormals-glTF-Binary/BoxBadNormals.glb"}) {
        expectFailsOrWellFormed(kModels / name);
    }
    expectErrorNaming(import(kModels / "glTF2/MissingBin/BoxTextured.gltf"), "BoxTextured.gltf",
                      "BoxTextured0.bin");
    expectErrorNaming(import(kModels / "glTF2/RecursiveNodes/RecursiveNodes.gltf"), "RecursiveNodes.gltf");
    // Every corner is infinite: nothing survives repair.
    expectErrorNaming(import(kModels / "glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb"),
                      "BoxWithInfinites.glb", "no usable triangles");
}

TEST(ModelImport, PointsAndLinesAreDropped) {
    REQUIRE_TEST_MODELS();
    expectErrorNaming(import(kModels / "OBJ/testpoints.obj"), "testpoints.obj", "no triangles");
    expectErrorNaming(import(kModels / "PLY/points.ply"), "points.ply", "no triangles");
    const Imported mixed = import(kModels / "OBJ/testmixed.obj");
    ASSERT_TRUE(mixed.mesh.ok()) << mixed.mesh.error();
    expectWellFormed(*mixed.mesh);
}

} // namespace
} // namespace speculum::document
