#include "scene/export/GltfImages.hpp"

#include "render/image/ColorSpace.hpp"
#include "render/imageio/TextureLoader.hpp"
#include "scene/import/MeshLibrary.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace speculum::scene {

namespace fs = std::filesystem;

std::string gltfMimeType(const unsigned char* bytes, std::size_t size) {
    static constexpr unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (size >= sizeof png && std::memcmp(bytes, png, sizeof png) == 0) {
        return "image/png";
    }
    if (size >= 3 && bytes[0] == 0xff && bytes[1] == 0xd8 && bytes[2] == 0xff) {
        return "image/jpeg";
    }
    return {};
}

base::Result<GltfImage> encodePng(const render::TextureImage& image) {
    const int w = image.width, h = image.height;
    if (w <= 0 || h <= 0) {
        return base::Error{"the image has no pixels"};
    }
    const std::size_t row = static_cast<std::size_t>(w) * 4;
    // TextureImage row 0 is the bottom row; PNG stores the top row first.
    std::vector<std::uint8_t> bytes8;
    std::vector<std::uint16_t> bytes16;
    const bool wide = image.highPrecision();
    if (wide) {
        bytes16.resize(row * static_cast<std::size_t>(h));
    } else {
        bytes8.resize(row * static_cast<std::size_t>(h));
    }
    for (int y = 0; y < h; ++y) {
        const std::size_t src = static_cast<std::size_t>(h - 1 - y) * row;
        const std::size_t dst = static_cast<std::size_t>(y) * row;
        if (!wide) {
            std::copy_n(image.rgba8.begin() + static_cast<std::ptrdiff_t>(src), row,
                        bytes8.begin() + static_cast<std::ptrdiff_t>(dst));
            continue;
        }
        for (std::size_t i = 0; i < row; ++i) {
            const float linear = image.linear[src + i];
            // Colour is sRGB-encoded, as glTF expects of a colour texture and as the loader decoded it;
            // alpha is linear.
            const float encoded = (i % 4 == 3) ? linear : render::linearToSrgb(linear);
            const float clamped = std::clamp(std::isfinite(encoded) ? encoded : 0.0f, 0.0f, 1.0f);
            bytes16[dst + i] = static_cast<std::uint16_t>(std::lround(clamped * 65535.0f));
        }
    }

    GltfImage out;
    out.mimeType = "image/png";
    OIIO::Filesystem::IOVecOutput memory(out.bytes);
    // The name only picks the PNG writer; the bytes go to `memory`.
    std::unique_ptr<OIIO::ImageOutput> writer = OIIO::ImageOutput::create("image.png", &memory);
    if (!writer) {
        return base::Error{"no PNG writer: " + OIIO::geterror()};
    }
    OIIO::ImageSpec spec(w, h, 4, wide ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8);
    spec.alpha_channel = 3;
    spec.attribute("oiio:ColorSpace", "sRGB");
    spec.attribute("oiio:UnassociatedAlpha", 1); // ours is straight; do not "un-premultiply" it
    spec.attribute("Software", "speculum " SPECULUM_VERSION);
    if (!writer->open("image.png", spec)) {
        return base::Error{"PNG encoding failed: " + writer->geterror()};
    }
    const bool written = wide ? writer->write_image(OIIO::TypeDesc::UINT16, bytes16.data())
                              : writer->write_image(OIIO::TypeDesc::UINT8, bytes8.data());
    if (!written || !writer->close()) {
        return base::Error{"PNG encoding failed: " + writer->geterror()};
    }
    if (gltfMimeType(out.bytes.data(), out.bytes.size()).empty()) {
        return base::Error{"PNG encoding produced no PNG"};
    }
    return out;
}

struct GltfImageSource::Models {
    // Model file → its importer (owning the aiScene), or null when it could not be read.
    std::map<std::string, std::unique_ptr<Assimp::Importer>> importers;
    std::map<std::string, std::string> errors;
    std::map<std::string, base::Result<GltfImage>> resolved;
};

GltfImageSource::GltfImageSource(MeshLibrary& meshes)
    : m_meshes(meshes)
    , m_models(std::make_unique<Models>()) {}

GltfImageSource::~GltfImageSource() = default;

