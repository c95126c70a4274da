#include "editor/ui/Inspector.hpp"

#include "editor/document/Commands.hpp"
#include "editor/document/NodeFactory.hpp"
#include "editor/ui/Icons.hpp"
#include "editor/ui/PropertyEditors.hpp"
#include "editor/view/Selection.hpp"

#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenu>
#include <QScrollArea>
#include <QScrollBar>
#include <QToolButton>
#include <QUndoStack>
#include <QVBoxLayout>

namespace speculum::ui {

using document::ComponentInfo;
using scene::NodeData;

namespace {

QString quoted(const std::string& name) {
    return QStringLiteral("\u201c%1\u201d").arg(QString::fromStdString(name));
}

} // namespace

Inspector::Inspector(scene::Scene& scene, QUndoStack& undoStack, view::Selection& selection, QWidget* parent)
    : QWidget(parent)
    , m_scene(scene)
    , m_undoStack(undoStack)
    , m_selection(selection) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    m_header = new QLabel(this);
    m_header->setObjectName(QStringLiteral("inspectorHeader"));
    QFont bold = m_header->font();
    bold.setBold(true);
    bold.setPointSizeF(bold.pointSizeF() * 1.1);
    m_header->setFont(bold);
    layout->addWidget(m_header);

    m_error = new QLabel(this);
    m_error->setObjectName(QStringLiteral("inspectorError"));
    m_error->setWordWrap(true);
    m_error->setStyleSheet(QStringLiteral("QLabel { background: #f8d7da; color: #721c24; border: 1px solid "
                                          "#d03030; border-radius: 3px; padding: 4px; }"));
    m_error->hide();
    layout->addWidget(m_error);

    m_scroll = new QScrollArea(this);
    m_scroll->setWidgetResizable(true);
    m_scroll->setFrameShape(QFrame::NoFrame);
    // Never cut a row off on the right (a vector's Z field behind a scroll bar): the panel is as wide as
    // its widest row needs (fitToContent), and the dock around it follows.
    m_scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    layout->addWidget(m_scroll, 1);

    connect(&selection, &view::Selection::changed, this, [this] {
        clearError();
        rebuild();
    });
    connect(&scene, &scene::Scene::sceneReset, this, &Inspector::rebuild);
    connect(&scene, &scene::Scene::nodeChanged, this, [this](scene::NodeId id) {
        if (id == m_selection.node()) {
            refresh();
        }
    });
    connect(&scene, &scene::Scene::settingsChanged, this, &Inspector::refresh);
    connect(&scene, &scene::Scene::cameraChanged, this, &Inspector::refresh);
    // A new undo step elsewhere (or an undo) ends the current gesture.
    connect(&undoStack, &QUndoStack::indexChanged, this, [this] {
        if (!m_committing) {
            ++m_gesture;
        }
    });
    rebuild();
}

QString Inspector::errorText() const {
    return m_error->isHidden() ? QString() : m_error->text();
}

QString Inspector::layoutSignature() const {
    QString sig;
    if (m_selection.isCamera()) {
        return QStringLiteral("camera");
    }
    const scene::Node* node = m_selection.selectedNode();
    if (!node) {
        return QStringLiteral("scene");
    }
    sig = QString::number(node->id());
    for (const ComponentInfo& c : document::nodeComponents()) {
        if (!c.present(node->data())) {
            continue;
        }
        sig += QLatin1Char('|') + c.key;
        for (const auto& p : c.properties) {
            if (p.isVisible(node->data())) {
                sig += QLatin1Char(',') + p.info.key;
            }
        }
    }
    return sig;
}

void Inspector::rebuild() {
    // The same node laid out again (a choice that adds or removes rows): the view stays where it was.
    const QString before = m_signature.section(QLatin1Char('|'), 0, 0);
    const int scrolled = m_scroll->verticalScrollBar()->value();
    m_signature = layoutSignature();
    const bool sameNode = !before.isEmpty() && before == m_signature.section(QLatin1Char('|'), 0, 0);
    m_editors.clear();
    m_notes.clear();
    // Replace the whole content widget: simplest way to drop every generated editor and layout.
    m_content = new QWidget;
    m_contentLayout = new QVBoxLayout(m_content);
    m_contentLayout->setContentsMargins(0, 0, 0, 0);

    if (const scene::Node* node = m_selection.selectedNode()) {
        const NodeData& d = node->data();
        m_header->setText(
            QStringLiteral("%1  ·  %2").arg(QString::fromStdString(d.name), kindName(nodeKind(d))));
        for (const ComponentInfo& c : document::nodeComponents()) {
            if (!c.present(d)) {
                continue;
            }
            QWidget* group = addGroup(c.title, c.key, c.optional);
            for (const auto& p : c.properties) {
                if (p.isVisible(d)) {
                    addEditor(group, p.info, p.get(d));
                    if (p.note) {
                        addNote(group, p.info.key, p.noteFor(d));
                    }
                }
            }
        }
        addComponentButton(d);
    } else {
        const bool cameraOnly = m_selection.isCamera();
        m_header->setText(cameraOnly ? tr("Camera") : tr("Scene"));
        if (!cameraOnly) {
            QWidget* settings = addGroup(tr("Scene settings"), {}, false);
            for (const auto& p : document::settingsProperties()) {
                addEditor(settings, p.info, p.get(m_scene.settings()));
            }
        }
        QWidget* camera = addGroup(tr("Camera"), {}, false);
        for (const auto& p : document::cameraProperties()) {
            addEditor(camera, p.info, p.get(m_scene.camera()));
        }
    }
    m_contentLayout->addStretch(1);
    // The old editors may be in the middle of emitting the edit that caused this rebuild: delete later.
    if (QWidget* old = m_scroll->takeWidget()) {
        old->hide();
        old->deleteLater();
    }
    m_scroll->setWidget(m_content);
    fitToContent();
    if (sameNode) {
        // After the new content is laid out, or the scroll bar's range is still the empty widget's.
        m_content->adjustSize();
        m_scroll->verticalScrollBar()->setValue(scrolled);
    }
    if (!m_invalidKey.isEmpty() && m_editors.contains(m_invalidKey)) {
        m_editors[m_invalidKey]->setInvalid(true);
    }
}

