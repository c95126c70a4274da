// `speculum bench` as a user runs it, on tiny scenes made here: the files it writes, that the CSV and the
// JSON agree, that the plots are real images, that a scene gets only the families it calls for, and that
// bad input, or a Ctrl-C mid-run, writes nothing.
#include "CliRun.hpp"
#include "support/TestPaths.hpp"

#include <OpenImageIO/imageio.h>
#include <QByteArray>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <chrono>
#include <cmath>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <set>
#include <spawn.h>
#include <sstream>
#include <sys/wait.h>
#include <thread>

namespace {

namespace fs = std::filesystem;
using speculum::test::CliRun;
using speculum::test::runSpeculum;

// A floor, a mirror, a teapot, a shadowing lamp and (optionally) a chrome ball.
std::string sceneJson(bool reflector) {
    std::string nodes = R"(
    {"name": "Floor", "transform": {"scale": [3, 1, 3]}, "mesh": {"builtin": "plane", "tessellation": 1},
     "material": {"color": [0.8, 0.8, 0.8]}},
    {"name": "Teapot", "transform": {"translate": [-1, 0, 0], "scale": [0.3, 0.3, 0.3]},
     "mesh": {"builtin": "teapot", "tessellation": 4}, "material": {"color": [0.8, 0.2, 0.1], "specular": 0.5}},
    {"name": "Mirror", "transform": {"translate": [0, 1, -2], "rotate": [90, 0, 0]},
     "mirror": {"size": [5, 2], "reflectivity": 0.9}},
    {"name": "Lamp", "transform": {"translate": [1, 3, 2]},
     "light": {"type": "point", "shadows": {"mapSize": 256, "pcf": 3}}})";
    if (reflector)
        nodes += R"(,
    {"name": "Ball", "transform": {"translate": [0.8, 0.5, 0], "scale": [0.5, 0.5, 0.5]},
     "mesh": {"builtin": "sphere", "tessellation": 24},
     "reflector": {"map": "cube", "resolution": 64, "reflectivity": 1}})";
    return R"({"format": "speculum-scene", "version": 1,
  "settings": {"background": [0.2, 0.25, 0.3], "mirrorDepth": 2, "ambient": 0.3},
  "camera": {"position": [0, 1.5, 4], "target": [0, 0.6, 0], "up": [0, 1, 0], "fovY": 60, "near": 0.1, "far": 30},
  "nodes": [)" +
           nodes + "]}\n";
}

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// RFC 4180 enough for our own output: commas, quotes doubled inside quoted fields.
std::vector<std::vector<std::string>> parseCsv(const std::string& text) {
    std::vector<std::vector<std::string>> rows(1);
    std::string field;
    bool quoted = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (quoted) {
            if (c == '"' && i + 1 < text.size() && text[i + 1] == '"')
                field += text[++i];
            else if (c == '"')
                quoted = false;
            else
                field += c;
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            rows.back().push_back(field);
            field.clear();
        } else if (c == '\n') {
            rows.back().push_back(field);
            field.clear();
            rows.emplace_back();
        } else {
            field += c;
        }
    }
    if (rows.back().empty())
        rows.pop_back();
    return rows;
}