namespace {

// PNG and JPEG bytes are embedded as they are, but only once they decode: a truncated or corrupt file
// that merely starts like one must not reach the glTF as an image no viewer can show.
base::Result<GltfImage> fromBytes(std::vector<unsigned char> bytes, const std::string& name) {
    auto decoded = render::decodeTexture(bytes.data(), bytes.size(), name);
    if (!decoded) {
        return base::Error{decoded.error()};
    }
    if (std::string mime = gltfMimeType(bytes.data(), bytes.size()); !mime.empty()) {
        return GltfImage{std::move(bytes), std::move(mime)};
    }
    return encodePng(*decoded);
}

} // namespace

base::Result<GltfImage> GltfImageSource::load(const std::string& name) {
    if (auto found = m_models->resolved.find(name); found != m_models->resolved.end()) {
        return found->second;
    }
    base::Result<GltfImage> result = base::Error{""};
    // "<model>#<texture>": the model must exist as a file; a plain path with '#' in it stays a path.
    const std::size_t hash = name.rfind('#');
    std::error_code ec;
    if (hash != std::string::npos && !fs::exists(name, ec) && fs::is_regular_file(name.substr(0, hash), ec)) {
        result = loadEmbedded(name.substr(0, hash), name.substr(hash + 1));
    } else if (!fs::is_regular_file(name, ec)) {
        result = base::Error{"cannot read texture '" + name + "': no such file"};
    } else {
        std::ifstream in(name, std::ios::binary);
        std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                         std::istreambuf_iterator<char>());
        if (!in.good() && !in.eof()) {
            result = base::Error{"cannot read texture '" + name + "'"};
        } else if (!gltfMimeType(bytes.data(), bytes.size()).empty()) {
            result = fromBytes(std::move(bytes), name);
        } else {
            // Not PNG/JPEG: the loader reads every format OIIO knows, by the file (TGA, BMP, EXR, ...).
            auto decoded = render::loadTexture(name);
            result = decoded ? encodePng(*decoded) : base::Result<GltfImage>(base::Error{decoded.error()});
        }
    }
    m_models->resolved.emplace(name, result);
    return result;
}

base::Result<GltfImage> GltfImageSource::loadEmbedded(const std::string& model, const std::string& texture) {
    auto [it, fresh] = m_models->importers.try_emplace(model);
    if (fresh) {
        auto importer = std::make_unique<Assimp::Importer>();
        // No post-processing: only the embedded textures are wanted.
        if (importer->ReadFile(model, 0)) {
            it->second = std::move(importer);
        } else {
            m_models->errors[model] = importer->GetErrorString();
        }
    }
    const std::string label = model + "#" + texture;
    const aiTexture* t = it->second ? it->second->GetScene()->GetEmbeddedTexture(texture.c_str()) : nullptr;
    if (!t || !t->pcData) {
        std::vector<Warning> ignored; // the import's own warnings were given when it was drawn
        if (auto decoded = m_meshes.embeddedTexture(label, ignored)) {
            return encodePng(*decoded);
        }
        return base::Error{
            "cannot read texture '" + label + "': " +
            (it->second ? std::string("the model has no such embedded texture") : m_models->errors[model])};
    }
    if (t->mHeight == 0) { // compressed: mWidth bytes of a file (PNG, JPEG, TGA, ...)
        const auto* data = reinterpret_cast<const unsigned char*>(t->pcData);
        return fromBytes(std::vector<unsigned char>(data, data + t->mWidth), label);
    }
    // Raw BGRA8 texels, top row first.
    render::TextureImage image;
    image.width = static_cast<int>(t->mWidth);
    image.height = static_cast<int>(t->mHeight);
    image.rgba8.resize(static_cast<std::size_t>(t->mWidth) * t->mHeight * 4);
    for (unsigned y = 0; y < t->mHeight; ++y) {
        for (unsigned x = 0; x < t->mWidth; ++x) {
            const aiTexel& s = t->pcData[y * t->mWidth + x];
            std::uint8_t* d =
                &image.rgba8[((t->mHeight - 1 - y) * static_cast<std::size_t>(t->mWidth) + x) * 4];
            d[0] = s.r;
            d[1] = s.g;
            d[2] = s.b;
            d[3] = s.a;
        }
    }
    return encodePng(image);
}

} // namespace speculum::scene