void Inspector::fitToContent() {
    const int scrollBar = m_scroll->verticalScrollBar()->sizeHint().width();
    m_scroll->setMinimumWidth(m_content->minimumSizeHint().width() + scrollBar);
}

void Inspector::refresh() {
    if (layoutSignature() != m_signature) {
        rebuild();
        return;
    }
    if (const scene::Node* node = m_selection.selectedNode()) {
        m_header->setText(
            QStringLiteral("%1  ·  %2")
                .arg(QString::fromStdString(node->data().name), kindName(nodeKind(node->data()))));
        for (auto it = m_editors.begin(); it != m_editors.end(); ++it) {
            if (const auto* p = document::findNodeProperty(it.key())) {
                it.value()->setValue(p->get(node->data()));
            }
        }
        for (auto it = m_notes.begin(); it != m_notes.end(); ++it) {
            if (const auto* p = document::findNodeProperty(it.key())) {
                showNote(it.value(), p->noteFor(node->data()));
            }
        }
        return;
    }
    for (auto it = m_editors.begin(); it != m_editors.end(); ++it) {
        if (const auto* p = document::findSettingsProperty(it.key())) {
            it.value()->setValue(p->get(m_scene.settings()));
        } else if (const auto* c = document::findCameraProperty(it.key())) {
            it.value()->setValue(c->get(m_scene.camera()));
        }
    }
}

QWidget* Inspector::addGroup(const QString& title, const QString& componentKey, bool removable) {
    auto* box = new QGroupBox(title, m_content);
    box->setObjectName(componentKey.isEmpty() ? title : componentKey + QStringLiteral(".group"));
    auto* form = new QFormLayout(box);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    form->setLabelAlignment(Qt::AlignRight | Qt::AlignVCenter);
    if (removable) {
        auto* remove = new QToolButton(box);
        remove->setObjectName(componentKey + QStringLiteral(".remove"));
        remove->setText(tr("Remove"));
        remove->setToolTip(tr("Remove the %1 component").arg(title.toLower()));
        remove->setAutoRaise(true);
        form->addRow(QString(), remove);
        connect(remove, &QToolButton::clicked, this,
                [this, componentKey] { changeComponent(componentKey, false); });
    }
    m_contentLayout->addWidget(box);
    return box;
}

void Inspector::addEditor(QWidget* group, const document::PropertyInfo& info, const QVariant& value) {
    PropertyEditor* editor = PropertyEditor::create(info, group);
    editor->setValue(value);
    auto* label = new QLabel(info.label, group);
    label->setToolTip(info.tooltip);
    static_cast<QFormLayout*>(group->layout())->addRow(label, editor);
    m_editors.insert(info.key, editor);
    connect(editor, &PropertyEditor::interactionStarted, this, [this] { ++m_gesture; });
    connect(editor, &PropertyEditor::edited, this,
            [this, key = info.key](const QVariant& v) { applyValue(key, v); });
}

// A line under an editor saying what its value does here when that differs from what it says; hidden
// while there is nothing to say.
void Inspector::addNote(QWidget* group, const QString& key, const QString& text) {
    auto* note = new QLabel(group);
    note->setObjectName(key + QStringLiteral(".note"));
    note->setWordWrap(true);
    note->setForegroundRole(QPalette::PlaceholderText);
    static_cast<QFormLayout*>(group->layout())->addRow(QString(), note);
    m_notes.insert(key, note);
    showNote(note, text);
}

void Inspector::showNote(QLabel* note, const QString& text) {
    note->setText(text);
    note->setVisible(!text.isEmpty());
}

