#pragma once

#include "base/Result.hpp"
#include "scene/model/Scene.hpp"

#include <QByteArray>
#include <QString>
#include <QUndoStack>
#include <vector>

namespace speculum::document {

// Copy and paste of nodes, between documents as within one. What is copied is a small project file
// holding the nodes' subtrees (docs/scene-format.md), so it carries everything a node has, unknown fields
// included, and can be pasted into a text editor too. Its paths (models, textures) are absolute: the
// document it is pasted into may live in another folder. The MIME type of the editor's clipboard data:
inline constexpr const char* kNodesMimeType = "application/x-speculum-nodes";

// The nodes under `roots` (a root under another root goes with that one), in tree order.
QByteArray copyNodes(const scene::Scene& scene, const std::vector<scene::NodeId>& roots);

struct Pasted {
    std::vector<scene::NodeId> nodes; // the pasted roots, in order
};

// Adds the nodes of `copied` (what copyNodes made, or any project file's text) under `parent` (kNoNode: the
// top level), where they were, with names made unique: one undo step, "Paste “A”" or "Paste 3 nodes". The
// error names what is wrong with the text; nothing is added then.
base::Result<Pasted> pasteNodes(scene::Scene& scene, QUndoStack& undo, const QByteArray& copied,
                                scene::NodeId parent = scene::kNoNode);

} // namespace speculum::document
