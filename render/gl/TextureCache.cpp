#include "render/gl/TextureCache.hpp"

#include "render/image/TextureLoader.hpp"

namespace speculum::render::gl {

GLuint TextureCache::get(const std::string& path) {
    if (auto it = m_textures.find(path); it != m_textures.end())
        return it->second.id();
    auto loaded = loadTexture(path);
    TextureImage image;
    if (loaded) {
        image = std::move(*loaded);
    } else {
        m_warnings.push_back("texture " + path + ": " + loaded.error() + " (showing a checker instead)");
        image = checkerTexture();
    }
    Texture texture = makeTexture();
    glBindTexture(GL_TEXTURE_2D, texture.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 image.rgba8.data());
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glBindTexture(GL_TEXTURE_2D, 0);
    const GLuint id = texture.id();
    m_textures.emplace(path, std::move(texture));
    return id;
}

} // namespace speculum::render::gl
