// `bench --shard K/N` and `bench --merge`, through bench::run as the command line calls it: a quick bench
// of a small scene run as two shards and merged writes what a run on one machine writes (the same records
// in the same order, the same errors, ties and distances to each family's best, the same images), times
// aside; the shards' folders are left as they were; a merge of overlapping or incomplete shards, or of
// another project, is refused with one line and writes nothing.
#include "app/BenchCommand.hpp"
#include "support/TestPaths.hpp"

#include <QByteArray>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <sstream>

namespace {

namespace fs = std::filesystem;
using speculum::app::bench::Options;

// A floor, a rough mirror (the glossy family, a noisy reference: ties), a teapot and a shadowing lamp.
constexpr const char* kScene = R"({"format": "speculum-scene", "version": 1,
  "settings": {"background": [0.2, 0.25, 0.3], "mirrorDepth": 2, "ambient": 0.3},
  "camera": {"position": [0, 1.5, 4], "target": [0, 0.6, 0], "up": [0, 1, 0], "fovY": 60, "near": 0.1, "far": 30},
  "nodes": [
    {"name": "Floor", "transform": {"scale": [3, 1, 3]}, "mesh": {"builtin": "plane", "tessellation": 1},
     "material": {"color": [0.8, 0.8, 0.8]}},
    {"name": "Teapot", "transform": {"translate": [-1, 0, 0], "scale": [0.3, 0.3, 0.3]},
     "mesh": {"builtin": "teapot", "tessellation": 4}, "material": {"color": [0.8, 0.2, 0.1], "specular": 0.5}},
    {"name": "Mirror", "transform": {"translate": [0, 1, -2], "rotate": [90, 0, 0]},
     "mirror": {"size": [5, 2], "reflectivity": 0.9, "roughness": 0.3}},
    {"name": "Lamp", "transform": {"translate": [1, 3, 2]},
     "light": {"type": "point", "shadows": {"mapSize": 256, "pcf": 3}}}]}
)";

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

QJsonObject loadJson(const fs::path& path) {
    return QJsonDocument::fromJson(QByteArray::fromStdString(readFile(path))).object();
}

// Every file under `folder` (relative name → contents).
std::map<std::string, std::string> filesUnder(const fs::path& folder) {
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(folder))
        if (entry.is_regular_file())
            files[fs::relative(entry.path(), folder).string()] = readFile(entry.path());
    return files;
}

// A record of results.json without what a shard measures where it runs: its times, where it ran.
QJsonObject withoutTimes(QJsonObject record) {
    for (const char* key : {"gpuMs", "cpuMs", "ranOn"})
        record.remove(key);
    return record;
}

class BenchShards : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        s_dir = fs::path(speculum::testDataPath()) / "bench-shards";
        fs::remove_all(s_dir);
        fs::create_directories(s_dir);
        std::ofstream(s_dir / "scene.speculum.json") << kScene;
        ASSERT_EQ(speculum::app::bench::run(options("whole")), 0);
        for (int k = 0; k < 2; ++k) {
            Options shard = options("shard" + std::to_string(k));
            shard.shard = speculum::base::Shard{k, 2, false};
            ASSERT_EQ(speculum::app::bench::run(shard), 0) << "shard " << k;
        }
    }

    static Options options(const std::string& out) {
        Options o;
        o.project = (s_dir / "scene.speculum.json").string();
        o.outDir = (s_dir / out).string();
        o.quick = true;
        o.width = 64;
        o.height = 40;
        return o;
    }

    static Options merge(const std::string& out, const std::vector<std::string>& shards) {
        Options o = options(out);
        for (const std::string& s : shards)
            o.mergeDirs.push_back((s_dir / s).string());
        return o;
    }

    // bench::run's exit status and the error lines it printed on stderr (between progress lines).
    static std::pair<int, std::string> runCapturingErrors(const Options& o) {
        ::testing::internal::CaptureStderr();
        const int status = speculum::app::bench::run(o);
        std::istringstream err(::testing::internal::GetCapturedStderr());
        std::string errors;
        for (std::string line; std::getline(err, line);)
            if (line.rfind("speculum: error: ", 0) == 0)
                errors += line + "\n";
        return {status, errors};
    }

    static fs::path s_dir;
};

fs::path BenchShards::s_dir;

TEST_F(BenchShards, AShardHoldsItsShareAndNoReport) {
    const QJsonObject whole = loadJson(s_dir / "whole" / "results.json");
    const QJsonObject shard = loadJson(s_dir / "shard1" / "results.json");
    const QJsonArray all = whole["results"].toArray(), share = shard["results"].toArray();
    ASSERT_GE(all.size(), 4) << "enough configurations to share";
    EXPECT_EQ(share.size(), all.size() / 2) << "every other one, from the second";
    EXPECT_EQ(share[0].toObject()["id"], all[1].toObject()["id"]);
    const QJsonObject info = shard["shard"].toObject();
    EXPECT_EQ(info["index"].toInt(), 1);
    EXPECT_EQ(info["count"].toInt(), 2);
    EXPECT_EQ(info["configurations"].toArray().size(), all.size()) << "the whole sweep's list";
    EXPECT_EQ(info["projectSha256"].toString().size(), 64);
    EXPECT_FALSE(fs::exists(s_dir / "shard1" / "report.md")) << "a share's findings would mislead";
    EXPECT_TRUE(fs::exists(s_dir / "shard1" / "shard")) << "its frames, kept for the merge";
}

