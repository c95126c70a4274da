#include "render/imageio/ImageWriter.hpp"

#include "render/image/ColorSpace.hpp"
#include "support/TestFolder.hpp"

#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <memory>
#include <string>
#include <unistd.h>
#include <vector>

namespace speculum::render {
namespace {

namespace fs = std::filesystem;

// A small frame with values below 0, above 1, a dark value on the linear sRGB segment and partial alpha.
Image testFrame() {
    Image image;
    image.width = 5;
    image.height = 3;
    image.rgba.resize(5 * 3 * 4);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            float* p = &image.rgba[(y * image.width + x) * 4];
            p[0] = -0.2f + 0.35f * x; // -0.2 .. 1.2
            p[1] = 0.002f + 0.3f * y; // includes the linear segment
            p[2] = 0.05f * (x + 1) * (y + 1);
            p[3] = (x == 4) ? 0.5f : 1.0f; // straight alpha
        }
    }
    return image;
}

Image flatFrame(int width, int height, float r, float g, float b) {
    Image image{width, height, {}};
    for (int i = 0; i < width * height; ++i) {
        image.rgba.insert(image.rgba.end(), {r, g, b, 1.0f});
    }
    return image;
}

struct ReadBack {
    OIIO::ImageSpec spec;
    std::vector<float> pixels; // as stored (8-bit values scaled to 0..1), straight alpha for 8-bit files
};

ReadBack readBack(const fs::path& path) {
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path.string(), &config);
    EXPECT_TRUE(in) << OIIO::geterror();
    if (!in) {
        return {};
    }
    ReadBack result{in->spec(), {}};
    result.pixels.resize(static_cast<std::size_t>(result.spec.width) * result.spec.height *
                         result.spec.nchannels);
    EXPECT_TRUE(in->read_image(0, 0, 0, result.spec.nchannels, OIIO::TypeDesc::FLOAT, result.pixels.data()))
        << in->geterror();
    return result;
}

std::vector<std::string> filesIn(const fs::path& folder) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) {
        names.push_back(entry.path().filename().string());
    }
    return names;
}

