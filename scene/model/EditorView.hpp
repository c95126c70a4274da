#pragma once

#include <QJsonObject>
#include <glm/vec3.hpp>

namespace speculum::scene {

// The editor's own view saved with a project: the optional top-level "editorView" of the file (added in
// issue 16; older files have none and open in the scene camera). Where the editor looked from and at when
// the file was saved, so that it reopens there. Only the editor reads it: `speculum render`, the exports
// and the sweep use the scene camera. The rest of the view (up, field of view, near plane) is the scene
// camera's, as view::ViewCamera keeps it, and the far plane follows from the distance.
//
// Moving the view is not an edit: it pushes no undo step and does not mark the document modified; the
// editor puts its current view here when it saves (and autosaves).
struct EditorView {
    glm::dvec3 position{0.0, 0.0, 1.0};
    glm::dvec3 target{0.0, 0.0, -3.0};
    QJsonObject extra; // unknown fields inside "editorView", written back
    bool operator==(const EditorView&) const = default;
};

} // namespace speculum::scene
