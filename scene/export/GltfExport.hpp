#pragma once

#include "base/Result.hpp"
#include "scene/import/MeshLibrary.hpp"
#include "scene/model/Scene.hpp"

#include <QString>
#include <functional>
#include <string>
#include <vector>

namespace speculum::scene {

// Writes the scene as a self-contained glTF 2.0 asset for Blender, three.js and other tools, by the
// extension: `.glb` (one binary file, images inside it) or `.gltf` (JSON, with `<name>.bin` and the images
// `<name>_<n>.png|.jpg` beside it, referred to by relative URIs). Built by speculum (GltfBuilder) and
// serialized by tinygltf, not Assimp.
//
// - Nodes keep their names, hierarchy and their pose at t = 0 (translation, rotation, scale; animations
//   are not exported). Meshes keep positions, normals, uvs (v turned to glTF's top-left origin), vertex
//   colours (COLOR_0) and tangents; a mesh drawn by several nodes is stored once.
// - Materials become metallic-roughness materials: the Blinn-Phong colour and opacity as baseColorFactor,
//   roughness and metallic by inverting the importer's conversion (roughness = (2 / (shininess + 2))^¼;
//   metallic from specularColor = mix(white, colour, metallic), least squares over the channels, so a
//   white specular colour, every hand-made material's, is a dielectric); base colour, emissive and normal
//   textures with the material's wrap modes; emission as emissiveFactor (brighter than 1 via
//   KHR_materials_emissive_strength); alpha mode and cutoff. The ambient/diffuse/specular weights have no
//   glTF counterpart and are dropped.
// - Images: PNG and JPEG files (and embedded textures, "<model>#<name>") are copied byte for byte; any
//   other format is decoded through OpenImageIO and written as PNG.
// - A whole model file on a node without a material of its own is written as the viewport draws it: a
//   child node per part the file's node tree places (its matrix that placement), each part's mesh once,
//   with the file's own material and textures.
// - A planar mirror becomes a quad of its size (the renderer's uvs) with metallic = its reflectivity and
//   roughness = its roughness; the curved reflector's mesh gets metallic = its reflectivity and its
//   roughness (both are GGX roughness, α = roughness², as glTF's).
// - Lights: KHR_lights_punctual point, spot (outer cone = spotAngle, inner = outer · (1 − spotBlend)) and
//   directional lights with their colour and intensity (glTF's point lights fall off with distance,
//   speculum's do not). A point light sits on its node; a spot or directional light on a child node
//   "<name> (light)" turned so that glTF's −Z is the node's −Y.
// - The scene camera: a perspective camera (yfov, znear, zfar) on a top-level node "Camera".
// - extensionsUsed lists exactly the extensions written.
//
// All or nothing: every file is written to a temporary in the target folder, and once all are complete
// they replace the previous files as one set (base::commitTogether, the main file last): a failure at any
// point leaves the previous export whole, with no partial output. Meshes and textures that cannot be
// loaded are skipped with a warning.
//
// A `.gltf` export never replaces a `<name>.bin` or `<name>_<n>.png` beside it that an earlier export to
// the same file did not write (the previous `.gltf` names its companions): mayReplace is asked with their
// paths; without it, or when it says no, the export is refused with one line and nothing is written.
using ReplaceUnrelatedFiles = std::function<bool(const std::vector<std::string>& paths)>;
base::Status exportGltf(const Scene& scene, const QString& path, MeshLibrary& meshes,
                        std::vector<std::string>& warnings, const ReplaceUnrelatedFiles& mayReplace = {});

} // namespace speculum::scene
