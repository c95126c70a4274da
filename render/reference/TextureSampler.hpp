#pragma once

#include "render/frame/FrameInput.hpp"
#include "render/image/Image.hpp"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace speculum::render::reference {

// A texture decoded to linear RGBA once, sampled like the GL sampler of gl::TextureCache at its base
// level: bilinear, the material's wrap modes, sRGB decoded before filtering for colour. Row 0 of the
// image is t = 0, as glTexImage2D uploads it (TextureImage: row 0 is the bottom row of the stored image).
class LinearTexture {
public:
    explicit LinearTexture(const TextureImage& image, TextureUse use = TextureUse::Color);
    glm::dvec4 sample(glm::dvec2 uv, TextureWrap wrapS = TextureWrap::Repeat,
                      TextureWrap wrapT = TextureWrap::Repeat) const;

private:
    glm::dvec4 texel(long long x, long long y) const;
    int m_width = 1;
    int m_height = 1;
    std::vector<float> m_rgba;
};

// Loads each texture once, keyed like gl::TextureCache: by source (the decoded image if given, else the
// file path) and use. A file that fails to load becomes the same checker the rasterizer shows, with a
// warning.
class TextureSet {
public:
    // Index of the texture for `source`, or -1 for an empty source.
    int add(const TextureSource& source, TextureUse use);
    const LinearTexture& operator[](int index) const { return m_textures[static_cast<std::size_t>(index)]; }
    const std::vector<std::string>& warnings() const { return m_warnings; }

private:
    std::map<std::tuple<const void*, std::string, bool>, int> m_indices;
    std::vector<LinearTexture> m_textures;
    std::vector<std::string> m_warnings;
};

// A material's textures in a TextureSet (-1: none).
struct MaterialTextures {
    int base = -1;
    int emission = -1;
    int normal = -1;

    static MaterialTextures add(TextureSet& set, const Material& material);
};

} // namespace speculum::render::reference
