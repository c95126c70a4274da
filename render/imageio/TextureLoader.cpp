#include "render/imageio/TextureLoader.hpp"

#include "render/image/ColorSpace.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <cassert>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <memory>
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

// Spreads 1..4 source channels to RGBA (1 = grey, 2 = grey + alpha, 3 = RGB, 4 = RGBA) and turns the
// rows over: source row 0 is the top of the stored image, TextureImage's row 0 its bottom.
template <typename T, typename U, typename Convert>
void expandToRgba(const std::vector<T>& src, int channels, int width, int height, U opaque, Convert convert,
                  std::vector<U>& dst) {
    const std::size_t w = static_cast<std::size_t>(width);
    dst.resize(w * static_cast<std::size_t>(height) * 4);
    for (int y = 0; y < height; ++y) {
        const std::size_t srcRow = static_cast<std::size_t>(y) * w;
        const std::size_t dstRow = static_cast<std::size_t>(height - 1 - y) * w;
        for (std::size_t x = 0; x < w; ++x) {
            const T* s = &src[(srcRow + x) * channels];
            U* d = &dst[(dstRow + x) * 4];
            if (channels <= 2) {
                d[0] = d[1] = d[2] = convert(s[0], false);
                d[3] = channels == 2 ? convert(s[1], true) : opaque;
            } else {
                d[0] = convert(s[0], false);
                d[1] = convert(s[1], false);
                d[2] = convert(s[2], false);
                d[3] = channels == 4 ? convert(s[3], true) : opaque;
            }
        }
    }
}

// Textures keep straight alpha; by default OIIO would premultiply PNG/TIFF colours on read.
OIIO::ImageSpec readConfig() {
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    return config;
}

// Reads the opened image `in` into a TextureImage; `label` names it in messages.
base::Result<TextureImage> decode(OIIO::ImageInput& in, const std::string& label) {
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

    const int channels = std::min(spec.nchannels, 4);
    const std::size_t pixels = static_cast<std::size_t>(spec.width) * spec.height;
    TextureImage texture;
    texture.width = spec.width;
    texture.height = spec.height;

    // The widest channel decides: a file with any channel beyond 8 bits keeps its precision.
    std::size_t widest = spec.format.size();
    for (const OIIO::TypeDesc& t : spec.channelformats)
        widest = std::max(widest, t.size());
    const bool floating = spec.format.is_floating_point();
    if (floating || widest > 1) {
        std::vector<float> data(pixels * channels);
        if (!in.read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, data.data()) || in.has_error()) {
            return failure(label, oneLine(in.geterror()));
        }
        const bool hasAlpha = channels == 2 || channels == 4;
        if (floating) {
            // Float files (EXR, float TIFF) hold linear, premultiplied values: unpremultiply.
            for (std::size_t i = 0; i < pixels && hasAlpha; ++i) {
                const float alpha = data[i * channels + channels - 1];
                for (int c = 0; c + 1 < channels && alpha > 0.0f; ++c) {
                    data[i * channels + c] /= alpha;
                }
            }
            expandToRgba(
                data, channels, spec.width, spec.height, 1.0f, [](float v, bool) { return v; },
                texture.linear);
        } else {
            // 16-bit (and 32-bit) integer files are encoded like 8-bit ones: colour decoded from sRGB.
            texture.decodedFromSrgb = true;
            expandToRgba(
                data, channels, spec.width, spec.height, 1.0f,
                [](float v, bool isAlpha) { return isAlpha ? v : srgbToLinear(v); }, texture.linear);
        }
    } else {
        std::vector<std::uint8_t> data(pixels * channels);
        if (!in.read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, data.data()) || in.has_error()) {
            return failure(label, oneLine(in.geterror()));
        }
        expandToRgba(
            data, channels, spec.width, spec.height, std::uint8_t(255),
            [](std::uint8_t v, bool) { return v; }, texture.rgba8);
    }
    in.close();
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

base::Result<TextureImage> loadTexture(const std::string& path) {
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
    return decode(*in, path);
}

base::Result<TextureImage> decodeTexture(const void* bytes, std::size_t size, const std::string& name) {
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
    return decode(*in, name);
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
