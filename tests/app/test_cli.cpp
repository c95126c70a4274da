// The speculum command line as a user runs it: exit status, the one-line error, the files it writes.
#include "render/StillRenderer.hpp"
#include "render/gl/HeadlessContext.hpp"
#include "support/CliRun.hpp"

#include <OpenImageIO/imageio.h>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

namespace test = speculum::test;
namespace fs = std::filesystem;

using test::CliRun;

CliRun speculum(const std::string& arguments) {
    return test::runSpeculum(arguments);
}

std::string demo() {
    return std::string(SPECULUM_SOURCE_DIR) + "/resources/scenes/teapot.speculum.json";
}

class Cli : public ::testing::Test {
protected:
    void SetUp() override {
        m_dir = fs::path(SPECULUM_TEST_DATA_DIR) /
                ("cli-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }
    fs::path m_dir;
};

TEST_F(Cli, RenderWritesThePngAtTheRequestedSizeWithMetadata) {
    const fs::path out = m_dir / "teapot.png";
    const CliRun run = speculum("render " + demo() + " -o " + out.string() + " --size 320x180");
    ASSERT_EQ(run.status, 0) << run.err;
    auto input = OIIO::ImageInput::open(out.string());
    ASSERT_TRUE(input);
    const OIIO::ImageSpec& spec = input->spec();
    EXPECT_EQ(spec.width, 320);
    EXPECT_EQ(spec.height, 180);
    EXPECT_EQ(spec.nchannels, 4);
    EXPECT_NE(spec.get_string_attribute("Software").find("speculum"), std::string::npos);
    EXPECT_NE(spec.get_string_attribute("ImageDescription").find("teapot.speculum.json"), std::string::npos);
    EXPECT_NE(run.out.find("teapot.png"), std::string::npos) << "prints the path it wrote";
}

TEST_F(Cli, RenderWritesEveryFormatByExtension) {
    for (const char* ext : {"jpg", "tif", "exr"}) {
        const fs::path out = m_dir / (std::string("still.") + ext);
        const CliRun run =
            speculum("render " + demo() + " -o " + out.string() + " --size 64x36 --ssaa 2 --time 0.5");
        ASSERT_EQ(run.status, 0) << ext << ": " << run.err;
        auto input = OIIO::ImageInput::open(out.string());
        ASSERT_TRUE(input) << ext;
        EXPECT_EQ(input->spec().width, 64);
        EXPECT_NE(run.err.find("rendering"), std::string::npos) << "supersampled renders report progress";
    }
}

TEST_F(Cli, BadInputFailsWithOneLineAndWritesNothing) {
    const fs::path out = m_dir / "out.png";
    const fs::path broken = m_dir / "broken.speculum.json";
    std::ofstream(broken)
        << R"({"format": "speculum-scene", "version": 1, "nodes": [{"name": "A", "mesh": {"builtin": "dodecahedron"}}]})";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"render /no/such/scene.json -o " + out.string(), "no such file"},
        {"render " + broken.string() + " -o " + out.string(), "nodes[0].mesh"},
        {"render " + demo() + " -o " + (m_dir / "out.bmpx").string(), "unsupported image format"},
        {"render " + demo() + " -o /no/such/folder/out.png", "does not exist"},
        {"render " + demo() + " -o " + out.string() + " --size 0x10", "--size"},
        {"render " + demo() + " -o " + out.string() + " --size big", "--size"},
        {"render " + demo() + " -o " + out.string() + " --ssaa 99", "--ssaa"},
        {"render " + demo() + " -o " + out.string() + " --time -1", "--time"},
        {"render " + demo(), "-o"},
        {"explain", "PROJECT"},
        {"render " + demo() + " -o " + out.string() + " --frobnicate", "--frobnicate"},
    };
    for (const auto& [args, expected] : cases) {
        const CliRun run = speculum(args);
        EXPECT_NE(run.status, 0) << args;
        EXPECT_NE(run.err.find(expected), std::string::npos) << args << " → " << run.err;
        EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << args << " → " << run.err;
        EXPECT_FALSE(fs::exists(out)) << args;
    }
}

// The largest still this machine's GPU renders in one piece, asked of the same driver the CLI uses.
int gpuStillLimit() {
    auto context = speculum::render::gl::HeadlessContext::create();
    EXPECT_TRUE(context.ok()) << (context.ok() ? "" : context.error());
    return context.ok() ? speculum::render::maxStillSize() : 0;
}

