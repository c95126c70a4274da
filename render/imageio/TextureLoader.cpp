#include "render/imageio/TextureLoader.hpp"

#include "base/Printable.hpp"
#include "render/image/ColorSpace.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <array>
#include <cassert>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <memory>
#include <new>
#include <numeric>
#include <system_error>
#include <vector>

namespace speculum::render {

namespace fs = std::filesystem;

namespace {

base::Error failure(const std::string& path, const std::string& reason) {
    return base::Error{"cannot read texture '" + path + "': " + reason};
}

std::string oneLine(std::string message) {
    std::replace(message.begin(), message.end(), '\n', ' ');
    while (!message.empty() && message.back() == ' ') {
        message.pop_back();
    }
    return message.empty() ? std::string("the file is corrupt or truncated") : message;
}

// Textures keep straight alpha; by default OIIO would premultiply PNG/TIFF colours on read.
OIIO::ImageSpec readConfig() {
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    return config;
}

std::string sizeText(int width, int height) {
    return std::to_string(width) + "×" + std::to_string(height);
}

// How a file's values become TextureImage's: 8-bit files stay sRGB-encoded bytes, 16/32-bit integer files
// are decoded from sRGB to linear floats, float files (EXR, float TIFF) are linear and premultiplied.
enum class TexelEncoding { Srgb8, SrgbWide, LinearFloat };

TexelEncoding encodingOf(const OIIO::ImageSpec& spec) {
    // The widest channel decides: a file with any channel beyond 8 bits keeps its precision.
    std::size_t widest = spec.format.size();
    for (const OIIO::TypeDesc& t : spec.channelformats)
        widest = std::max(widest, t.size());
    if (spec.format.is_floating_point())
        return TexelEncoding::LinearFloat;
    return widest > 1 ? TexelEncoding::SrgbWide : TexelEncoding::Srgb8;
}

std::size_t texelBytes(TexelEncoding encoding) {
    return encoding == TexelEncoding::Srgb8 ? 4 : 4 * sizeof(float);
}

int ceilDiv(int a, int b) {
    return a / b + (a % b != 0);
}

bool fits(int width, int height, std::size_t bytesPerTexel, const TextureLimits& limits) {
    return width <= limits.maxSide && height <= limits.maxSide &&
           static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * bytesPerTexel <=
               limits.maxBytes;
}

// Which of the file's levels is read and by what factor it is reduced.
struct ReadPlan {
    int level = 0;
    OIIO::ImageSpec spec; // the level's
    int factor = 1;
    int width = 0; // of the texture made
    int height = 0;
};

// The largest level of `in` that fits `limits` (a file with MIP levels), or else its smallest, reduced
// further by the smallest whole factor that fits. Only headers are read.
ReadPlan planRead(OIIO::ImageInput& in, TexelEncoding encoding, const TextureLimits& limits) {
    ReadPlan plan;
    plan.spec = in.spec();
    while (!fits(plan.spec.width, plan.spec.height, texelBytes(encoding), limits)) {
        if (!in.seek_subimage(0, plan.level + 1)) {
            (void)in.geterror(); // no further level is no error of the file's
            break;
        }
        ++plan.level;
        plan.spec = in.spec();
    }
    const int largest = std::max(plan.spec.width, plan.spec.height);
    while (plan.factor < largest &&
           !fits(ceilDiv(plan.spec.width, plan.factor), ceilDiv(plan.spec.height, plan.factor),
                 texelBytes(encoding), limits))
        ++plan.factor;
    plan.width = ceilDiv(plan.spec.width, plan.factor);
    plan.height = ceilDiv(plan.spec.height, plan.factor);
    return plan;
}

// 8-bit sRGB codes to linear values, for averaging 8-bit texels where light adds up.
float srgbCodeToLinear(float encoded) {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i)
            t[static_cast<std::size_t>(i)] = srgb8ToLinear(static_cast<std::uint8_t>(i));
        return t;
    }();
    return table[toUnorm8(encoded)];
}

// Averages blocks of source rows into texels of TextureImage, one output row at a time. Colour is
// averaged in linear light; float files are averaged premultiplied, then unpremultiplied, as filtering
// premultiplied values is what keeps transparent texels' colours out.
constexpr float kLargestHalf = 65504.0f;

