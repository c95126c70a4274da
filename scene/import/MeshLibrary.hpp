#pragma once

#include "base/Result.hpp"
#include "render/image/Image.hpp"
#include "render/mesh/MeshData.hpp"
#include "scene/import/ModelImport.hpp"
#include "scene/model/SceneData.hpp"
#include "scene/model/Warning.hpp"

#include <QDateTime>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace speculum::scene {

// CPU meshes for snapshots, cached so that a node's MeshHandle is the same pointer frame after frame (the
// renderer keys its GPU buffers on that identity). Built-ins are cached by (kind, tessellation); files by
// absolute path, modification time and size, so editing a model on disk re-imports it on the next frame.
// A file is read once into an ImportedModel (parts, materials, embedded textures); its flattened mesh is
// built on first use and cached with it. Failed imports are cached too (same key), so a broken file costs
// one attempt, not one per frame.
// Not thread-safe; one per document or per CLI run (a worker thread imports with importModelFile and
// hands the result over with addModel on the owning thread).
class MeshLibrary {
public:
    render::MeshHandle builtin(BuiltinMesh kind, int tessellation);

    // The whole file (read on first use). The reader's notes on it are appended as ModelFileNote warnings
    // the first time a file (version) is imported.
    base::Result<std::shared_ptr<const ImportedModel>> model(const std::string& absolutePath,
                                                             std::vector<Warning>& warnings);

    // Every part of the file placed by its node tree, as one mesh.
    base::Result<render::MeshHandle> file(const std::string& absolutePath, std::vector<Warning>& warnings);

    // One part of the file in its own coordinates; an out-of-range part is an error naming the part count.
    base::Result<render::MeshHandle> part(const std::string& absolutePath, int part,
                                          std::vector<Warning>& warnings);

    // Any of the above, by the component (file with `part` → part, without → flattened).
    base::Result<render::MeshHandle> get(const MeshComponent& mesh, std::vector<Warning>& warnings);

    // Takes a model imported elsewhere (a worker thread) for `absolutePath`, keyed by the file's current
    // time and size, so the next get() does not read it again.
    void addModel(const std::string& absolutePath, std::shared_ptr<const ImportedModel> model);

    // A texture embedded in a model file, by its name "/abs/model.glb#*0" (the model is imported if it is
    // not cached yet). Null when the name is not such a texture (no '#', the part before it is not a
    // model file, or the whole name is an existing file) or the model has no texture by that name.
    std::shared_ptr<const render::TextureImage> embeddedTexture(const std::string& name,
                                                                std::vector<Warning>& warnings);

    // Bounds of a mesh handed out (or any mesh), computed once per mesh and cached by its identity.
    render::Bounds bounds(const render::MeshHandle& mesh);

    // Drops everything; handles already handed out stay valid (shared ownership).
    void clear();
    std::size_t size() const { return m_builtins.size() + m_files.size(); }

private:
    struct FileEntry {
        QDateTime modified;
        qint64 size = -1;
        std::shared_ptr<const ImportedModel> model; // null when the import failed
        render::MeshHandle flattened;               // built on first use
        std::string flattenError;
        std::string error;
    };
    struct BoundsEntry {
        std::weak_ptr<const render::MeshData> mesh;
        render::Bounds bounds;
    };
    base::Result<FileEntry*> entry(const std::string& absolutePath, std::vector<Warning>& warnings);

    std::map<std::pair<BuiltinMesh, int>, render::MeshHandle> m_builtins;
    std::map<std::string, FileEntry> m_files;
    std::unordered_map<const render::MeshData*, BoundsEntry> m_bounds;
};

} // namespace speculum::scene