void Inspector::addComponentButton(const NodeData& d) {
    auto* button = new QToolButton(m_content);
    button->setObjectName(QStringLiteral("addComponent"));
    button->setText(tr("Add Component"));
    button->setPopupMode(QToolButton::InstantPopup);
    button->setToolButtonStyle(Qt::ToolButtonTextOnly);
    auto* menu = new QMenu(button);
    for (const ComponentInfo& c : document::nodeComponents()) {
        if (c.optional && !c.present(d)) {
            QAction* action = menu->addAction(c.title);
            action->setObjectName(QStringLiteral("add.") + c.key);
            connect(action, &QAction::triggered, this, [this, key = c.key] { changeComponent(key, true); });
        }
    }
    button->setMenu(menu);
    button->setEnabled(!menu->isEmpty());
    m_contentLayout->addWidget(button, 0, Qt::AlignLeft);
}

void Inspector::changeComponent(const QString& key, bool add) {
    const scene::Node* node = m_selection.selectedNode();
    const ComponentInfo* c = document::findComponent(key);
    if (!node || !c) {
        return;
    }
    NodeData data = node->data();
    const base::Status status = add ? c->add(data) : c->remove(data);
    if (!status) {
        showError(key, QString::fromStdString(status.error()));
        return;
    }
    clearError();
    const QString text = add ? tr("Add %1 to %2").arg(c->title, quoted(node->name()))
                             : tr("Remove %1 from %2").arg(c->title, quoted(node->name()));
    document::pushEdit(m_undoStack, new document::SetNodeDataCommand(m_scene, node->id(), data, text));
}

base::Status Inspector::applyValue(const QString& key, const QVariant& value) {
    base::Status status = base::Done{};
    if (m_selection.selectedNode()) {
        status = commitNode(key, value);
    } else if (document::findSettingsProperty(key)) {
        status = commitSettings(key, value);
    } else {
        status = commitCamera(key, value);
    }
    if (status) {
        clearError();
    } else {
        showError(key, QString::fromStdString(status.error()));
    }
    return status;
}

base::Status Inspector::commitNode(const QString& key, const QVariant& value) {
    const scene::Node* node = m_selection.selectedNode();
    const auto* p = document::findNodeProperty(key);
    if (!node || !p) {
        return base::Error{"no such property: " + key.toStdString()};
    }
    NodeData data = node->data();
    if (auto status = p->set(data, value); !status) {
        return status;
    }
    if (data == node->data()) {
        return base::Done{};
    }
    const QString text = key == QStringLiteral("node.name")
                             ? tr("Rename %1 to %2").arg(quoted(node->name()), quoted(data.name))
                             : tr("Change %1 of %2").arg(p->info.label, quoted(node->name()));
    m_committing = true;
    document::pushEdit(m_undoStack,
                       new document::SetNodeDataCommand(m_scene, node->id(), data, text, mergeKey(key)));
    m_committing = false;
    return base::Done{};
}

base::Status Inspector::commitSettings(const QString& key, const QVariant& value) {
    const auto* p = document::findSettingsProperty(key);
    if (!p) {
        return base::Error{"no such property: " + key.toStdString()};
    }
    scene::SceneSettings settings = m_scene.settings();
    if (auto status = p->set(settings, value); !status) {
        return status;
    }
    if (settings == m_scene.settings()) {
        return base::Done{};
    }
    auto* command = new document::SetSettingsCommand(m_scene, settings, true);
    command->setText(tr("Change %1").arg(p->info.label));
    command->setMergeKey(mergeKey(key));
    m_committing = true;
    document::pushEdit(m_undoStack, command);
    m_committing = false;
    return base::Done{};
}

base::Status Inspector::commitCamera(const QString& key, const QVariant& value) {
    const auto* p = document::findCameraProperty(key);
    if (!p) {
        return base::Error{"no such property: " + key.toStdString()};
    }
    scene::CameraData camera = m_scene.camera();
    if (auto status = p->set(camera, value); !status) {
        return status;
    }
    if (camera == m_scene.camera()) {
        return base::Done{};
    }
    auto* command = new document::SetCameraCommand(m_scene, camera, true);
    command->setText(tr("Change camera %1").arg(p->info.label.toLower()));
    command->setMergeKey(mergeKey(key));
    m_committing = true;
    document::pushEdit(m_undoStack, command);
    m_committing = false;
    return base::Done{};
}

void Inspector::showError(const QString& key, const QString& text) {
    m_error->setText(tr("Not applied: %1").arg(text));
    m_error->show();
    if (!m_invalidKey.isEmpty() && m_editors.contains(m_invalidKey)) {
        m_editors[m_invalidKey]->setInvalid(false);
    }
    m_invalidKey = key;
    if (m_editors.contains(key)) {
        m_editors[key]->setInvalid(true);
    }
    emit message(text);
}

void Inspector::clearError() {
    m_error->hide();
    m_error->clear();
    if (!m_invalidKey.isEmpty() && m_editors.contains(m_invalidKey)) {
        m_editors[m_invalidKey]->setInvalid(false);
    }
    m_invalidKey.clear();
}

} // namespace speculum::ui
