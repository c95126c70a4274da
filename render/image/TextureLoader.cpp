#include "render/image/TextureLoader.hpp"

#include "render/image/ColorSpace.hpp"

#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <cassert>
#include <filesystem>
#include <memory>
#include <system_error>
#include <vector>

namespace speculum::render {

namespace fs = std::filesystem;

namespace {

Error failure(const std::string& path, const std::string& reason) {
    return Error{"cannot read texture '" + path + "': " + reason};
}

std::string oneLine(std::string message) {
    std::replace(message.begin(), message.end(), '\n', ' ');
    while (!message.empty() && message.back() == ' ') {
        message.pop_back();
    }
    return message.empty() ? std::string("the file is corrupt or truncated") : message;
}

// Spreads 1..4 source channels to RGBA: 1 = grey, 2 = grey + alpha, 3 = RGB, 4 = RGBA.
template <typename T, typename Convert>
void expandToRgba(const std::vector<T>& src, int channels, std::size_t pixels, Convert toByte,
                  std::vector<std::uint8_t>& dst) {
    dst.resize(pixels * 4);
    for (std::size_t i = 0; i < pixels; ++i) {
        const T* s = &src[i * channels];
        std::uint8_t* d = &dst[i * 4];
        if (channels <= 2) {
            d[0] = d[1] = d[2] = toByte(s[0], false);
            d[3] = channels == 2 ? toByte(s[1], true) : 255;
        } else {
            d[0] = toByte(s[0], false);
            d[1] = toByte(s[1], false);
            d[2] = toByte(s[2], false);
            d[3] = channels == 4 ? toByte(s[3], true) : 255;
        }
    }
}

} // namespace

Result<TextureImage> loadTexture(const std::string& path) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) {
        return failure(path, "the file does not exist");
    }
    if (fs::is_directory(status)) {
        return failure(path, "it is a folder");
    }

    // Textures keep straight alpha; by default OIIO would premultiply PNG/TIFF colours on read.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path, &config);
    if (!in) {
        return failure(path, oneLine(OIIO::geterror()));
    }
    const OIIO::ImageSpec spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) {
        return failure(path, "the image has no pixels");
    }
    // Checked before allocating: a hostile header must not make us reserve gigabytes.
    if (spec.width > kMaxTextureSide || spec.height > kMaxTextureSide) {
        return failure(path, "the image is " + std::to_string(spec.width) + "x" +
                                 std::to_string(spec.height) + "; the largest supported size is " +
                                 std::to_string(kMaxTextureSide) + " per side");
    }
    if (spec.depth > 1) {
        return failure(path, "volume images are not supported");
    }

    const int channels = std::min(spec.nchannels, 4);
    const std::size_t pixels = static_cast<std::size_t>(spec.width) * spec.height;
    TextureImage texture{spec.width, spec.height, {}};

    if (spec.format.is_floating_point()) {
        // Float files (EXR, float TIFF) hold linear, premultiplied values: unpremultiply and encode.
        std::vector<float> data(pixels * channels);
        if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, data.data()) || in->has_error()) {
            return failure(path, oneLine(in->geterror()));
        }
        const bool hasAlpha = channels == 2 || channels == 4;
        if (hasAlpha) {
            for (std::size_t i = 0; i < pixels; ++i) {
                const float alpha = data[i * channels + channels - 1];
                for (int c = 0; c + 1 < channels && alpha > 0.0f; ++c) {
                    data[i * channels + c] /= alpha;
                }
            }
        }
        expandToRgba(
            data, channels, pixels,
            [](float v, bool isAlpha) { return isAlpha ? toUnorm8(v) : linearToSrgb8(v); }, texture.rgba8);
    } else {
        // Integer files are taken as already encoded; OIIO rescales 16-bit values with rounding.
        std::vector<std::uint8_t> data(pixels * channels);
        if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, data.data()) || in->has_error()) {
            return failure(path, oneLine(in->geterror()));
        }
        expandToRgba(
            data, channels, pixels, [](std::uint8_t v, bool) { return v; }, texture.rgba8);
    }
    in->close();
    return texture;
}

TextureImage checkerTexture(int size) {
    assert(size > 0 && "checkerTexture(): size must be positive");
    const int cell = std::max(1, size / 8);
    TextureImage texture{size, size, std::vector<std::uint8_t>(static_cast<std::size_t>(size) * size * 4)};
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
