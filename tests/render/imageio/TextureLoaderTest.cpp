#include "render/imageio/TextureLoader.hpp"

#include "render/image/ColorSpace.hpp"
#include "support/BombPng.hpp"
#include "support/TestFolder.hpp"

#include <OpenImageIO/imageio.h>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <limits>
#include <sys/resource.h>
#include <sys/stat.h>

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#endif
#include <iterator>
#include <string>
#include <vector>

namespace speculum::render {
namespace {

namespace fs = std::filesystem;

// Writes a file with OIIO directly, so the loader is tested against files it did not produce itself.
template <typename T>
void writeRaw(const fs::path& path, int width, int height, int channels, OIIO::TypeDesc type,
              const std::vector<T>& pixels) {
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out) << OIIO::geterror();
    OIIO::ImageSpec spec(width, height, channels, type);
    if (channels == 2 || channels == 4) {
        spec.alpha_channel = channels - 1;
        spec.attribute("oiio:UnassociatedAlpha", 1);
    }
    ASSERT_TRUE(out->open(path.string(), spec)) << out->geterror();
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc(OIIO::BaseTypeFromC<T>::value), pixels.data()))
        << out->geterror();
    ASSERT_TRUE(out->close()) << out->geterror();
}

// Deterministic "noise" so compressed files are large enough to truncate in the middle of the data.
std::vector<std::uint8_t> noisyBytes(std::size_t count) {
    std::vector<std::uint8_t> bytes(count);
    std::uint32_t state = 12345;
    for (auto& b : bytes) {
        state = state * 1664525U + 1013904223U;
        b = static_cast<std::uint8_t>(state >> 24);
    }
    return bytes;
}

