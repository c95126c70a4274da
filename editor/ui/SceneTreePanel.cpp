#include "editor/ui/SceneTreePanel.hpp"

#include "editor/ui/SceneTreeModel.hpp"
#include "editor/ui/Selection.hpp"

#include <QHeaderView>
#include <QMenu>
#include <QTreeView>
#include <QVBoxLayout>

namespace speculum::ui {

SceneTreePanel::SceneTreePanel(SceneTreeModel& model, Selection& selection, QWidget* parent)
    : QWidget(parent)
    , m_model(model)
    , m_selection(selection) {
    m_view = new QTreeView(this);
    m_view->setObjectName(QStringLiteral("sceneTree"));
    m_view->setModel(&model);
    m_view->header()->hide();
    m_view->setSelectionMode(QAbstractItemView::SingleSelection);
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
    connect(&selection, &Selection::changed, this, &SceneTreePanel::syncFromSelection);
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
        m_view->setCurrentIndex(index);
        m_view->edit(index);
    }
}

void SceneTreePanel::syncFromSelection() {
    if (m_syncing) {
        return;
    }
    m_syncing = true;
    QModelIndex index;
    if (m_selection.isCamera()) {
        index = m_model.cameraIndex();
    } else if (m_selection.node() != document::kNoNode) {
        index = m_model.indexOf(m_selection.node());
    }
    if (index.isValid()) {
        for (QModelIndex p = index.parent(); p.isValid(); p = p.parent()) {
            m_view->expand(p);
        }
        m_view->selectionModel()->setCurrentIndex(index, QItemSelectionModel::ClearAndSelect);
        m_view->scrollTo(index);
    } else {
        m_view->selectionModel()->clearSelection();
    }
    m_syncing = false;
}

void SceneTreePanel::syncToSelection() {
    // While rows go away the view moves its current index to a neighbour; that is not a user's choice.
    if (m_syncing || m_model.isRemovingRows()) {
        return;
    }
    m_syncing = true;
    const QModelIndexList selected = m_view->selectionModel()->selectedIndexes();
    if (selected.isEmpty()) {
        m_selection.clear();
    } else if (m_model.isCamera(selected.front())) {
        m_selection.selectCamera();
    } else {
        m_selection.selectNode(m_model.nodeId(selected.front()));
    }
    m_syncing = false;
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
