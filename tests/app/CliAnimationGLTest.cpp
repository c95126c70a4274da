// `speculum render --frames`, `--turntable`, `--shard` and `speculum join` run as a user runs them: the
// frames of an image sequence are the stills at the same times, a clip decodes (through libavformat) to
// those frames within the codec's loss, a turntable loops, shards together are the whole sequence byte for
// byte, and every bad input is one line that writes nothing.
#include "CliRun.hpp"
#include "render/video/VideoWriter.hpp"
#include "support/TestPaths.hpp"

#include <OpenImageIO/imageio.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
namespace video = speculum::render::video;
using speculum::test::CliRun;

CliRun cli(const std::string& arguments) {
    return speculum::test::runSpeculum(arguments);
}

std::string scene(const std::string& name) {
    return speculum::testSourcePath("resources/scenes/" + name);
}

std::string readAll(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// The pixels of an 8-bit image as RGB bytes, row 0 at the top.
std::vector<std::uint8_t> rgbOf(const fs::path& path) {
    auto input = OIIO::ImageInput::open(path.string());
    EXPECT_TRUE(input) << path;
    if (!input)
        return {};
    const OIIO::ImageSpec& spec = input->spec();
    std::vector<std::uint8_t> rgb(static_cast<std::size_t>(spec.width) * spec.height * 3);
    EXPECT_TRUE(input->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, rgb.data()));
    return rgb;
}

std::string attributeOf(const fs::path& path, const std::string& name) {
    auto input = OIIO::ImageInput::open(path.string());
    return input ? std::string(input->spec().get_string_attribute(name)) : std::string();
}

double psnr(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
        sum += (double(a[i]) - b[i]) * (double(a[i]) - b[i]);
    const double mse = sum / double(a.size());
    return mse == 0.0 ? 100.0 : 10.0 * std::log10(255.0 * 255.0 / mse);
}

double rmse(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
        sum += (double(a[i]) - b[i]) * (double(a[i]) - b[i]);
    return std::sqrt(sum / double(a.size()));
}

std::string frameFile(const fs::path& folder, int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "shot_%04d.png", frame);
    return (folder / name).string();
}

