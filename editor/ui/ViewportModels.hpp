#pragma once

#include "scene/import/ModelImport.hpp"
#include "scene/model/Warning.hpp"

#include <QDateTime>
#include <QObject>
#include <QString>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace speculum::scene {
class MeshLibrary;
class Scene;
} // namespace speculum::scene

namespace speculum::ui {

class ModelImportJob;

// Reads the model files a document references on worker threads, so that the viewport never reads one
// on the GUI thread: a project opened with a big model, a model changed on disk, a file that takes seconds
// to refuse (a node graph that unfolds into billions of nodes) or, should a reader regress, one that would
// block for good, would otherwise freeze the GUI and its autosave in paintGL.
//
// prepare() runs before anything asks the MeshLibrary for the scene's files: every referenced file that
// is new, or changed on disk (time and size), gets a ModelImportJob, and an empty stand-in in the library
// meanwhile (so the library, keyed the same way, does not read the file itself); the finished model
// replaces the stand-in and changed() asks for a repaint. A file that failed keeps its stand-in (the
// failure is cached, like the library's own) and its error; correct() puts the frame's warnings about such
// nodes right. Files that are not regular files are not read at all; their warning names what they are.
class ViewportModels : public QObject {
    Q_OBJECT

public:
    explicit ViewportModels(scene::MeshLibrary& meshes, QObject* parent = nullptr);
    ~ViewportModels() override;

    // Starts the reads the scene needs (a stat per referenced file when nothing changed).
    void prepare(const scene::Scene& scene);
    // A model read elsewhere (Import's worker) for the file as it is now.
    void adopt(const std::string& absolutePath, std::shared_ptr<const scene::ImportedModel> model);
    // The document was replaced (the library was cleared): forget everything; running reads are cancelled.
    void clear();
    bool isLoading() const;

    // The frame's warnings (scene::snapshot's) with those about nodes whose file is still loading or
    // failed replaced by what is true: the snapshot's MeshSkipped and ReflectorWithoutMesh of that node
    // and file give way to one MeshLoading or one MeshSkipped with the read's own error. Then come the
    // readers' notes of reads that ended since the last call (unless takePending is false: an export's
    // warnings, the viewport shows those).
    std::vector<scene::Warning> correct(std::vector<scene::Warning> warnings, bool takePending = true);

signals:
    void changed(); // a read ended: draw again

private:
    enum class State { Loading, Ready, Failed };
    struct Entry {
        QDateTime modified;
        qint64 size = -1;
        State state = State::Loading;
        std::string error;
        bool errorNamesFile = false; // the reader's errors do ("dag.gltf: the node graph ..."), a stat's not
        ModelImportJob* job = nullptr;
    };
    struct User {
        std::string node;
        std::string path;
    };
    void start(const std::string& path, Entry& entry);
    void finished(ModelImportJob* job);
    void retire(ModelImportJob* job);
    void need(const std::string& node, const std::string& path);

    scene::MeshLibrary& m_meshes;
    std::map<std::string, Entry> m_entries;
    std::vector<User> m_users;                     // of the last prepare()
    std::vector<scene::Warning> m_pendingWarnings; // of reads that ended, not shown yet
};

} // namespace speculum::ui
