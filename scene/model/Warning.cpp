#include "scene/model/Warning.hpp"

#include "base/Printable.hpp"

#include <QFileInfo>

namespace speculum::scene {

namespace {

std::string aboutNode(const std::string& node, const std::string& what) {
    return "node " + base::quoted(node) + ": " + what;
}

} // namespace

Warning meshSkipped(const std::string& node, const std::string& file, const std::string& reason) {
    return {WarningCode::MeshSkipped, node, file, aboutNode(node, "mesh skipped: " + reason)};
}

Warning meshLoading(const std::string& node, const std::string& file) {
    const std::string name = QFileInfo(QString::fromStdString(file)).fileName().toStdString();
    return {WarningCode::MeshLoading, node, file,
            aboutNode(node, "mesh loading: " + base::quoted(name) + "...")};
}

Warning reflectorWithoutMesh(const std::string& node, const std::string& file) {
    return {WarningCode::ReflectorWithoutMesh, node, file,
            aboutNode(node, "reflector skipped: it needs a mesh on the same node")};
}

Warning modelFileNote(const std::string& file, const std::string& note) {
    return {WarningCode::ModelFileNote, {}, file, note};
}

std::vector<std::string> messages(const std::vector<Warning>& warnings) {
    std::vector<std::string> out;
    out.reserve(warnings.size());
    for (const Warning& w : warnings) {
        out.push_back(w.message);
    }
    return out;
}

} // namespace speculum::scene
