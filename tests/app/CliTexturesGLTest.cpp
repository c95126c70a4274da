// Texture files that exist but cannot be used, as a user meets them on the command line: bytes that are no
// image, a cut PNG, an empty file, a file that cannot be read, a model's own missing or corrupt image, and a
// 69-byte PNG that declares 16384×16384 texels. Each is one error line naming the file, exit status 1 and
// no output, unless --keep-going (a warning, and the command goes on without it).
#include "CliRun.hpp"
#include "support/BombPng.hpp"
#include "support/TestPaths.hpp"

#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <string>
#include <vector>

namespace {

namespace test = speculum::test;
namespace fs = std::filesystem;

using test::CliRun;

std::size_t lineCount(const std::string& text) {
    return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

std::string contents(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

void writeBytes(const fs::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// Bytes that no image reader takes for an image.
std::string noise(std::size_t count) {
    std::string bytes(count, '\0');
    std::uint32_t state = 777;
    for (char& b : bytes) {
        state = state * 1664525U + 1013904223U;
        b = static_cast<char>(state >> 24);
    }
    return bytes;
}

// A 64×64 PNG of noise cut to half its bytes: it starts like a PNG and its header reads, its pixels do not.
void writeCutPng(const fs::path& path) {
    const std::string pixels = noise(64 * 64 * 3);
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out && out->open(path.string(), OIIO::ImageSpec(64, 64, 3, OIIO::TypeDesc::UINT8)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data()) && out->close());
    out.reset();
    const std::string whole = contents(path);
    writeBytes(path, whole.substr(0, whole.size() / 2));
}

// A project of a textured floor, a box and a light, the camera looking at them.
void writeTexturedScene(const fs::path& project, const std::string& texture) {
    std::ofstream(project) << R"({"format": "speculum-scene", "version": 1,
        "camera": {"position": [0, 1, 3], "target": [0, 0, 0], "up": [0, 1, 0], "fovY": 60, "near": 0.1,
                   "far": 20},
        "nodes": [{"name": "Box", "mesh": {"builtin": "box"}},
                  {"name": "Light", "transform": {"translate": [0, 2, 2]}, "light": {"type": "point"}},
                  {"name": "Floor", "mesh": {"builtin": "plane"}, "material": {"texture": ")"
                           << texture << R"("}}]})";
}

// A one-triangle glTF whose material's base colour is the image file `image` beside it.
void writeModelWithImage(const fs::path& model, const std::string& image) {
    std::ofstream(model) << R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
        "textures": [{"source": 0}], "images": [{"uri": ")"
                         << image << R"("}],
        "buffers": [{"byteLength": 60, "uri": "data:application/octet-stream;base64,AACAvwAAgL8AAAAAAACAPwAAgL8AAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAIA/AAAAAAAAAD8AAIA/"}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 24}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                       "min": [-1, -1, 0], "max": [1, 1, 0]},
                      {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"}]})";
}

class CliTextures : public ::testing::Test {
protected:
    void SetUp() override { m_dir = test::freshCliFolder("cli"); }

    // Every command that reads the project's textures, each writing into m_dir/out*.
    std::vector<std::string> commands(const fs::path& project) const {
        const std::string p = project.string(), d = m_dir.string();
        return {"render " + p + " -o " + d + "/out.png --size 64x48",
                "render " + p + " -o " + d + "/out.exr --size 64x48 --reference --samples 1",
                "export " + p + " -o " + d + "/out.glb",
                "bench " + p + " --out " + d + "/out-bench --quick --size 64x48",
                "time " + p + " --size 64x48 --frames 1"};
    }

    // Each command fails with one line naming `named`, and writes nothing.
    void expectEveryCommandFails(const fs::path& project, const std::string& named) {
        for (const std::string& command : commands(project)) {
            const CliRun run = test::runSpeculum(command);
            EXPECT_EQ(run.status, 1) << command << " → " << run.err;
            EXPECT_EQ(lineCount(run.err), 1u) << command << " → " << run.err;
            EXPECT_EQ(run.err.rfind("speculum: error: ", 0), 0u) << run.err;
            EXPECT_NE(run.err.find(named), std::string::npos) << command << " → " << run.err;
            EXPECT_NE(run.err.find("--keep-going"), std::string::npos) << run.err;
        }
        for (const char* out : {"out.png", "out.exr", "out.glb", "out-bench"})
            EXPECT_FALSE(fs::exists(m_dir / out)) << out << " was written by a command that failed";
    }

