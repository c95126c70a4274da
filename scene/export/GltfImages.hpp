#pragma once

#include "base/Result.hpp"
#include "render/image/Image.hpp"

#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace speculum::scene {

// An image as glTF 2.0 may hold it: PNG or JPEG bytes, top row first as those files store it.
struct GltfImage {
    std::vector<unsigned char> bytes;
    std::string mimeType; // "image/png" or "image/jpeg"
    std::string extension() const { return mimeType == "image/jpeg" ? ".jpg" : ".png"; }
};

// "image/png" or "image/jpeg" by the file's signature, or "" for anything else (TGA, BMP, EXR, ...).
std::string gltfMimeType(const unsigned char* bytes, std::size_t size);

// Encodes a texture (row 0 the BOTTOM row, TextureImage's convention) as a PNG through OpenImageIO, top
// row first as PNG stores it: 8-bit sRGB for `rgba8`, 16-bit sRGB-encoded for `linear` (so a 16-bit source
// keeps its precision). Alpha is straight.
base::Result<GltfImage> encodePng(const render::TextureImage& image);

// Turns speculum's texture names into glTF images: a file path (absolute) or an embedded texture of a model
// ("<absolute model path>#<Assimp's name>", SceneData.hpp). PNG and JPEG bytes are taken as they are once
// they decode, so nothing is re-encoded and nothing undecodable embedded; any other format is decoded through
// OpenImageIO and written as PNG. Each model file is read once per exporter; each name is resolved once. An
// embedded texture the model file does not give by that name is asked of `meshes`
// (MeshLibrary::embeddedTexture, the decoded image the renderer uses) and written as PNG.
class MeshLibrary;
class GltfImageSource {
public:
    explicit GltfImageSource(MeshLibrary& meshes);
    ~GltfImageSource();
    GltfImageSource(const GltfImageSource&) = delete;
    GltfImageSource& operator=(const GltfImageSource&) = delete;

    base::Result<GltfImage> load(const std::string& name);

private:
    base::Result<GltfImage> loadEmbedded(const std::string& model, const std::string& texture);

    MeshLibrary& m_meshes;
    struct Models;
    std::unique_ptr<Models> m_models;
};

} // namespace speculum::scene
