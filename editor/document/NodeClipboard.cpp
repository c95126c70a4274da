#include "editor/document/NodeClipboard.hpp"

#include "editor/document/Commands.hpp"
#include "editor/document/EditTransaction.hpp"
#include "editor/document/NodeFactory.hpp"
#include "scene/project/ProjectFile.hpp"

#include <QDir>
#include <algorithm>

namespace speculum::document {

namespace {

// Paths in the copy are written relative to the root folder and read back against it: absolute wherever
// the copy is pasted.
QDir pathBase() {
    return QDir::root();
}

bool underAnother(const scene::Scene& scene, scene::NodeId id, const std::vector<scene::NodeId>& roots) {
    for (scene::NodeId other : roots)
        if (other != id && scene.isAncestor(other, id))
            return true;
    return false;
}

} // namespace

QByteArray copyNodes(const scene::Scene& scene, const std::vector<scene::NodeId>& roots) {
    scene::SceneData copied;
    scene.forEachNode([&](const scene::Node& node) {
        const bool selected = std::find(roots.begin(), roots.end(), node.id()) != roots.end();
        if (selected && !underAnother(scene, node.id(), roots))
            copied.nodes.push_back(node.toTree());
    });
    return scene::serializeProject(copied, pathBase());
}

base::Result<Pasted> pasteNodes(scene::Scene& scene, QUndoStack& undo, const QByteArray& copied,
                                scene::NodeId parent) {
    std::vector<std::string> warnings;
    auto data = scene::parseProject(copied, pathBase(), warnings);
    if (!data)
        return base::Error{"the clipboard holds no speculum nodes: " + data.error()};
    if (data->nodes.empty())
        return base::Error{"the clipboard holds no nodes"};
    EditTransaction edit(
        undo, data->nodes.size() > 1 ? QStringLiteral("Paste %1 nodes").arg(data->nodes.size()) : QString());
    Pasted pasted;
    for (scene::NodeTree& tree : data->nodes) {
        // One at a time: each name is made unique against what is pasted before.
        tree.data.name = uniqueName(scene, tree.data.name);
        const QString name = QString::fromStdString(tree.data.name);
        auto* command = new AddNodeCommand(scene, std::move(tree), parent);
        command->setText(QStringLiteral("Paste \u201c%1\u201d").arg(name));
        edit.push(command);
        pasted.nodes.push_back(command->nodeId());
    }
    edit.commit();
    return pasted;
}

} // namespace speculum::document
