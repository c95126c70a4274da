// The model read in a child process: a reader that crashes, hangs or is cancelled ends in a one-line
// refusal naming the file while this process goes on, no child is left behind, and a model read in the
// child arrives exactly as the same read in-process gives it (parts, meshes, materials, embedded textures,
// node tree, unit scale, bounds, warnings).
#include "scene/import/ModelImportProcess.hpp"

#include "scene/import/ModelImport.hpp"
#include "scene/import/ModelSerialization.hpp"
#include "support/TestPaths.hpp"

#include <QJsonArray>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace speculum::document {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

const fs::path kModels = "/usr/share/assimp/models";
const fs::path kSeeds = fs::path(speculum::testSourcePath()) / "tests/fuzz/model-seeds";

#define REQUIRE_TEST_MODELS()                                                                                \
    if (!fs::is_directory(kModels)) {                                                                        \
        GTEST_SKIP() << kModels << " is missing; install the assimp-testmodels package";                     \
    }

fs::path freshFolder() {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const fs::path folder = fs::path(speculum::testDataPath()) / "editor_import_child" /
                            (std::string(info->test_suite_name()) + "." + info->name());
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

fs::path writeTriangleObj(const fs::path& folder) {
    const fs::path path = folder / "triangle.obj";
    std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    return path;
}

// No child of this process is left, running or zombie.
bool noChildren() {
    errno = 0;
    return ::waitpid(-1, nullptr, WNOHANG) == -1 && errno == ECHILD;
}

// Restores the defaults a test changed.
struct ChildSettings {
    ~ChildSettings() {
        scene::detail::setImportChildTestAction(nullptr);
        scene::setModelImportCpuLimit(scene::kDefaultModelImportCpuSeconds);
    }
};

void expectOneLineNaming(const std::string& message, const std::string& file) {
    EXPECT_EQ(message.rfind(file + ": ", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(ImportChild, AssimpCrashIsARefusalNamingTheFile) {
    // A 370-byte PLY on which Assimp 5.2's post-processing dereferences a bad pointer (found by fuzzing).
    const fs::path folder = freshFolder();
    const fs::path file = folder / "model.ply";
    fs::copy_file(kSeeds / "ply-postprocess-crash.ply", file);
    std::vector<std::string> warnings;
    const auto result = scene::importModelFile(file.string(), warnings);
    ASSERT_FALSE(result.ok());
    expectOneLineNaming(result.error(), "model.ply");
    EXPECT_NE(result.error().find("crashed on this file (SIG"), std::string::npos) << result.error();
    EXPECT_TRUE(noChildren());
    // And this process reads the next file as usual.
    EXPECT_TRUE(scene::importModelFile(writeTriangleObj(folder).string(), warnings).ok());
}

TEST(ImportChild, ReaderThatAbortsIsARefusal) {
    ChildSettings restore;
    scene::detail::setImportChildTestAction([] { std::abort(); });
    std::vector<std::string> warnings;
    const auto result = scene::importModelFile(writeTriangleObj(freshFolder()).string(), warnings);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error(),
              "triangle.obj: the model reader crashed on this file (SIGABRT); it is probably damaged");
    EXPECT_TRUE(noChildren());
}

// A reader killed from outside (kill -9 on the child, not the kernel's out-of-memory killer) is said to
// be that, not an out-of-memory failure the user would chase.
TEST(ImportChild, AReaderKilledFromOutsideIsNotCalledOutOfMemory) {
    ChildSettings restore;
    scene::detail::setImportChildTestAction([] { ::raise(SIGKILL); });
    std::vector<std::string> warnings;
    const auto result = scene::importModelFile(writeTriangleObj(freshFolder()).string(), warnings);
    ASSERT_FALSE(result.ok());
    expectOneLineNaming(result.error(), "triangle.obj");
    EXPECT_EQ(result.error().find("ran out of memory"), std::string::npos) << result.error();
    EXPECT_NE(result.error().find("killed"), std::string::npos) << result.error();
    EXPECT_TRUE(noChildren());
}

TEST(ImportChild, HangingReaderIsStoppedByTheCpuLimit) {
    ChildSettings restore;
    scene::setModelImportCpuLimit(1);
    scene::detail::setImportChildTestAction([] {
        volatile unsigned long spin = 0;
        for (;;) {
            spin = spin + 1;
        }
    });
    std::vector<std::string> warnings;
    const auto started = Clock::now();
    const auto result = scene::importModelFile(writeTriangleObj(freshFolder()).string(), warnings);
    const double seconds = std::chrono::duration<double>(Clock::now() - started).count();
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error(), "triangle.obj: took more than 1 s of CPU to read; stopped");
    EXPECT_LT(seconds, 10.0); // 1 s of CPU, however busy the machine
    EXPECT_TRUE(noChildren());
}

TEST(ImportChild, PlyThatHangsAssimpIsStoppedByTheCpuLimit) {
    // A 288-byte PLY on which Assimp 5.2's reader never finishes (found by fuzzing).
    ChildSettings restore;
    scene::setModelImportCpuLimit(2);
    const fs::path file = freshFolder() / "model.ply";
    fs::copy_file(kSeeds / "ply-reader-hang.ply", file);
    std::vector<std::string> warnings;
    const auto result = scene::importModelFile(file.string(), warnings);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error(), "model.ply: took more than 2 s of CPU to read; stopped");
    EXPECT_TRUE(noChildren());
}

TEST(ImportChild, CancelStopsASlowReadPromptlyAndReapsTheChild) {
    ChildSettings restore;
    scene::detail::setImportChildTestAction([] { ::sleep(60); }); // a reader that takes its time
    std::atomic<bool> cancel{false};
    scene::ImportControl control;
    control.cancel = &cancel;
    std::vector<std::string> warnings;
    Clock::time_point cancelledAt;
    std::thread canceller([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        cancelledAt = Clock::now();
        cancel = true;
    });
    const auto result = scene::importModelFile(writeTriangleObj(freshFolder()).string(), warnings, control);
    const auto returnedAt = Clock::now();
    canceller.join();
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error(), "cancelled");
    EXPECT_LT(std::chrono::duration<double>(returnedAt - cancelledAt).count(), 1.0);
    EXPECT_TRUE(noChildren());
}

