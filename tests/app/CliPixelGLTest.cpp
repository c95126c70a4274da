// `speculum explain PROJECT --pixel X,Y`: one pixel's exact path beside the raster's recipe, on the demos,
// checked against the stills `render` and `render --reference` write of the same frame.
#include "CliRun.hpp"
#include "support/TestPaths.hpp"

#include <OpenImageIO/imageio.h>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
namespace test = speculum::test;
using test::CliRun;

std::string demo(const std::string& name) {
    return speculum::testSourcePath("resources/scenes/" + name + ".speculum.json");
}

QJsonObject explainPixel(const std::string& scene, const std::string& size, const std::string& pixel) {
    const CliRun run =
        test::runSpeculum("explain " + demo(scene) + " --size " + size + " --pixel " + pixel + " --json");
    EXPECT_EQ(run.status, 0) << run.err;
    return QJsonDocument::fromJson(QByteArray::fromStdString(run.out)).object();
}

std::vector<std::string> events(const QJsonObject& root) {
    std::vector<std::string> out;
    for (const auto& v : root["exact"].toObject()["path"].toArray())
        out.push_back(v.toObject()["event"].toString().toStdString() + " " +
                      v.toObject()["target"].toString().toStdString());
    return out;
}

std::vector<float> readPixel(const fs::path& file, int x, int y) {
    auto in = OIIO::ImageInput::open(file.string());
    EXPECT_TRUE(in) << file;
    if (!in)
        return {};
    const OIIO::ImageSpec& spec = in->spec();
    std::vector<float> pixels(std::size_t(spec.width) * spec.height * spec.nchannels);
    EXPECT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
    const std::size_t p = (std::size_t(y) * spec.width + x) * spec.nchannels;
    return {pixels[p], pixels[p + 1], pixels[p + 2]};
}

glm::dvec3 vec(const QJsonValue& value) {
    const QJsonArray a = value.toArray();
    return {a[0].toDouble(), a[1].toDouble(), a[2].toDouble()};
}

TEST(CliPixel, ThroughTheFloorMirrorThePathListsTheMirrorThenTheBallAndTheRecipeItsStencilLevel) {
    const QJsonObject root = explainPixel("facing-balls", "160x90", "55,75");
    const std::vector<std::string> path = events(root);
    ASSERT_GE(path.size(), 3u);
    EXPECT_EQ(path[0], "mirror Floor mirror");
    EXPECT_EQ(path[1], "reflector Left ball");
    // The raster: the floor's mask marks level 1, and the mirror pass draws the reflected scene there.
    bool masked = false, reflected = false;
    for (const auto& value : root["raster"].toObject()["steps"].toArray()) {
        const QJsonObject step = value.toObject();
        if (step["target"].toString() != "Floor mirror" || !step["wrote"].toBool())
            continue;
        if (step["pass"].toString() == "mirror-mask") {
            masked = true;
            EXPECT_EQ(step["stencil"].toInt(), 1);
            EXPECT_EQ(step["mirrorLevel"].toInt(), 1);
        }
        if (step["pass"].toString() == "mirror") {
            reflected = true;
            EXPECT_EQ(step["stencil"].toInt(), 1);
            EXPECT_NE(step["what"].toString().indexOf("where the stencil is 1"), -1);
        }
    }
    EXPECT_TRUE(masked);
    EXPECT_TRUE(reflected);
    // The ball seen in the mirror reads its map: the recipe names it.
    EXPECT_EQ(root["lookup"].toObject()["reflector"].toString(), "Left ball");
}

TEST(CliPixel, OnTheChromeBallTheRecipeNamesTheTexelTheExactReflectionPointsInto) {
    const QJsonObject root = explainPixel("chrome", "320x180", "160,90");
    ASSERT_EQ(events(root).front(), "reflector Chrome ball");
    const QJsonObject lookup = root["lookup"].toObject();
    EXPECT_EQ(lookup["layout"].toString(), "cube");
    EXPECT_EQ(lookup["texel"].toArray().size(), 2);
    EXPECT_FALSE(lookup["componentLabel"].toString().isEmpty());
    // The exact path's reflected direction and the centre of the texel the map reads: within a texel.
    const glm::dvec3 reflected = vec(root["exact"].toObject()["path"].toArray()[0].toObject()["outgoing"]);
    const glm::dvec3 texel = vec(lookup["texelCentre"]);
    const double angle = std::acos(std::clamp(glm::dot(reflected, texel), -1.0, 1.0));
    const double texelAngle = std::sqrt(lookup["texelSolidAngle"].toDouble());
    EXPECT_LT(angle, texelAngle) << "reflected and texel centre " << angle << " rad apart, a texel is "
                                 << texelAngle;
    bool capture = false;
    for (const auto& c : root["causes"].toArray())
        capture = capture || c.toObject()["code"].toString() == "capture-point";
    EXPECT_TRUE(capture);
}