std::string contentsOf(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

void writeBytes(const fs::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::vector<std::uint8_t> pixel(const TextureImage& image, int x, int y) {
    const auto* p = &image.rgba8[(static_cast<std::size_t>(y) * image.width + x) * 4];
    return {p[0], p[1], p[2], p[3]};
}

using Bytes = std::vector<std::uint8_t>;

// The file's rows top first, as OIIO writes them: top row red, transparent green (colour must survive
// alpha 0); bottom row blue, half grey.
const std::vector<std::uint8_t> kTwoByTwo = {255, 0, 0,   255, 0,   200, 0,   0,
                                             0,   0, 255, 255, 100, 100, 100, 128};

// TextureImage row 0 is the BOTTOM row of the stored image (t = 0 for glTexImage2D, v = 0).
void expectTwoByTwoBottomRowFirst(const TextureImage& texture) {
    ASSERT_EQ(texture.width, 2);
    ASSERT_EQ(texture.height, 2);
    EXPECT_FALSE(texture.highPrecision());
    EXPECT_EQ(pixel(texture, 0, 0), (Bytes{0, 0, 255, 255}));     // bottom left of the file
    EXPECT_EQ(pixel(texture, 1, 0), (Bytes{100, 100, 100, 128})); // bottom right
    EXPECT_EQ(pixel(texture, 0, 1), (Bytes{255, 0, 0, 255}));     // top left
    EXPECT_EQ(pixel(texture, 1, 1), (Bytes{0, 200, 0, 0}));       // top right
}

TEST(TextureLoader, RgbaPngKeepsExactBytesStraightAlphaAndPutsTheBottomRowFirst) {
    const fs::path path = test::freshTestFolder() / "rgba.png";
    writeRaw<std::uint8_t>(path, 2, 2, 4, OIIO::TypeDesc::UINT8, kTwoByTwo);
    const base::Result<TextureImage> texture = loadTexture(path.string());
    ASSERT_TRUE(texture.ok()) << texture.error();
    expectTwoByTwoBottomRowFirst(*texture);
}

TEST(TextureLoader, TallImageRowsAreTurnedOver) {
    // 1×3: rows 10, 20, 30 from the top of the file come out as 30, 20, 10.
    const fs::path path = test::freshTestFolder() / "tall.png";
    writeRaw<std::uint8_t>(path, 1, 3, 1, OIIO::TypeDesc::UINT8, {10, 20, 30});
    const base::Result<TextureImage> texture = loadTexture(path.string());
    ASSERT_TRUE(texture.ok()) << texture.error();
    EXPECT_EQ(texture->rgba8, (Bytes{30, 30, 30, 255, 20, 20, 20, 255, 10, 10, 10, 255}));
}

TEST(TextureLoader, DecodesPngAndTgaFromMemoryLikeFromTheirFiles) {
    const fs::path folder = test::freshTestFolder();
    for (const char* name : {"embedded.png", "embedded.tga", "embedded.bmp"}) {
        writeRaw<std::uint8_t>(folder / name, 2, 2, 4, OIIO::TypeDesc::UINT8, kTwoByTwo);
        const std::string bytes = contentsOf(folder / name);
        ASSERT_FALSE(bytes.empty());
        // The name has no extension, as an embedded texture's ("model.glb#*0"): the bytes decide.
        const base::Result<TextureImage> decoded =
            decodeTexture(bytes.data(), bytes.size(), "/abs/model.glb#*0");
        ASSERT_TRUE(decoded.ok()) << name << ": " << decoded.error();
        const base::Result<TextureImage> loaded = loadTexture((folder / name).string());
        ASSERT_TRUE(loaded.ok()) << loaded.error();
        EXPECT_EQ(decoded->width, 2) << name;
        EXPECT_EQ(decoded->rgba8, loaded->rgba8) << name;
        if (std::string(name) == "embedded.png")
            expectTwoByTwoBottomRowFirst(*decoded);
    }
}

TEST(TextureLoader, GarbageInMemoryIsAnErrorNamingTheTexture) {
    const Bytes noise = noisyBytes(4000);
    const base::Result<TextureImage> texture = decodeTexture(noise.data(), noise.size(), "/abs/duck.glb#*3");
    ASSERT_FALSE(texture.ok());
    EXPECT_NE(texture.error().find("/abs/duck.glb#*3"), std::string::npos) << texture.error();
    const base::Result<TextureImage> empty = decodeTexture(nullptr, 0, "/abs/duck.glb#*4");
    ASSERT_FALSE(empty.ok());
    EXPECT_NE(empty.error().find("/abs/duck.glb#*4"), std::string::npos) << empty.error();
    // A PNG cut short in memory fails like a truncated file.
    const fs::path path = test::freshTestFolder() / "cut.png";
    writeRaw(path, 64, 64, 3, OIIO::TypeDesc::UINT8, noisyBytes(64 * 64 * 3));
    const std::string whole = contentsOf(path);
#if defined(__SANITIZE_ADDRESS__)
    __lsan_disable(); // OIIO's PNG reader leaks its error string on a truncated read (see below)
#endif
    const base::Result<TextureImage> cut = decodeTexture(whole.data(), whole.size() / 2, "/abs/cut.glb#*0");
#if defined(__SANITIZE_ADDRESS__)
    __lsan_enable();
#endif
    EXPECT_FALSE(cut.ok());
}

TEST(TextureLoader, RgbPngGetsOpaqueAlpha) {
    const fs::path path = test::freshTestFolder() / "rgb.png";
    writeRaw<std::uint8_t>(path, 2, 1, 3, OIIO::TypeDesc::UINT8, {10, 20, 30, 40, 50, 60});
    const base::Result<TextureImage> texture = loadTexture(path.string());
    ASSERT_TRUE(texture.ok()) << texture.error();
    EXPECT_EQ(texture->rgba8, (Bytes{10, 20, 30, 255, 40, 50, 60, 255}));
}

TEST(TextureLoader, GreyIsSpreadToRgb) {
    const fs::path folder = test::freshTestFolder();
    writeRaw<std::uint8_t>(folder / "grey.png", 2, 1, 1, OIIO::TypeDesc::UINT8, {0, 77});
    const base::Result<TextureImage> grey = loadTexture((folder / "grey.png").string());
    ASSERT_TRUE(grey.ok()) << grey.error();
    EXPECT_EQ(grey->rgba8, (Bytes{0, 0, 0, 255, 77, 77, 77, 255}));

    writeRaw<std::uint8_t>(folder / "grey-alpha.png", 1, 1, 2, OIIO::TypeDesc::UINT8, {90, 30});
    const base::Result<TextureImage> greyAlpha = loadTexture((folder / "grey-alpha.png").string());
    ASSERT_TRUE(greyAlpha.ok()) << greyAlpha.error();
    EXPECT_EQ(greyAlpha->rgba8, (Bytes{90, 90, 90, 30}));
}

TEST(TextureLoader, SixteenBitIsDecodedFromSrgbToLinearFloat) {
    const fs::path path = test::freshTestFolder() / "deep.png";
    // 33024 lies between the 8-bit codes 128 and 129 (×257): it must not be rounded to either.
    writeRaw<std::uint16_t>(path, 3, 1, 3, OIIO::TypeDesc::UINT16,
                            {0, 65535, 33024, 257, 254 * 257, 32768, 65535, 0, 1000});
    const base::Result<TextureImage> texture = loadTexture(path.string());
    ASSERT_TRUE(texture.ok()) << texture.error();
    ASSERT_TRUE(texture->highPrecision());
    EXPECT_TRUE(texture->rgba8.empty());
    EXPECT_TRUE(texture->decodedFromSrgb);
    ASSERT_EQ(texture->linear.size(), 12u);
    const float codes[9] = {0, 65535, 33024, 257, 254 * 257, 32768, 65535, 0, 1000};
    for (int i = 0; i < 3; ++i) {
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(texture->linear[i * 4 + c], srgbToLinear(codes[i * 3 + c] / 65535.0f), 1e-6f)
                << i << c;
        EXPECT_EQ(texture->linear[i * 4 + 3], 1.0f);
    }
    EXPECT_GT(texture->linear[2], srgb8ToLinear(128) + 1e-3f);
}

TEST(TextureLoader, SixteenBitRowsAreTurnedOverToo) {
    const fs::path path = test::freshTestFolder() / "deep-tall.png";
    writeRaw<std::uint16_t>(path, 1, 2, 1, OIIO::TypeDesc::UINT16, {65535, 0});
    const base::Result<TextureImage> texture = loadTexture(path.string());
    ASSERT_TRUE(texture.ok()) << texture.error();
    ASSERT_EQ(texture->linear.size(), 8u);
    EXPECT_EQ(texture->linear[0], 0.0f); // the file's bottom row (black) first
    EXPECT_EQ(texture->linear[4], 1.0f);
}

TEST(TextureLoader, JpegLoadsCloseToItsColour) {
    const fs::path path = test::freshTestFolder() / "flat.jpg";
    std::vector<std::uint8_t> flat;
    for (int i = 0; i < 16 * 16; ++i) {
        flat.insert(flat.end(), {200, 120, 40});
    }
    writeRaw(path, 16, 16, 3, OIIO::TypeDesc::UINT8, flat);
    const base::Result<TextureImage> texture = loadTexture(path.string());
    ASSERT_TRUE(texture.ok()) << texture.error();
    ASSERT_EQ(texture->width, 16);
    const Bytes p = pixel(*texture, 7, 7);
    EXPECT_NEAR(p[0], 200, 3);
    EXPECT_NEAR(p[1], 120, 3);
    EXPECT_NEAR(p[2], 40, 3);
    EXPECT_EQ(p[3], 255);
}

TEST(TextureLoader, FloatFilesStayLinearAndStraight) {
    const fs::path folder = test::freshTestFolder();
    // EXR holds premultiplied linear values: they come out unpremultiplied, not encoded, not rounded.
    writeRaw<float>(folder / "linear.exr", 1, 1, 4, OIIO::TypeDesc::FLOAT,
                    {0.2158605f * 0.5f, 0.5f, 0.0f, 0.5f});
    const base::Result<TextureImage> texture = loadTexture((folder / "linear.exr").string());
    ASSERT_TRUE(texture.ok()) << texture.error();
    ASSERT_TRUE(texture->highPrecision());
    EXPECT_FALSE(texture->decodedFromSrgb);
    ASSERT_EQ(texture->linear.size(), 4u);
    EXPECT_NEAR(texture->linear[0], 0.2158605f, 1e-6f);
    EXPECT_NEAR(texture->linear[1], 1.0f, 1e-6f);
    EXPECT_EQ(texture->linear[2], 0.0f);
    EXPECT_EQ(texture->linear[3], 0.5f);
    // Half floats, values above 1 kept.
    writeRaw<float>(folder / "half.exr", 1, 1, 3, OIIO::TypeDesc::HALF, {4.0f, 0.25f, 0.125f});
    const base::Result<TextureImage> half = loadTexture((folder / "half.exr").string());
    ASSERT_TRUE(half.ok()) << half.error();
    ASSERT_EQ(half->linear.size(), 4u);
    EXPECT_EQ(half->linear[0], 4.0f);
    EXPECT_EQ(half->linear[1], 0.25f);
    EXPECT_EQ(half->linear[3], 1.0f);
}

// A float file's negative, NaN and infinite texels are not light: each becomes 0 (or, infinite, the
// largest half float), and coverage stays within 0..1, so no still shows negative or non-finite radiance.
TEST(TextureLoader, FloatTexelsThatAreNotLightBecomePhysical) {
    const fs::path folder = test::freshTestFolder();
    const float inf = std::numeric_limits<float>::infinity();
    writeRaw<float>(folder / "hostile.exr", 2, 1, 4, OIIO::TypeDesc::FLOAT,
                    {-65504.0f, std::nanf(""), inf, 1.0f, 0.5f, -1.0f, 2.0f, 3.0f});
    const base::Result<TextureImage> texture = loadTexture((folder / "hostile.exr").string());
    ASSERT_TRUE(texture.ok()) << texture.error();
    ASSERT_EQ(texture->linear.size(), 8u);
    for (std::size_t i = 0; i < texture->linear.size(); ++i) {
        EXPECT_TRUE(std::isfinite(texture->linear[i])) << i;
        EXPECT_GE(texture->linear[i], 0.0f) << i;
    }
    EXPECT_EQ(texture->linear[0], 0.0f);
    EXPECT_EQ(texture->linear[1], 0.0f);
    EXPECT_EQ(texture->linear[2], 65504.0f);
    EXPECT_EQ(texture->linear[7], 1.0f) << "coverage ends at 1";
    EXPECT_EQ(texture->linear[4], 0.5f) << "premultiplied by a coverage of 1";
}

TEST(TextureLoader, MissingFileIsAnErrorNamingThePath) {
    const fs::path path = test::freshTestFolder() / "missing.png";
    const base::Result<TextureImage> texture = loadTexture(path.string());
    ASSERT_FALSE(texture.ok());
    EXPECT_NE(texture.error().find(path.string()), std::string::npos) << texture.error();
    EXPECT_NE(texture.error().find("does not exist"), std::string::npos) << texture.error();
}

TEST(TextureLoader, GarbageBytesAreAnError) {
    const fs::path folder = test::freshTestFolder();
    const Bytes noise = noisyBytes(4000);
    const std::string garbage(noise.begin(), noise.end());
    for (const char* name : {"garbage.png", "garbage.jpg", "garbage.tif", "garbage.exr", "garbage.xyz"}) {
        writeBytes(folder / name, garbage);
        const base::Result<TextureImage> texture = loadTexture((folder / name).string());
        ASSERT_FALSE(texture.ok()) << name;
        EXPECT_NE(texture.error().find(name), std::string::npos) << texture.error();
    }
}

// Writes a noisy image, cuts the file in half, and expects an error rather than a half-grey texture.
void expectTruncatedFileFails(const fs::path& path) {
    writeRaw(path, 64, 64, 3, OIIO::TypeDesc::UINT8, noisyBytes(64 * 64 * 3));
    ASSERT_TRUE(loadTexture(path.string()).ok()) << "the intact file must load";
    const std::string whole = contentsOf(path);
    ASSERT_GT(whole.size(), 2000u);
    writeBytes(path, whole.substr(0, whole.size() / 2));
    const base::Result<TextureImage> texture = loadTexture(path.string());
    ASSERT_FALSE(texture.ok()) << path << " was cut to " << whole.size() / 2 << " bytes but loaded";
    EXPECT_NE(texture.error().find(path.string()), std::string::npos) << texture.error();
}

TEST(TextureLoader, TruncatedPngIsAnError) {
#if defined(__SANITIZE_ADDRESS__)
    // OpenImageIO 2.4's PNG reader leaks its error string when libpng longjmps out of a truncated read;
    // that leak is the library's, so LeakSanitizer is told to ignore allocations made during this call.
    __lsan_disable();
#endif
    expectTruncatedFileFails(test::freshTestFolder() / "cut.png");
#if defined(__SANITIZE_ADDRESS__)
    __lsan_enable();
#endif
}

TEST(TextureLoader, TruncatedJpegIsAnError) {
    expectTruncatedFileFails(test::freshTestFolder() / "cut.jpg");
}

TEST(TextureLoader, TruncatedTiffIsAnError) {
    expectTruncatedFileFails(test::freshTestFolder() / "cut.tif");
}

TEST(TextureLoader, AbsurdSizeIsRefused) {
    const fs::path path = test::freshTestFolder() / "wide.png";
    writeRaw(path, kMaxTextureSide + 1, 1, 1, OIIO::TypeDesc::UINT8,
             std::vector<std::uint8_t>(kMaxTextureSide + 1));
    const base::Result<TextureImage> texture = loadTexture(path.string());
    ASSERT_FALSE(texture.ok());
    EXPECT_NE(texture.error().find("16384"), std::string::npos) << texture.error();
}

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The most memory this test program has held at once, in bytes.
std::size_t peakResidentBytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<std::size_t>(usage.ru_maxrss) * 1024;
}

TEST(TextureLoader, ADecompressionBombIsRefusedBeforeItsDeclaredPixelsAreAllocated) {
    const fs::path path = test::freshTestFolder() / "bomb.png";
    speculum::test::writeBombPng(path);
    const auto start = std::chrono::steady_clock::now();
    const base::Result<TextureImage> texture = loadTexture(path.string());
    EXPECT_LT(secondsSince(start), 1.0) << "69 bytes are refused at once, not after allocating 16384×16384";
    ASSERT_FALSE(texture.ok()) << "the file holds a few bytes of its 2 GiB of texels";
    EXPECT_NE(texture.error().find(path.string()), std::string::npos) << texture.error();
    EXPECT_NE(texture.error().find("16384×16384"), std::string::npos) << texture.error();
    EXPECT_LT(peakResidentBytes(), std::size_t{1} << 30) << "nothing near the declared size was allocated";

    const std::string bytes = speculum::test::bombPng();
    const base::Result<TextureImage> embedded = decodeTexture(bytes.data(), bytes.size(), "/abs/bomb.glb#*0");
    ASSERT_FALSE(embedded.ok());
    EXPECT_NE(embedded.error().find("/abs/bomb.glb#*0"), std::string::npos) << embedded.error();
}

// An 8×4 RGBA file of 2×2 blocks: opaque white, opaque black, a white/black mix and transparent red.
fs::path writeBlocks(const fs::path& folder) {
    std::vector<std::uint8_t> pixels(8 * 4 * 4);
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 8; ++x) {
            std::uint8_t* p = &pixels[static_cast<std::size_t>(y * 8 + x) * 4];
            const int block = (y / 2) * 4 + x / 2;
            const std::uint8_t grey = block == 0 || (block == 2 && (x + y) % 2 == 0) ? 255 : 0;
            p[0] = block == 3 ? 255 : grey;
            p[1] = p[2] = block == 3 ? 0 : grey;
            p[3] = block == 3 ? 0 : 255;
        }
    }
    const fs::path path = folder / "blocks.png";
    writeRaw(path, 8, 4, 4, OIIO::TypeDesc::UINT8, pixels);
    return path;
}