TEST_F(Cli, RenderWiderThanTheGpuAllowsWritesTheWholeImage) {
    const int limit = gpuStillLimit();
    ASSERT_GT(limit, 0);
    const int width = limit + 16;
    const fs::path out = m_dir / "wide.png";
    const CliRun run =
        speculum("render " + demo() + " -o " + out.string() + " --size " + std::to_string(width) + "x8");
    ASSERT_EQ(run.status, 0) << run.err;
    auto input = OIIO::ImageInput::open(out.string());
    ASSERT_TRUE(input);
    EXPECT_EQ(input->spec().width, width);
    EXPECT_EQ(input->spec().height, 8);
}

TEST_F(Cli, SizesNoImageCanHoldAreRefusedBeforeAnyWork) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"huge.png", "1000000x1000000"}, // 14901 GiB of pixels
        {"wide.jpg", "70000x8"},         // JPEG holds at most 65500 pixels per side
    };
    for (const auto& [name, size] : cases) {
        const fs::path out = m_dir / name;
        const CliRun run = speculum("render " + demo() + " -o " + out.string() + " --size " + size);
        EXPECT_NE(run.status, 0) << size;
        const std::string named = name == "huge.png" ? size : "JPEG";
        EXPECT_NE(run.err.find(named), std::string::npos) << size << " → " << run.err;
        EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << size << " → " << run.err;
        EXPECT_FALSE(fs::exists(out)) << size;
    }
    EXPECT_EQ(std::distance(fs::directory_iterator(m_dir), fs::directory_iterator{}), 0) << "nothing written";
}

TEST_F(Cli, FailedRenderLeavesAnExistingFileIntact) {
    const fs::path out = m_dir / "keep.png";
    std::ofstream(out) << "precious";
    const CliRun run = speculum("render /no/such/scene.json -o " + out.string());
    EXPECT_NE(run.status, 0);
    std::ifstream in(out);
    std::string content((std::istreambuf_iterator<char>(in)), {});
    EXPECT_EQ(content, "precious");
    EXPECT_EQ(std::distance(fs::directory_iterator(m_dir), fs::directory_iterator{}), 1)
        << "no temp files left";
}

TEST_F(Cli, ExplainJsonListsShadowAndMainPassesWithReasons) {
    const CliRun run = speculum("explain " + demo() + " --size 320x180 --json");
    ASSERT_EQ(run.status, 0) << run.err;
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(QByteArray::fromStdString(run.out), &error);
    ASSERT_EQ(error.error, QJsonParseError::NoError) << run.out;
    const QJsonArray passes = doc.object()["passes"].toArray();
    bool shadow = false, main = false;
    for (const auto& value : passes) {
        const QJsonObject p = value.toObject();
        EXPECT_FALSE(p["reason"].toString().isEmpty());
        EXPECT_TRUE(p.contains("gpuMs"));
        EXPECT_TRUE(p.contains("cpuMs"));
        EXPECT_TRUE(p.contains("target"));
        shadow |= p["kind"].toString() == "shadow" && p["target"].toString() == "Light";
        main |= p["kind"].toString() == "main";
    }
    EXPECT_TRUE(shadow) << run.out;
    EXPECT_TRUE(main) << run.out;
    EXPECT_TRUE(doc.object()["skipped"].isArray());
}

// What a frame could not do as asked (here a texture that is missing; a map larger than the GPU holds
// is reported the same way) is listed by explain, in text and JSON.
TEST_F(Cli, ExplainListsTheFramesWarnings) {
    const fs::path project = m_dir / "untextured.speculum.json";
    std::ofstream(project) << R"({"format": "speculum-scene", "version": 1, "nodes": [{"name": "Box",
        "mesh": {"builtin": "box"}, "material": {"texture": "missing-marble.png"}}]})";
    const CliRun text = speculum("explain " + project.string() + " --size 64x36");
    ASSERT_EQ(text.status, 0) << text.err;
    const std::size_t section = text.out.find("Warnings:");
    ASSERT_NE(section, std::string::npos) << text.out;
    EXPECT_NE(text.out.find("missing-marble.png", section), std::string::npos) << text.out;

    const CliRun json = speculum("explain " + project.string() + " --size 64x36 --json");
    ASSERT_EQ(json.status, 0) << json.err;
    const QJsonArray warnings =
        QJsonDocument::fromJson(QByteArray::fromStdString(json.out)).object()["warnings"].toArray();
    ASSERT_EQ(warnings.size(), 1) << json.out;
    EXPECT_TRUE(warnings[0].toString().contains("missing-marble.png")) << json.out;
}

