// The speculum command line as a user runs it: exit status, the one-line error, the files it writes.
#include "CliRun.hpp"
#include "render/gl/HeadlessContext.hpp"
#include "render/renderer/StillRenderer.hpp"
#include "support/TestPaths.hpp"

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
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace {

namespace test = speculum::test;
namespace fs = std::filesystem;

using test::CliRun;

CliRun speculum(const std::string& arguments) {
    return test::runSpeculum(arguments);
}

std::string demo() {
    return speculum::testSourcePath("resources/scenes/teapot.speculum.json");
}

std::string readAll(const fs::path& path);

class Cli : public ::testing::Test {
protected:
    void SetUp() override { m_dir = test::freshCliFolder("cli"); }
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

// The screen-space debug view as a still: the floor of the screen-space demo in the sources' colours,
// said in the metadata; the tracer has no such view.
TEST_F(Cli, RenderDrawsTheScreenSpaceSources) {
    const std::string project = speculum::testSourcePath("resources/scenes/screen-space.speculum.json");
    const fs::path out = m_dir / "sources.png";
    const CliRun run =
        speculum("render " + project + " -o " + out.string() + " --size 160x90 --screen-space-sources");
    ASSERT_EQ(run.status, 0) << run.err;
    auto input = OIIO::ImageInput::open(out.string());
    ASSERT_TRUE(input);
    EXPECT_NE(input->spec().get_string_attribute("speculum:settings").find("screen-space sources"),
              std::string::npos);
    std::vector<unsigned char> pixels(160 * 90 * 4);
    ASSERT_TRUE(input->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, pixels.data()));
    int green = 0; // the floor's pixels that meet what the image shows
    for (std::size_t i = 0; i < pixels.size(); i += 4)
        green += pixels[i] < 40 && pixels[i + 1] > 200 && pixels[i + 2] < 40 ? 1 : 0;
    EXPECT_GT(green, 160 * 90 / 20);
    const CliRun refused = speculum("render " + project + " -o " + (m_dir / "no.png").string() +
                                    " --size 64x36 --reference --screen-space-sources");
    EXPECT_EQ(refused.status, 2);
    EXPECT_NE(refused.err.find("--screen-space-sources: not with --reference"), std::string::npos)
        << refused.err;
    EXPECT_FALSE(fs::exists(m_dir / "no.png"));
}

TEST_F(Cli, RenderWritesEveryFormatByExtension) {
    // The tuned ones, and some of what else OpenImageIO writes (8-bit WebP and Targa, float Radiance HDR).
    for (const char* ext : {"jpg", "tif", "exr", "webp", "tga", "hdr"}) {
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

// Each command has help of its own, on stdout with status 0, naming its own options.
TEST_F(Cli, EachCommandHasItsOwnHelp) {
    const std::vector<std::pair<std::string, std::vector<std::string>>> commands = {
        {"render",
         {"--output", "--size", "--ssaa", "--time", "--reference", "--samples", "--screen-space-sources",
          "--keep-going"}},
        {"explain", {"--size", "--time", "--frame", "--animated", "--preview", "--preview-drag", "--json"}},
        {"bench", {"--out", "--size", "--quick", "--keep-going"}},
        {"time", {"--size", "--frames", "--animated", "--half-float", "--json"}},
        {"export", {"--output", "--keep-going"}},
    };
    for (const auto& [command, options] : commands) {
        for (const char* flag : {" --help", " -h", " scene.speculum.json --help"}) {
            const CliRun run = speculum(command + flag);
            EXPECT_EQ(run.status, 0) << command << flag << ": " << run.err;
            EXPECT_TRUE(run.err.empty()) << run.err;
            EXPECT_NE(run.out.find("Usage: speculum " + command + " [OPTIONS] [PROJECT]"), std::string::npos)
                << run.out;
            for (const std::string& option : options)
                EXPECT_NE(run.out.find(option), std::string::npos) << command << " --help lacks " << option;
            EXPECT_NE(run.out.find("--quiet"), std::string::npos);
        }
    }
    EXPECT_EQ(speculum("explain --help").out.find("--ssaa"), std::string::npos) << "render's options only";
}

// --opt=value means --opt value, and a bad value gets the same message either way.
TEST_F(Cli, OptionsTakeTheirValueAfterAnEqualsSignToo) {
    const fs::path out = m_dir / "equals.png";
    const CliRun run =
        speculum("render " + demo() + " --output=" + out.string() + " --size=64x36 --ssaa=2 --time=0.5");
    ASSERT_EQ(run.status, 0) << run.err;
    auto input = OIIO::ImageInput::open(out.string());
    ASSERT_TRUE(input);
    EXPECT_EQ(input->spec().width, 64);
    EXPECT_EQ(input->spec().height, 36);
    for (const char* bad : {"--size=big", "--ssaa=99", "--time=-1"}) {
        const std::string spaced = std::string(bad).replace(std::string(bad).find('='), 1, " ");
        const CliRun equals = speculum("render " + demo() + " -o " + out.string() + " " + bad);
        const CliRun separate = speculum("render " + demo() + " -o " + out.string() + " " + spaced);
        EXPECT_EQ(equals.status, 2) << bad;
        EXPECT_EQ(equals.err, separate.err) << bad;
    }
    EXPECT_NE(
        speculum("render " + demo() + " -o " + out.string() + " --size").err.find("--size: missing value"),
        std::string::npos);
}

// Values are read one way for every option: an option given twice, or given an empty value, is refused
// by name; numbers are plain decimals with nothing around them (a space, a hexadecimal float) for whole
// numbers and seconds alike. Each is one line, status 2, nothing written.
TEST_F(Cli, EveryOptionValueIsReadTheSameStrictWay) {
    const fs::path out = m_dir / "strict.png";
    const std::string render = "render " + demo() + " --size 32x18 ";
    const struct {
        std::string arguments;
        std::string said;
    } cases[] = {
        {render + "-o " + out.string() + " -o " + out.string(), "--output: given more than once"},
        {render + "-o " + out.string() + " --output=" + out.string(), "--output: given more than once"},
        {render + "-o " + out.string() + " --size 16x16", "--size: given more than once"},
        {render + "-o " + out.string() + " --ssaa ''", "--ssaa: missing value"},
        {render + "-o ''", "--output: missing value"},
        {render + "-o " + out.string() + " --ssaa ' 1'", "--ssaa: expected a whole number, got ' 1'"},
        {render + "-o " + out.string() + " --time ' 1'", "--time: expected a number of seconds, got ' 1'"},
        {render + "-o " + out.string() + " --time 0x1p1",
         "--time: expected a number of seconds, got '0x1p1'"},
        {render + "-o " + out.string() + " --time inf", "--time: expected a number of seconds, got 'inf'"},
    };
    for (const auto& c : cases) {
        const CliRun run = speculum(c.arguments);
        EXPECT_EQ(run.status, 2) << c.arguments;
        EXPECT_EQ(run.err, "speculum: error: " + c.said + "\n") << c.arguments;
        EXPECT_FALSE(fs::exists(out)) << c.arguments;
    }
    EXPECT_EQ(speculum(render + "-o " + out.string() + " --time 1.5e0 -q").status, 0) << "a plain decimal";
    for (const std::string recover : {"--recover", "--recover ''", "--recover a b"}) {
        const CliRun run = speculum(recover);
        EXPECT_EQ(run.status, 2) << recover;
        EXPECT_EQ(run.err, "speculum: error: --recover takes one recovery file\n") << recover;
    }
}

// --quiet leaves stderr to warnings and errors; without it a log gets a line per tenth of the work, and a
// terminal one line rewritten in place.
TEST_F(Cli, ProgressIsQuietOnRequestSparseInALogAndOneLineOnATerminal) {
    const fs::path out = m_dir / "progress.png";
    const std::string render = "render " + demo() + " -o " + out.string() + " --size 48x27 --ssaa 5";
    const CliRun quiet = speculum(render + " --quiet");
    ASSERT_EQ(quiet.status, 0) << quiet.err;
    EXPECT_TRUE(quiet.err.empty()) << quiet.err;
    EXPECT_NE(quiet.out.find(out.string()), std::string::npos) << "the output's path still goes to stdout";
    EXPECT_EQ(speculum(render + " -q --size 0x0").status, 2) << "errors still print and fail";

    const CliRun logged = speculum(render); // stderr is a file here
    ASSERT_EQ(logged.status, 0) << logged.err;
    std::size_t lines = 0;
    for (std::size_t at = logged.err.find("speculum: rendering "); at != std::string::npos;
         at = logged.err.find("speculum: rendering ", at + 1))
        ++lines;
    EXPECT_GE(lines, 2u) << logged.err;
    EXPECT_LE(lines, 11u) << "25 samples, at most a line per tenth: " << logged.err;
    EXPECT_EQ(logged.err.find('\r'), std::string::npos);

    // Under a pseudo-terminal (script(1)): carriage returns and erase-to-end-of-line, one final line.
    const fs::path typescript = m_dir / "typescript.txt";
    const std::string command = "script -qefc \"" + speculum::testCliBinary() + " " + render + "\" " +
                                typescript.string() + " >/dev/null 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0);
    const std::string screen = readAll(typescript);
    EXPECT_NE(screen.find("\rspeculum: rendering "), std::string::npos) << screen;
    EXPECT_NE(screen.find("\x1b[K"), std::string::npos) << screen;
    EXPECT_NE(screen.find("rendering 100%"), std::string::npos) << screen;
}

TEST_F(Cli, BadInputFailsWithOneLineAndWritesNothing) {
    const fs::path out = m_dir / "out.png";
    const fs::path broken = m_dir / "broken.speculum.json";
    std::ofstream(broken)
        << R"({"format": "speculum-scene", "version": 1, "nodes": [{"name": "A", "mesh": {"builtin": "dodecahedron"}}]})";
    const fs::path pipe = m_dir / "pipe.speculum.json";
    ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"render /no/such/scene.json -o " + out.string(), "file not found"},
        {"render " + pipe.string() + " -o " + out.string(), "it is a FIFO (named pipe), not a regular file"},
        {"render /dev/null -o " + out.string(), "it is a device, not a regular file"},
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
        EXPECT_FALSE(p["code"].toString().isEmpty()) << "every pass names its reason's code";
        EXPECT_TRUE(p.contains("gpuMs"));
        EXPECT_TRUE(p.contains("cpuMs"));
        EXPECT_TRUE(p.contains("target"));
        shadow |= p["kind"].toString() == "shadow" && p["target"].toString() == "Light" &&
                  p["code"].toString() == "shadow-first-map";
        main |= p["kind"].toString() == "main";
    }
    EXPECT_TRUE(shadow) << run.out;
    EXPECT_TRUE(main) << run.out;
    EXPECT_TRUE(doc.object()["skipped"].isArray());
    for (const auto& value : doc.object()["skipped"].toArray()) {
        EXPECT_FALSE(value.toObject()["reason"].toString().isEmpty());
        EXPECT_FALSE(value.toObject()["code"].toString().isEmpty()) << "every skip names its reason's code";
    }
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
    const std::string chrome = speculum::testSourcePath("resources/scenes/chrome.speculum.json");
    const CliRun first = speculum("explain " + chrome + " --size 160x90 --json");
    ASSERT_EQ(first.status, 0) << first.err;
    EXPECT_NE(first.out.find("\"envmap\""), std::string::npos) << "the first frame captures the environment";
    const CliRun second = speculum("explain " + chrome + " --size 160x90 --json --frame 2");
    ASSERT_EQ(second.status, 0) << second.err;
    EXPECT_EQ(second.out.find("\"envmap\""), std::string::npos)
        << "a static scene reuses its environment map";
    EXPECT_EQ(second.out.find("\"shadow\""), std::string::npos) << "and its shadow maps";
    // Both reuses are skips, with their codes.
    const QJsonDocument doc = QJsonDocument::fromJson(QByteArray::fromStdString(second.out));
    std::vector<std::string> codes;
    for (const auto& value : doc.object()["skipped"].toArray())
        codes.push_back(value.toObject()["code"].toString().toStdString());
    EXPECT_NE(std::find(codes.begin(), codes.end(), "shadow-map-reused"), codes.end()) << second.out;
    EXPECT_NE(std::find(codes.begin(), codes.end(), "envmap-unchanged"), codes.end()) << second.out;
    EXPECT_NE(speculum("explain " + chrome + " --frame 0").status, 0);
}

// `explain --frame N --animated` plays the frames as the editor does, so a time-sliced map shows the face
// each frame redraws while something moves; without --animated the frames are identical and it rests.
TEST_F(Cli, ExplainOfAnAnimatedFrameShowsTheTimeSlicedFace) {
    const fs::path project = m_dir / "sliced.speculum.json";
    std::ofstream(project) << R"({"format": "speculum-scene", "version": 1,
        "camera": {"position": [0, 1, 6], "target": [0, 0.5, 0]},
        "nodes": [
          {"name": "Floor", "transform": {"scale": [8, 1, 8]}, "mesh": {"builtin": "plane"}},
          {"name": "Hopper", "transform": {"translate": [2, 0.5, 0]}, "mesh": {"builtin": "box"},
           "animation": {"bounce": {"height": 1, "period": 2}}},
          {"name": "Ball", "transform": {"translate": [0, 1, 0]}, "mesh": {"builtin": "sphere"},
           "reflector": {"resolution": 32, "update": "time-sliced"}},
          {"name": "Light", "transform": {"translate": [0, 4, 2]}, "light": {"type": "point"}}]})";
    auto envmapPass = [](const CliRun& run) {
        const QJsonObject root = QJsonDocument::fromJson(QByteArray::fromStdString(run.out)).object();
        for (const auto& value : root["passes"].toArray())
            if (value.toObject()["kind"].toString() == "envmap")
                return value.toObject();
        return QJsonObject{};
    };
    const CliRun played =
        speculum("explain " + project.string() + " --size 64x36 --json --frame 3 --animated");
    ASSERT_EQ(played.status, 0) << played.err;
    const QJsonObject pass = envmapPass(played);
    EXPECT_EQ(pass["code"].toString(), "envmap-time-sliced") << played.out;
    // Frame 1 drew the map whole, frame 2 its +X face, frame 3 the −X face.
    EXPECT_TRUE(pass["reason"].toString().contains("only its −X face this frame")) << played.out;
    const QJsonObject root = QJsonDocument::fromJson(QByteArray::fromStdString(played.out)).object();
    EXPECT_TRUE(root["animated"].toBool());
    EXPECT_NEAR(root["frameTime"].toDouble(), 2.0 / 60.0, 1e-9);

    const CliRun text = speculum("explain " + project.string() + " --size 64x36 --frame 3 --animated");
    ASSERT_EQ(text.status, 0) << text.err;
    EXPECT_NE(text.out.find("The last of 3 frames played 1/60 s apart"), std::string::npos) << text.out;

    const CliRun rested = speculum("explain " + project.string() + " --size 64x36 --json --frame 3");
    ASSERT_EQ(rested.status, 0) << rested.err;
    EXPECT_TRUE(envmapPass(rested).isEmpty()) << "identical frames: the map rests";
    EXPECT_NE(rested.out.find("envmap-unchanged"), std::string::npos) << rested.out;
}

