#pragma once

#include "editor/document/MeshLibrary.hpp"
#include "editor/document/Scene.hpp"
#include "render/Result.hpp"

#include <QString>
#include <string>
#include <vector>

namespace speculum::document {

// Writes the scene as glTF 2.0 through Assimp's exporter, so it can be taken to Blender and other tools:
// `.gltf` (JSON + .bin beside it) or `.glb` (one binary file), by the extension.
//
// The node hierarchy keeps its names and its rest transforms (animations are not exported). Meshes keep
// positions, normals and uvs; materials become metallic-roughness materials with the Blinn-Phong colour as
// base colour and the texture as base-colour texture (its path relative to the exported file). A planar
// mirror becomes a quad of its size with a perfectly smooth metallic material; the curved reflector's mesh
// gets the same material. Lights and the camera are exported as empty nodes at their places (glTF lights
// are an extension Assimp 5.2 does not write). Meshes that cannot be loaded are skipped with a warning.
render::Status exportGltf(const Scene& scene, const QString& path, MeshLibrary& meshes,
                          std::vector<std::string>& warnings);

} // namespace speculum::document
