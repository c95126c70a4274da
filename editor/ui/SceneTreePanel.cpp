#include "editor/ui/SceneTreePanel.hpp"

#include "editor/ui/SceneTreeModel.hpp"
#include "editor/view/Selection.hpp"

#include <QHeaderView>
#include <QMenu>
#include <QTreeView>
#include <QVBoxLayout>
#include <algorithm>
#include <vector>

namespace speculum::ui {

SceneTreePanel::SceneTreePanel(SceneTreeModel& model, view::Selection& selection, QWidget* parent)
    : QWidget(parent)
    , m_model(model)
    , m_selection(selection) {
    m_view = new QTreeView(this);
    m_view->setObjectName(QStringLiteral("sceneTree"));
    m_view->setModel(&model);
    m_view->header()->hide();
    // Ctrl+click adds or removes a node, Shift+click a range, as in other editors.
    m_view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_view->setEditTriggers(QAbstractItemView::EditKeyPressed | QAbstractItemView::DoubleClicked);
    m_view->setDragDropMode(QAbstractItemView::InternalMove);
    m_view->setDefaultDropAction(Qt::MoveAction);
    m_view->setDragEnabled(true);
    m_view->setAcceptDrops(true);
    m_view->setDropIndicatorShown(true);
    m_view->setContextMenuPolicy(Qt::CustomContextMenu);
    m_view->setUniformRowHeights(true);
    m_view->setIconSize(QSize(18, 18));

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_view);

    connect(m_view->selectionModel(), &QItemSelectionModel::currentChanged, this,
            &SceneTreePanel::syncToSelection);
    connect(m_view->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &SceneTreePanel::syncToSelection);
    connect(&selection, &view::Selection::changed, this, &SceneTreePanel::syncFromSelection);
    connect(m_view, &QTreeView::customContextMenuRequested, this, &SceneTreePanel::showContextMenu);
    // Rows come back after a move or an undo: show the selection again, and new rows' parents open.
    connect(&model, &QAbstractItemModel::rowsInserted, this, [this](const QModelIndex& parent) {
        if (parent.isValid()) {
            m_view->expand(parent);
        }
        syncFromSelection();
    });
    connect(&model, &QAbstractItemModel::rowsRemoved, this, &SceneTreePanel::syncFromSelection);
    connect(&model, &QAbstractItemModel::modelReset, this, [this] {
        m_view->expandAll();
        syncFromSelection();
    });
    m_view->expandAll();
}

void SceneTreePanel::setContextActions(QList<QAction*> actions, QMenu* addMenu) {
    m_actions = std::move(actions);
    m_addMenu = addMenu;
}

void SceneTreePanel::editSelected() {
    const QModelIndex index = m_model.indexOf(m_selection.node());
    if (index.isValid()) {
        // NoUpdate: the rest of a multiple selection stays selected.
        m_view->selectionModel()->setCurrentIndex(index, QItemSelectionModel::NoUpdate);
        m_view->edit(index);
    }
}

void SceneTreePanel::syncFromSelection() {
    if (m_syncing) {
        return;
    }
    m_syncing = true;
    QItemSelection rows;
    QModelIndex current;
    auto add = [&](const QModelIndex& index) {
        if (!index.isValid()) {
            return;
        }
        for (QModelIndex p = index.parent(); p.isValid(); p = p.parent()) {
            m_view->expand(p);
        }
        rows.select(index, index);
        current = index;
    };
    if (m_selection.isCamera()) {
        add(m_model.cameraIndex());
    } else {
        for (scene::NodeId id : m_selection.nodes()) { // the current node is last
            add(m_model.indexOf(id));
        }
    }
    QItemSelectionModel* model = m_view->selectionModel();
    if (current.isValid()) {
        model->setCurrentIndex(current, QItemSelectionModel::NoUpdate);
        model->select(rows, QItemSelectionModel::ClearAndSelect);
        m_view->scrollTo(current);
    } else {
        model->clearSelection();
    }
    m_syncing = false;
}

void SceneTreePanel::syncToSelection() {
    // While rows go away the view moves its current index to a neighbour; that is not a user's choice.
    if (m_syncing || m_model.isRemovingRows()) {
        return;
    }
    m_syncing = true;
    const QItemSelectionModel* model = m_view->selectionModel();
    const QModelIndex currentIndex = model->currentIndex();
    const bool currentSelected = currentIndex.isValid() && model->isSelected(currentIndex);
    bool camera = false;
    std::vector<scene::NodeId> ids;
    for (const QModelIndex& index : model->selectedIndexes()) {
        if (m_model.isCamera(index)) {
            camera = true;
        } else {
            ids.push_back(m_model.nodeId(index));
        }
    }
    // The camera is selected alone: clicking it (even with Ctrl) selects just the camera; adding nodes to a
    // selected camera (Ctrl+click, Shift+click, Ctrl+A) leaves the camera out.
    const bool cameraClicked = currentSelected && m_model.isCamera(currentIndex) && !m_selection.isCamera();
    const bool mixed = camera && !ids.empty();
    if (camera && (ids.empty() || cameraClicked)) {
        m_selection.selectCamera();
    } else if (ids.empty()) {
        m_selection.clear();
    } else {
        // Keep the order in which the nodes were picked: those already selected first, in their order.
        std::vector<scene::NodeId> ordered;
        for (scene::NodeId id : m_selection.nodes()) {
            if (std::find(ids.begin(), ids.end(), id) != ids.end()) {
                ordered.push_back(id);
            }
        }
        for (scene::NodeId id : ids) {
            if (std::find(ordered.begin(), ordered.end(), id) == ordered.end()) {
                ordered.push_back(id);
            }
        }
        m_selection.setNodes(ordered, currentSelected ? m_model.nodeId(currentIndex) : scene::kNoNode);
    }
    m_syncing = false;
    if (mixed) {
        syncFromSelection(); // show what was kept
    }
}

void SceneTreePanel::showContextMenu(const QPoint& pos) {
    const QModelIndex index = m_view->indexAt(pos);
    if (!index.isValid()) {
        m_selection.clear();
    }
    QMenu menu(this);
    if (m_addMenu) {
        menu.addMenu(m_addMenu);
        menu.addSeparator();
    }
    for (QAction* action : m_actions) {
        if (action) {
            menu.addAction(action);
        } else {
            menu.addSeparator();
        }
    }
    menu.exec(m_view->viewport()->mapToGlobal(pos));
}

} // namespace speculum::ui