TEST(TextureLoader, AFileLargerThanTheLimitsIsReadSmallerWithEachBlockAveragedInLinearLight) {
    const fs::path path = writeBlocks(test::freshTestFolder());
    TextureLimits limits;
    limits.maxSide = 4;
    std::string reduced;
    const base::Result<TextureImage> texture = loadTexture(path.string(), limits, &reduced);
    ASSERT_TRUE(texture.ok()) << texture.error();
    ASSERT_EQ(texture->width, 4);
    ASSERT_EQ(texture->height, 2);
    EXPECT_EQ(reduced, "texture '" + path.string() + "' is 8×4; loaded at 4×2");
    // Row 1 is the file's top row of blocks (TextureImage puts the bottom row first).
    EXPECT_EQ(pixel(*texture, 0, 1), (Bytes{255, 255, 255, 255}));
    EXPECT_EQ(pixel(*texture, 1, 1), (Bytes{0, 0, 0, 255}));
    EXPECT_EQ(pixel(*texture, 2, 1), (Bytes{188, 188, 188, 255})) << "half the light of white, sRGB-encoded";
    EXPECT_EQ(pixel(*texture, 3, 1), (Bytes{255, 0, 0, 0})) << "straight alpha keeps a transparent colour";

    std::string untouched = "stale";
    ASSERT_TRUE(loadTexture(path.string(), {}, &untouched).ok());
    EXPECT_EQ(untouched, "stale") << "a file read at its own size gives no warning";
}

