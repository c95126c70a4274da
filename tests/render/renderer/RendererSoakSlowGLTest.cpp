// Hard cases under load: 1000 animated frames of each demo scene with the camera sweeping through mirror
// planes (and, exactly on them, at some frames), checking every frame for NaN pixels and GL errors, and
// that memory stays flat. Labelled "slow": run with `ctest -L slow` (figures go in the benchmarks notes).
#include "scene/evaluate/Snapshot.hpp"
#include "scene/import/MeshLibrary.hpp"
#include "scene/project/ProjectFile.hpp"
#include "support/GlTest.hpp"
#include "support/TestPaths.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

namespace speculum::test {
namespace {

// Resident memory of this process in MiB (Linux).
double residentMiB() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("VmRSS:", 0) == 0)
            return std::stod(line.substr(6)) / 1024.0;
    return 0.0;
}

struct Sweep {
    const char* scene;
    bool cycleMaps = false; // switch the reflector's map type every third of the run
    // Camera position at frame i of n; exactly on a mirror plane at some frames.
    glm::dvec3 (*position)(int i, int n);
    glm::dvec3 target;
};

void soak(render::Renderer& renderer, const Sweep& sweep, int frames) {
    scene::Scene scene;
    std::vector<std::string> warnings;
    ASSERT_TRUE(scene::openProject(scene,
                                   QString::fromStdString(speculum::testSourcePath("resources/scenes/")) +
                                       sweep.scene,
                                   warnings)
                    .ok());
    scene::MeshLibrary meshes;
    // Memory is compared from a frame after the warm-up (and, when the map type cycles, after the last
    // switch, which legitimately allocates the new map) to the end.
    const int baselineFrame = sweep.cycleMaps ? frames * 2 / 3 + 50 : 100;
    double memoryAtBaseline = 0.0;
    int nanFrames = 0;
    for (int i = 0; i < frames; ++i) {
        std::vector<scene::Warning> snapshotWarnings;
        render::FrameInput input = scene::snapshot(scene, i / 30.0, meshes, snapshotWarnings);
        input.camera.position = sweep.position(i, frames);
        input.camera.target = sweep.target;
        if (sweep.cycleMaps && !input.reflectors.empty())
            input.reflectors[0].map = static_cast<render::ReflectorMap>(std::min(2, i * 3 / frames));
        auto still = render::renderStill(renderer, input, {160, 90, 1});
        ASSERT_TRUE(still.ok()) << still.error();
        for (float v : still->image.rgba)
            if (!std::isfinite(v)) {
                ++nanFrames;
                break;
            }
        if (i == baselineFrame)
            memoryAtBaseline = residentMiB();
    }
    const double memoryAtEnd = residentMiB();
    std::printf(
        "[ soak ] %s: %d frames, NaN frames %d, resident memory %.1f MiB at frame %d, %.1f MiB at %d\n",
        sweep.scene, frames, nanFrames, memoryAtBaseline, baselineFrame, memoryAtEnd, frames);
    EXPECT_EQ(nanFrames, 0);
    EXPECT_LT(memoryAtEnd - memoryAtBaseline, 16.0) << "memory grows with frames";
}

TEST_F(GlTest, ThousandFramesOfTheTeapotDemoWithTheCameraCrossingTheTable) {
    // Around the table and up and down through its plane (y = −1), exactly on it every 50 frames.
    soak(renderer(),
         {"teapot.speculum.json",
          false,
          [](int i, int) {
              const double a = i * 0.013;
              return glm::dvec3(2.5 * std::cos(a), -1.0 + 1.2 * std::sin(i * 2.0 * M_PI / 100.0),
                                -3.0 + 2.5 * std::sin(a));
          },
          {0.0, -0.8, -3.0}},
         1000);
}

TEST_F(GlTest, ThousandFramesOfTheMirrorRoomWithTheCameraPassingThroughTheMirrors) {
    // Side to side through both facing mirrors (x = ±3), exactly on them at some frames.
    soak(renderer(),
         {"mirrors.speculum.json",
          false,
          [](int i, int n) {
              const double x = -4.0 + 8.0 * (i % 200) / 200.0; // hits ±3 exactly at frames 25 and 175
              return glm::dvec3(x, 1.2 + 0.3 * std::sin(i * 0.05), 1.5 - 3.0 * double(i) / n);
          },
          {0.0, 1.0, -2.0}},
         1000);
}

TEST_F(GlTest, ThousandFramesOfTheChromeDemoWithTheCameraCirclingAcrossTheMapSeams) {
    // Around the chrome ball and over it, a third of the frames with each map type: the reflected
    // directions sweep every seam (cube edges, the paraboloid's equator, the tennis-ball's component
    // boundaries).
    soak(renderer(),
         {"chrome.speculum.json",
          true,
          [](int i, int) {
              const double a = i * 2.0 * M_PI / 250.0;
              return glm::dvec3(3.0 * std::cos(a), 0.2 + 2.5 * (0.5 + 0.5 * std::sin(i * 0.021)),
                                3.0 * std::sin(a));
          },
          {0.0, 0.8, 0.0}},
         1000);
}

} // namespace
} // namespace speculum::test