class BenchCli : public ::testing::Test {
protected:
    void SetUp() override {
        m_dir = fs::path(speculum::testDataPath()) /
                ("bench-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }

    fs::path writeScene(const std::string& name, const std::string& json) {
        const fs::path path = m_dir / name;
        std::ofstream(path) << json;
        return path;
    }

    CliRun bench(const fs::path& scene, const fs::path& out,
                 const std::string& extra = "--quick --size 64x40") {
        return runSpeculum("bench " + scene.string() + " --out " + out.string() + " " + extra);
    }

    fs::path m_dir;
};

QJsonObject loadJson(const fs::path& path) {
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(QByteArray::fromStdString(readFile(path)), &error);
    EXPECT_EQ(error.error, QJsonParseError::NoError) << error.errorString().toStdString();
    return doc.object();
}

TEST_F(BenchCli, WritesResultsThatAgreePlotsAndAReport) {
    const fs::path scene = writeScene("all.speculum.json", sceneJson(true));
    const fs::path out = m_dir / "out";
    const auto start = std::chrono::steady_clock::now();
    const CliRun run = bench(scene, out);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_EQ(run.status, 0) << run.err;
    std::printf("[ measured ] bench --quick --size 64x40 of a five-node scene: %.1f s\n", seconds);
    EXPECT_NE(run.err.find("[1/"), std::string::npos) << "progress on stderr: " << run.err;
    EXPECT_NE(run.out.find("report.md"), std::string::npos) << "prints the report's path";

    for (const char* file : {"results.csv", "results.json", "report.md", "reference.png", "render.png"})
        EXPECT_TRUE(fs::is_regular_file(out / file)) << file;
    for (const fs::directory_entry& e : fs::directory_iterator(out))
        EXPECT_NE(e.path().filename().string().rfind(".speculum-bench", 0), 0u) << "staging left behind";

    const QJsonObject root = loadJson(out / "results.json");
    EXPECT_EQ(root["format"].toString(), "speculum-bench");
    EXPECT_EQ(root["size"].toString(), "64x40");
    const QJsonArray results = root["results"].toArray();
    const auto csv = parseCsv(readFile(out / "results.csv"));
    ASSERT_EQ(csv.size(), std::size_t(results.size()) + 1) << "a header and one row per record";
    std::map<std::string, std::size_t> column;
    for (std::size_t i = 0; i < csv[0].size(); ++i)
        column[csv[0][i]] = i;
    for (const char* name : {"id",
                             "family",
                             "gpuMs",
                             "cpuMs",
                             "memoryBytes",
                             "rmse",
                             "psnr",
                             "psnrMirrors",
                             "psnrReflector",
                             "map",
                             "resolution",
                             "pcf",
                             "tessellation",
                             "mirrorDepth",
                             "mae",
                             "relativeMse",
                             "ssim",
                             "flip",
                             "hdrFlip",
                             "flipMirrors",
                             "flipReflector",
                             "referenceNoise",
                             "psnrLow",
                             "psnrHigh",
                             "tiedWith",
                             "flipMap"})
        ASSERT_TRUE(column.count(name)) << "CSV column " << name;

    std::set<std::string> families;
    std::map<std::string, std::map<int, double>> depthMirrors; // mirror-depth: depth → PSNR on mirrors
    for (qsizetype i = 0; i < results.size(); ++i) {
        const QJsonObject r = results[i].toObject();
        const std::vector<std::string>& row = csv[std::size_t(i) + 1];
        ASSERT_EQ(row.size(), csv[0].size());
        const std::string id = r["id"].toString().toStdString();
        EXPECT_EQ(row[column["id"]], id);
        EXPECT_EQ(row[column["family"]], r["family"].toString().toStdString());
        families.insert(row[column["family"]]);
        for (const char* field :
             {"gpuMs", "cpuMs", "memoryBytes", "rmse", "psnr", "psnrMirrors", "psnrReflector", "mae",
              "relativeMse", "ssim", "flip", "hdrFlip", "flipMirrors", "flipReflector", "referenceNoise"}) {
            const QJsonValue v = r[field];
            const std::string cell = row[column[field]];
            if (v.isNull()) {
                EXPECT_TRUE(cell.empty()) << id << " " << field;
                continue;
            }
            ASSERT_TRUE(v.isDouble()) << id << " " << field;
            ASSERT_FALSE(cell.empty()) << id << " " << field;
            EXPECT_NEAR(std::stod(cell), v.toDouble(), 1e-6 * std::max(1.0, std::abs(v.toDouble())))
                << id << " " << field;
        }
        // Errors a user can trust: finite PSNR in a plausible range, times and memory that are there.
        EXPECT_TRUE(std::isfinite(r["psnr"].toDouble()));
        EXPECT_GT(r["psnr"].toDouble(), 5.0) << id;
        EXPECT_LT(r["psnr"].toDouble(), 100.0) << id << ": not identical to the exact image";
        EXPECT_GT(r["rmse"].toDouble(), 0.0) << id;
        EXPECT_GT(r["gpuMs"].toDouble(), 0.0) << id;
        EXPECT_GT(r["memoryBytes"].toDouble(), 64 * 40 * 8) << id;
        EXPECT_TRUE(r["psnrMirrors"].isDouble()) << id << ": the mirror is in view";
        EXPECT_TRUE(r["psnrReflector"].isDouble()) << id << ": the ball is in view";
        const QJsonObject settings = r["settings"].toObject();
        EXPECT_EQ(settings["map"].toString().toStdString(), row[column["map"]]) << id;
        EXPECT_EQ(settings["tessellation"].toInt(), std::stoi(row[column["tessellation"]])) << id;
        EXPECT_TRUE(fs::is_regular_file(out / r["errorMap"].toString().toStdString())) << id;
        // The perceptual figures: in range, not identical to the exact image, the map written.
        EXPECT_GT(r["flip"].toDouble(), 0.0) << id;
        EXPECT_LT(r["flip"].toDouble(), 1.0) << id;
        EXPECT_GT(r["hdrFlip"].toDouble(), 0.0) << id;
        EXPECT_GT(r["ssim"].toDouble(), 0.0) << id;
        EXPECT_LT(r["ssim"].toDouble(), 1.0) << id;
        EXPECT_GT(r["mae"].toDouble(), 0.0) << id;
        const QJsonArray interval = r["psnrInterval"].toArray();
        ASSERT_EQ(interval.size(), 2) << id;
        // For the error against a noiseless image: never worse than the PSNR measured against the noisy one.
        EXPECT_LE(interval[0].toDouble(), interval[1].toDouble()) << id;
        EXPECT_GE(interval[1].toDouble(), r["psnr"].toDouble() - 1e-9) << id;
        EXPECT_TRUE(fs::is_regular_file(out / r["flipMap"].toString().toStdString())) << id;
        if (r["family"].toString() == "mirror-depth")
            depthMirrors["d"][settings["mirrorDepth"].toInt()] = r["psnrMirrors"].toDouble();
    }
    EXPECT_EQ(families, (std::set<std::string>{"scene", "envmap", "parallax", "mirror-technique",
                                               "mirror-depth", "shadows", "tessellation", "screen-space"}));
    // Reflections two mirrors deep are closer to the endless recursion than one.
    ASSERT_EQ(depthMirrors["d"].size(), 2u);
    EXPECT_GE(depthMirrors["d"][2], depthMirrors["d"][1] - 0.01);

    // One plot per swept family, real images a person can read.
    for (const std::string& family : families) {
        if (family == "scene")
            continue;
        const fs::path plot = out / ("plot-" + family + ".png");
        auto input = OIIO::ImageInput::open(plot.string());
        ASSERT_TRUE(input) << plot;
        const OIIO::ImageSpec spec = input->spec();
        EXPECT_GE(spec.width, 800);
        EXPECT_GE(spec.height, 500);
        std::vector<unsigned char> pixels(std::size_t(spec.width) * spec.height * spec.nchannels);
        ASSERT_TRUE(input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, pixels.data()));
        std::set<unsigned> colours;
        for (std::size_t p = 0; p + 2 < pixels.size(); p += spec.nchannels)
            colours.insert(unsigned(pixels[p]) << 16 | unsigned(pixels[p + 1]) << 8 | pixels[p + 2]);
        EXPECT_GT(colours.size(), 20u) << plot << ": axes, text and coloured points, not a blank image";
        EXPECT_NE(readFile(out / "report.md").find("](plot-" + family + ".png)"), std::string::npos)
            << "the report embeds " << plot;
        EXPECT_TRUE(fs::is_regular_file(out / ("plot-" + family + "-flip.png"))) << family;
        EXPECT_NE(readFile(out / "report.md").find("](plot-" + family + "-flip.png)"), std::string::npos)
            << "the report embeds FLIP's plot of " << family;
    }
    const std::string report = readFile(out / "report.md");
    EXPECT_NE(report.find("within 1 dB"), std::string::npos);
    EXPECT_NE(report.find("equal error"), std::string::npos);
    EXPECT_NE(report.find("tracer's time"), std::string::npos);
    EXPECT_NE(report.find("Best by FLIP"), std::string::npos);
    EXPECT_NE(report.find("cheapest within one JND (FLIP)"), std::string::npos);
    EXPECT_NE(report.find("| PSNR 95 % |"), std::string::npos);
}

TEST_F(BenchCli, ASceneWithoutAReflectorHasNoMapRows) {
    const fs::path scene = writeScene("mirrors.speculum.json", sceneJson(false));
    const fs::path out = m_dir / "out";
    // --convergence on a scene without rough surfaces: the reference is exact, and the report says so.
    const CliRun run = bench(scene, out, "--quick --size 64x40 --convergence");
    ASSERT_EQ(run.status, 0) << run.err;
    const QJsonObject root = loadJson(out / "results.json");
    EXPECT_TRUE(root["convergence"].toObject()["exact"].toBool());
    EXPECT_FALSE(root.contains("furnace")) << "no rough surface, no furnace";
    EXPECT_NE(readFile(out / "report.md").find("## Convergence of the reference"), std::string::npos);
    EXPECT_NE(readFile(out / "report.md").find("exact with one path"), std::string::npos);
    const QJsonArray results = root["results"].toArray();
    ASSERT_FALSE(results.isEmpty());
    for (const QJsonValue& v : results) {
        const QJsonObject r = v.toObject();
        EXPECT_NE(r["family"].toString(), "envmap");
        EXPECT_NE(r["family"].toString(), "parallax");
        EXPECT_TRUE(r["psnrReflector"].isNull());
        EXPECT_FALSE(r["settings"].toObject().contains("map"));
    }
    EXPECT_FALSE(fs::exists(out / "plot-envmap.png"));
    for (const auto& row : parseCsv(readFile(out / "results.csv")))
        EXPECT_NE(row[1], "envmap");
}

// Two facing balls, one bouncing: the bounces family (0, 1, 2 bounces, each its own frame) and the update
// family (every frame, then time-sliced, played), with their rows, columns and report lines.
TEST_F(BenchCli, FacingBallsGetTheBouncesAndUpdateFamilies) {
    const fs::path scene = writeScene("balls.speculum.json", R"({"format": "speculum-scene", "version": 1,
  "camera": {"position": [0, 0.6, 4], "target": [0, 0.5, 0], "fovY": 50, "near": 0.1, "far": 30},
  "nodes": [
    {"name": "Floor", "transform": {"scale": [3, 1, 3]}, "mesh": {"builtin": "plane"},
     "material": {"color": [0.8, 0.3, 0.2]}},
    {"name": "Left", "transform": {"translate": [-0.6, 0.5, 0], "scale": [0.5, 0.5, 0.5]},
     "mesh": {"builtin": "sphere", "tessellation": 16}, "reflector": {"resolution": 32, "reflectivity": 1}},
    {"name": "Right", "transform": {"translate": [0.6, 0.5, 0], "scale": [0.5, 0.5, 0.5]},
     "mesh": {"builtin": "sphere", "tessellation": 16}, "reflector": {"resolution": 32, "reflectivity": 1},
     "animation": {"bounce": {"height": 1, "period": 1}}},
    {"name": "Lamp", "transform": {"translate": [1, 3, 2]}, "light": {"type": "point"}}]})");
    const fs::path out = m_dir / "out";
    const CliRun run = bench(scene, out);
    ASSERT_EQ(run.status, 0) << run.err;
    std::map<std::string, double> bounces, update;
    for (const QJsonValue& v : loadJson(out / "results.json")["results"].toArray()) {
        const QJsonObject r = v.toObject();
        const QJsonObject settings = r["settings"].toObject();
        EXPECT_TRUE(settings.contains("bounces")) << "two reflectors: every row says its bounces";
        if (r["family"].toString() == "bounces")
            bounces[settings["bounces"].toVariant().toString().toStdString()] = r["psnrReflector"].toDouble();
        if (r["family"].toString() == "update") {
            EXPECT_EQ(r["reference"].toString(), "played");
            update[settings["update"].toString().toStdString()] = r["psnrReflector"].toDouble();
        }
    }
    ASSERT_EQ(bounces.size(), 3u) << "0, 1 and 2 bounces, each drawn, not one frame shared";
    EXPECT_GT(bounces["1"], bounces["0"]) << "the first bounce shows each ball in the other";
    ASSERT_EQ(update.size(), 2u);
    EXPECT_TRUE(update.count("always") && update.count("time-sliced"));
    const std::string report = readFile(out / "report.md");
    EXPECT_NE(report.find("A first bounce gains"), std::string::npos) << report;
    EXPECT_NE(report.find("Time-sliced, the maps"), std::string::npos) << report;
    EXPECT_TRUE(fs::exists(out / "reference-played.png"));
}