TEST(ImportChild, ProgressArrivesFromTheChildInOrder) {
    std::vector<double> fractions;
    std::vector<std::string> phases;
    scene::ImportControl control;
    control.progress = [&](double fraction, const char* phase) {
        fractions.push_back(fraction);
        phases.emplace_back(phase);
    };
    std::vector<std::string> warnings;
    ASSERT_TRUE(scene::importModelFile(writeTriangleObj(freshFolder()).string(), warnings, control).ok());
    ASSERT_GE(fractions.size(), 3u);
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
    EXPECT_EQ(fractions.back(), 1.0);
    EXPECT_EQ(phases.front(), "reading");
    EXPECT_EQ(phases.back(), "done");
}

TEST(ImportChild, RefusalsOfTheReaderKeepTheirMessages) {
    const fs::path folder = freshFolder();
    const fs::path points = folder / "points.obj";
    std::ofstream(points) << "v 0 0 0\nv 1 0 0\np 1\np 2\n";
    std::vector<std::string> warnings, inProcessWarnings;
    const auto child = scene::importModelFile(points.string(), warnings);
    const auto inProcess = scene::detail::importModelFileInProcess(points.string(), inProcessWarnings);
    ASSERT_FALSE(child.ok());
    ASSERT_FALSE(inProcess.ok());
    EXPECT_EQ(child.error(), inProcess.error());
    EXPECT_EQ(warnings, inProcessWarnings);
}

// Run by hand (--gtest_also_run_disabled_tests) to measure what the child costs: each file in
// SPECULUM_IMPORT_BENCH_FILES (colon-separated), imported in the child and in-process, best of 3.
TEST(ImportChild, DISABLED_Overhead) {
    const char* files = std::getenv("SPECULUM_IMPORT_BENCH_FILES");
    if (files == nullptr) {
        GTEST_SKIP() << "set SPECULUM_IMPORT_BENCH_FILES";
    }
    std::string list = files;
    for (std::size_t start = 0; start < list.size();) {
        const std::size_t end = std::min(list.find(':', start), list.size());
        const std::string file = list.substr(start, end - start);
        start = end + 1;
        double best[2] = {1e9, 1e9};
        for (int round = 0; round < 3; ++round) {
            for (int inChild = 0; inChild < 2; ++inChild) {
                std::vector<std::string> warnings;
                const auto started = Clock::now();
                const auto model = inChild ? scene::importModelFile(file, warnings)
                                           : scene::detail::importModelFileInProcess(file, warnings);
                const double ms = std::chrono::duration<double, std::milli>(Clock::now() - started).count();
                ASSERT_TRUE(model.ok()) << model.error();
                best[inChild] = std::min(best[inChild], ms);
            }
        }
        std::printf("%s: in-process %.1f ms, child %.1f ms\n", file.c_str(), best[0], best[1]);
    }
}

// --- The same model through the child as in-process ---

void expectSameMesh(const render::MeshData& a, const render::MeshData& b, const std::string& what) {
    EXPECT_TRUE(a.positions == b.positions) << what;
    EXPECT_TRUE(a.normals == b.normals) << what;
    EXPECT_TRUE(a.uvs == b.uvs) << what;
    EXPECT_TRUE(a.colors == b.colors) << what;
    EXPECT_TRUE(a.tangents == b.tangents) << what;
    EXPECT_TRUE(a.indices == b.indices) << what;
}

