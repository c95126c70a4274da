#include "render/gl/TextureCache.hpp"

#include "base/Printable.hpp"
#include "render/gl/Allocation.hpp"
#include "render/gl/Memory.hpp"
#include "render/image/ColorSpace.hpp"
#include "render/imageio/TextureLoader.hpp"

#include <algorithm>
#include <cmath>

namespace speculum::render::gl {

GLint glWrap(TextureWrap wrap) {
    switch (wrap) {
    case TextureWrap::ClampToEdge:
        return GL_CLAMP_TO_EDGE;
    case TextureWrap::MirroredRepeat:
        return GL_MIRRORED_REPEAT;
    case TextureWrap::Repeat:
        break;
    }
    return GL_REPEAT;
}

namespace {

bool complete(const TextureImage& image) {
    const std::size_t n = static_cast<std::size_t>(std::max(image.width, 0)) * std::max(image.height, 0) * 4;
    return n > 0 && (image.rgba8.size() == n || image.linear.size() == n);
}

void upload(const TextureImage& image, TextureUse use) {
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (!image.highPrecision()) {
        glTexImage2D(GL_TEXTURE_2D, 0, use == TextureUse::Color ? GL_SRGB8_ALPHA8 : GL_RGBA8, image.width,
                     image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba8.data());
        return;
    }
    // The loader decoded integer files as colour; a data texture wants the values as stored. Half floats
    // end at 65504: larger or non-finite values would upload as infinities, so they are clamped.
    constexpr float kHalfMax = 65504.0f;
    const bool encode = use == TextureUse::Data && image.decodedFromSrgb;
    const bool clamp = std::any_of(image.linear.begin(), image.linear.end(),
                                   [&](float v) { return !(std::abs(v) <= kHalfMax); });
    if (!encode && !clamp) {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, image.width, image.height, 0, GL_RGBA, GL_FLOAT,
                     image.linear.data());
        return;
    }
    std::vector<float> values(image.linear);
    for (std::size_t i = 0; i < values.size(); ++i) {
        float v = std::isfinite(values[i]) ? std::clamp(values[i], -kHalfMax, kHalfMax) : 0.0f;
        if (encode && i % 4 != 3)
            v = linearToSrgb(v);
        values[i] = v;
    }
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, image.width, image.height, 0, GL_RGBA, GL_FLOAT,
                 values.data());
}

// The image to upload for `source`: its own decoded image (returned), else its file read within the GPU's
// texture size or the checker, either one left in `loaded` (and null returned). Each stand-in and each file
// read smaller than it is adds a warning.
const TextureImage* imageFor(const TextureSource& source, TextureImage& loaded,
                             std::vector<std::string>& warnings) {
    if (source.image && complete(*source.image))
        return source.image.get();
    if (source.image) {
        warnings.push_back("texture " + source.path +
                           ": the decoded image has no pixels (showing a checker instead)");
        loaded = checkerTexture();
        return nullptr;
    }
    GLint maxTextureSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTextureSize);
    TextureLimits limits;
    limits.maxSide = std::clamp(static_cast<int>(maxTextureSize), 1, kMaxTextureSide);
    std::string reduced;
    auto file = loadTexture(source.path, limits, &reduced);
    if (!file) {
        warnings.push_back("texture " + source.path + ": " + file.error() + " (showing a checker instead)");
        loaded = checkerTexture();
        return nullptr;
    }
    if (!reduced.empty())
        warnings.push_back(std::move(reduced));
    loaded = std::move(*file);
    return nullptr;
}

} // namespace

TextureCache::Entry* TextureCache::entry(const TextureSource& source, TextureUse use) {
    if (source.empty())
        return nullptr;
    // An image is its own identity (two embedded images may share a name); a file is its path.
    Key key{source.image.get(), source.image ? std::string() : source.path, use == TextureUse::Data};
    if (auto it = m_textures.find(key); it != m_textures.end()) {
        // A new image may reuse the address of a freed one: only a live pointer to this very image counts.
        if (!source.image || it->second.owner.lock() == source.image)
            return &it->second;
        m_textures.erase(it);
    }
    TextureImage loadedImage;
    const TextureImage* image = imageFor(source, loadedImage, m_warnings);
    Entry e;
    e.owner = source.image;
    e.texture = makeTexture();
    glBindTexture(GL_TEXTURE_2D, e.texture.id());
    {
        // Checked: a texture that does not fit would sample as black with no word said. It shows the
        // checker instead, with a warning, and is not tried again while the cache holds its entry.
        const TextureImage& uploaded = image ? *image : loadedImage;
        const int levels =
            1 + static_cast<int>(std::floor(std::log2(std::max({uploaded.width, uploaded.height, 1}))));
        const std::size_t texel = uploaded.highPrecision() ? 8 : 4;
        base::Status fits = beginAllocation(mipChainTexels(uploaded.width, uploaded.height, levels) * texel);
        if (fits) {
            upload(uploaded, use);
            glGenerateMipmap(GL_TEXTURE_2D);
            fits = finishAllocation();
        }
        if (!fits) {
            m_warnings.push_back("texture " + base::quoted(source.path) + ": the " +
                                 std::to_string(uploaded.width) + "×" + std::to_string(uploaded.height) +
                                 " image " + fits.error() + " (showing a checker instead)");
            upload(checkerTexture(), use);
            glGenerateMipmap(GL_TEXTURE_2D);
            (void)finishAllocation();
        }
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    e.wrapS = e.wrapT = GL_REPEAT;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glBindTexture(GL_TEXTURE_2D, 0);
    return &m_textures.emplace(std::move(key), std::move(e)).first->second;
}

GLuint TextureCache::get(const TextureSource& source, TextureUse use) {
    Entry* e = entry(source, use);
    return e ? e->texture.id() : 0;
}

void TextureCache::bind(const TextureSource& source, const std::array<TextureWrap, 2>& wrap, TextureUse use,
                        int unit) {
    Entry* e = entry(source, use);
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, e ? e->texture.id() : 0);
    if (!e)
        return;
    // Wrap modes belong to the material, the texture to its source: two materials may share one image
    // with different modes, so the modes are set when they differ from the last draw's.
    const GLint s = glWrap(wrap[0]), t = glWrap(wrap[1]);
    if (e->wrapS != s)
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, e->wrapS = s);
    if (e->wrapT != t)
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, e->wrapT = t);
}

} // namespace speculum::render::gl
