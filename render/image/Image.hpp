#pragma once

#include "base/Result.hpp"

#include <cstdint>
#include <glm/vec4.hpp>
#include <string>
#include <utility>
#include <vector>

namespace speculum::render {

// A rendered frame: linear RGBA floats, row 0 at the top.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<float> rgba; // width * height * 4

    glm::vec4 at(int x, int y) const {
        const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 4;
        return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
    }
};

// Key/value attributes stored in the written file (OpenImageIO attribute names, e.g. "Software").
struct ImageMetadata {
    std::vector<std::pair<std::string, std::string>> attributes;
};

// What a texture's values mean, which decides how the rasterizer uploads it and the tracer decodes it:
// colour (8-bit files sRGB-decoded before filtering) or data (normal maps: the values as stored).
enum class TextureUse { Color, Data };

// A texture as loaded from disk or from a model's embedded image, ready to upload. Row 0 is the BOTTOM
// row of the image as it is stored in its file, so that row 0 is t = 0 for glTexImage2D and v = 0 in
// speculum's texture coordinates (docs/scene-format.md: v = 0 is the bottom row of the stored image).
//
// Exactly one of the two pixel arrays is filled: `rgba8` for 8-bit files (colour sRGB-encoded, alpha
// straight), or `linear` for files with more than 8 bits per channel (16-bit integer, half, float): linear
// values, straight alpha, so nothing is rounded to 8 bits on the way to the GPU.
struct TextureImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba8; // width * height * 4, or empty when `linear` holds the pixels
    std::vector<float> linear;       // width * height * 4, or empty
    // `linear` was decoded from sRGB-encoded integers (a 16-bit PNG): data textures such as normal maps
    // hold raw values, so their readers encode these back. False for float files, which store linear values.
    bool decodedFromSrgb = false;

    bool highPrecision() const { return !linear.empty(); }
};

} // namespace speculum::render