TEST_F(BenchCli, BadInputFailsWithOneLineAndWritesNothing) {
    const fs::path good = writeScene("good.speculum.json", sceneJson(false));
    const fs::path broken =
        writeScene("broken.speculum.json", "{\"format\": \"speculum-scene\", \"version\": 1,");
    auto oneLine = [](const CliRun& run) {
        return !run.err.empty() && run.err.find('\n') == run.err.size() - 1;
    };

    const CliRun missing = bench(m_dir / "nope.speculum.json", m_dir / "new");
    EXPECT_NE(missing.status, 0);
    EXPECT_TRUE(oneLine(missing)) << missing.err;
    EXPECT_FALSE(fs::exists(m_dir / "new")) << "no folder for a failed run";

    const CliRun bad = bench(broken, m_dir / "new" / "deeper");
    EXPECT_NE(bad.status, 0);
    EXPECT_TRUE(oneLine(bad)) << bad.err;
    EXPECT_FALSE(fs::exists(m_dir / "new"));

    const fs::path file = m_dir / "results-file";
    std::ofstream(file) << "mine";
    const CliRun notFolder = bench(good, file);
    EXPECT_NE(notFolder.status, 0);
    EXPECT_TRUE(oneLine(notFolder)) << notFolder.err;
    EXPECT_EQ(readFile(file), "mine");

    const CliRun noOut = runSpeculum("bench " + good.string() + " --quick");
    EXPECT_NE(noOut.status, 0);
    EXPECT_TRUE(oneLine(noOut)) << noOut.err;

    // An existing folder keeps its other files, through a failed run and a good one.
    const fs::path folder = m_dir / "existing";
    fs::create_directories(folder);
    std::ofstream(folder / "notes.txt") << "keep me";
    EXPECT_NE(bench(broken, folder).status, 0);
    EXPECT_EQ(std::vector<fs::path>(fs::directory_iterator(folder), {}).size(), 1u);
    // A plot an earlier run left for a family this scene lacks would mix two runs: it goes.
    std::ofstream(folder / "plot-envmap.png") << "from an earlier run";
    const CliRun ok = bench(good, folder);
    ASSERT_EQ(ok.status, 0) << ok.err;
    EXPECT_EQ(readFile(folder / "notes.txt"), "keep me");
    EXPECT_TRUE(fs::is_regular_file(folder / "results.json"));
    EXPECT_FALSE(fs::exists(folder / "plot-envmap.png"));
}