// `explain --preview SCALE[,CUT]` explains the frame as the editor's preview at that level draws it: every
// effect the preview gives up is a skip with a code starting "preview-", and the JSON says the level and
// the size drawn. --preview-drag is a handle drag's preview, whose shadow maps are drawn smaller.
TEST_F(Cli, ExplainPreviewShowsWhatThePreviewGivesUp) {
    const std::string mirrors = speculum::testSourcePath("resources/scenes/mirrors.speculum.json");
    auto json = [](const CliRun& run) {
        return QJsonDocument::fromJson(QByteArray::fromStdString(run.out)).object();
    };
    auto previewReasons = [](const QJsonObject& root) {
        QStringList reasons;
        for (const auto& skip : root["skipped"].toArray())
            if (skip.toObject()["code"].toString().startsWith("preview-"))
                reasons.append(skip.toObject()["reason"].toString());
        return reasons;
    };
    auto mirrorPasses = [](const QJsonObject& root) {
        int n = 0;
        for (const auto& pass : root["passes"].toArray())
            n += pass.toObject()["kind"].toString() == "mirror";
        return n;
    };
    const CliRun rest = speculum("explain " + mirrors + " --size 160x90 --json");
    ASSERT_EQ(rest.status, 0) << rest.err;
    EXPECT_TRUE(json(rest)["preview"].isNull());
    EXPECT_TRUE(previewReasons(json(rest)).isEmpty());

    const CliRun drag =
        speculum("explain " + mirrors + " --size 160x90 --json --preview 0.5,2 --preview-drag");
    ASSERT_EQ(drag.status, 0) << drag.err;
    const QJsonObject preview = json(drag)["preview"].toObject();
    EXPECT_EQ(preview["drawnSize"].toString(), "80x45") << drag.out;
    EXPECT_EQ(preview["mirrorDepthCut"].toInt(), 2);
    EXPECT_TRUE(preview["drag"].toBool());
    const QStringList reasons = previewReasons(json(drag));
    EXPECT_TRUE(
        reasons.contains("preview: drawn at 50% of the output's width and height and scaled up to it"))
        << reasons.join("\n").toStdString();
    EXPECT_TRUE(reasons.contains("preview: mirrors nest 2 levels deep, not 4 (settings.mirrorDepth)"))
        << reasons.join("\n").toStdString();
    EXPECT_TRUE(reasons.contains("preview: shadow map drawn at 512², not 1024², while a handle is dragged"))
        << reasons.join("\n").toStdString();
    EXPECT_LT(mirrorPasses(json(drag)), mirrorPasses(json(rest))) << "mirrors nest less deep";

    // A static frame after the first: the preview holds the environment map instead of checking it.
    const std::string chrome = speculum::testSourcePath("resources/scenes/chrome.speculum.json");
    const CliRun held = speculum("explain " + chrome + " --size 160x90 --frame 2 --preview 0.25");
    ASSERT_EQ(held.status, 0) << held.err;
    EXPECT_NE(held.out.find("A preview while the view moves, drawn at 40x23"), std::string::npos) << held.out;
    EXPECT_NE(held.out.find("preview: environment map held while the view moves"), std::string::npos)
        << held.out;

    EXPECT_EQ(speculum("explain " + chrome + " --preview 2").status, 2);
    EXPECT_EQ(speculum("explain " + chrome + " --preview 0.5,x").status, 2);
    EXPECT_EQ(speculum("explain " + chrome + " --preview-drag").status, 2) << "a bad command line";
}

