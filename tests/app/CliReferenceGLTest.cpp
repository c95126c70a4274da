// `speculum render --reference`: writes the traced still with the same metadata as a rasterized one, and
// nothing at all when it fails.
#include "CliRun.hpp"
#include "support/TestPaths.hpp"

#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <array>
#include <cstdio>
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
    return speculum::testSourcePath("resources/scenes/teapot.speculum.json");
}

class ReferenceCli : public ::testing::Test {
protected:
    void SetUp() override {
        m_dir =
            fs::path(speculum::testDataPath()) /
            ("reference-cli-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }
    fs::path m_dir;
};

TEST_F(ReferenceCli, WritesTheTracedStillWithMetadata) {
    const fs::path out = m_dir / "teapot.png";
    const CliRun run =
        speculum("render " + demo() + " -o " + out.string() + " --size 160x90 --ssaa 2 --reference");
    ASSERT_EQ(run.status, 0) << run.err;
    // The path it wrote, then the noise: the teapot has no rough reflection, so none.
    EXPECT_EQ(run.out.substr(0, run.out.find('\n') + 1), out.string() + "\n");
    EXPECT_NE(run.out.find("(0 pixels), exact"), std::string::npos) << run.out;
    EXPECT_NE(run.err.find("traced 160x90 with 4 samples per pixel"), std::string::npos) << run.err;
    auto input = OIIO::ImageInput::open(out.string());
    ASSERT_TRUE(input);
    const OIIO::ImageSpec& spec = input->spec();
    EXPECT_EQ(spec.width, 160);
    EXPECT_EQ(spec.height, 90);
    EXPECT_NE(spec.get_string_attribute("speculum:settings").find("reference"), std::string::npos);
    EXPECT_NE(spec.get_string_attribute("speculum:renderer").find("reference ray tracer"), std::string::npos);
    // Not an empty frame: the marble table and the teapot differ from the background.
    std::vector<unsigned char> pixels(160 * 90 * spec.nchannels);
    ASSERT_TRUE(input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, pixels.data()));
    const auto [low, high] = std::minmax_element(pixels.begin(), pixels.end());
    EXPECT_GT(*high - *low, 100);
}

// --samples sets the paths through rough reflections; the noise they leave is printed. The mirrors demo
// has a rough mirror (roughness 0.15) in view.
TEST_F(ReferenceCli, SamplesSetThePathsAndTheNoiseIsPrinted) {
    const std::string mirrors = speculum::testSourcePath("resources/scenes/mirrors.speculum.json");
    const fs::path out = m_dir / "mirrors.exr";
    const CliRun run =
        speculum("render " + mirrors + " -o " + out.string() + " --size 64x36 --reference --samples 8");
    ASSERT_EQ(run.status, 0) << run.err;
    const std::string first = out.string() + "\n";
    ASSERT_EQ(run.out.substr(0, first.size()), first);
    const std::string noise = run.out.substr(first.size());
    EXPECT_EQ(noise.find("reference: 64\u00d736, 8 paths per glossy pixel ("), 0u) << noise;
    EXPECT_NE(noise.find(" RMS standard error\n"), std::string::npos) << noise;
    EXPECT_EQ(noise.find("(0 pixels)"), std::string::npos) << noise;
    auto input = OIIO::ImageInput::open(out.string());
    ASSERT_TRUE(input);
    EXPECT_NE(input->spec().get_string_attribute("speculum:settings").find("8 paths"), std::string::npos);
    // The noise at full precision in the file, for scripts: the printed figure, rounded.
    const double noiseRms = std::stod(input->spec().get_string_attribute("speculum:noiseRms", "-1"));
    EXPECT_GT(noiseRms, 0.0);
    EXPECT_GT(std::stoi(input->spec().get_string_attribute("speculum:glossyPixels", "0")), 0);

    for (const char* bad : {"0", "abc", "65537"}) {
        const fs::path none = m_dir / (std::string("bad-") + bad + ".png");
        const CliRun refused = speculum("render " + mirrors + " -o " + none.string() +
                                        " --size 64x36 --reference --samples " + bad);
        EXPECT_EQ(refused.status, 2) << bad;
        EXPECT_TRUE(refused.out.empty()) << refused.out;
        EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
        EXPECT_NE(refused.err.find("--samples"), std::string::npos) << refused.err;
        EXPECT_FALSE(fs::exists(none)) << bad;
    }
    const CliRun rasterized =
        speculum("render " + mirrors + " -o " + (m_dir / "r.png").string() + " --size 64x36 --samples 4");
    EXPECT_EQ(rasterized.status, 2);
    EXPECT_NE(rasterized.err.find("--samples: only with --reference"), std::string::npos) << rasterized.err;
}

TEST_F(ReferenceCli, FailuresWriteNothing) {
    const fs::path out = m_dir / "missing-folder" / "teapot.png";
    CliRun run = speculum("render " + demo() + " -o " + out.string() + " --reference");
    EXPECT_NE(run.status, 0);
    EXPECT_NE(run.err.find("does not exist"), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(out));

    const fs::path png = m_dir / "none.png";
    run = speculum("render " + (m_dir / "no-such.speculum.json").string() + " -o " + png.string() +
                   " --reference");
    EXPECT_NE(run.status, 0);
    EXPECT_NE(run.err.find("file not found"), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(png));
}

} // namespace
