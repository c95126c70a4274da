#pragma once

#include <QList>
#include <QWidget>

class QAction;
class QTreeView;
class QMenu;

namespace speculum::view {
class Selection;
}

namespace speculum::ui {

class SceneTreeModel;

// The Scene dock: the tree of nodes (SceneTreeModel) kept in step with the shared Selection both ways,
// with in-place rename (F2 or double-click), drag-and-drop reparenting and a context menu with the
// window's edit actions.
class SceneTreePanel : public QWidget {
    Q_OBJECT

public:
    SceneTreePanel(SceneTreeModel& model, view::Selection& selection, QWidget* parent = nullptr);

    QTreeView& view() { return *m_view; }
    // The actions shown in the context menu (null entries become separators); the Add menu is appended.
    void setContextActions(QList<QAction*> actions, QMenu* addMenu);
    // Starts renaming the selected node in place.
    void editSelected();

private:
    void syncFromSelection();
    void syncToSelection();
    void showContextMenu(const QPoint& pos);

    SceneTreeModel& m_model;
    view::Selection& m_selection;
    QTreeView* m_view = nullptr;
    QList<QAction*> m_actions;
    QMenu* m_addMenu = nullptr;
    bool m_syncing = false;
};

} // namespace speculum::ui