// `speculum export`: a self-contained .glb (the demo's marble PNG inside it, camera and light there), a
// .gltf with its companions; bad input fails with one line and writes nothing.
// A demo drawn as it asks prints no warning: the scene's own settings (a sharp reflector that needs no
// pre-filter, mirrors out of view) are not something dropped.
TEST_F(Cli, TheDemosRenderWithoutWarnings) {
    for (const char* name : {"teapot", "mirrors", "chrome", "glossy", "models"}) {
        const fs::path out = m_dir / (std::string(name) + ".png");
        const CliRun run = speculum(
            "render " + speculum::testSourcePath(std::string("resources/scenes/") + name + ".speculum.json") +
            " -o " + out.string() + " --size 64x36 -q");
        EXPECT_EQ(run.status, 0) << name << ": " << run.err;
        EXPECT_EQ(run.err, "") << name;
    }
}

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

    // Again over its own earlier export: replaced without a word. Over a .bin nobody exported: refused.
    const CliRun again = speculum("export " + demo() + " -o " + out.string() + " -q");
    EXPECT_EQ(again.status, 0) << again.err;
    EXPECT_TRUE(again.err.empty()) << again.err;
    const fs::path other = m_dir / "other.gltf";
    std::ofstream(m_dir / "other.bin") << "not an export's";
    const CliRun refused = speculum("export " + demo() + " -o " + other.string());
    EXPECT_EQ(refused.status, 1);
    EXPECT_EQ(refused.err, "speculum: error: export: " + (m_dir / "other.bin").string() +
                               " exists and is not part of an earlier export to other.gltf; move it or "
                               "export under another name; nothing was written\n");
    EXPECT_FALSE(fs::exists(other));
    std::ifstream kept(m_dir / "other.bin");
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(kept), {}), "not an export's");
}

