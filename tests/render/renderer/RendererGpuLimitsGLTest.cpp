// Map sizes beyond what the GPU holds: a shadow map or reflector resolution larger than the context's
// limits is drawn at the largest size it holds, with a warning in the frame report, and no GL error.
#include "scene/evaluate/Snapshot.hpp"
#include "scene/import/MeshLibrary.hpp"
#include "scene/project/ProjectFile.hpp"
#include "support/GlTest.hpp"
#include "support/TestPaths.hpp"

#include <algorithm>
#include <cmath>

namespace speculum::test {
namespace {

using namespace render;

// The chrome demo (a point light with a cube shadow map, the chrome ball) with a spot light added, so
// both kinds of shadow map are drawn.
FrameInput chromeScene() {
    scene::Scene scene;
    std::vector<std::string> warnings;
    EXPECT_TRUE(scene::openProject(
                    scene,
                    QString::fromStdString(speculum::testSourcePath("resources/scenes/chrome.speculum.json")),
                    warnings)
                    .ok());
    scene::MeshLibrary meshes;
    std::vector<scene::Warning> snapshotWarnings;
    FrameInput input = scene::snapshot(scene, 0.0, meshes, snapshotWarnings);
    EXPECT_EQ(input.reflectors.size(), 1u);
    Light spot;
    spot.name = "Spot";
    spot.type = LightType::Spot;
    spot.position = {-2.0, 4.0, 2.0};
    spot.direction = glm::normalize(glm::dvec3(2.0, -4.0, -2.0));
    spot.spotAngle = 40.0;
    spot.intensity = 0.5;
    spot.shadows = render::ShadowParams{1024, 3};
    input.lights.push_back(spot);
    return input;
}

bool mentions(const std::vector<std::string>& warnings, const std::string& what) {
    return std::any_of(warnings.begin(), warnings.end(),
                       [&](const std::string& w) { return w.find(what) != std::string::npos; });
}

// Limits lowered to a few hundred texels stand for a GPU's: the real ones (16384 on llvmpipe) would take
// gigabytes of memory to reach.
TEST_F(GlTest, MapsLargerThanTheGpuHoldsAreDrawnAtItsLimitWithAWarning) {
    renderer().lowerGpuLimits({512, 256, 512, 512});
    struct Case {
        ReflectorMap map;
        ReflectorFill fill;
        int expected; // resolution drawn
    };
    for (const Case& c : {Case{ReflectorMap::Cube, ReflectorFill::Resampled, 256},
                          Case{ReflectorMap::DualParaboloid, ReflectorFill::Resampled, 256},
                          Case{ReflectorMap::TennisBall, ReflectorFill::Direct, 512 / 3}}) {
        SCOPED_TRACE(int(c.map));
        FrameInput asked = chromeScene();
        asked.reflectors[0].map = c.map;
        asked.reflectors[0].fill = c.fill;
        asked.reflectors[0].resolution = 100000;
        for (Light& light : asked.lights)
            light.shadows->mapSize = 100000;
        const Image over = renderImage(asked, 160, 90);
        const std::vector<std::string> warnings = lastReport().warnings;
        EXPECT_TRUE(mentions(warnings, "reflector \"Chrome ball\": resolution 100000"))
            << ::testing::PrintToString(warnings);
        EXPECT_TRUE(mentions(warnings, "light \"Light\"")) << ::testing::PrintToString(warnings);
        EXPECT_TRUE(mentions(warnings, "light \"Spot\"")) << ::testing::PrintToString(warnings);
        // The plan says which sizes it drew: fitted while planning, with the warnings, the one plan of the
        // frame.
        const FrameReport& report = lastReport();
        EXPECT_FALSE(report.drawAgain);
        EXPECT_EQ(report.plan.reflectorResolution(0), c.expected);
        ASSERT_EQ(report.plan.shadows.size(), 2u);
        EXPECT_EQ(report.plan.shadows[0].mapSize, 256);
        EXPECT_EQ(report.plan.shadows[1].mapSize, 512);
        ASSERT_EQ(report.plan.warnings.size(), 3u) << ::testing::PrintToString(report.plan.warnings);
        EXPECT_TRUE(std::equal(report.plan.warnings.begin(), report.plan.warnings.end(), warnings.begin()))
            << "the report's warnings open with the plan's";
        const auto envmap = std::find_if(report.ran.begin(), report.ran.end(), [&](const PassRun& run) {
            return report.planned(run).kind == PassKind::Envmap;
        });
        ASSERT_NE(envmap, report.ran.end());
        EXPECT_EQ(report.planned(*envmap).details.resolution, c.expected) << report.reason(*envmap);

        // The same as asking for those sizes in the first place.
        FrameInput fitting = asked;
        fitting.reflectors[0].resolution = c.expected;
        fitting.lights[0].shadows->mapSize = 256; // a point light's cube map
        fitting.lights[1].shadows->mapSize = 512;
        const Image at = renderImage(fitting, 160, 90);
        EXPECT_TRUE(lastReport().warnings.empty()) << ::testing::PrintToString(lastReport().warnings);
        ASSERT_EQ(over.rgba.size(), at.rgba.size());
        EXPECT_TRUE(std::equal(over.rgba.begin(), over.rgba.end(), at.rgba.begin()));
        for (float v : over.rgba)
            ASSERT_TRUE(std::isfinite(v));
    }
}

// At the driver's own limit, for the map that is cheap to reach: one 2D shadow map as large as the GPU
// allows (16384² on llvmpipe: 1 GiB of depth).
TEST_F(GlTest, SpotShadowMapBeyondTheDriversLimitIsDrawnAtTheLimit) {
    FrameInput input = chromeScene();
    input.lights.erase(input.lights.begin()); // the spot light alone
    input.lights[0].shadows->mapSize = 100000;
    renderImage(input, 64, 36);
    const int limit = std::min(renderer().gpuLimits().maxTextureSize, renderer().gpuLimits().maxViewportSize);
    ASSERT_EQ(lastReport().warnings.size(), 1u) << ::testing::PrintToString(lastReport().warnings);
    EXPECT_NE(lastReport().warnings[0].find(std::to_string(limit) + "²"), std::string::npos)
        << lastReport().warnings[0];
}

} // namespace
} // namespace speculum::test
