#pragma once

#include "render/image/Image.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <unordered_map>
#include <vector>

namespace speculum::render::reference {

// A texture decoded to linear RGB once, sampled like the GL sampler of gl::TextureCache at its base
// level: bilinear, repeat wrapping, sRGB decoded before filtering. Row 0 of the image is t = 0, as
// glTexImage2D uploads it.
class LinearTexture {
public:
    explicit LinearTexture(const TextureImage& image);
    glm::dvec3 sample(glm::dvec2 uv) const;

private:
    glm::dvec3 texel(long long x, long long y) const;
    int m_width = 1;
    int m_height = 1;
    std::vector<float> m_rgb;
};

// Loads each texture path once; a file that fails to load becomes the same checker the rasterizer shows,
// with a warning.
class TextureSet {
public:
    // Index of the texture for `path`, or -1 for an empty path.
    int add(const std::string& path);
    const LinearTexture& operator[](int index) const { return m_textures[static_cast<std::size_t>(index)]; }
    const std::vector<std::string>& warnings() const { return m_warnings; }

private:
    std::unordered_map<std::string, int> m_indices;
    std::vector<LinearTexture> m_textures;
    std::vector<std::string> m_warnings;
};

} // namespace speculum::render::reference