TEST_F(Cli, BadExportFailsWithOneLineAndWritesNothing) {
    const fs::path glb = m_dir / "out.glb";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"export /no/such/scene.json -o " + glb.string(), "file not found"},
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

// The command line's own edges, silent drops in scripts, and one-line messages.
namespace {

// Runs the binary under `env` with the given environment changes ("-u DISPLAY ..."), stdin from /dev/null.
CliRun speculumWithEnv(const std::string& env, const std::string& arguments) {
    static int counter = 0;
    const fs::path errFile = fs::temp_directory_path() / ("speculum-cli-env-" + std::to_string(::getpid()) +
                                                          "-" + std::to_string(++counter));
    const std::string command = "env " + env + " " + speculum::testCliBinary() + " " + arguments + " 2>" +
                                errFile.string() + " </dev/null";
    CliRun run;
    FILE* pipe = ::popen(command.c_str(), "r");
    std::array<char, 4096> buffer{};
    while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe))
        run.out.append(buffer.data(), n);
    const int raw = ::pclose(pipe);
    run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    std::ifstream in(errFile);
    run.err.assign(std::istreambuf_iterator<char>(in), {});
    fs::remove(errFile);
    return run;
}

std::string readAll(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), {});
}

std::size_t lines(const std::string& text) {
    return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

// Every line of stderr is one of speculum's own ("speculum: ..."): nothing forged, nothing from Qt.
void expectOwnLines(const std::string& err, const std::string& context) {
    std::size_t start = 0;
    while (start < err.size()) {
        const std::size_t end = err.find('\n', start);
        const std::string line =
            err.substr(start, end == std::string::npos ? std::string::npos : end - start);
        EXPECT_EQ(line.rfind("speculum: ", 0), 0u) << context << ": " << line;
        if (end == std::string::npos)
            break;
        start = end + 1;
    }
}

// A small scene: camera at z = 3 looking at the origin, `nodes` (a JSON array body) in it.
void writeScene(const fs::path& path, const std::string& nodes) {
    std::ofstream(path) << R"({"format": "speculum-scene", "version": 1,
        "camera": {"position": [0, 0, 3], "target": [0, 0, 0], "up": [0, 1, 0], "fovY": 60, "near": 0.1,
                   "far": 20},
        "nodes": [)" << nodes
                        << "]}";
}

const char* kBox = R"({"name": "Box", "mesh": {"builtin": "box"}})";
const char* kLight =
    R"({"name": "Light", "transform": {"translate": [0, 2, 2]}, "light": {"type": "point"}})";

TEST_F(Cli, OutputPathEdgesFailWithOneLineAndAClearStatus) {
    const fs::path loop = m_dir / "loop";
    fs::create_directory_symlink(loop, loop); // loop -> loop
    const fs::path file = m_dir / "plain-file";
    std::ofstream(file) << "x";
    const std::string longName(300, 'n');
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"render " + demo() + " -o " + (loop / "out.png").string() + " --size 64x48", "symbolic links"},
        {"render " + demo() + " -o " + (m_dir / (longName + ".png")).string() + " --size 64x48", "255 bytes"},
        {"render " + demo() + " -o " + (file / "out.png").string() + " --size 64x48", "not a folder"},
        {"export " + demo() + " -o " + (loop / "out.glb").string(), "symbolic links"},
        {"export " + demo() + " -o " + (m_dir / (longName + ".glb")).string(), "255 bytes"},
        {"bench " + demo() + " --out " + (loop / "sub").string() + " --quick", "symbolic links"},
        {"bench " + demo() + " --out " + (m_dir / longName).string() + " --quick", "255 bytes"},
    };
    for (const auto& [args, expected] : cases) {
        const CliRun run = speculum(args);
        EXPECT_EQ(run.status, 1) << args << " → " << run.err;
        EXPECT_EQ(lines(run.err), 1u) << args << " → " << run.err;
        EXPECT_EQ(run.err.rfind("speculum: error: ", 0), 0u) << run.err;
        EXPECT_NE(run.err.find(expected), std::string::npos) << args << " → " << run.err;
    }
    EXPECT_EQ(std::distance(fs::directory_iterator(m_dir), fs::directory_iterator{}), 2) << "nothing written";
}

