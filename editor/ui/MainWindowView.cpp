// The main window's part in the editor view: the view presets and guides, the keyboard handed back to the
// viewport after a field (FieldKeys), the vertical orbit preference, and the project's saved editor view
// ("editorView"), which is put in place when a document opens and taken from the viewport when it is saved.
// Moving the view is never an edit.
#include "editor/ui/FieldKeys.hpp"
#include "editor/ui/MainWindow.hpp"
#include "editor/ui/ViewPresetActions.hpp"
#include "editor/ui/Viewport.hpp"
#include "scene/model/Scene.hpp"
#include "scene/model/SceneData.hpp"

namespace speculum::ui {

void MainWindow::createViewPlacement() {
    addViewPresetActions(*this, m_viewMenu, *m_viewport);
    new FieldKeys(*this, *m_viewport);
    // The viewport has put the view back on the scene camera already (its own connection to the reset
    // runs first); a saved editor view takes its place.
    connect(m_viewport, &Viewport::viewReset, this, [this] {
        if (const auto& saved = scene().editorView()) {
            m_viewport->placeView(saved->position, saved->target);
        }
    });
}

void MainWindow::rememberEditorView() {
    const auto [position, target] = m_viewport->viewPositionTarget();
    scene::EditorView view;
    view.position = position;
    view.target = target;
    // The file's unknown fields of the view stay with the scene (SceneData::unknown), written back.
    scene().setEditorView(view); // the scene drops a view its file could not hold
}

} // namespace speculum::ui
