// `speculum bench --quick` on the chrome and mirrors demos, as the README suggests running it: both finish,
// and each gets the families its scene calls for. Labelled slow (each run takes tens of seconds).
#include "CliRun.hpp"
#include "support/TestPaths.hpp"

#include <QByteArray>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <set>

namespace {

namespace fs = std::filesystem;

std::set<std::string> benchFamilies(const std::string& demo) {
    const fs::path out = fs::path(speculum::testDataPath()) / ("bench-demo-" + demo);
    fs::remove_all(out);
    const std::string scene = speculum::testSourcePath("resources/scenes/") + demo + ".speculum.json";
    const auto start = std::chrono::steady_clock::now();
    const speculum::test::CliRun run =
        speculum::test::runSpeculum("bench " + scene + " --out " + out.string() + " --quick");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(run.status, 0) << run.err;
    std::printf("[ measured ] bench --quick %s: %.1f s\n", demo.c_str(), seconds);
    std::ifstream in(out / "results.json", std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), {});
    std::set<std::string> families;
    for (const QJsonValue& v : QJsonDocument::fromJson(QByteArray::fromStdString(text))["results"].toArray())
        families.insert(v.toObject()["family"].toString().toStdString());
    return families;
}

TEST(BenchDemos, ChromeSweepsTheMapParallaxAndShadows) {
    EXPECT_EQ(benchFamilies("chrome"), (std::set<std::string>{"scene", "envmap", "parallax", "shadows"}));
}

// Its back mirror is rough (roughness 0.15), so the glossy family runs too.
TEST(BenchDemos, MirrorsSweepsTechniqueDepthShadowsTessellationAndGlossy) {
    EXPECT_EQ(benchFamilies("mirrors"), (std::set<std::string>{"scene", "mirror-technique", "mirror-depth",
                                                               "shadows", "tessellation", "glossy"}));
}

} // namespace