std::vector<std::string> filesIn(const fs::path& folder) {
    std::vector<std::string> names;
    if (fs::exists(folder))
        for (const auto& entry : fs::directory_iterator(folder))
            names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

class CliAnimation : public ::testing::Test {
protected:
    void SetUp() override { m_dir = speculum::test::freshCliFolder("animation"); }
    fs::path m_dir;

    // The teapot demo's frames 0..23 at 24 fps, 160x90, as a PNG sequence in `folder`.
    void renderTeapotSequence(const fs::path& folder) {
        const CliRun run =
            cli("render " + scene("teapot.speculum.json") + " --frames 0..23 --fps 24 --size 160x90 -q -o '" +
                (folder / "shot_%04d.png").string() + "'");
        ASSERT_EQ(run.status, 0) << run.err;
    }
};

TEST_F(CliAnimation, PngSequenceFramesAreTheStillsAtTheSameTimes) {
    renderTeapotSequence(m_dir / "seq");
    ASSERT_EQ(filesIn(m_dir / "seq").size(), 24u);
    for (int frame = 0; frame < 24; ++frame) {
        const fs::path still = m_dir / ("still" + std::to_string(frame) + ".png");
        const CliRun run = cli("render " + scene("teapot.speculum.json") + " --size 160x90 -q --time " +
                               std::to_string(frame / 24.0) + " -o " + still.string());
        ASSERT_EQ(run.status, 0) << run.err;
        EXPECT_EQ(rgbOf(frameFile(m_dir / "seq", frame)), rgbOf(still)) << "frame " << frame;
    }
    // Per-frame metadata: which frame, and the clip it belongs to.
    EXPECT_EQ(attributeOf(frameFile(m_dir / "seq", 7), "speculum:frame"), "7");
    EXPECT_NE(attributeOf(frameFile(m_dir / "seq", 7), "speculum:clip").find("fps 24"), std::string::npos);
    // Frames differ: the teapot bounces.
    EXPECT_NE(rgbOf(frameFile(m_dir / "seq", 0)), rgbOf(frameFile(m_dir / "seq", 12)));
}

TEST_F(CliAnimation, ClipsDecodeToTheSequencesFramesWithinTheCodecsLoss) {
    renderTeapotSequence(m_dir / "seq");
    struct Case {
        const char* name;
        const char* codec;
        double minPsnr; // the loss each codec is documented to stay within (docs/animation.md)
    };
    for (const Case& c :
         {Case{"clip.mp4", "h264", 35.0}, Case{"clip.webm", "vp9", 32.0}, Case{"clip.gif", "gif", 20.0}}) {
        const CliRun run = cli("render " + scene("teapot.speculum.json") +
                               " --frames 0..23 --fps 24 --size 160x90 -q -o " + (m_dir / c.name).string());
        ASSERT_EQ(run.status, 0) << run.err;
        EXPECT_EQ(run.out, (m_dir / c.name).string() + "\n");
        auto decoded = video::decodeVideo((m_dir / c.name).string());
        ASSERT_TRUE(decoded) << decoded.error();
        EXPECT_EQ(decoded->codec, c.codec);
        EXPECT_EQ(decoded->width, 160);
        EXPECT_EQ(decoded->height, 90);
        ASSERT_EQ(decoded->frames.size(), 24u) << c.name;
        if (std::string(c.codec) != "gif") {
            EXPECT_NEAR(decoded->fps, 24.0, 1e-6) << c.name;
        }
        double worst = 100.0;
        for (int frame = 0; frame < 24; ++frame)
            worst = std::min(
                worst, psnr(decoded->frames[std::size_t(frame)], rgbOf(frameFile(m_dir / "seq", frame))));
        EXPECT_GE(worst, c.minPsnr) << c.name << ": the worst frame's PSNR against its PNG";
        RecordProperty(std::string(c.codec) + "WorstPsnr", std::to_string(worst));
    }
}

TEST_F(CliAnimation, TurntableLoopsWithoutASeam) {
    // Six seconds a turn at 2 fps: 12 frames; the teapot demo's animation (6 s a loop) repeats with it.
    const std::string common =
        "render " + scene("teapot.speculum.json") + " --turntable 6 --fps 2 --size 160x90 -q ";
    CliRun run = cli(common + "-o '" + (m_dir / "shot_%04d.png").string() + "'");
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(run.err.find("warning"), std::string::npos) << run.err;
    ASSERT_EQ(filesIn(m_dir).size(), 12u) << "SECONDS x fps frames";
    // The frame after the last is the first again...
    run = cli(common + "--frames 12..12 -o '" + (m_dir / "next" / "shot_%04d.png").string() + "'");
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_LT(rmse(rgbOf(frameFile(m_dir / "next", 12)), rgbOf(frameFile(m_dir, 0))), 0.5);
    // ...so the last leads into the first as any frame leads into the next.
    double steps = 0.0;
    for (int frame = 0; frame < 11; ++frame)
        steps += rmse(rgbOf(frameFile(m_dir, frame)), rgbOf(frameFile(m_dir, frame + 1)));
    const double typical = steps / 11.0, seam = rmse(rgbOf(frameFile(m_dir, 11)), rgbOf(frameFile(m_dir, 0)));
    EXPECT_GT(typical, 1.0) << "the camera moves";
    EXPECT_GT(seam, 0.5 * typical);
    EXPECT_LT(seam, 1.5 * typical);
}

// A copy of the facing-balls demo whose reflectors are time-sliced: which face a frame redraws depends on
// every frame before it, so a shard must draw those first.
fs::path timeSlicedScene(const fs::path& folder) {
    std::string text = readAll(scene("facing-balls.speculum.json"));
    const std::string from = "\"update\": \"on-change\"", to = "\"update\": \"time-sliced\"";
    int replaced = 0;
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at)) {
        text.replace(at, from.size(), to);
        ++replaced;
    }
    EXPECT_EQ(replaced, 3);
    const fs::path project = folder / "sliced.speculum.json";
    std::ofstream(project) << text;
    return project;
}