TEST(CliPixel, TheColoursAreTheStillsPixels) {
    const fs::path dir = test::freshCliFolder("pixel");
    const std::string size = "160x90";
    const fs::path raster = dir / "raster.exr", exact = dir / "exact.exr";
    ASSERT_EQ(
        test::runSpeculum("render " + demo("facing-balls") + " --size " + size + " -o " + raster.string())
            .status,
        0);
    ASSERT_EQ(test::runSpeculum("render " + demo("facing-balls") + " --size " + size + " --reference -o " +
                                exact.string())
                  .status,
              0);
    for (const auto& [x, y] : {std::pair{55, 75}, std::pair{70, 80}, std::pair{2, 2}}) {
        const QJsonObject root =
            explainPixel("facing-balls", size, std::to_string(x) + "," + std::to_string(y));
        const glm::dvec3 r = vec(root["raster"].toObject()["colour"]);
        const glm::dvec3 e = vec(root["exact"].toObject()["colour"]);
        const std::vector<float> rs = readPixel(raster, x, y), es = readPixel(exact, x, y);
        ASSERT_EQ(rs.size(), 3u);
        ASSERT_EQ(es.size(), 3u);
        for (int c = 0; c < 3; ++c) {
            // The EXR holds half floats: the colours agree to its precision.
            EXPECT_NEAR(r[c], rs[std::size_t(c)], 2e-3 * std::max(1.0, std::abs(r[c]))) << x << "," << y;
            EXPECT_NEAR(e[c], es[std::size_t(c)], 2e-3 * std::max(1.0, std::abs(e[c]))) << x << "," << y;
        }
    }
}

TEST(CliPixel, TheBackgroundIsOneSegmentAndSaysSo) {
    const QJsonObject root = explainPixel("chrome", "320x180", "160,2");
    const std::vector<std::string> path = events(root);
    ASSERT_EQ(path.size(), 1u);
    EXPECT_EQ(path[0], "background ");
    bool said = false;
    for (const auto& c : root["causes"].toArray())
        said = said || c.toObject()["code"].toString() == "background";
    EXPECT_TRUE(said);
}

TEST(CliPixel, AGlossyPixelListsItsSampledPathsAndTheirNoise) {
    const QJsonObject root = explainPixel("facing-balls", "160x90", "70,60"); // the satin ball
    const QJsonObject exact = root["exact"].toObject();
    EXPECT_TRUE(exact["glossy"].toBool());
    EXPECT_FALSE(exact["samples"].toArray().isEmpty());
    EXPECT_GT(exact["standardError"].toDouble(), 0.0);
}

TEST(CliPixel, APixelOutsideTheImageIsOneClearLine) {
    const CliRun run = test::runSpeculum("explain " + demo("chrome") + " --size 320x180 --pixel 320,10");
    EXPECT_NE(run.status, 0);
    EXPECT_TRUE(run.out.empty());
    EXPECT_NE(run.err.find("--pixel: '320,10' is outside the 320x180 image"), std::string::npos) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    const CliRun garbled = test::runSpeculum("explain " + demo("chrome") + " --pixel 10x10");
    EXPECT_NE(garbled.status, 0);
    EXPECT_NE(garbled.err.find("--pixel: expected X,Y"), std::string::npos) << garbled.err;
}

TEST(CliPixel, TextShowsBothRecipesAndWhyTheyDiffer) {
    const CliRun run = test::runSpeculum("explain " + demo("chrome") + " --size 320x180 --pixel 160,90");
    ASSERT_EQ(run.status, 0) << run.err;
    for (const char* heading : {"Exact path", "Raster recipe", "Why they differ", "map lookup"})
        EXPECT_NE(run.out.find(heading), std::string::npos) << heading << "\n" << run.out;
}

} // namespace
