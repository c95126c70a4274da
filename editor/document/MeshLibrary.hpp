#pragma once

#include "editor/document/SceneData.hpp"
#include "render/Result.hpp"
#include "render/mesh/MeshData.hpp"

#include <QDateTime>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace speculum::document {

// CPU meshes for snapshots, cached so that a node's MeshHandle is the same pointer frame after frame (the
// renderer keys its GPU buffers on that identity). Built-ins are cached by (kind, tessellation); files by
// absolute path and modification time, so editing a model on disk re-imports it on the next frame. Failed
// imports are cached too (same key), so a broken file costs one attempt, not one per frame.
// Not thread-safe; one per document or per CLI run.
class MeshLibrary {
public:
    render::MeshHandle builtin(BuiltinMesh kind, int tessellation);

    // Import warnings are appended the first time a file (version) is imported.
    render::Result<render::MeshHandle> file(const std::string& absolutePath,
                                            std::vector<std::string>& warnings);

    // Either of the above, by the component.
    render::Result<render::MeshHandle> get(const MeshComponent& mesh, std::vector<std::string>& warnings);

    // Drops everything; handles already handed out stay valid (shared ownership).
    void clear();
    std::size_t size() const { return m_builtins.size() + m_files.size(); }

private:
    struct FileEntry {
        QDateTime modified;
        qint64 size = -1;
        render::MeshHandle mesh; // null when the import failed
        std::string error;
    };
    std::map<std::pair<BuiltinMesh, int>, render::MeshHandle> m_builtins;
    std::map<std::string, FileEntry> m_files;
};

} // namespace speculum::document
