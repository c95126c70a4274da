#pragma once

#include "base/Result.hpp"
#include "editor/document/ProjectFileWatch.hpp"
#include "scene/import/MeshLibrary.hpp"
#include "scene/model/Scene.hpp"

#include <QObject>
#include <QString>
#include <string>
#include <vector>

class QUndoStack;

namespace speculum::document {

// The open document as the editor holds it: the scene, its undo history, and the meshes it is drawn and
// picked with (the CPU mesh cache the viewport, exports and imports share, so that a model read once is
// not read again). New, Open and Restore replace the document in place: the scene is reset, the history
// cleared, and the mesh library replaced by an empty one before anyone sees the new scene (the references
// handed out stay valid; the meshes of the old document are let go).
class DocumentSession : public QObject {
    Q_OBJECT

public:
    explicit DocumentSession(QObject* parent = nullptr);
    ~DocumentSession() override;

    scene::Scene& scene() { return *m_scene; }
    const scene::Scene& scene() const { return *m_scene; }
    QUndoStack& undoStack() { return *m_undoStack; }
    scene::MeshLibrary& meshes() { return m_meshes; }

    // Unsaved changes: edits since the last save, or a document restored from a recovery file.
    bool isModified() const;

    // The document becomes `data` titled `projectPath` (empty: untitled), with no history. `unsaved`: it
    // counts as modified until saved (a restored recovery file).
    void replace(scene::SceneData data, const QString& projectPath, bool unsaved = false);
    // Opens a project file; on failure the open document stays exactly as it was. Load warnings are appended.
    base::Status open(const QString& absolutePath, std::vector<std::string>& warnings);
    // Writes the document; on success the file becomes the document's and the history is clean. Saving
    // over the document's own file after someone else changed it on disk is refused (the error says so)
    // unless `overwrite` is DiskChanges::Overwrite: the user chose to keep this version.
    enum class DiskChanges { Refuse, Overwrite };
    base::Status save(const QString& absolutePath, DiskChanges overwrite = DiskChanges::Refuse);
    // The document's file on disk is no longer what this editor last read or wrote (another editor or
    // program saved it); fileWatch().changedOnDisk says so as it happens.
    bool changedOnDisk() const { return m_fileWatch.changed(); }
    ProjectFileWatch& fileWatch() { return m_fileWatch; }

private:
    void clearHistory(bool unsaved);

    scene::Scene* m_scene = nullptr;   // QObject child
    QUndoStack* m_undoStack = nullptr; // QObject child
    scene::MeshLibrary m_meshes;
    bool m_restoredUnsaved = false;
    ProjectFileWatch m_fileWatch;
};

} // namespace speculum::document