TEST_F(Cli, AnOutputThatIsAnInputIsRefusedAndLeftIntact) {
    // A project whose name is also an image name, and a texture it reads, reached directly, through a
    // symlink and through a hard link: each refused before anything is written.
    const fs::path texture = m_dir / "tex_0.png";
    {
        auto out = OIIO::ImageOutput::create(texture.string());
        ASSERT_TRUE(out);
        const OIIO::ImageSpec spec(2, 2, 3, OIIO::TypeDesc::UINT8);
        ASSERT_TRUE(out->open(texture.string(), spec));
        const std::array<unsigned char, 12> pixels{255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data()));
        out->close();
    }
    const fs::path project = m_dir / "scene.png";
    writeScene(project,
               R"({"name": "Box", "mesh": {"builtin": "box"}, "material": {"texture": "tex_0.png"}})");
    const fs::path json = m_dir / "scene.speculum.json";
    fs::copy_file(project, json);
    fs::create_symlink(project, m_dir / "link.png");
    fs::create_hard_link(project, m_dir / "hard.png");
    fs::create_symlink(texture, m_dir / "texlink.png");
    fs::create_directory(m_dir / "sub");
    const std::string projectBytes = readAll(project), textureBytes = readAll(texture);
    const std::string p = project.string(), d = m_dir.string();
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"render " + json.string() + " -o " + json.string(), "unsupported image format"},
        {"render " + p + " -o " + p + " --size 64x48", "reads"},
        {"render " + p + " -o " + d + "/link.png --size 64x48", "reads"},
        {"render " + p + " -o " + d + "/hard.png --size 64x48", "reads"},
        {"render " + p + " -o " + d + "/sub/../scene.png --size 64x48 --reference", "reads"},
        {"render " + p + " -o " + texture.string() + " --size 64x48", "tex_0.png"},
        {"render " + p + " -o " + d + "/texlink.png --size 64x48", "tex_0.png"},
        {"export " + p + " -o " + d + "/tex.gltf", "tex_0.png"}, // would write tex_0.png beside tex.gltf
        {"bench " + p + " --out " + d + " --quick", "holds"},
        {"bench " + p + " --out " + p + " --quick", "not a folder"},
    };
    for (const auto& [args, expected] : cases) {
        const CliRun run = speculum(args);
        EXPECT_EQ(run.status, 1) << args << " → " << run.err;
        EXPECT_EQ(lines(run.err), 1u) << args << " → " << run.err;
        EXPECT_NE(run.err.find(expected), std::string::npos) << args << " → " << run.err;
        EXPECT_EQ(readAll(project), projectBytes) << args;
        EXPECT_EQ(readAll(json), projectBytes) << args;
        EXPECT_EQ(readAll(texture), textureBytes) << args;
    }
    EXPECT_FALSE(fs::exists(m_dir / "tex.gltf"));
    EXPECT_FALSE(fs::exists(m_dir / "tex.bin"));
    EXPECT_TRUE(fs::is_empty(m_dir / "sub"));
    // The same project renders fine to a name of its own.
    const CliRun ok = speculum("render " + p + " -o " + d + "/sub/still.png --size 64x48");
    EXPECT_EQ(ok.status, 0) << ok.err;
}

