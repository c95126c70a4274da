#pragma once

#include "render/frame/FrameInput.hpp"
#include "render/gl/Objects.hpp"

#include <array>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace speculum::render::gl {

// A texture's use (render::TextureUse) decides its upload: colour textures are sRGB-decoded by the sampler
// (8-bit: GL_SRGB8_ALPHA8), data textures (normal maps) are read as stored (GL_RGBA8). High-precision
// images upload as GL_RGBA16F either way, holding linear colour or raw data.

// Material textures, uploaded once with mipmaps, keyed by their source (the decoded image when one is
// given, else the file path) and their use. A file that fails to load gets a visible checker texture and
// one warning, so a broken texture is obvious but never fatal.
class TextureCache {
public:
    // The texture for `source`, loading it the first time; 0 for an empty source.
    GLuint get(const TextureSource& source, TextureUse use);
    // Binds `source` on texture unit `unit` with its wrap modes (set on the texture when they change).
    void bind(const TextureSource& source, const std::array<TextureWrap, 2>& wrap, TextureUse use, int unit);
    std::vector<std::string> takeWarnings() { return std::exchange(m_warnings, {}); }

private:
    struct Entry {
        Texture texture;
        std::weak_ptr<const TextureImage> owner; // a decoded image's entry is stale once it is gone
        GLint wrapS = 0;
        GLint wrapT = 0;
    };
    using Key = std::tuple<const void*, std::string, bool>;
    Entry* entry(const TextureSource& source, TextureUse use);
    std::map<Key, Entry> m_textures;
    std::vector<std::string> m_warnings;
};

// The GL wrap mode for a texture wrap mode.
GLint glWrap(TextureWrap wrap);

} // namespace speculum::render::gl
