#include "render/reference/TextureSampler.hpp"

#include "render/image/ColorSpace.hpp"
#include "render/imageio/TextureLoader.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>

namespace speculum::render::reference {

namespace {

// GL's wrap of a texel index (OpenGL 3.3 §3.8.10) along an axis of `size` texels.
long long wrapIndex(long long i, long long size, TextureWrap wrap) {
    switch (wrap) {
    case TextureWrap::ClampToEdge:
        return std::clamp(i, 0LL, size - 1);
    case TextureWrap::MirroredRepeat: {
        const long long m = ((i % (2 * size)) + 2 * size) % (2 * size);
        return m < size ? m : 2 * size - 1 - m;
    }
    case TextureWrap::Repeat:
        break;
    }
    return ((i % size) + size) % size;
}

// Brings a coordinate near [0, 1] without changing what it samples (keeps the numbers small).
double reduce(double c, TextureWrap wrap) {
    switch (wrap) {
    case TextureWrap::ClampToEdge:
        return std::clamp(c, -1.0, 2.0);
    case TextureWrap::MirroredRepeat:
        return c - 2.0 * std::floor(c * 0.5);
    case TextureWrap::Repeat:
        break;
    }
    return c - std::floor(c);
}

} // namespace

LinearTexture::LinearTexture(const TextureImage& image, TextureUse use) {
    const std::size_t n = static_cast<std::size_t>(std::max(image.width, 0)) * std::max(image.height, 0);
    const bool eight = n > 0 && image.rgba8.size() == n * 4;
    const bool deep = n > 0 && image.linear.size() == n * 4;
    if (!eight && !deep) {
        m_rgba = {1.0f, 1.0f, 1.0f, 1.0f}; // an empty image samples as white (no texture)
        return;
    }
    m_width = image.width;
    m_height = image.height;
    m_rgba.resize(n * 4);
    if (deep) {
        // Data textures want the stored values: integers the loader decoded as sRGB are encoded back (as
        // gl::TextureCache uploads them).
        // gl::TextureCache stores them as half floats: non-finite values become 0 and the rest end at
        // ±65504 there, so they do here.
        const bool encode = use == TextureUse::Data && image.decodedFromSrgb;
        for (std::size_t i = 0; i < n * 4; ++i) {
            const float v = image.linear[i];
            const float clamped = std::isfinite(v) ? std::clamp(v, -65504.0f, 65504.0f) : 0.0f;
            m_rgba[i] = encode && i % 4 != 3 ? linearToSrgb(clamped) : clamped;
        }
        return;
    }
    float decode[256];
    for (int code = 0; code < 256; ++code)
        decode[code] = use == TextureUse::Color ? srgb8ToLinear(static_cast<std::uint8_t>(code))
                                                : static_cast<float>(code) / 255.0f;
    for (std::size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c)
            m_rgba[i * 4 + c] = decode[image.rgba8[i * 4 + c]];
        m_rgba[i * 4 + 3] = static_cast<float>(image.rgba8[i * 4 + 3]) / 255.0f;
    }
}

glm::dvec4 LinearTexture::texel(long long x, long long y) const {
    const std::size_t i = static_cast<std::size_t>(y * m_width + x) * 4;
    return {m_rgba[i], m_rgba[i + 1], m_rgba[i + 2], m_rgba[i + 3]};
}

glm::dvec4 LinearTexture::sample(glm::dvec2 uv, TextureWrap wrapS, TextureWrap wrapT) const {
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y))
        uv = {0.0, 0.0};
    uv = {reduce(uv.x, wrapS), reduce(uv.y, wrapT)};
    // GL's texel-centre convention: texel i covers [i, i+1) / size, so its centre is at (i + 0.5) / size.
    const double x = uv.x * m_width - 0.5;
    const double y = uv.y * m_height - 0.5;
    const double x0 = std::floor(x), y0 = std::floor(y);
    const double fx = x - x0, fy = y - y0;
    const auto ix = static_cast<long long>(x0), iy = static_cast<long long>(y0);
    const long long xa = wrapIndex(ix, m_width, wrapS), xb = wrapIndex(ix + 1, m_width, wrapS);
    const long long ya = wrapIndex(iy, m_height, wrapT), yb = wrapIndex(iy + 1, m_height, wrapT);
    const glm::dvec4 low = glm::mix(texel(xa, ya), texel(xb, ya), fx);
    const glm::dvec4 high = glm::mix(texel(xa, yb), texel(xb, yb), fx);
    return glm::mix(low, high, fy);
}

int TextureSet::add(const TextureSource& source, TextureUse use) {
    if (source.empty())
        return -1;
    std::tuple<const void*, std::string, bool> key{
        source.image.get(), source.image ? std::string() : source.path, use == TextureUse::Data};
    if (auto it = m_indices.find(key); it != m_indices.end())
        return it->second;
    if (source.image) {
        const TextureImage& image = *source.image;
        const std::size_t n = static_cast<std::size_t>(std::max(image.width, 0)) * std::max(image.height, 0);
        if (n > 0 && (image.rgba8.size() == n * 4 || image.linear.size() == n * 4)) {
            m_textures.emplace_back(image, use);
        } else {
            m_warnings.push_back("texture " + source.path +
                                 ": the decoded image has no pixels (showing a checker instead)");
            m_textures.emplace_back(checkerTexture(), use);
        }
    } else {
        std::string reduced;
        auto loaded = loadTexture(source.path, {}, &reduced);
        if (!loaded)
            m_warnings.push_back("texture " + source.path + ": " + loaded.error() +
                                 " (showing a checker instead)");
        else if (!reduced.empty())
            m_warnings.push_back(std::move(reduced));
        m_textures.emplace_back(loaded ? *loaded : checkerTexture(), use);
    }
    const int index = static_cast<int>(m_textures.size()) - 1;
    m_indices.emplace(std::move(key), index);
    return index;
}

MaterialTextures MaterialTextures::add(TextureSet& set, const Material& m) {
    MaterialTextures t;
    t.base = set.add(m.texture, TextureUse::Color);
    t.emission = set.add(m.emissionTexture, TextureUse::Color);
    t.normal = set.add(m.normalTexture, TextureUse::Data);
    return t;
}

} // namespace speculum::render::reference