TEST_F(Cli, AMistypedCommandIsRefusedWithASuggestion) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"rendr " + demo(), "unknown command 'rendr' (did you mean 'render'?)"},
        {"rendr", "unknown command 'rendr' (did you mean 'render'?)"},
        {"expoer " + demo() + " -o x.glb", "did you mean 'export'?"},
        {"Bench " + demo(), "did you mean 'bench'?"},
        {"frobnicate a b", "unknown command 'frobnicate' (commands:"},
        {"\"$(printf 're\\nnder')\" " + demo(), "unknown command 're\\nnder'"}, // escaped, on one line
    };
    for (const auto& [args, expected] : cases) {
        const CliRun run = speculumWithEnv("-u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM", args);
        EXPECT_EQ(run.status, 2) << args << " → " << run.err;
        EXPECT_EQ(lines(run.err), 1u) << args << " → " << run.err;
        EXPECT_EQ(run.err.rfind("speculum: error: ", 0), 0u) << run.err;
        EXPECT_NE(run.err.find(expected), std::string::npos) << args << " → " << run.err;
    }
}

TEST_F(Cli, TheEditorWithoutADisplaySaysSoInOneLine) {
    // A project path (existing or not) still means the editor, not an unknown command.
    for (const std::string& args : {std::string(), demo(), (m_dir / "new.speculum.json").string()}) {
        const CliRun run = speculumWithEnv("-u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM", args);
        EXPECT_EQ(run.status, 1) << args << " → " << run.err;
        EXPECT_EQ(lines(run.err), 1u) << args << " → " << run.err;
        EXPECT_NE(run.err.find("speculum: error: the editor needs a display"), std::string::npos) << run.err;
        EXPECT_EQ(run.err.find("qt."), std::string::npos) << run.err;
    }
    // The headless commands need none (scripts/run's fallback).
    const CliRun still =
        speculumWithEnv("-u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM",
                        "render " + demo() + " -o " + (m_dir / "t.png").string() + " --size 64x48");
    EXPECT_EQ(still.status, 0) << still.err;
}