TEST_F(CliAnimation, ShardsTogetherAreTheWholeSequenceByteForByte) {
    const fs::path project = timeSlicedScene(m_dir);
    const std::string common = "render " + project.string() + " --frames 0..8 --size 96x54 -q ";
    CliRun run = cli(common + "-o '" + (m_dir / "whole" / "shot_%04d.png").string() + "'");
    ASSERT_EQ(run.status, 0) << run.err;
    for (const std::string layout : {"", " --contiguous"})
        for (int k = 0; k < 3; ++k) {
            run = cli(
                common + "--shard " + std::to_string(k) + "/3" + layout + " -o '" +
                (m_dir / ("shards" + layout.substr(0, layout.empty() ? 0 : 3)) / "shot_%04d.png").string() +
                "'");
            ASSERT_EQ(run.status, 0) << run.err;
            EXPECT_EQ(std::count(run.out.begin(), run.out.end(), '\n'), 3) << "three frames each";
        }
    ASSERT_EQ(filesIn(m_dir / "whole").size(), 9u);
    for (const char* shards : {"shards", "shards --"})
        for (int frame = 0; frame <= 8; ++frame)
            EXPECT_EQ(readAll(frameFile(m_dir / shards, frame)), readAll(frameFile(m_dir / "whole", frame)))
                << shards << " frame " << frame;
}

TEST_F(CliAnimation, JoinEncodesASequenceAndRefusesMissingOrMismatchedFrames) {
    renderTeapotSequence(m_dir / "seq");
    const std::string pattern = "'" + (m_dir / "seq" / "shot_%04d.png").string() + "'";
    CliRun run = cli("join " + pattern + " -q -o " + (m_dir / "clip.mp4").string());
    ASSERT_EQ(run.status, 0) << run.err;
    auto decoded = video::decodeVideo((m_dir / "clip.mp4").string());
    ASSERT_TRUE(decoded) << decoded.error();
    EXPECT_EQ(decoded->frames.size(), 24u);
    EXPECT_NEAR(decoded->fps, 24.0, 1e-6) << "the frames' own rate";

    fs::rename(frameFile(m_dir / "seq", 5), m_dir / "aside.png");
    run = cli("join " + pattern + " -q -o " + (m_dir / "gap.mp4").string());
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.err.find("lacks frame 5 of 0..23"), std::string::npos) << run.err;
    fs::rename(m_dir / "aside.png", frameFile(m_dir / "seq", 5));
    // A frame of another clip (another size; then the same size, other settings) in its place.
    run = cli("render " + scene("teapot.speculum.json") + " --frames 5..5 --size 80x46 -q -o '" +
              (m_dir / "seq" / "shot_%04d.png").string() + "'");
    ASSERT_EQ(run.status, 0) << run.err;
    run = cli("join " + pattern + " -q -o " + (m_dir / "size.mp4").string());
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.err.find("frame 5 is 80x46"), std::string::npos) << run.err;
    run = cli("render " + scene("teapot.speculum.json") + " --frames 5..5 --size 160x90 --ssaa 2 -q -o '" +
              (m_dir / "seq" / "shot_%04d.png").string() + "'");
    ASSERT_EQ(run.status, 0) << run.err;
    run = cli("join " + pattern + " -q -o " + (m_dir / "other.mp4").string());
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.err.find("frame 5 belongs to another clip"), std::string::npos) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    // A sequence finished in two runs (as a stopped render is resumed) is one clip.
    fs::create_directories(m_dir / "resumed");
    for (const char* range : {"0..9", "10..23"}) {
        run = cli("render " + scene("teapot.speculum.json") + " --frames " + range +
                  " --size 160x90 -q -o '" + (m_dir / "resumed" / "shot_%04d.png").string() + "'");
        ASSERT_EQ(run.status, 0) << run.err;
    }
    run = cli("join '" + (m_dir / "resumed" / "shot_%04d.png").string() + "' -q -o " +
              (m_dir / "resumed.mp4").string());
    EXPECT_EQ(run.status, 0) << run.err;
    for (const char* refused : {"gap.mp4", "size.mp4", "other.mp4"})
        EXPECT_FALSE(fs::exists(m_dir / refused)) << refused;
}