std::string contentsOf(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

ImageMetadata testMetadata() {
    return ImageMetadata{{{"Software", "speculum test"},
                          {"ImageDescription", "a test frame"},
                          {"speculum:scene", "mirrors.speculum.json"},
                          {"speculum:time", "1.5"}}};
}

// 8-bit formats that keep alpha: exact sRGB codes, straight alpha, decoding lands within half a code.
void expectEightBitRoundTrip(const fs::path& path) {
    const Image frame = testFrame();
    ASSERT_TRUE(writeImage(path.string(), frame, testMetadata()).ok());
    const ReadBack back = readBack(path);
    ASSERT_EQ(back.spec.width, frame.width);
    ASSERT_EQ(back.spec.height, frame.height);
    ASSERT_EQ(back.spec.nchannels, 4);
    EXPECT_EQ(back.spec.format, OIIO::TypeDesc::UINT8);
    for (int y = 0; y < frame.height; ++y) {
        for (int x = 0; x < frame.width; ++x) {
            const glm::vec4 expected = frame.at(x, y);
            const float* got = &back.pixels[(y * frame.width + x) * 4];
            for (int c = 0; c < 3; ++c) {
                const float clamped = std::clamp(expected[c], 0.0f, 1.0f);
                // Stored code is the rounded sRGB encoding...
                EXPECT_NEAR(got[c] * 255.0f, std::round(linearToSrgb(clamped) * 255.0f), 1e-3f)
                    << path << " pixel " << x << "," << y << " channel " << c;
                // ...so decoding it gives back the linear value to within half a code step.
                EXPECT_NEAR(linearToSrgb(srgbToLinear(got[c])), linearToSrgb(clamped), 0.5f / 255.0f + 1e-5f);
            }
            EXPECT_NEAR(got[3] * 255.0f, std::round(expected.a * 255.0f), 1e-3f) << "alpha must be straight";
        }
    }
}

TEST(ImageWriter, PngIsEightBitSrgbWithStraightAlphaAndMetadata) {
    const fs::path path = test::freshTestFolder() / "frame.png";
    expectEightBitRoundTrip(path);
    const ReadBack back = readBack(path);
    EXPECT_EQ(back.spec.get_string_attribute("Software"), "speculum test");
    EXPECT_EQ(back.spec.get_string_attribute("ImageDescription"), "a test frame");
    EXPECT_EQ(back.spec.get_string_attribute("speculum:scene"), "mirrors.speculum.json");
    EXPECT_EQ(back.spec.get_string_attribute("speculum:time"), "1.5");
}

TEST(ImageWriter, TiffIsEightBitSrgbWithStraightAlphaAndMetadata) {
    for (const char* name : {"frame.tif", "frame.tiff"}) {
        const fs::path path = test::freshTestFolder() / name;
        expectEightBitRoundTrip(path);
        const ReadBack back = readBack(path);
        EXPECT_EQ(back.spec.get_string_attribute("Software"), "speculum test");
        // TIFF has no place for custom keys: they are folded into the description.
        EXPECT_EQ(back.spec.get_string_attribute("ImageDescription"),
                  "a test frame\nspeculum:scene=mirrors.speculum.json\nspeculum:time=1.5");
    }
}

TEST(ImageWriter, JpegIsEightBitSrgbWithoutAlpha) {
    const fs::path folder = test::freshTestFolder();
    const Image frame = flatFrame(16, 16, 0.214f, 0.5f, 0.05f);
    for (const char* name : {"frame.jpg", "frame.jpeg", "FRAME.JPG"}) {
        ASSERT_TRUE(writeImage((folder / name).string(), frame, testMetadata()).ok()) << name;
        const ReadBack back = readBack(folder / name);
        ASSERT_EQ(back.spec.width, 16);
        ASSERT_EQ(back.spec.height, 16);
        ASSERT_EQ(back.spec.nchannels, 3);
        // JPEG is lossy, but a flat colour survives to within a couple of codes.
        for (int c = 0; c < 3; ++c) {
            const float expected = linearToSrgb(frame.rgba[c]);
            EXPECT_NEAR(back.pixels[(8 * 16 + 8) * 3 + c], expected, 3.0f / 255.0f)
                << name << " channel " << c;
        }
        EXPECT_EQ(back.spec.get_string_attribute("Software"), "speculum test");
        EXPECT_EQ(back.spec.get_string_attribute("ImageDescription"),
                  "a test frame\nspeculum:scene=mirrors.speculum.json\nspeculum:time=1.5");
    }
}

TEST(ImageWriter, ExrIsLinearHalfWithPremultipliedAlphaAndMetadata) {
    const fs::path path = test::freshTestFolder() / "frame.exr";
    const Image frame = testFrame();
    ASSERT_TRUE(writeImage(path.string(), frame, testMetadata()).ok());
    const ReadBack back = readBack(path);
    ASSERT_EQ(back.spec.width, frame.width);
    ASSERT_EQ(back.spec.height, frame.height);
    ASSERT_EQ(back.spec.nchannels, 4);
    EXPECT_EQ(back.spec.format, OIIO::TypeDesc::HALF);
    for (int y = 0; y < frame.height; ++y) {
        for (int x = 0; x < frame.width; ++x) {
            const glm::vec4 expected = frame.at(x, y);
            const float* got = &back.pixels[(y * frame.width + x) * 4];
            for (int c = 0; c < 3; ++c) {
                // Linear, unclamped (negative and > 1 survive), premultiplied; half precision.
                const float want = expected[c] * expected.a;
                EXPECT_NEAR(got[c], want, 1e-3f * std::max(1.0f, std::abs(want)))
                    << x << "," << y << " c" << c;
            }
            EXPECT_FLOAT_EQ(got[3], expected.a);
        }
    }
    EXPECT_EQ(back.spec.get_string_attribute("Software"), "speculum test");
    EXPECT_EQ(back.spec.get_string_attribute("ImageDescription"), "a test frame");
    EXPECT_EQ(back.spec.get_string_attribute("speculum:scene"), "mirrors.speculum.json");
}

// Every other format OpenImageIO writes is written too: lossless 8-bit ones hold the sRGB codes exactly
// (with alpha where the format has it), Radiance HDR holds linear light; a name OIIO lists but cannot write
// (.pfm, under its pnm writer) is refused up front, and the message lists what can be written.
TEST(ImageWriter, OtherFormatsGoThroughOpenImageIO) {
    const fs::path folder = test::freshTestFolder();
    const Image frame = testFrame();
    for (const char* ext : {".tga", ".bmp", ".ppm", ".sgi", ".dpx", ".hdr"}) {
        const fs::path path = folder / (std::string("frame") + ext);
        ASSERT_TRUE(isSupportedImagePath(path.string())) << ext;
        const base::Status written = writeImage(path.string(), frame, testMetadata());
        ASSERT_TRUE(written.ok()) << ext << ": " << written.error();
        const ReadBack back = readBack(path);
        ASSERT_EQ(back.spec.width, frame.width) << ext;
        ASSERT_EQ(back.spec.height, frame.height) << ext;
        const bool hdr = std::string(ext) == ".hdr";
        const int channels = back.spec.nchannels;
        for (int y = 0; y < frame.height; ++y) {
            for (int x = 0; x < frame.width; ++x) {
                const glm::vec4 expected = frame.at(x, y);
                const float* got = &back.pixels[static_cast<std::size_t>(y * frame.width + x) * channels];
                for (int c = 0; c < 3; ++c) {
                    if (hdr) { // linear, RGBE's 8-bit mantissa: within 1% of the brightest channel
                        const float largest = std::max({expected.r, expected.g, expected.b, 0.0f});
                        EXPECT_NEAR(got[c], std::max(expected[c], 0.0f), 0.01f * largest + 1e-4f) << ext;
                    } else {
                        EXPECT_NEAR(got[c] * 255.0f,
                                    std::round(linearToSrgb(std::clamp(expected[c], 0.0f, 1.0f)) * 255.0f),
                                    1e-3f)
                            << ext << " pixel " << x << "," << y << " channel " << c;
                    }
                }
            }
        }
    }
    // Lossy ones, on a frame big enough for JPEG 2000's tiles: the colour within a few codes.
    const Image flat = flatFrame(64, 32, 0.2f, 0.5f, 0.8f);
    for (const char* ext : {".webp", ".jp2"}) {
        const fs::path path = folder / (std::string("flat") + ext);
        const base::Status written = writeImage(path.string(), flat, testMetadata());
        ASSERT_TRUE(written.ok()) << ext << ": " << written.error();
        const ReadBack back = readBack(path);
        ASSERT_EQ(back.spec.width, 64) << ext;
        ASSERT_EQ(back.spec.height, 32) << ext;
        const float* centre = &back.pixels[static_cast<std::size_t>(16 * 64 + 32) * back.spec.nchannels];
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(centre[c] * 255.0f, std::round(linearToSrgb(flat.at(32, 16)[c]) * 255.0f), 3.0f)
                << ext;
    }
    EXPECT_FALSE(isSupportedImagePath("frame.pfm"));
    EXPECT_FALSE(isSupportedImagePath("frame.null"));
    const std::string list = supportedImageFormats();
    EXPECT_EQ(list.rfind(".png, .jpg, .jpeg, .tif, .tiff, .exr; and through OpenImageIO: ", 0), 0u) << list;
    for (const char* ext : {".webp", ".tga", ".bmp", ".hdr"})
        EXPECT_NE(list.find(ext), std::string::npos) << ext;
    EXPECT_EQ(list.find(".pfm"), std::string::npos) << list;
}

TEST(ImageWriter, SoftwareDefaultsToSpeculum) {
    const fs::path path = test::freshTestFolder() / "frame.png";
    ASSERT_TRUE(writeImage(path.string(), flatFrame(2, 2, 1, 1, 1)).ok());
    const std::string software = readBack(path).spec.get_string_attribute("Software");
    EXPECT_EQ(software.rfind("speculum", 0), 0u) << software;
}

TEST(ImageWriter, TextureBytesAreWrittenUnchanged) {
    const fs::path path = test::freshTestFolder() / "texture.png";
    TextureImage texture{3, 2, {}};
    for (int i = 0; i < 3 * 2 * 4; ++i) {
        texture.rgba8.push_back(static_cast<std::uint8_t>(i * 37 % 256));
    }
    ASSERT_TRUE(writeImage(path.string(), texture).ok());
    const ReadBack back = readBack(path);
    ASSERT_EQ(back.pixels.size(), texture.rgba8.size());
    for (std::size_t i = 0; i < texture.rgba8.size(); ++i) {
        EXPECT_EQ(std::lround(back.pixels[i] * 255.0f), texture.rgba8[i]) << i;
    }
}

TEST(ImageWriter, OverwritesAnExistingFileAndLeavesNoTemporaryFile) {
    const fs::path folder = test::freshTestFolder();
    const fs::path path = folder / "frame.png";
    std::ofstream(path) << "old contents";
    ASSERT_TRUE(writeImage(path.string(), flatFrame(4, 4, 0.5f, 0.5f, 0.5f)).ok());
    EXPECT_EQ(readBack(path).spec.width, 4);
    EXPECT_EQ(filesIn(folder), std::vector<std::string>{"frame.png"});
}

TEST(ImageWriter, WritesToARelativePathInTheWorkingFolder) {
    const fs::path folder = test::freshTestFolder();
    const fs::path previous = fs::current_path();
    fs::current_path(folder);
    const base::Status status = writeImage("relative.png", flatFrame(2, 2, 0, 0, 0));
    fs::current_path(previous);
    ASSERT_TRUE(status.ok()) << status.error();
    EXPECT_EQ(filesIn(folder), std::vector<std::string>{"relative.png"});
}

TEST(ImageWriter, UnknownExtensionIsRefusedAndNothingIsWritten) {
    const fs::path folder = test::freshTestFolder();
    const base::Status status = writeImage((folder / "frame.bmpx").string(), flatFrame(2, 2, 1, 0, 0));
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find(".bmpx"), std::string::npos) << status.error();
    EXPECT_NE(status.error().find(".png"), std::string::npos) << status.error();
    EXPECT_NE(status.error().find(".exr"), std::string::npos) << status.error();
    EXPECT_TRUE(filesIn(folder).empty());

    const base::Status noExtension = writeImage((folder / "frame").string(), flatFrame(2, 2, 1, 0, 0));
    ASSERT_FALSE(noExtension.ok());
    EXPECT_NE(noExtension.error().find("extension"), std::string::npos) << noExtension.error();
    EXPECT_TRUE(filesIn(folder).empty());
}