TEST_F(Cli, AMissingModelOrTextureFailsUnlessKeepGoing) {
    const fs::path project = m_dir / "missing.speculum.json";
    writeScene(project, std::string(kBox) + "," + kLight +
                            R"(, {"name": "Statue", "mesh": {"file": "models/statue.obj"}},
                               {"name": "Floor", "mesh": {"builtin": "plane"},
                                "material": {"texture": "gone/floor.png"}})");
    const fs::path out = m_dir / "out.png";
    const fs::path glb = m_dir / "out.glb";
    for (const std::string& command :
         {"render " + project.string() + " -o " + out.string() + " --size 64x48",
          "render " + project.string() + " -o " + out.string() + " --size 64x48 --reference",
          "export " + project.string() + " -o " + glb.string(),
          "bench " + project.string() + " --out " + (m_dir / "b").string() + " --quick --size 64x48"}) {
        const CliRun run = speculum(command);
        EXPECT_EQ(run.status, 1) << command << " → " << run.err;
        EXPECT_EQ(lines(run.err), 1u) << command << " → " << run.err;
        EXPECT_NE(run.err.find("statue.obj"), std::string::npos) << run.err;
        EXPECT_NE(run.err.find("and 1 more"), std::string::npos) << run.err;
        EXPECT_NE(run.err.find("--keep-going"), std::string::npos) << run.err;
    }
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(glb));
    EXPECT_FALSE(fs::exists(m_dir / "b"));

    const CliRun going =
        speculum("render " + project.string() + " -o " + out.string() + " --size 64x48 --keep-going");
    ASSERT_EQ(going.status, 0) << going.err;
    EXPECT_TRUE(fs::exists(out));
    EXPECT_NE(going.err.find("speculum: warning: node 'Statue'"), std::string::npos) << going.err;
    EXPECT_NE(going.err.find("statue.obj"), std::string::npos) << going.err;
    EXPECT_NE(going.err.find("speculum: warning: node 'Floor': texture"), std::string::npos) << going.err;
    EXPECT_EQ(going.err.find("speculum: error"), std::string::npos) << going.err;
    const CliRun exported = speculum("export " + project.string() + " -o " + glb.string() + " --keep-going");
    EXPECT_EQ(exported.status, 0) << exported.err;
    EXPECT_NE(exported.err.find("floor.png"), std::string::npos) << exported.err;
}