// Ctrl-C while the sweep runs: the run stops at its next step with the shell's status for an interrupt,
// says so, and leaves the disk as it found it (the folder it made is gone, no staging folder is left).
TEST_F(BenchCli, InterruptedRunStopsAndWritesNothing) {
    const fs::path scene = writeScene("scene.speculum.json", sceneJson(true));
    const fs::path out = m_dir / "interrupted";
    const fs::path errFile = m_dir / "interrupted.err";
    const std::string binary = speculum::testCliBinary();
    const std::vector<std::string> args = {binary,       "bench",   scene.string(), "--out",
                                           out.string(), "--quick", "--size",       "320x180"};
    std::vector<char*> argv;
    for (const std::string& a : args)
        argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_addopen(&files, 2, errFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid = 0;
    ASSERT_EQ(posix_spawn(&pid, binary.c_str(), &files, nullptr, argv.data(), environ), 0);
    posix_spawn_file_actions_destroy(&files);

    // The staging folder appears once the run is under way (its signal handlers are in place by then).
    auto staging = [&] {
        std::error_code ec;
        for (const fs::directory_entry& e : fs::directory_iterator(out, ec))
            if (e.path().filename().string().rfind(".speculum-bench-", 0) == 0)
                return true;
        return false;
    };
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!staging() && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ASSERT_TRUE(staging()) << "the run never started: " << readFile(errFile);
    ::kill(pid, SIGINT);
    int raw = 0;
    ASSERT_EQ(::waitpid(pid, &raw, 0), pid);
    ASSERT_TRUE(WIFEXITED(raw)) << "killed instead of stopping: " << readFile(errFile);
    EXPECT_EQ(WEXITSTATUS(raw), 130) << readFile(errFile);
    EXPECT_NE(readFile(errFile).find("interrupted"), std::string::npos) << readFile(errFile);
    EXPECT_FALSE(fs::exists(out)) << "the folder the run made is removed again";
}

} // namespace
