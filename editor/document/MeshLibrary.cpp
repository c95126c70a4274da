#include "editor/document/MeshLibrary.hpp"

#include "editor/document/ModelImport.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/mesh/Teapot.hpp"

#include <QFileInfo>
#include <memory>

namespace speculum::document {

render::MeshHandle MeshLibrary::builtin(BuiltinMesh kind, int tessellation) {
    auto& slot = m_builtins[{kind, tessellation}];
    if (!slot) {
        switch (kind) {
        case BuiltinMesh::Teapot:
            slot = std::make_shared<const render::MeshData>(render::makeTeapot(tessellation));
            break;
        case BuiltinMesh::Sphere:
            slot = std::make_shared<const render::MeshData>(render::makeSphere(tessellation));
            break;
        case BuiltinMesh::Box:
            slot = std::make_shared<const render::MeshData>(render::makeBox());
            break;
        case BuiltinMesh::Plane:
            slot = std::make_shared<const render::MeshData>(render::makePlane(tessellation));
            break;
        }
    }
    return slot;
}

render::Result<render::MeshHandle> MeshLibrary::file(const std::string& absolutePath,
                                                     std::vector<std::string>& warnings) {
    const QFileInfo info(QString::fromStdString(absolutePath));
    if (!info.isFile()) {
        // Not cached: the file may appear later (being copied in, or the user fixes the path on disk).
        m_files.erase(absolutePath);
        return render::Error{absolutePath + ": no such file"};
    }
    const QDateTime modified = info.lastModified();
    const qint64 size = info.size();
    auto it = m_files.find(absolutePath);
    if (it == m_files.end() || it->second.modified != modified || it->second.size != size) {
        FileEntry entry{modified, size, nullptr, {}};
        render::Result<render::MeshData> imported = importModel(absolutePath, warnings);
        if (imported) {
            entry.mesh = std::make_shared<const render::MeshData>(std::move(imported).value());
        } else {
            entry.error = imported.error();
        }
        it = m_files.insert_or_assign(absolutePath, std::move(entry)).first;
    }
    if (!it->second.mesh) {
        return render::Error{it->second.error};
    }
    return it->second.mesh;
}

render::Result<render::MeshHandle> MeshLibrary::get(const MeshComponent& mesh,
                                                    std::vector<std::string>& warnings) {
    if (mesh.builtin) {
        return builtin(*mesh.builtin, mesh.tessellation);
    }
    return file(mesh.file, warnings);
}

void MeshLibrary::clear() {
    m_builtins.clear();
    m_files.clear();
}

} // namespace speculum::document