void expectSameNodes(const scene::ImportedNode& a, const scene::ImportedNode& b) {
    EXPECT_EQ(a.name, b.name);
    EXPECT_TRUE(a.local == b.local) << a.name;
    EXPECT_EQ(a.parts, b.parts) << a.name;
    ASSERT_EQ(a.children.size(), b.children.size()) << a.name;
    for (std::size_t i = 0; i < a.children.size(); ++i) {
        expectSameNodes(a.children[i], b.children[i]);
    }
}

void expectSameModel(const scene::ImportedModel& a, const scene::ImportedModel& b) {
    ASSERT_EQ(a.parts.size(), b.parts.size());
    for (std::size_t i = 0; i < a.parts.size(); ++i) {
        EXPECT_EQ(a.parts[i].name, b.parts[i].name);
        EXPECT_EQ(a.parts[i].material, b.parts[i].material);
        ASSERT_EQ(bool(a.parts[i].mesh), bool(b.parts[i].mesh));
        if (a.parts[i].mesh) {
            expectSameMesh(*a.parts[i].mesh, *b.parts[i].mesh, a.parts[i].name);
        }
    }
    EXPECT_TRUE(a.materials == b.materials);
    ASSERT_EQ(a.embeddedTextures.size(), b.embeddedTextures.size());
    for (const auto& [key, image] : a.embeddedTextures) {
        ASSERT_EQ(b.embeddedTextures.count(key), 1u) << key;
        const render::TextureImage& other = *b.embeddedTextures.at(key);
        EXPECT_EQ(image->width, other.width);
        EXPECT_EQ(image->height, other.height);
        EXPECT_TRUE(image->rgba8 == other.rgba8) << key;
        EXPECT_TRUE(image->linear == other.linear) << key;
        EXPECT_EQ(image->decodedFromSrgb, other.decodedFromSrgb);
    }
    expectSameNodes(a.root, b.root);
    EXPECT_EQ(a.unitScale, b.unitScale);
    EXPECT_TRUE(a.bounds.min == b.bounds.min && a.bounds.max == b.bounds.max);
}

std::size_t triangles(const scene::ImportedModel& model) {
    std::size_t count = 0;
    for (const scene::ImportedPart& part : model.parts) {
        count += part.mesh ? part.mesh->triangleCount() : 0;
    }
    return count;
}

class SameAsInProcess : public ::testing::TestWithParam<const char*> {};

TEST_P(SameAsInProcess, PartsMaterialsTexturesNodesAndWarnings) {
    REQUIRE_TEST_MODELS();
    const fs::path file = kModels / GetParam();
    std::vector<std::string> warnings, inProcessWarnings;
    const auto child = scene::importModelFile(file.string(), warnings);
    const auto inProcess = scene::detail::importModelFileInProcess(file.string(), inProcessWarnings);
    ASSERT_TRUE(child.ok()) << child.error();
    ASSERT_TRUE(inProcess.ok()) << inProcess.error();
    EXPECT_GT(child->parts.size(), 0u);
    EXPECT_GT(triangles(*child), 0u);
    expectSameModel(*child, *inProcess);
    EXPECT_EQ(warnings, inProcessWarnings);
}

INSTANTIATE_TEST_SUITE_P(Models, SameAsInProcess,
                         ::testing::Values("OBJ/spider.obj",                                // OBJ + MTL + jpg
                                           "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", // embedded PNG
                                           "FBX/spider.fbx", "FBX/cubes_with_names.fbx",    // FBX, units
                                           "Collada/kwxport_test_vcolors.dae"));            // vertex colours

TEST(ImportChild, KnownValuesOfTheTexturedGlb) {
    REQUIRE_TEST_MODELS();
    const fs::path glb = kModels / "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
    std::vector<std::string> warnings;
    const auto model = scene::importModelFile(glb.string(), warnings);
    ASSERT_TRUE(model.ok()) << model.error();
    ASSERT_EQ(model->parts.size(), 1u);
    EXPECT_EQ(model->parts[0].mesh->triangleCount(), 12u);
    ASSERT_EQ(model->embeddedTextures.count(glb.string() + "#*0"), 1u);
    const render::TextureImage& image = *model->embeddedTextures.at(glb.string() + "#*0");
    EXPECT_GT(image.width, 0);
    EXPECT_EQ(image.rgba8.size(), std::size_t(image.width) * image.height * 4);
}

// --- The stream between them ---