TEST_F(CliAnimation, BadInputIsOneLineAndWritesNothing) {
    const std::string teapot = "render " + scene("teapot.speculum.json") + " ";
    const std::string seq = " -o '" + (m_dir / "shot_%04d.png").string() + "'";
    struct Case {
        std::string arguments;
        int status;
        std::string says;
    };
    const std::vector<Case> cases = {
        {teapot + "--frames 0..3 -o " + (m_dir / "out.png").string(), 1, "needs a frame number"},
        {teapot + "--frames 5..2" + seq, 2, "is empty: B comes before A"},
        {teapot + "--frames 0.." + seq, 2, "expected A..B"},
        {teapot + "--frames 0..3 --fps 0" + seq, 2, "--fps: '0' is out of range (1..240)"},
        {teapot + "--frames 0..3 --fps 10000" + seq, 2, "--fps: '10000' is out of range (1..240)"},
        {teapot + "--frames 0..3 -o " + (m_dir / "clip.avi").string(), 1, "unknown extension"},
        {teapot + "--frames 0..3 --size 161x90 -o " + (m_dir / "clip.mp4").string(), 1,
         "even width and height"},
        {teapot + "--frames 0..3 --shard 0/2 -o " + (m_dir / "clip.mp4").string(), 1, "speculum join"},
        {teapot + "--frames 0..3 --shard 2/2" + seq, 2, "K is out of range (0..1"},
        {teapot + "--frames 0..3 --fps 60 -o " + (m_dir / "clip.gif").string(), 1,
         "at most 50 frames a second"},
        {teapot + "--frames 0..3 --contiguous" + seq, 2, "only with --shard"},
        {teapot + "--fps 12" + seq, 2, "only with --frames"},
        {teapot + "--frames 0..3 --time 1" + seq, 2, "not with --frames"},
        {teapot + "--frames 0..3 -o '" + (m_dir / "a%d" / "x.png").string() + "'", 1, "not its folder"},
        {teapot + "--frames 0..3 -o '" + (m_dir / "x%d_%d.png").string() + "'", 1, "one frame number"},
        {"join '" + (m_dir / "none_%04d.png").string() + "' -o " + (m_dir / "c.mp4").string(), 1,
         "no frame of"},
        {"join '" + (m_dir / "none_%04d.png").string() + "' -o " + (m_dir / "c.mkv").string(), 1,
         "a clip is"},
    };
    for (const Case& c : cases) {
        const CliRun run = cli(c.arguments);
        EXPECT_EQ(run.status, c.status) << c.arguments << "\n" << run.err;
        EXPECT_NE(run.err.find(c.says), std::string::npos) << c.arguments << "\n" << run.err;
        EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
        EXPECT_TRUE(run.out.empty()) << run.out;
        EXPECT_TRUE(filesIn(m_dir).empty()) << c.arguments;
    }
}

TEST(VideoFormats, AMissingEncoderNamesTheOnesThereAre) {
    const auto status = video::checkVideoTarget(video::VideoFormat::Mp4, 160, 90, 24,
                                                {video::VideoFormat::WebM, video::VideoFormat::Gif});
    ASSERT_FALSE(status);
    EXPECT_EQ(status.error(),
              "this FFmpeg has no H.264 encoder for .mp4; it can write .webm (VP9), .gif, or an "
              "image sequence");
    EXPECT_FALSE(video::checkVideoTarget(video::VideoFormat::Gif, 160, 90, 24, {}));
    // Debian's FFmpeg has all three.
    EXPECT_EQ(video::availableVideoFormats().size(), 3u);
}

} // namespace