TEST(TextureLoader, TheMemoryBudgetReducesFloatFilesByTheirSixteenBytesATexel) {
    const fs::path path = test::freshTestFolder() / "float.exr";
    writeRaw(path, 4, 4, 3, OIIO::TypeDesc::FLOAT, std::vector<float>(4 * 4 * 3, 0.5f));
    TextureLimits limits;
    limits.maxBytes = 2 * 2 * 16; // 2×2 float RGBA texels
    std::string reduced;
    const base::Result<TextureImage> texture = loadTexture(path.string(), limits, &reduced);
    ASSERT_TRUE(texture.ok()) << texture.error();
    EXPECT_EQ(texture->width, 2);
    EXPECT_EQ(texture->height, 2);
    ASSERT_TRUE(texture->highPrecision());
    EXPECT_FLOAT_EQ(texture->linear[0], 0.5f);
    EXPECT_FLOAT_EQ(texture->linear[3], 1.0f);
    EXPECT_NE(reduced.find("is 4×4; loaded at 2×2"), std::string::npos) << reduced;
}

TEST(TextureLoader, AFileWithMipLevelsIsReadFromTheLargestLevelThatFits) {
    // A tiled EXR whose levels hold different values, so the test sees which one was read.
    const fs::path path = test::freshTestFolder() / "levels.exr";
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out && out->supports("mipmap")) << OIIO::geterror();
    OIIO::ImageSpec spec(8, 8, 3, OIIO::TypeDesc::HALF);
    spec.tile_width = spec.tile_height = 4;
    spec.attribute("textureformat", "Plain Texture"); // what makes OpenEXR's writer keep MIP levels
    spec.attribute("openexr:levelmode", 1);
    ASSERT_TRUE(out->open(path.string(), spec, OIIO::ImageOutput::Create)) << out->geterror();
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, std::vector<float>(8 * 8 * 3, 1.0f).data()));
    for (int side = 4; side >= 1; side /= 2) {
        OIIO::ImageSpec level(side, side, 3, OIIO::TypeDesc::HALF);
        level.tile_width = level.tile_height = 4;
        ASSERT_TRUE(out->open(path.string(), level, OIIO::ImageOutput::AppendMIPLevel)) << out->geterror();
        const float value = side == 4 ? 0.25f : 0.0f;
        ASSERT_TRUE(
            out->write_image(OIIO::TypeDesc::FLOAT,
                             std::vector<float>(static_cast<std::size_t>(side * side * 3), value).data()));
    }
    ASSERT_TRUE(out->close()) << out->geterror();
    out.reset(); // OpenEXR finishes a tiled file when its writer goes

    TextureLimits limits;
    limits.maxSide = 4;
    std::string reduced;
    const base::Result<TextureImage> texture = loadTexture(path.string(), limits, &reduced);
    ASSERT_TRUE(texture.ok()) << texture.error();
    EXPECT_EQ(texture->width, 4);
    EXPECT_FLOAT_EQ(texture->linear[0], 0.25f) << "the file's own 4×4 level, not level 0 averaged";
    EXPECT_NE(reduced.find("is 8×8; loaded at 4×4"), std::string::npos) << reduced;
    const base::Result<TextureImage> whole = loadTexture(path.string());
    ASSERT_TRUE(whole.ok()) << whole.error();
    EXPECT_EQ(whole->width, 8);
    EXPECT_FLOAT_EQ(whole->linear[0], 1.0f);
}