TEST_F(BenchShards, MergedShardsWriteWhatOneMachineWrites) {
    const auto before = filesUnder(s_dir / "shard0");
    ASSERT_EQ(speculum::app::bench::run(merge("merged", {"shard1", "shard0"})), 0);
    EXPECT_EQ(filesUnder(s_dir / "shard0"), before) << "a merge leaves its inputs as they were";

    const QJsonObject whole = loadJson(s_dir / "whole" / "results.json");
    const QJsonObject merged = loadJson(s_dir / "merged" / "results.json");
    const QJsonArray a = whole["results"].toArray(), b = merged["results"].toArray();
    ASSERT_EQ(a.size(), b.size());
    bool comparedWithBest = false;
    for (qsizetype i = 0; i < a.size(); ++i) {
        EXPECT_EQ(withoutTimes(a[i].toObject()), withoutTimes(b[i].toObject()))
            << "record " << i << ": " << a[i].toObject()["id"].toString().toStdString();
        comparedWithBest = comparedWithBest || b[i].toObject()["flipToBest"].isDouble();
        EXPECT_EQ(b[i].toObject()["ranOn"].toObject()["shard"].toString(), i % 2 == 0 ? "0/2" : "1/2");
    }
    EXPECT_TRUE(comparedWithBest) << "the merge compares frames of different shards";
    EXPECT_EQ(whole["references"].toArray().size(), merged["references"].toArray().size());
    EXPECT_EQ(whole["furnace"], merged["furnace"]) << "run once, by the shard with the first glossy row";
    EXPECT_EQ(merged["shards"].toArray().size(), 2);
    EXPECT_FALSE(merged["timesFromSeveralMachines"].toBool()) << "both shards ran here";

    // The same files: the images byte for byte (the plots and the report differ by the times).
    const auto oneMachine = filesUnder(s_dir / "whole"), joined = filesUnder(s_dir / "merged");
    for (const auto& [name, contents] : oneMachine) {
        ASSERT_TRUE(joined.count(name)) << name;
        const bool image = name.rfind("errors/", 0) == 0 || name.rfind("flip/", 0) == 0 ||
                           name.rfind("reference", 0) == 0 || name == "render.png";
        if (image) {
            EXPECT_EQ(joined.at(name), contents) << name;
        }
    }
    EXPECT_EQ(joined.size(), oneMachine.size()) << "nothing more, nothing less";
    const std::string report = joined.at("report.md");
    EXPECT_NE(report.find("## Where it ran"), std::string::npos);
    EXPECT_NE(report.find("| 1/2 |"), std::string::npos) << "where each configuration ran";
}

TEST_F(BenchShards, OverlappingOrMissingShardsAreRefusedAndWriteNothing) {
    fs::copy(s_dir / "shard0", s_dir / "shard0-again", fs::copy_options::recursive);
    const auto [overlap, overlapError] =
        runCapturingErrors(merge("overlap", {"shard0", "shard0-again", "shard1"}));
    EXPECT_EQ(overlap, 1);
    EXPECT_NE(overlapError.find("is in both"), std::string::npos) << overlapError;
    EXPECT_EQ(std::count(overlapError.begin(), overlapError.end(), '\n'), 1) << overlapError;
    EXPECT_FALSE(fs::exists(s_dir / "overlap"));

    const auto [twice, twiceError] = runCapturingErrors(merge("twice", {"shard0", "shard0", "shard1"}));
    EXPECT_EQ(twice, 1);
    EXPECT_NE(twiceError.find("given twice"), std::string::npos) << twiceError;
    EXPECT_FALSE(fs::exists(s_dir / "twice"));

    const auto [gap, gapError] = runCapturingErrors(merge("gap", {"shard0"}));
    EXPECT_EQ(gap, 1);
    EXPECT_NE(gapError.find("shard 1/2 measures it"), std::string::npos) << gapError;
    EXPECT_EQ(std::count(gapError.begin(), gapError.end(), '\n'), 1) << gapError;
    EXPECT_FALSE(fs::exists(s_dir / "gap"));

    const auto [whole, wholeError] = runCapturingErrors(merge("notshard", {"shard0", "whole"}));
    EXPECT_EQ(whole, 1);
    EXPECT_NE(wholeError.find("not of a shard"), std::string::npos) << wholeError;
    EXPECT_FALSE(fs::exists(s_dir / "notshard"));
}

TEST_F(BenchShards, AMergeOfAnotherProjectOrIntoAShardIsRefused) {
    std::ofstream(s_dir / "other.speculum.json") << std::string(kScene) << " ";
    Options other = merge("other", {"shard0", "shard1"});
    other.project = (s_dir / "other.speculum.json").string();
    const auto [status, error] = runCapturingErrors(other);
    EXPECT_EQ(status, 1);
    EXPECT_NE(error.find("not the project the shards measured"), std::string::npos) << error;
    EXPECT_FALSE(fs::exists(s_dir / "other"));

    const auto before = filesUnder(s_dir / "shard0");
    const auto [inside, insideError] = runCapturingErrors(merge("shard0/merged", {"shard0", "shard1"}));
    EXPECT_EQ(inside, 1);
    EXPECT_NE(insideError.find("inside"), std::string::npos) << insideError;
    EXPECT_EQ(filesUnder(s_dir / "shard0"), before);
}

} // namespace