TEST(ImageWriter, MissingFolderIsAnErrorNamingThePath) {
    const fs::path path = test::freshTestFolder() / "no-such-folder" / "frame.png";
    const base::Status status = writeImage(path.string(), flatFrame(2, 2, 1, 0, 0));
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find(path.string()), std::string::npos) << status.error();
    EXPECT_NE(status.error().find("does not exist"), std::string::npos) << status.error();
    EXPECT_FALSE(fs::exists(path.parent_path()));
}

TEST(ImageWriter, FolderThatIsAFileIsAnError) {
    const fs::path folder = test::freshTestFolder();
    const fs::path file = folder / "file.png";
    std::ofstream(file) << "not a folder";
    const fs::path path = file / "frame.png";
    const base::Status status = writeImage(path.string(), flatFrame(2, 2, 1, 0, 0));
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find(path.string()), std::string::npos) << status.error();
    EXPECT_NE(status.error().find("not a folder"), std::string::npos) << status.error();
    EXPECT_EQ(contentsOf(file), "not a folder");
}

TEST(ImageWriter, ReadOnlyFolderIsAnError) {
    if (::geteuid() == 0) {
        GTEST_SKIP() << "root may write anywhere; the path-under-a-file case covers unwritable targets";
    }
    const fs::path folder = test::freshTestFolder() / "locked";
    fs::create_directory(folder);
    fs::permissions(folder, fs::perms::owner_read | fs::perms::owner_exec);
    const base::Status status = writeImage((folder / "frame.png").string(), flatFrame(2, 2, 1, 0, 0));
    fs::permissions(folder, fs::perms::owner_all);
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find("not writable"), std::string::npos) << status.error();
    EXPECT_TRUE(filesIn(folder).empty());
}