namespace {

// Runs `speculum ARGS` in the background in `folder`, waits until `ready` (a shell test) holds, sends
// SIGINT, and returns the exit status; stderr is left in folder/err.txt.
int interruptedRun(const fs::path& folder, const std::string& arguments, const std::string& ready) {
    // set -m: a job of its own, so the shell does not start it with SIGINT ignored as it would a plain
    // background command.
    const std::string script = "set -m; cd '" + folder.string() + "' && { " + speculum::testCliBinary() +
                               " " + arguments + " >/dev/null 2>err.txt & p=$!; n=0; until " + ready +
                               " || [ $n -gt 1200 ]; do sleep 0.05; n=$((n+1)); done; kill -INT $p; wait $p; "
                               "echo $? > status.txt; }";
    std::ofstream(folder / "run.sh") << script << "\n";
    EXPECT_EQ(std::system(("/bin/sh '" + (folder / "run.sh").string() + "'").c_str()), 0);
    fs::remove(folder / "run.sh");
    return std::stoi(readAll(folder / "status.txt"));
}

} // namespace

TEST_F(CliAnimation, CtrlCKeepsFinishedFramesAndRemovesThePartialClip) {
    const std::string teapot = "render " + scene("teapot.speculum.json") + " --size 160x90 --frames 0..5000 ";
    fs::create_directories(m_dir / "seq");
    EXPECT_EQ(interruptedRun(m_dir, teapot + "-o 'seq/shot_%04d.png'", "[ -e seq/shot_0003.png ]"), 130);
    std::string err = readAll(m_dir / "err.txt");
    const std::size_t kept = filesIn(m_dir / "seq").size();
    EXPECT_GE(kept, 4u);
    EXPECT_NE(err.find("interrupted; frames 0.." + std::to_string(kept - 1) +
                       " are kept; resume with --frames " + std::to_string(kept) + "..5000"),
              std::string::npos)
        << err;
    for (const std::string& name : filesIn(m_dir / "seq"))
        EXPECT_NE(name[0], '.') << "no temporary left: " << name;

    fs::create_directories(m_dir / "clip");
    EXPECT_EQ(interruptedRun(m_dir / "clip", teapot + "-o clip.mp4", "grep -q 'frame [1-9]' err.txt"), 130);
    err = readAll(m_dir / "clip" / "err.txt");
    EXPECT_NE(err.find("interrupted; the partial clip was removed"), std::string::npos) << err;
    EXPECT_EQ(filesIn(m_dir / "clip"), (std::vector<std::string>{"err.txt", "status.txt"}));
}

TEST_F(CliAnimation, AFullDiskMidClipLeavesNoHalfWrittenClip) {
    // A file-size limit of 64 blocks: the clip outgrows it after some frames, where a full disk would stop
    // it.
    std::ofstream(m_dir / "clip.mp4") << "the previous clip";
    const CliRun run = speculum::test::runSpeculum("render " + scene("teapot.speculum.json") +
                                                       " --size 320x180 --frames 0..400 -q -o " +
                                                       (m_dir / "clip.mp4").string(),
                                                   "trap '' XFSZ; ulimit -f 64");
    EXPECT_EQ(run.status, 1) << run.err;
    EXPECT_NE(run.err.find("no clip was written"), std::string::npos) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_EQ(readAll(m_dir / "clip.mp4"), "the previous clip");
    EXPECT_EQ(filesIn(m_dir), std::vector<std::string>{"clip.mp4"}) << "no temporary left";
}