TEST_F(Cli, EveryDropIsAWarning) {
    // Nine lights: the ninth is not drawn. 65 small mirrors in view: a frame holds at most 64 mirror
    // views, so the last is drawn without its reflection. A box in front hides a few (expected: no warning).
    std::string nodes =
        R"({"name": "Box", "mesh": {"builtin": "box"}, "transform": {"translate": [0, 0, 1.5],
            "scale": [0.2, 0.2, 0.2]}})";
    for (int i = 1; i <= 9; ++i)
        nodes += R"(, {"name": "L)" + std::to_string(i) + R"(", "transform": {"translate": [)" +
                 std::to_string(i - 5) + R"(, 2, 2]}, "light": {"type": "point", "intensity": 0.2}})";
    for (int i = 0; i < 65; ++i)
        nodes += R"(, {"name": "M)" + std::to_string(i) + R"(", "transform": {"translate": [)" +
                 std::to_string((i % 13) * 0.3 - 1.8) + ", " + std::to_string((i / 13) * 0.3 - 0.6) +
                 R"(, -1], "rotate": [90, 0, 0]}, "mirror": {"size": [0.25, 0.25]}})";
    const fs::path project = m_dir / "drops.speculum.json";
    writeScene(project, nodes);
    for (const std::string& extra : {std::string(), std::string(" --reference")}) {
        const CliRun run = speculum("render " + project.string() + " -o " + (m_dir / "d.png").string() +
                                    " --size 64x48" + extra);
        ASSERT_EQ(run.status, 0) << run.err;
        EXPECT_NE(run.err.find("speculum: warning: light 'L9' ignored: at most 8 lights are drawn"),
                  std::string::npos)
            << run.err;
        EXPECT_EQ(run.err.find("'L8' ignored"), std::string::npos) << run.err;
        if (extra.empty()) {
            EXPECT_NE(
                run.err.find("speculum: warning: mirror 'M64': skipped: no reflection: the frame already "
                             "has 64 mirror views"),
                std::string::npos)
                << run.err;
            EXPECT_EQ(run.err.find("occluded"), std::string::npos) << "hidden mirrors are no drop";
        }
        expectOwnLines(run.err, extra);
    }
    // The demo drops nothing: no warnings at all.
    const CliRun clean = speculum("render " + demo() + " -o " + (m_dir / "c.png").string() + " --size 64x48");
    ASSERT_EQ(clean.status, 0) << clean.err;
    EXPECT_EQ(clean.err.find("warning"), std::string::npos) << clean.err;
}

TEST_F(Cli, NamesInMessagesAreEscapedOnOneLine) {
    // A node name that tries to start a line of its own, with an escape for the terminal.
    const std::string forged = R"(Evil\n speculum: error: forged\u001b[2J)";
    const std::string shown = "'Evil\\n speculum: error: forged\\x1b[2J'";
    std::string lights;
    for (int i = 1; i <= 8; ++i)
        lights += R"(, {"name": "L)" + std::to_string(i) + R"(", "light": {"type": "point"}})";
    const fs::path project = m_dir / "forged.speculum.json";
    writeScene(project, std::string(kBox) + lights + R"(, {"name": ")" + forged +
                            R"(", "light": {"type": "point"}}, {"name": ")" + forged +
                            R"(", "mesh": {"file": "no-such-model.obj"}})");
    const fs::path out = m_dir / "f.png";
    const CliRun strict = speculum("render " + project.string() + " -o " + out.string() + " --size 64x48");
    EXPECT_EQ(strict.status, 1) << strict.err;
    EXPECT_EQ(lines(strict.err), 1u) << strict.err;
    EXPECT_NE(strict.err.find(shown), std::string::npos) << strict.err;
    expectOwnLines(strict.err, "strict");

    const CliRun going =
        speculum("render " + project.string() + " -o " + out.string() + " --size 64x48 --keep-going");
    ASSERT_EQ(going.status, 0) << going.err;
    EXPECT_NE(going.err.find("speculum: warning: light " + shown + " ignored"), std::string::npos)
        << going.err;
    EXPECT_NE(going.err.find("speculum: warning: node " + shown), std::string::npos) << going.err;
    EXPECT_EQ(going.err.find('\x1b'), std::string::npos) << "no raw escape reaches the terminal";
    expectOwnLines(going.err, "keep-going");

    // Values from the command line are escaped the same way.
    const CliRun size =
        speculum("render " + demo() + " -o " + out.string() + " --size \"$(printf '1\\n2')\"");
    EXPECT_EQ(size.status, 2);
    EXPECT_EQ(lines(size.err), 1u) << size.err;
    EXPECT_NE(size.err.find("'1\\n2'"), std::string::npos) << size.err;
}

} // namespace
