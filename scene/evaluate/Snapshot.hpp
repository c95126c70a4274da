#pragma once

#include "render/frame/FrameInput.hpp"
#include "scene/import/MeshLibrary.hpp"
#include "scene/model/Scene.hpp"
#include "scene/model/Warning.hpp"

#include <vector>

namespace speculum::scene {

// The renderer's per-frame input: the scene with animations evaluated at timeSeconds, world matrices
// composed in double (parent world × T × R × S), absolute texture paths and meshes from `meshes`.
//
// Per node, in file order (parents before children):
//   mesh (and no reflector) → a DrawItem with the node's material, or the default material;
//   light                   → a Light at the world origin of the node, pointing along its world −Y;
//   mirror                  → a Mirror (world matrix, size, reflectivity, technique, material if any);
//   reflector               → a Reflector, whose surface is the node's mesh (not also a DrawItem).
// A mesh that cannot be loaded (MeshSkipped, with the node and the model file) or a reflector without a
// mesh (ReflectorWithoutMesh) give a warning, and that part of the
// node is skipped; the reader's notes on a model file read for it come too (ModelFileNote). snapshot never
// fails.
render::FrameInput snapshot(const Scene& scene, double timeSeconds, MeshLibrary& meshes,
                            std::vector<Warning>& warnings);

} // namespace speculum::scene