    fs::path m_dir;
};

TEST_F(CliTextures, ATextureThatExistsButDoesNotDecodeFailsEveryCommandUnlessKeepGoing) {
    writeBytes(m_dir / "noise.png", noise(4000));
    writeCutPng(m_dir / "cut.png");
    writeBytes(m_dir / "empty.png", "");
    for (const std::string& texture : {(m_dir / "noise.png").string(), (m_dir / "cut.png").string(),
                                       (m_dir / "empty.png").string(), std::string("/proc/self/mem")}) {
        SCOPED_TRACE(texture);
        const fs::path project = m_dir / "scene.speculum.json";
        writeTexturedScene(project, texture);
        expectEveryCommandFails(project, "'" + texture + "'");

        const CliRun going = test::runSpeculum("render " + project.string() + " -o " +
                                               (m_dir / "out.png").string() + " --size 64x48 --keep-going");
        EXPECT_EQ(going.status, 0) << going.err;
        EXPECT_NE(going.err.find("speculum: warning: node 'Floor': "), std::string::npos) << going.err;
        EXPECT_NE(going.err.find(texture), std::string::npos) << going.err;
        EXPECT_TRUE(fs::exists(m_dir / "out.png"));
        fs::remove(m_dir / "out.png");
    }
}

TEST_F(CliTextures, AnExportWithKeepGoingEmbedsNoImageThatDoesNotDecode) {
    writeCutPng(m_dir / "cut.png");
    const fs::path project = m_dir / "scene.speculum.json";
    writeTexturedScene(project, (m_dir / "cut.png").string());
    const fs::path glb = m_dir / "out.glb";
    const CliRun run =
        test::runSpeculum("export " + project.string() + " -o " + glb.string() + " --keep-going");
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_NE(run.err.find("cut.png"), std::string::npos) << "the texture left out is named: " << run.err;
    const std::string written = contents(glb);
    EXPECT_EQ(written.find("\"images\""), std::string::npos) << "the cut PNG must not be embedded";
    EXPECT_EQ(written.find("\x89PNG"), std::string::npos) << "no PNG bytes in the .glb";
}

TEST_F(CliTextures, AModelsOwnMissingOrCorruptImageFailsUnlessKeepGoing) {
    const fs::path project = m_dir / "model.speculum.json";
    std::ofstream(project) << R"({"format": "speculum-scene", "version": 1,
        "camera": {"position": [0, 0, 3], "target": [0, 0, 0], "up": [0, 1, 0], "fovY": 60, "near": 0.1,
                   "far": 20},
        "nodes": [{"name": "Light", "transform": {"translate": [0, 2, 2]}, "light": {"type": "point"}},
                  {"name": "Statue", "mesh": {"file": "statue.gltf"}}]})";
    writeModelWithImage(m_dir / "statue.gltf", "skin.png");
    for (const bool present : {false, true}) {
        SCOPED_TRACE(present ? "skin.png is noise" : "skin.png is missing");
        if (present)
            writeBytes(m_dir / "skin.png", noise(4000));
        expectEveryCommandFails(project, (m_dir / "skin.png").string());
        const CliRun going = test::runSpeculum("render " + project.string() + " -o " +
                                               (m_dir / "out.png").string() + " --size 64x48 --keep-going");
        EXPECT_EQ(going.status, 0) << going.err;
        EXPECT_NE(going.err.find("speculum: warning: node 'Statue': "), std::string::npos) << going.err;
        EXPECT_NE(going.err.find("skin.png"), std::string::npos) << going.err;
        fs::remove(m_dir / "out.png");
    }
}

TEST_F(CliTextures, ADecompressionBombIsRefusedAtOnceInLittleMemory) {
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "AddressSanitizer reserves far more address space than the cap allows";
#endif
    speculum::test::writeBombPng(m_dir / "bomb.png");
    ASSERT_EQ(fs::file_size(m_dir / "bomb.png"), 69u);
    const fs::path project = m_dir / "bomb.speculum.json";
    writeTexturedScene(project, (m_dir / "bomb.png").string());
    // 2 GiB of address space: the program and its libraries fit, the declared 16384×16384 texels do not.
    for (const std::string& command : commands(project)) {
        const auto start = std::chrono::steady_clock::now();
        const CliRun run = test::runSpeculum(command, "ulimit -v 2097152");
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        EXPECT_EQ(run.status, 1) << command << " → " << run.err;
        EXPECT_EQ(lineCount(run.err), 1u) << command << " → " << run.err;
        EXPECT_NE(run.err.find("bomb.png"), std::string::npos) << run.err;
        EXPECT_NE(run.err.find("16384×16384"), std::string::npos) << run.err;
        EXPECT_LT(seconds, 5.0) << command << ": a 69-byte file is refused at once";
    }
}

} // namespace
