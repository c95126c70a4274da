#include "render/reference/TextureSampler.hpp"

#include "render/image/ColorSpace.hpp"
#include "render/image/TextureLoader.hpp"

#include <cmath>
#include <glm/common.hpp>

namespace speculum::render::reference {

LinearTexture::LinearTexture(const TextureImage& image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.rgba8.size() < static_cast<std::size_t>(image.width) * image.height * 4) {
        m_rgb = {1.0f, 1.0f, 1.0f}; // an empty image samples as white (no texture)
        return;
    }
    m_width = image.width;
    m_height = image.height;
    m_rgb.resize(static_cast<std::size_t>(m_width) * m_height * 3);
    float decode[256];
    for (int code = 0; code < 256; ++code)
        decode[code] = srgb8ToLinear(static_cast<std::uint8_t>(code));
    for (std::size_t i = 0, n = static_cast<std::size_t>(m_width) * m_height; i < n; ++i)
        for (int c = 0; c < 3; ++c)
            m_rgb[i * 3 + c] = decode[image.rgba8[i * 4 + c]];
}

glm::dvec3 LinearTexture::texel(long long x, long long y) const {
    const long long w = m_width, h = m_height;
    x = ((x % w) + w) % w;
    y = ((y % h) + h) % h;
    const std::size_t i = static_cast<std::size_t>(y * w + x) * 3;
    return {m_rgb[i], m_rgb[i + 1], m_rgb[i + 2]};
}

glm::dvec3 LinearTexture::sample(glm::dvec2 uv) const {
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y))
        uv = {0.0, 0.0};
    // Repeat first (keeps the numbers small), then GL's texel-centre convention: texel i covers
    // [i, i+1) / size, so its centre is at (i + 0.5) / size.
    uv -= glm::floor(uv);
    const double x = uv.x * m_width - 0.5;
    const double y = uv.y * m_height - 0.5;
    const double x0 = std::floor(x), y0 = std::floor(y);
    const double fx = x - x0, fy = y - y0;
    const auto ix = static_cast<long long>(x0), iy = static_cast<long long>(y0);
    const glm::dvec3 top = glm::mix(texel(ix, iy), texel(ix + 1, iy), fx);
    const glm::dvec3 bottom = glm::mix(texel(ix, iy + 1), texel(ix + 1, iy + 1), fx);
    return glm::mix(top, bottom, fy);
}

int TextureSet::add(const std::string& path) {
    if (path.empty())
        return -1;
    if (auto it = m_indices.find(path); it != m_indices.end())
        return it->second;
    auto loaded = loadTexture(path);
    if (!loaded)
        m_warnings.push_back("texture " + path + ": " + loaded.error() + " (showing a checker instead)");
    m_textures.emplace_back(loaded ? *loaded : checkerTexture());
    const int index = static_cast<int>(m_textures.size()) - 1;
    m_indices.emplace(path, index);
    return index;
}

} // namespace speculum::render::reference
