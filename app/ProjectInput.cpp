#include "app/ProjectInput.hpp"

#include "editor/document/ProjectFile.hpp"
#include "editor/document/Snapshot.hpp"

#include <QFileInfo>
#include <iostream>

namespace speculum::app {

void printWarnings(const std::vector<std::string>& warnings) {
    for (const std::string& w : warnings)
        std::cerr << "speculum: warning: " << w << "\n";
}

render::Status loadProjectScene(const std::string& project, document::Scene& scene) {
    const QString path = QString::fromStdString(project);
    const QFileInfo info(path);
    if (!info.exists())
        return render::Error{project + ": no such file"};
    if (!info.isFile())
        return render::Error{project + ": not a file"};
    std::vector<std::string> warnings;
    if (render::Status opened = document::openProject(scene, path, warnings); !opened)
        return render::Error{project + ": " + opened.error()};
    printWarnings(warnings);
    return render::Done{};
}

render::Result<ProjectFrame> loadProjectFrame(const std::string& project, double time) {
    document::Scene scene;
    if (render::Status opened = loadProjectScene(project, scene); !opened)
        return render::Error{opened.error()};
    ProjectFrame frame;
    frame.meshes = std::make_unique<document::MeshLibrary>();
    std::vector<std::string> warnings;
    frame.input = document::snapshot(scene, time, *frame.meshes, warnings);
    printWarnings(warnings);
    scene.forEachNode([&](const document::Node& node) {
        const auto& mesh = node.data().mesh;
        if (mesh && mesh->builtin == document::BuiltinMesh::Teapot)
            frame.teapotTessellations.insert(mesh->tessellation);
    });
    return frame;
}

} // namespace speculum::app
