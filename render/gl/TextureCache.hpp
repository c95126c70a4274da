#pragma once

#include "render/gl/Objects.hpp"

#include <string>
#include <unordered_map>
#include <vector>

namespace speculum::render::gl {

// Colour textures by file path, uploaded once as sRGB with mipmaps. A file that fails to load gets a
// visible checker texture and one warning, so a broken texture is obvious but never fatal.
class TextureCache {
public:
    GLuint get(const std::string& path);
    std::vector<std::string> takeWarnings() { return std::exchange(m_warnings, {}); }

private:
    std::unordered_map<std::string, Texture> m_textures;
    std::vector<std::string> m_warnings;
};

} // namespace speculum::render::gl
