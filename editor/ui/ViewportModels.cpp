#include "editor/ui/ViewportModels.hpp"

#include "base/FileKind.hpp"
#include "base/Printable.hpp"
#include "editor/ui/ModelImportJob.hpp"
#include "scene/import/MeshLibrary.hpp"
#include "scene/model/Scene.hpp"

#include <QDir>
#include <QFileInfo>
#include <algorithm>

namespace speculum::ui {

namespace {

std::string fileName(const std::string& path) {
    return QFileInfo(QString::fromStdString(path)).fileName().toStdString();
}

// The stand-in an unread or failed file leaves in the library makes the snapshot say what is not true
// ("no triangles", "part 2 does not exist"), and of a reflector on that node that it has no mesh.
bool isFromStandIn(const scene::Warning& warning, const std::string& node, const std::string& file) {
    return (warning.code == scene::WarningCode::MeshSkipped ||
            warning.code == scene::WarningCode::ReflectorWithoutMesh) &&
           warning.node == node && warning.file == file;
}

} // namespace

ViewportModels::ViewportModels(scene::MeshLibrary& meshes, QObject* parent)
    : QObject(parent)
    , m_meshes(meshes) {}

// The jobs are children: their destructors cancel them and wait for their workers.
ViewportModels::~ViewportModels() = default;

bool ViewportModels::isLoading() const {
    return std::any_of(m_entries.begin(), m_entries.end(),
                       [](const auto& e) { return e.second.state == State::Loading; });
}

void ViewportModels::retire(ModelImportJob* job) {
    // Not waited for here (that would be the GUI thread waiting on a read): it ends on its own.
    disconnect(job, nullptr, this, nullptr);
    job->cancel();
    connect(job, &ModelImportJob::finished, job, &QObject::deleteLater);
}

void ViewportModels::clear() {
    for (auto& [path, entry] : m_entries) {
        if (entry.job) {
            retire(entry.job);
        }
    }
    m_entries.clear();
    m_users.clear();
    m_pendingWarnings.clear();
}

void ViewportModels::prepare(const scene::Scene& scene) {
    m_users.clear();
    const bool hasProject = !scene.projectPath().isEmpty();
    const QDir projectDir = QFileInfo(scene.projectPath()).absoluteDir();
    // As scene::snapshot resolves them: relative paths (set by code) against the project's folder.
    auto absolute = [&](const std::string& path) {
        if (path.empty() || !hasProject || !QDir::isRelativePath(QString::fromStdString(path))) {
            return path;
        }
        return QDir::cleanPath(projectDir.absoluteFilePath(QString::fromStdString(path))).toStdString();
    };
    scene.forEachNode([&](const scene::Node& node) {
        const scene::NodeData& d = node.data();
        if (d.mesh && !d.mesh->builtin && !d.mesh->file.empty()) {
            need(d.name, absolute(d.mesh->file));
        }
        if (d.material) {
            // "/abs/model.glb#*0": a texture embedded in a model file, which the library reads for it.
            for (const render::TextureSource* texture :
                 {&d.material->texture, &d.material->emissionTexture, &d.material->normalTexture}) {
                const std::string path = absolute(texture->path);
                const std::size_t hash = path.rfind('#');
                if (hash != std::string::npos && hash > 0 &&
                    !QFileInfo(QString::fromStdString(path)).exists()) {
                    need(d.name, path.substr(0, hash));
                }
            }
        }
    });
}

void ViewportModels::need(const std::string& node, const std::string& path) {
    m_users.push_back({node, path});
    const QFileInfo info(QString::fromStdString(path)); // a stat: it cannot block, even on a FIFO
    auto it = m_entries.find(path);
    if (!info.isFile()) {
        if (it != m_entries.end() && it->second.job) {
            retire(it->second.job);
        }
        const base::Status regular = base::requireRegularFile(path);
        if (!info.exists() || regular) {
            // Missing: the library says so itself, and reads nothing.
            if (it != m_entries.end()) {
                m_entries.erase(it);
            }
            return;
        }
        // A FIFO, a device, a folder: never read; the library would only say "no such file".
        Entry& e = m_entries[path];
        e = Entry{};
        e.state = State::Failed;
        e.error = regular.error();
        return;
    }
    if (it != m_entries.end() && it->second.size == info.size() &&
        it->second.modified == info.lastModified()) {
        return; // loading, loaded or failed as the file is now
    }
    Entry& e = m_entries[path];
    if (e.job) {
        retire(e.job); // the file changed under it
    }
    e = Entry{};
    e.modified = info.lastModified();
    e.size = info.size();
    start(path, e);
}

void ViewportModels::start(const std::string& path, Entry& entry) {
    // The stand-in, keyed by the file as it is now, keeps the library from reading the file itself.
    m_meshes.addModel(path, std::make_shared<const scene::ImportedModel>());
    auto* job = new ModelImportJob(QString::fromStdString(path), this);
    connect(job, &ModelImportJob::finished, this, [this, job] { finished(job); });
    entry.state = State::Loading;
    entry.job = job;
    job->start();
}

void ViewportModels::finished(ModelImportJob* job) {
    job->deleteLater();
    const auto it = std::find_if(m_entries.begin(), m_entries.end(),
                                 [job](const auto& e) { return e.second.job == job; });
    if (it == m_entries.end()) {
        return;
    }
    Entry& e = it->second;
    e.job = nullptr;
    ModelImportJob::Output out = job->takeOutput();
    for (const auto& w : out.warnings) {
        m_pendingWarnings.push_back(
            scene::modelFileNote(it->first, base::quoted(fileName(it->first)) + ": " + w));
    }
    if (out.model) {
        m_meshes.addModel(it->first,
                          std::make_shared<const scene::ImportedModel>(std::move(out.model).value()));
        e.state = State::Ready;
    } else {
        e.state = State::Failed;
        e.error = out.model.error();
        e.errorNamesFile = true;
    }
    emit changed();
}

void ViewportModels::adopt(const std::string& absolutePath,
                           std::shared_ptr<const scene::ImportedModel> model) {
    const QFileInfo info(QString::fromStdString(absolutePath));
    if (!model || !info.isFile()) {
        return;
    }
    Entry& e = m_entries[absolutePath];
    if (e.job) {
        retire(e.job);
    }
    e = Entry{};
    e.modified = info.lastModified();
    e.size = info.size();
    e.state = State::Ready;
    m_meshes.addModel(absolutePath, std::move(model));
}

std::vector<scene::Warning> ViewportModels::correct(std::vector<scene::Warning> warnings, bool takePending) {
    std::vector<scene::Warning> own;
    for (const User& user : m_users) {
        const auto it = m_entries.find(user.path);
        if (it == m_entries.end() || it->second.state == State::Ready) {
            continue;
        }
        std::erase_if(warnings,
                      [&](const scene::Warning& w) { return isFromStandIn(w, user.node, user.path); });
        const Entry& entry = it->second;
        const std::string errorPrefix =
            entry.errorNamesFile ? std::string() : base::quoted(fileName(user.path)) + ": ";
        scene::Warning warning =
            entry.state == State::Loading
                ? scene::meshLoading(user.node, user.path)
                : scene::meshSkipped(user.node, user.path, errorPrefix + base::printable(entry.error, 200));
        // A node may name the file twice (its mesh and an embedded texture): one warning says it.
        const bool said = std::any_of(own.begin(), own.end(), [&](const scene::Warning& w) {
            return w.code == warning.code && w.node == warning.node && w.file == warning.file;
        });
        if (!said) {
            own.push_back(std::move(warning));
        }
    }
    warnings.insert(warnings.end(), own.begin(), own.end());
    if (takePending) {
        warnings.insert(warnings.end(), m_pendingWarnings.begin(), m_pendingWarnings.end());
        m_pendingWarnings.clear();
    }
    return warnings;
}

} // namespace speculum::ui