TEST_F(CliAnimation, ShardsThatSplitTheRangeDifferentlyAreRefused) {
    const std::string common = "render " + scene("teapot.speculum.json") + " --size 64x36 -q -o '" +
                               (m_dir / "shot_%04d.png").string() + "' ";
    CliRun run = cli(common + "--frames 0..5 --shard 0/2");
    ASSERT_EQ(run.status, 0) << run.err;
    const std::vector<std::string> before = filesIn(m_dir);
    for (const char* other : {"--frames 0..5 --shard 1/3", "--frames 0..5 --shard 1/2 --contiguous",
                              "--frames 0..7 --shard 1/2"}) {
        run = cli(common + other);
        EXPECT_EQ(run.status, 1) << other;
        EXPECT_NE(run.err.find("would overlap it or leave gaps"), std::string::npos) << run.err;
        EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
        EXPECT_EQ(filesIn(m_dir), before) << other << ": nothing drawn";
    }
    run = cli(common + "--frames 0..5 --shard 1/2");
    ASSERT_EQ(run.status, 0) << run.err;
    run = cli("join '" + (m_dir / "shot_%04d.png").string() + "' -q -o " + (m_dir / "clip.gif").string());
    EXPECT_EQ(run.status, 0) << run.err;
    // A record of another split, left by hand, stops the join.
    std::ofstream(m_dir / ".shot_%04d.png.shard-2-of-3") << "2/3\nframes 0..5, interleaved in 3\n";
    run = cli("join '" + (m_dir / "shot_%04d.png").string() + "' -q -o " + (m_dir / "clip2.gif").string());
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.err.find("they overlap or leave gaps"), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(m_dir / "clip2.gif"));
    // A whole render of the range draws every frame and clears the records.
    run = cli(common + "--frames 0..5");
    ASSERT_EQ(run.status, 0) << run.err;
    for (const std::string& name : filesIn(m_dir))
        EXPECT_EQ(name.find(".shard-"), std::string::npos) << name;
}

TEST_F(CliAnimation, AFullDiskMidSequenceKeepsTheFramesDoneAndSaysWhereToResume) {
    // A real full disk: a 48 KiB tmpfs mounted in a mount namespace of the command's own (root only), which
    // a dozen of these frames fill. The namespace's shell copies out what the render left before the tmpfs
    // goes with it.
    const fs::path disk = m_dir / "disk", kept = m_dir / "kept";
    fs::create_directories(disk);
    fs::create_directories(kept);
    const std::string script = "unshare -m sh -c '\n"
                               "mount -t tmpfs -o size=48k tmpfs \"" +
                               disk.string() + "\" || exit 77\n" + speculum::testCliBinary() + " render \"" +
                               scene("teapot.speculum.json") + "\" --size 160x90 --frames 0..99 -q -o \"" +
                               (disk / "shot_%04d.png").string() + "\" >/dev/null 2>\"" +
                               (m_dir / "err.txt").string() + "\"\n" + "echo $? >\"" +
                               (m_dir / "status.txt").string() + "\"\nls -A \"" + disk.string() + "\" >\"" +
                               (m_dir / "listing.txt").string() + "\"\ncp \"" + disk.string() +
                               "\"/shot_* \"" + kept.string() + "\"\n'\n";
    std::ofstream(m_dir / "run.sh") << script;
    const int raw = std::system(("/bin/sh '" + (m_dir / "run.sh").string() + "'").c_str());
    if (::geteuid() != 0 || (WIFEXITED(raw) && WEXITSTATUS(raw) == 77))
        GTEST_SKIP() << "no tmpfs of our own here (it needs root and mount namespaces)";
    ASSERT_EQ(readAll(m_dir / "status.txt"), "1\n") << readAll(m_dir / "err.txt");
    const std::string err = readAll(m_dir / "err.txt");
    const std::vector<std::string> frames = filesIn(kept);
    ASSERT_GE(frames.size(), 2u) << err;
    ASSERT_LT(frames.size(), 100u);
    const std::string next = std::to_string(frames.size());
    EXPECT_NE(err.find("the disk is full"), std::string::npos) << err;
    EXPECT_NE(err.find("frames 0.." + std::to_string(frames.size() - 1) + " are kept; resume with --frames " +
                       next + "..99"),
              std::string::npos)
        << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_EQ(readAll(m_dir / "listing.txt").find('.'), readAll(m_dir / "listing.txt").find(".png"))
        << "only whole frames, no temporary: " << readAll(m_dir / "listing.txt");
    for (const std::string& frame : frames)
        EXPECT_EQ(rgbOf(kept / frame).size(), 160u * 90u * 3u) << frame << " is whole";
}