TEST(TextureLoader, FolderIsAnError) {
    const fs::path folder = test::freshTestFolder();
    const base::Result<TextureImage> texture = loadTexture(folder.string());
    ASSERT_FALSE(texture.ok());
    EXPECT_NE(texture.error().find("folder"), std::string::npos) << texture.error();
}

TEST(TextureLoader, FifoIsRefusedWithoutOpeningIt) {
    // Opening a FIFO for reading blocks until a writer comes: the loader must not even try.
    const fs::path path = test::freshTestFolder() / "pipe.png";
    ASSERT_EQ(mkfifo(path.c_str(), 0600), 0);
    const base::Result<TextureImage> texture = loadTexture(path.string());
    ASSERT_FALSE(texture.ok());
    EXPECT_NE(texture.error().find(path.string()), std::string::npos) << texture.error();
    EXPECT_NE(texture.error().find("not a regular file"), std::string::npos) << texture.error();
}

TEST(TextureLoader, DeviceIsRefused) {
    const base::Result<TextureImage> texture = loadTexture("/dev/zero");
    ASSERT_FALSE(texture.ok());
    EXPECT_NE(texture.error().find("not a regular file"), std::string::npos) << texture.error();
}

TEST(CheckerTexture, IsAMagentaAndBlackChecker) {
    const TextureImage checker = checkerTexture(64);
    ASSERT_EQ(checker.width, 64);
    ASSERT_EQ(checker.height, 64);
    ASSERT_EQ(checker.rgba8.size(), 64u * 64u * 4u);
    const Bytes magenta{255, 0, 255, 255};
    const Bytes black{0, 0, 0, 255};
    EXPECT_EQ(pixel(checker, 0, 0), magenta);
    EXPECT_EQ(pixel(checker, 63, 63), magenta);
    EXPECT_EQ(pixel(checker, 8, 0), black);
    EXPECT_EQ(pixel(checker, 0, 8), black);
    EXPECT_EQ(pixel(checker, 8, 8), magenta);
    int magentaCount = 0;
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x) {
            const Bytes p = pixel(checker, x, y);
            EXPECT_TRUE(p == magenta || p == black);
            magentaCount += p == magenta;
        }
    }
    EXPECT_EQ(magentaCount, 64 * 64 / 2);
    EXPECT_EQ(checkerTexture(3).width, 3);
}

} // namespace
} // namespace speculum::render