TEST(ImageWriter, TargetThatIsAFolderIsAnError) {
    const fs::path folder = test::freshTestFolder();
    fs::create_directory(folder / "frame.png");
    const base::Status status = writeImage((folder / "frame.png").string(), flatFrame(2, 2, 1, 0, 0));
    ASSERT_FALSE(status.ok());
    EXPECT_TRUE(fs::is_directory(folder / "frame.png"));
    EXPECT_EQ(filesIn(folder), std::vector<std::string>{"frame.png"});
}

TEST(ImageWriter, EmptyImageIsAnError) {
    const fs::path folder = test::freshTestFolder();
    const base::Status status = writeImage((folder / "frame.png").string(), Image{});
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find("empty"), std::string::npos) << status.error();
    EXPECT_TRUE(filesIn(folder).empty());
}

TEST(ImageWriter, FailureInsideTheEncoderLeavesTheOldFileAndNoTemporaryFile) {
    // libpng refuses images wider than 1,000,000 pixels: the encoder fails after the file was opened.
    const fs::path folder = test::freshTestFolder();
    const fs::path path = folder / "frame.png";
    std::ofstream(path) << "precious";
    const base::Status status = writeImage(path.string(), flatFrame(1000001, 1, 0.5f, 0.5f, 0.5f));
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find(path.string()), std::string::npos) << status.error();
    EXPECT_EQ(contentsOf(path), "precious");
    EXPECT_EQ(filesIn(folder), std::vector<std::string>{"frame.png"});
}