class BlockAverager {
public:
    BlockAverager(const ReadPlan& plan, int channels, TexelEncoding encoding, TextureImage& out)
        : m_plan(plan)
        , m_channels(channels)
        , m_encoding(encoding)
        , m_linearize(encoding == TexelEncoding::SrgbWide ||
                      (encoding == TexelEncoding::Srgb8 && plan.factor > 1))
        , m_out(out) {}

    // Output row `row` (0 the top of the file) from `rowCount` source rows of floats starting at `rows`.
    void averageRow(const float* rows, int rowCount, int row) {
        const std::size_t stride = static_cast<std::size_t>(m_plan.spec.width) * m_channels;
        for (int x = 0; x < m_plan.width; ++x) {
            std::array<float, 4> sum{};
            const int x0 = x * m_plan.factor, x1 = std::min(m_plan.spec.width, x0 + m_plan.factor);
            for (int r = 0; r < rowCount; ++r)
                for (int sx = x0; sx < x1; ++sx)
                    for (int c = 0; c < m_channels; ++c)
                        sum[c] += value(rows[r * stride + static_cast<std::size_t>(sx) * m_channels + c], c);
            const float count = static_cast<float>(rowCount * (x1 - x0));
            for (float& v : sum)
                v /= count;
            store(sum, static_cast<std::size_t>(m_plan.height - 1 - row) * m_plan.width + x);
        }
    }

private:
    bool isAlpha(int c) const { return (m_channels == 2 || m_channels == 4) && c == m_channels - 1; }

    float value(float v, int c) const {
        v = physical(v, isAlpha(c));
        if (!m_linearize || isAlpha(c))
            return v;
        return m_encoding == TexelEncoding::Srgb8 ? srgbCodeToLinear(v) : srgbToLinear(v);
    }

    // What a texel can mean: light and coverage are never negative, NaN or infinite. A float file's
    // such texels (a difference image, a broken export) would otherwise be negative radiance in every
    // still, down to -65504. Coverage ends at 1; light at the largest half float, as the EXR stills do.
    static float physical(float v, bool alpha) {
        if (std::isnan(v) || v < 0.0f)
            return 0.0f;
        return std::min(v, alpha ? 1.0f : kLargestHalf);
    }

    // Spreads 1..4 channels to RGBA (1 = grey, 2 = grey + alpha, 3 = RGB, 4 = RGBA) at texel `index`.
    void store(const std::array<float, 4>& m, std::size_t index) {
        const bool grey = m_channels <= 2;
        std::array<float, 4> rgba{m[0], grey ? m[0] : m[1], grey ? m[0] : m[2], 1.0f};
        if (m_channels == 2 || m_channels == 4)
            rgba[3] = m[static_cast<std::size_t>(m_channels - 1)];
        if (m_encoding == TexelEncoding::LinearFloat && rgba[3] > 0.0f &&
            (m_channels == 2 || m_channels == 4))
            for (int c = 0; c < 3; ++c)
                rgba[c] /= rgba[3];
        for (int c = 0; c < 4; ++c) {
            if (m_encoding != TexelEncoding::Srgb8)
                m_out.linear[index * 4 + c] = rgba[c];
            else
                m_out.rgba8[index * 4 + c] =
                    m_linearize && c < 3 ? linearToSrgb8(rgba[c]) : toUnorm8(rgba[c]);
        }
    }

    const ReadPlan& m_plan;
    const int m_channels;
    const TexelEncoding m_encoding;
    const bool m_linearize;
    TextureImage& m_out;
};

void allocate(TextureImage& texture, TexelEncoding encoding) {
    const std::size_t values = static_cast<std::size_t>(texture.width) * texture.height * 4;
    if (encoding == TexelEncoding::Srgb8)
        texture.rgba8.resize(values);
    else
        texture.linear.resize(values);
}

// How many source rows one read asks for at least: few enough that the strip of a 16384-texel-wide float
// file stays at 16 MiB.
constexpr int kStripRows = 64;

// Source rows per read: whole blocks of `factor` rows and, for a tiled file, whole rows of tiles (which
// OpenImageIO reads only whole).
int rowsPerRead(const ReadPlan& plan) {
    const int tileRows = std::max(plan.spec.tile_height, 1);
    const int unit = std::lcm(plan.factor, tileRows);
    return unit * std::max(1, kStripRows / unit);
}

