#include "editor/document/DocumentSession.hpp"

#include "scene/project/ProjectFile.hpp"

#include <QFileInfo>
#include <QUndoStack>

namespace speculum::document {

DocumentSession::DocumentSession(QObject* parent)
    : QObject(parent)
    , m_scene(new scene::Scene(this))
    , m_undoStack(new QUndoStack(this)) {
    // Every reset is a new document (New, Open, Restore): its meshes start from nothing, and before the
    // scene's sceneReset, so whoever draws the new scene finds no mesh of the old one.
    connect(m_scene, &scene::Scene::aboutToReset, this, [this] { m_meshes = scene::MeshLibrary(); });
}

DocumentSession::~DocumentSession() {
    // The commands refer to the scene: they go first.
    delete m_undoStack;
    m_undoStack = nullptr;
}

bool DocumentSession::isModified() const {
    return !m_undoStack->isClean() || m_restoredUnsaved;
}

void DocumentSession::clearHistory(bool unsaved) {
    m_undoStack->clear();
    m_undoStack->setClean();
    m_restoredUnsaved = unsaved;
}

void DocumentSession::replace(scene::SceneData data, const QString& projectPath, bool unsaved) {
    m_scene->reset(std::move(data));
    m_scene->setProjectPath(projectPath);
    clearHistory(unsaved);
    m_fileWatch.track(projectPath); // a restored document: changes from here on are someone else's
}

base::Status DocumentSession::open(const QString& absolutePath, std::vector<std::string>& warnings) {
    base::Status status = scene::openProject(*m_scene, absolutePath, warnings);
    if (status) {
        clearHistory(false); // the old document's commands refer to nodes that no longer exist
        m_fileWatch.track(absolutePath);
    }
    return status;
}

base::Status DocumentSession::save(const QString& absolutePath, DiskChanges overwrite) {
    if (overwrite == DiskChanges::Refuse && absolutePath == m_fileWatch.path() && m_fileWatch.changed()) {
        return base::Error{QFileInfo(absolutePath).fileName().toStdString() +
                           " changed on disk since this editor last read or saved it (another editor or "
                           "program saved it); reload it, overwrite it with this version, or save as "
                           "another file"};
    }
    base::Status status = scene::saveProject(*m_scene, absolutePath);
    if (status) {
        m_scene->setProjectPath(absolutePath);
        m_undoStack->setClean();
        m_restoredUnsaved = false;
        m_fileWatch.track(absolutePath);
    }
    return status;
}

} // namespace speculum::document