scene::MaterialComponent everyFieldSet() {
    scene::MaterialComponent m;
    m.color = {0.1, 0.2, 0.3};
    m.ambient = 0.4;
    m.diffuse = 0.5;
    m.specular = 0.6;
    m.shininess = 7.0;
    m.emission = {0.8, 0.9, 1.1};
    m.texture.path = "/a/base.png";
    m.specularColor = {0.3, 0.2, 0.1};
    m.emissionTexture.path = "/a/glow.png";
    m.normalTexture.path = "/a/normal.png";
    m.normalScale = 0.75;
    m.wrap = {scene::TextureWrap::ClampToEdge, scene::TextureWrap::MirroredRepeat};
    m.opacity = 0.25;
    m.alphaMode = scene::AlphaMode::Mask;
    m.alphaCutoff = 0.3;
    return m;
}

TEST(ImportChildStream, MaterialRoundTripsEveryField) {
    // The child's serialization walks Material's declaration; every declared field is set above to something
    // other than its default, so a field the walk missed would come back as its default.
    const scene::MaterialComponent material = everyFieldSet();
    render::Material::fields([&](const auto& field) {
        EXPECT_FALSE(material.*field.member == scene::MaterialComponent{}.*field.member)
            << field.spec.name << " is not set in everyFieldSet()";
    });
    scene::detail::ByteWriter out;
    scene::detail::writeMaterial(out, material);
    scene::detail::ByteReader in(out.out);
    scene::MaterialComponent back;
    ASSERT_TRUE(scene::detail::readMaterial(in, back));
    EXPECT_TRUE(in.atEnd());
    EXPECT_TRUE(back == material);
}

scene::detail::ChildImport sampleAnswer() {
    scene::detail::ChildImport answer;
    answer.ok = true;
    answer.notes = {"only the first texture coordinate set is used"};
    scene::ImportedModel& model = answer.model;
    model.materials = {everyFieldSet(), scene::MaterialComponent{}};
    render::MeshData mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    mesh.uvs = {{0, 0}, {1, 0}, {0, 1}};
    mesh.indices = {0, 1, 2};
    model.parts = {{"tri", render::freezeMesh(render::MeshData(mesh)), 0}, {"empty", nullptr, -1}};
    auto image = std::make_shared<render::TextureImage>();
    image->width = 1;
    image->height = 1;
    image->rgba8 = {1, 2, 3, 4};
    model.embeddedTextures["/m.fbx#*1"] = image;
    answer.compressedTextures["/m.glb#*0"] = {"*0", std::string("\x89PNG", 4)};
    model.root.name = "root";
    model.root.local[3][0] = 2.0;
    model.root.children.resize(2);
    model.root.children[0].name = "a";
    model.root.children[0].parts = {0};
    model.root.children[1].name = "b";
    model.root.children[1].children.resize(1);
    model.root.children[1].children[0].parts = {1, 0};
    model.unitScale = 0.01;
    model.bounds = {{0, 0, 0}, {1, 1, 0}};
    return answer;
}

TEST(ImportChildStream, ModelRoundTrips) {
    const scene::detail::ChildImport answer = sampleAnswer();
    const auto back = scene::detail::deserializeChildImport(scene::detail::serializeChildImport(answer));
    ASSERT_TRUE(back.ok()) << back.error();
    EXPECT_TRUE(back->ok);
    EXPECT_EQ(back->notes, answer.notes);
    EXPECT_TRUE(back->compressedTextures == answer.compressedTextures);
    expectSameModel(back->model, answer.model);

    scene::detail::ChildImport refused;
    refused.error = "no triangles";
    refused.notes = {"a note"};
    const auto refusedBack =
        scene::detail::deserializeChildImport(scene::detail::serializeChildImport(refused));
    ASSERT_TRUE(refusedBack.ok());
    EXPECT_FALSE(refusedBack->ok);
    EXPECT_EQ(refusedBack->error, "no triangles");
    EXPECT_EQ(refusedBack->notes, refused.notes);
}

TEST(ImportChildStream, CutShortOrDamagedStreamIsAnError) {
    const std::string bytes = scene::detail::serializeChildImport(sampleAnswer());
    for (std::size_t length = 0; length < bytes.size(); ++length) {
        EXPECT_FALSE(scene::detail::deserializeChildImport(std::string_view(bytes).substr(0, length)).ok())
            << length;
    }
    // Every byte flipped in turn: an error or a model that passed every check, never a crash or a
    // runaway allocation (the sanitizer builds check the reads).
    for (std::size_t at = 0; at < bytes.size(); ++at) {
        std::string damaged = bytes;
        damaged[at] = static_cast<char>(damaged[at] ^ 0xff);
        (void)scene::detail::deserializeChildImport(damaged);
    }
}

} // namespace
} // namespace speculum::document