bool readRows(OIIO::ImageInput& in, const ReadPlan& plan, int y0, int y1, int channels, float* strip) {
    const OIIO::ImageSpec& s = plan.spec;
    if (s.tile_width > 0)
        return in.read_tiles(0, plan.level, s.x, s.x + s.width, s.y + y0, s.y + y1, s.z, s.z + 1, 0, channels,
                             OIIO::TypeDesc::FLOAT, strip);
    return in.read_scanlines(0, plan.level, s.y + y0, s.y + y1, s.z, 0, channels, OIIO::TypeDesc::FLOAT,
                             strip);
}

// Reads `plan`'s level of `in` in strips of rows and averages them into `out`, so that no more than one
// strip of the file's full-size pixels is ever held.
bool readInStrips(OIIO::ImageInput& in, const ReadPlan& plan, int channels, TexelEncoding encoding,
                  TextureImage& out) {
    const OIIO::ImageSpec& s = plan.spec;
    const int rows = rowsPerRead(plan);
    std::vector<float> strip(static_cast<std::size_t>(rows) * s.width * channels);
    BlockAverager averager(plan, channels, encoding, out);
    const std::size_t stride = static_cast<std::size_t>(s.width) * channels;
    for (int y0 = 0; y0 < s.height; y0 += rows) {
        const int y1 = std::min(s.height, y0 + rows);
        if (!readRows(in, plan, y0, y1, channels, strip.data()) || in.has_error())
            return false;
        if (y0 == 0) // only once the file has shown it holds pixels: a header alone costs no texture
            allocate(out, encoding);
        for (int y = y0; y < y1; y += plan.factor)
            averager.averageRow(strip.data() + static_cast<std::size_t>(y - y0) * stride,
                                std::min(plan.factor, y1 - y), y / plan.factor);
    }
    return true;
}

// Reads the opened image `in` into a TextureImage within `limits`; `label` names it in messages and in
// the warning left in `reduced` (when given) if it was read smaller.
base::Result<TextureImage> decode(OIIO::ImageInput& in, const std::string& label, const TextureLimits& limits,
                                  std::string* reduced) {
    const OIIO::ImageSpec spec = in.spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) {
        return failure(label, "the image has no pixels");
    }
    // Checked before allocating: a hostile header must not make us reserve gigabytes.
    if (spec.width > kMaxTextureSide || spec.height > kMaxTextureSide) {
        return failure(label, "the image is " + std::to_string(spec.width) + "x" +
                                  std::to_string(spec.height) + "; the largest supported size is " +
                                  std::to_string(kMaxTextureSide) + " per side");
    }
    if (spec.depth > 1) {
        return failure(label, "volume images are not supported");
    }
    const TexelEncoding encoding = encodingOf(spec);
    const int channels = std::min(spec.nchannels, 4);
    const ReadPlan plan = planRead(in, encoding, limits);
    TextureImage texture;
    texture.width = plan.width;
    texture.height = plan.height;
    // 16-bit (and 32-bit) integer files are encoded like 8-bit ones: colour decoded from sRGB.
    texture.decodedFromSrgb = encoding == TexelEncoding::SrgbWide;
    try {
        if (!readInStrips(in, plan, channels, encoding, texture)) {
            return failure(label, "its " + sizeText(spec.width, spec.height) +
                                      " pixels do not decode: " + oneLine(in.geterror()));
        }
    } catch (const std::bad_alloc&) {
        // The limits keep a decode far below what a machine holds; this is one that has less left.
        return failure(label, "not enough memory to decode its " + sizeText(spec.width, spec.height) +
                                  " texels at " + sizeText(plan.width, plan.height));
    }
    in.close();
    if (reduced && (plan.width < spec.width || plan.height < spec.height))
        *reduced = "texture " + base::quoted(label) + " is " + sizeText(spec.width, spec.height) +
                   "; loaded at " + sizeText(plan.width, plan.height);
    return texture;
}