TEST_F(Cli, ExplainTextIsReadable) {
    const CliRun run = speculum("explain " + demo() + " --size 160x90");
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_NE(run.out.find("shadow"), std::string::npos);
    EXPECT_NE(run.out.find("main"), std::string::npos);
}

} // namespace

namespace {

TEST_F(Cli, ExplainOfASecondStaticFrameShowsTheReusedMaps) {
    const std::string chrome = std::string(SPECULUM_SOURCE_DIR) + "/resources/scenes/chrome.speculum.json";
    const CliRun first = speculum("explain " + chrome + " --size 160x90 --json");
    ASSERT_EQ(first.status, 0) << first.err;
    EXPECT_NE(first.out.find("\"envmap\""), std::string::npos) << "the first frame captures the environment";
    const CliRun second = speculum("explain " + chrome + " --size 160x90 --json --frame 2");
    ASSERT_EQ(second.status, 0) << second.err;
    EXPECT_EQ(second.out.find("\"envmap\""), std::string::npos)
        << "a static scene reuses its environment map";
    EXPECT_EQ(second.out.find("\"shadow\""), std::string::npos) << "and its shadow maps";
    EXPECT_NE(second.out.find("reused"), std::string::npos);
    EXPECT_NE(speculum("explain " + chrome + " --frame 0").status, 0);
}

// `speculum export`: a self-contained .glb (the demo's marble PNG inside it, camera and light there), a
// .gltf with its companions; bad input fails with one line and writes nothing.
TEST_F(Cli, ExportWritesASelfContainedGlb) {
    const fs::path out = m_dir / "teapot.glb";
    const CliRun run = speculum("export " + demo() + " -o " + out.string());
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_NE(run.out.find(out.string()), std::string::npos) << "prints the path it wrote";
    std::ifstream in(out, std::ios::binary);
    const std::string file((std::istreambuf_iterator<char>(in)), {});
    ASSERT_GT(file.size(), 20u);
    ASSERT_EQ(file.substr(0, 4), "glTF");
    std::uint32_t jsonLength = 0;
    std::memcpy(&jsonLength, file.data() + 12, 4);
    const QJsonObject json =
        QJsonDocument::fromJson(QByteArray::fromStdString(file.substr(20, jsonLength))).object();
    ASSERT_FALSE(json.isEmpty());
    EXPECT_EQ(json["cameras"].toArray().size(), 1);
    EXPECT_EQ(json["extensions"].toObject()["KHR_lights_punctual"].toObject()["lights"].toArray().size(), 1);
    const QJsonArray images = json["images"].toArray();
    ASSERT_EQ(images.size(), 1) << "the marble";
    EXPECT_EQ(images[0].toObject()["mimeType"].toString(), "image/png");
    EXPECT_FALSE(images[0].toObject().contains("uri"));
    EXPECT_EQ(file.find("marble.png"), std::string::npos) << "no path to the source image";
    EXPECT_EQ(std::distance(fs::directory_iterator(m_dir), fs::directory_iterator{}), 1) << "only the .glb";
}

TEST_F(Cli, ExportGltfWritesItsCompanionsBesideIt) {
    const fs::path out = m_dir / "teapot.gltf";
    const CliRun run = speculum("export " + demo() + " -o " + out.string());
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_TRUE(fs::exists(out));
    EXPECT_TRUE(fs::exists(m_dir / "teapot.bin"));
    EXPECT_TRUE(fs::exists(m_dir / "teapot_0.png"));
}

TEST_F(Cli, BadExportFailsWithOneLineAndWritesNothing) {
    const fs::path glb = m_dir / "out.glb";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"export /no/such/scene.json -o " + glb.string(), "no such file"},
        {"export " + demo() + " -o " + (m_dir / "out.obj").string(), "unsupported export format"},
        {"export " + demo() + " -o /no/such/folder/out.glb", "does not exist"},
        {"export " + demo(), "-o"},
        {"export -o " + glb.string(), "PROJECT"},
    };
    for (const auto& [args, expected] : cases) {
        const CliRun run = speculum(args);
        EXPECT_NE(run.status, 0) << args;
        EXPECT_NE(run.err.find(expected), std::string::npos) << args << " → " << run.err;
        EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << args << " → " << run.err;
    }
    EXPECT_EQ(std::distance(fs::directory_iterator(m_dir), fs::directory_iterator{}), 0) << "nothing written";
}

} // namespace
