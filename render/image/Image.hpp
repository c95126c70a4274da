#pragma once

#include "render/Result.hpp"

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

// An 8-bit texture as loaded from disk; colour textures are sRGB-encoded.
struct TextureImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba8; // width * height * 4, row 0 at the top
};

} // namespace speculum::render
