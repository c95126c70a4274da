#pragma once

#include "base/Result.hpp"
#include "render/image/Image.hpp"
#include "render/mesh/MeshData.hpp"
#include "scene/model/SceneData.hpp"

#include <atomic>
#include <functional>
#include <glm/mat4x4.hpp>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace speculum::scene {

// A model file as speculum keeps it: its meshes ("parts", Assimp's scene order), its materials already
// converted to speculum's, the textures embedded in it, and its node tree. One Assimp read gives all of it;
// MeshLibrary caches it per file, the editor turns it into scene nodes (modelNodeTree), and a whole-file
// mesh component draws flattenModel() of it.
struct ImportedPart {
    std::string name;        // the mesh's own name in the file, or "" when it has none
    render::MeshHandle mesh; // repaired, in the mesh's own coordinates, the file's unit scale not applied
    int material = -1;       // index into ImportedModel::materials, -1 for the default material
};

struct ImportedNode {
    std::string name;
    glm::dmat4 local{1.0};  // relative to the parent node
    std::vector<int> parts; // indices into ImportedModel::parts drawn at this node
    std::vector<ImportedNode> children;
};

struct ImportedModel {
    std::vector<ImportedPart> parts;
    std::vector<MaterialComponent> materials; // texture paths absolute, embedded ones "<model path>#<name>"
    // Embedded textures by the name the materials use ("<model path>#*0"), decoded once.
    std::map<std::string, std::shared_ptr<const render::TextureImage>> embeddedTextures;
    ImportedNode root;      // the file's root node; root.local includes unitScale
    double unitScale = 1.0; // scene units (metres) per file unit: FBX UnitScaleFactor, 1 for glTF (metres)
    render::Bounds bounds;  // of every part placed by the node tree, unit scale included
};

// What a long import reports and how it is stopped: `progress` (0..1, with a short phase name) may be
// called from the importing thread; `cancel` is polled between steps, and a cancelled import returns the
// error "cancelled".
struct ImportControl {
    std::function<void(double fraction, const char* phase)> progress;
    const std::atomic<bool>* cancel = nullptr;
};

// Reads any format Assimp knows (OBJ+MTL, glTF 2 / .glb, FBX, Collada, PLY, STL, ...) with its node
// tree, parts, materials and textures. Points and lines are dropped; each part goes through
// render::repairMesh() (normals, degenerate triangles) and is welded. What the file has that speculum
// cannot show (a second uv set, clearcoat, metallic-roughness textures, ...) is named once in `warnings`,
// each prefixed with the file name. Errors name the file and the reason ("model.obj: file is empty").
// Only regular files are read. Never throws; safe to call from a worker thread.
// The file checks run here; Assimp's read and the conversion run in a child process limited to
// modelImportCpuLimit() seconds of CPU, so that a reader that crashes, hangs or exhausts memory ends in a
// one-line refusal ("model.ply: the model reader crashed on this file (SIGSEGV); ...") and the editor
// keeps running.
base::Result<ImportedModel> importModelFile(const std::string& path, std::vector<std::string>& warnings,
                                            const ImportControl& control = {});

// CPU seconds one model read may take before it is stopped (default kDefaultModelImportCpuSeconds,
// generous: a multi-million-triangle FBX takes a few). Tests and the fuzzer set a low one.
inline constexpr int kDefaultModelImportCpuSeconds = 600;
void setModelImportCpuLimit(int seconds);
int modelImportCpuLimit();

// Every part placed by the node tree (unit scale included) as one mesh: what a mesh component with a file
// and no `part` draws.
base::Result<render::MeshData> flattenModel(const ImportedModel& model);

// Reads a file as one flattened triangle mesh (importModelFile + flattenModel).
base::Result<render::MeshData> importModel(const std::string& path, std::vector<std::string>& warnings);

// The model as scene nodes: one node per file node (name, transform; the root carries the unit scale),
// and under it one child per part with `mesh: {file, part}` and the part's material. `path` is the
// absolute path the mesh components name.
// Transforms with shear cannot be written as translate/rotate/scale: they are approximated and named in
// `warnings` when given.
NodeTree modelNodeTree(const ImportedModel& model, const std::string& path, const std::string& rootName,
                       std::vector<std::string>* warnings = nullptr);

} // namespace speculum::scene
