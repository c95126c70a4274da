#pragma once

#include "editor/document/Properties.hpp"
#include "scene/model/Scene.hpp"

#include <QHash>
#include <QWidget>

class QLabel;
class QScrollArea;
class QUndoStack;
class QVBoxLayout;

namespace speculum::view {
class Selection;
}

namespace speculum::ui {

class PropertyEditor;

// The Properties dock. Its editors are generated from the property descriptions (document/Properties.hpp)
// of the selected node's components; with nothing selected it shows the scene settings and the camera,
// with the camera row selected the camera. Every edit is an undoable command: consecutive edits within one
// gesture (a slider drag, a held spin arrow, a colour dialog) merge into one undo step. A value the
// description refuses is not applied: the message shows at the top, the field turns red.
class Inspector : public QWidget {
    Q_OBJECT

public:
    Inspector(scene::Scene& scene, QUndoStack& undoStack, view::Selection& selection,
              QWidget* parent = nullptr);

    // The editor of a property key ("mirror.reflectivity"), if shown.
    PropertyEditor* editor(const QString& key) const { return m_editors.value(key); }
    // The message about the last refused value; empty when the last edit was applied.
    QString errorText() const;

    // Applies a value as if typed into the editor (scripting and tests). Returns the validation result.
    base::Status applyValue(const QString& key, const QVariant& value);

signals:
    void message(const QString& text); // for the status bar

private:
    void rebuild();
    // The panel's least width: its widest row, every field shown whole.
    void fitToContent();
    void refresh();
    QString layoutSignature() const;
    void showError(const QString& key, const QString& text);
    void clearError();
    void addEditor(QWidget* group, const document::PropertyInfo& info, const QVariant& value);
    void addNote(QWidget* group, const QString& key, const QString& text);
    static void showNote(QLabel* note, const QString& text);
    QWidget* addGroup(const QString& title, const QString& componentKey, bool removable);
    void addComponentButton(const scene::NodeData& data);
    void changeComponent(const QString& key, bool add);
    QString mergeKey(const QString& key) const { return key + QLatin1Char('#') + QString::number(m_gesture); }

    base::Status commitNode(const QString& key, const QVariant& value);
    base::Status commitSettings(const QString& key, const QVariant& value);
    base::Status commitCamera(const QString& key, const QVariant& value);

    scene::Scene& m_scene;
    QUndoStack& m_undoStack;
    view::Selection& m_selection;
    QLabel* m_header = nullptr;
    QLabel* m_error = nullptr;
    QScrollArea* m_scroll = nullptr;
    QWidget* m_content = nullptr;
    QVBoxLayout* m_contentLayout = nullptr;
    QHash<QString, PropertyEditor*> m_editors;
    QHash<QString, QLabel*> m_notes; // by property key: the editors' notes (Property::note)
    QString m_signature;
    QString m_invalidKey;
    int m_gesture = 0;
    bool m_committing = false;
};

} // namespace speculum::ui