// The format of an in-memory image by its first bytes, as a file extension OIIO knows; empty if unknown
// (TGA has no signature at its start).
std::string formatFromMagic(const unsigned char* b, std::size_t size) {
    auto starts = [&](const char* magic, std::size_t n) {
        return size >= n && std::memcmp(b, magic, n) == 0;
    };
    if (starts("\x89PNG\r\n\x1a\n", 8))
        return "png";
    if (starts("\xff\xd8\xff", 3))
        return "jpg";
    if (starts("BM", 2))
        return "bmp";
    if (starts("GIF8", 4))
        return "gif";
    if (starts("II*\0", 4) || starts("MM\0*", 4))
        return "tif";
    if (starts("\x76\x2f\x31\x01", 4))
        return "exr";
    if (starts("#?RADIANCE", 10) || starts("#?RGBE", 6))
        return "hdr";
    if (starts("8BPS", 4))
        return "psd";
    if (starts("DDS ", 4))
        return "dds";
    if (size >= 12 && std::memcmp(b, "RIFF", 4) == 0 && std::memcmp(b + 8, "WEBP", 4) == 0)
        return "webp";
    return {};
}

} // namespace

base::Result<TextureImage> loadTexture(const std::string& path, const TextureLimits& limits,
                                       std::string* reduced) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) {
        return failure(path, "the file does not exist");
    }
    if (fs::is_directory(status)) {
        return failure(path, "it is a folder");
    }
    // Checked before opening: reading a FIFO would block until someone writes to it, a device forever.
    if (!fs::is_regular_file(status)) {
        return failure(path, "it is not a regular file (a FIFO, socket or device)");
    }
    const OIIO::ImageSpec config = readConfig();
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path, &config);
    if (!in) {
        return failure(path, oneLine(OIIO::geterror()));
    }
    return decode(*in, path, limits, reduced);
}

base::Result<TextureImage> decodeTexture(const void* bytes, std::size_t size, const std::string& name,
                                         const TextureLimits& limits, std::string* reduced) {
    if (!bytes || size == 0) {
        return failure(name, "the embedded image is empty");
    }
    const auto* b = static_cast<const unsigned char*>(bytes);
    std::string format = formatFromMagic(b, size);
    static constexpr char kTgaFooter[] = "TRUEVISION-XFILE."; // TGA 2.0 ends with it (and a NUL)
    if (format.empty() && size >= sizeof(kTgaFooter) &&
        std::memcmp(b + size - sizeof(kTgaFooter), kTgaFooter, sizeof(kTgaFooter)) == 0)
        format = "tga";
    if (format.empty()) {
        // No signature: the name's extension if it is a plain one ("x.tga"), else TGA, the one common
        // format with neither a signature nor (before 2.0) a footer.
        const std::string extension = fs::path(name).extension().string();
        const bool plain = extension.size() > 1 &&
                           std::all_of(extension.begin() + 1, extension.end(),
                                       [](char c) { return std::isalnum(static_cast<unsigned char>(c)); });
        format = plain ? extension.substr(1) : "tga";
    }
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::create(format);
    if (!in) {
        (void)OIIO::geterror();
        return failure(name, "the embedded image's format (" + format + ") is not supported");
    }
    if (!in->supports("ioproxy")) {
        return failure(name, "OpenImageIO cannot read " + format + " images from memory");
    }
    OIIO::Filesystem::IOMemReader proxy(bytes, size);
    OIIO::ImageSpec config = readConfig();
    OIIO::ImageSpec spec;
    in->set_ioproxy(&proxy);
    if (!in->open("memory." + format, spec, config)) {
        return failure(name, oneLine(in->geterror()));
    }
    return decode(*in, name, limits, reduced);
}

TextureImage checkerTexture(int size) {
    assert(size > 0 && "checkerTexture(): size must be positive");
    const int cell = std::max(1, size / 8);
    TextureImage texture;
    texture.width = texture.height = size;
    texture.rgba8.resize(static_cast<std::size_t>(size) * size * 4);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const bool magenta = ((x / cell) + (y / cell)) % 2 == 0;
            std::uint8_t* p = &texture.rgba8[(static_cast<std::size_t>(y) * size + x) * 4];
            p[0] = magenta ? 255 : 0;
            p[1] = 0;
            p[2] = magenta ? 255 : 0;
            p[3] = 255;
        }
    }
    return texture;
}

} // namespace speculum::render
