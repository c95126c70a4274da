// `speculum render --reference`: writes the traced still with the same metadata as a rasterized one, and
// nothing at all when it fails.
#include "support/CliRun.hpp"

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
    return std::string(SPECULUM_SOURCE_DIR) + "/resources/scenes/teapot.speculum.json";
}

class ReferenceCli : public ::testing::Test {
protected:
    void SetUp() override {
        m_dir =
            fs::path(SPECULUM_TEST_DATA_DIR) /
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
    EXPECT_EQ(run.out, out.string() + "\n");
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
