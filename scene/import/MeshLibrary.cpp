#include "scene/import/MeshLibrary.hpp"

#include "base/FileKind.hpp"
#include "base/Printable.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/mesh/Teapot.hpp"
#include "scene/import/ModelImport.hpp"
#include "scene/import/ModelNodes.hpp"

#include <QFileInfo>
#include <memory>

namespace speculum::scene {

render::MeshHandle MeshLibrary::builtin(BuiltinMesh kind, int tessellation) {
    auto& slot = m_builtins[{kind, tessellation}];
    if (!slot) {
        switch (kind) {
        case BuiltinMesh::Teapot:
            slot = render::freezeMesh(render::makeTeapot(tessellation));
            break;
        case BuiltinMesh::Sphere:
            slot = render::freezeMesh(render::makeSphere(tessellation));
            break;
        case BuiltinMesh::Box:
            slot = render::freezeMesh(render::makeBox());
            break;
        case BuiltinMesh::Plane:
            slot = render::freezeMesh(render::makePlane(tessellation));
            break;
        }
    }
    return slot;
}

base::Result<MeshLibrary::FileEntry*> MeshLibrary::entry(const std::string& absolutePath,
                                                         std::vector<Warning>& warnings) {
    const QFileInfo info(QString::fromStdString(absolutePath));
    if (!info.isFile()) {
        // Not cached: the file may appear later (being copied in, or the user fixes the path on disk).
        m_files.erase(absolutePath);
        const base::Status regular = base::requireRegularFile(absolutePath);
        return base::Error{base::quoted(absolutePath) + ": " +
                           (regular ? std::string("no such file") : regular.error())};
    }
    const QDateTime modified = info.lastModified();
    const qint64 size = info.size();
    auto it = m_files.find(absolutePath);
    if (it == m_files.end() || it->second.modified != modified || it->second.size != size) {
        FileEntry fresh;
        fresh.modified = modified;
        fresh.size = size;
        std::vector<std::string> notes;
        base::Result<ImportedModel> imported = importModelFile(absolutePath, notes);
        for (const std::string& note : notes) {
            warnings.push_back(modelFileNote(absolutePath, note));
        }
        if (imported) {
            fresh.model = std::make_shared<const ImportedModel>(std::move(imported).value());
        } else {
            fresh.error = imported.error();
        }
        it = m_files.insert_or_assign(absolutePath, std::move(fresh)).first;
    }
    if (!it->second.model) {
        return base::Error{it->second.error};
    }
    return &it->second;
}

base::Result<std::shared_ptr<const ImportedModel>> MeshLibrary::model(const std::string& absolutePath,
                                                                      std::vector<Warning>& warnings) {
    auto found = entry(absolutePath, warnings);
    if (!found) {
        return base::Error{found.error()};
    }
    return found.value()->model;
}

base::Result<render::MeshHandle> MeshLibrary::file(const std::string& absolutePath,
                                                   std::vector<Warning>& warnings) {
    auto found = entry(absolutePath, warnings);
    if (!found) {
        return base::Error{found.error()};
    }
    FileEntry& e = *found.value();
    if (!e.flattened && e.flattenError.empty()) {
        // One part drawn once, untransformed (a PLY or STL scan): the part's mesh is the whole model.
        int placed = 0;
        render::MeshHandle only;
        detail::forEachPlacedPart(*e.model, [&](int part, const glm::dmat4& world) {
            ++placed;
            only = world == glm::dmat4(1.0) ? e.model->parts[part].mesh : nullptr;
        });
        if (placed == 1 && only) {
            e.flattened = only;
            return e.flattened;
        }
        auto flat = flattenModel(*e.model);
        if (flat) {
            e.flattened = render::freezeMesh(std::move(flat).value());
        } else {
            e.flattenError =
                base::quoted(QFileInfo(QString::fromStdString(absolutePath)).fileName().toStdString()) +
                ": " + flat.error();
        }
    }
    if (!e.flattened) {
        return base::Error{e.flattenError};
    }
    return e.flattened;
}

base::Result<render::MeshHandle> MeshLibrary::part(const std::string& absolutePath, int part,
                                                   std::vector<Warning>& warnings) {
    auto found = entry(absolutePath, warnings);
    if (!found) {
        return base::Error{found.error()};
    }
    const ImportedModel& model = *found.value()->model;
    const std::string name =
        base::quoted(QFileInfo(QString::fromStdString(absolutePath)).fileName().toStdString());
    if (part < 0 || part >= static_cast<int>(model.parts.size())) {
        return base::Error{name + ": part " + std::to_string(part) + " does not exist (the file has " +
                           std::to_string(model.parts.size()) + " parts, 0.." +
                           std::to_string(static_cast<int>(model.parts.size()) - 1) + ")"};
    }
    if (!model.parts[part].mesh) {
        return base::Error{name + ": part " + std::to_string(part) + " has no triangles"};
    }
    return model.parts[part].mesh;
}

base::Result<render::MeshHandle> MeshLibrary::get(const MeshComponent& mesh, std::vector<Warning>& warnings) {
    if (mesh.builtin) {
        return builtin(*mesh.builtin, mesh.tessellation);
    }
    if (mesh.part) {
        return part(mesh.file, *mesh.part, warnings);
    }
    return file(mesh.file, warnings);
}

void MeshLibrary::addModel(const std::string& absolutePath, std::shared_ptr<const ImportedModel> model) {
    const QFileInfo info(QString::fromStdString(absolutePath));
    if (!model || !info.isFile()) {
        return;
    }
    FileEntry fresh;
    fresh.modified = info.lastModified();
    fresh.size = info.size();
    fresh.model = std::move(model);
    m_files.insert_or_assign(absolutePath, std::move(fresh));
}

std::shared_ptr<const render::TextureImage> MeshLibrary::embeddedTexture(const std::string& name,
                                                                         std::vector<Warning>& warnings) {
    const std::size_t hash = name.rfind('#');
    if (hash == std::string::npos || hash == 0 || hash + 1 == name.size()) {
        return nullptr;
    }
    const std::string modelPath = name.substr(0, hash);
    if (!QFileInfo(QString::fromStdString(modelPath)).isFile() ||
        QFileInfo(QString::fromStdString(name)).isFile()) {
        return nullptr;
    }
    auto found = entry(modelPath, warnings);
    if (!found) {
        return nullptr;
    }
    const auto& textures = found.value()->model->embeddedTextures;
    const auto it = textures.find(name);
    return it == textures.end() ? nullptr : it->second;
}

render::Bounds MeshLibrary::bounds(const render::MeshHandle& mesh) {
    if (!mesh) {
        return {};
    }
    auto it = m_bounds.find(mesh.get());
    if (it != m_bounds.end() && it->second.mesh.lock() == mesh) {
        return it->second.bounds;
    }
    // Drop entries of meshes that are gone, so the map does not grow with every re-import.
    for (auto stale = m_bounds.begin(); stale != m_bounds.end();) {
        stale = stale->second.mesh.expired() ? m_bounds.erase(stale) : std::next(stale);
    }
    const render::Bounds b = render::computeBounds(*mesh);
    m_bounds[mesh.get()] = {mesh, b};
    return b;
}

void MeshLibrary::clear() {
    m_builtins.clear();
    m_files.clear();
    m_bounds.clear();
}

} // namespace speculum::scene
