#pragma once

#include "scene/export/GltfImages.hpp"
#include "scene/import/MeshLibrary.hpp"
#include "scene/model/Scene.hpp"

#include <string>
#include <tiny_gltf.h>
#include <vector>

namespace speculum::scene {

// How the document refers to its binary data and images.
struct GltfLayout {
    // true (.glb): one buffer, the GLB's BIN chunk, with the images in it (bufferView + mimeType).
    // false (.gltf): the buffer is the file `binUri` beside the JSON, the images separate files named
    // `imageStem` + "_<n>.png|.jpg" beside it (relative, percent-encoded URIs).
    bool binary = true;
    std::string binUri;
    std::string imageStem;
};

// A glTF 2.0 asset in memory: the document, with its one buffer (if it has binary data) in
// `model.buffers`, ready to be written as .glb or .gltf (GltfExport.cpp).
struct GltfAsset {
    tinygltf::Model model;
    struct ImageFile {
        std::string fileName; // relative to the JSON's folder (.gltf only)
        GltfImage image;
    };
    std::vector<ImageFile> imageFiles; // .gltf only: written beside the JSON
};

// Builds the asset from the scene (GltfExport.hpp says what is exported and how). Anything that cannot be
// exported (a mesh or texture that does not load) is skipped with a warning naming the node.
GltfAsset buildGltf(const Scene& scene, MeshLibrary& meshes, const GltfLayout& layout,
                    std::vector<std::string>& warnings);

} // namespace speculum::scene