TEST(ImageWriter, JpegTooLargeIsAnErrorNotAnExit) {
    // libjpeg stops at 65500 pixels per side, and OIIO 2.4's JPEG writer would exit() the process there.
    const fs::path folder = test::freshTestFolder();
    const fs::path path = folder / "frame.jpg";
    std::ofstream(path) << "precious";
    const base::Status status = writeImage(path.string(), flatFrame(65501, 1, 0.5f, 0.5f, 0.5f));
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find("65500"), std::string::npos) << status.error();
    EXPECT_EQ(contentsOf(path), "precious");
    EXPECT_EQ(filesIn(folder), std::vector<std::string>{"frame.jpg"});
}

TEST(ImageWriter, SupportedPaths) {
    for (const char* path :
         {"a.png", "a.PNG", "dir/a.jpg", "a.jpeg", "a.tif", "a.TIFF", "a.exr", "a.b.Exr"}) {
        EXPECT_TRUE(isSupportedImagePath(path)) << path;
    }
    for (const char* path :
         {"a.txt", "a", "png", "a.png.txt", "a.", "", "a.pfm", "a.null", "a.term", "a.zfile"}) {
        EXPECT_FALSE(isSupportedImagePath(path)) << path;
    }
    EXPECT_EQ(
        supportedImageFormats().rfind(".png, .jpg, .jpeg, .tif, .tiff, .exr; and through OpenImageIO: ", 0),
        0u);
}

} // namespace
} // namespace speculum::render
