#pragma once

#include "editor/document/Properties.hpp"

#include <QVariant>
#include <QWidget>

namespace speculum::ui {

// One generated editor for a property description: spin box (with a slider for ranged numbers), vector
// and colour fields, combo box, check box, line edit, or file chooser. It shows a value and reports what
// the user entered; it never validates or clamps (spin boxes accept any number, so a value out of range
// reaches the property's validation and is refused with a message instead of being silently clamped).
//
// Child widgets are named after the property key so tests and scripts can find them:
// "<key>" (spin box, line edit, combo, check box), "<key>.slider", "<key>.x|y|z" (vectors),
// "<key>.r|g|b" and "<key>.swatch" (colours), "<key>.browse" (files).
//
// The mouse wheel edits a spin box, slider or combo box only once it has focus (clicked or tabbed into);
// over an unfocused one it scrolls the panel instead.
class PropertyEditor : public QWidget {
    Q_OBJECT

public:
    static PropertyEditor* create(const document::PropertyInfo& info, QWidget* parent = nullptr);

    const document::PropertyInfo& info() const { return m_info; }
    // Shows a value without emitting edited().
    virtual void setValue(const QVariant& value) = 0;
    // Marks the editor as holding a refused value (red frame) or clears the mark.
    void setInvalid(bool invalid);
    // How a number field shows `value` with `decimals` decimals: fixed when that carries it to a part in a
    // thousand, else scientific ("5e-05"), so a tiny value never shows as 0.000.
    static QString numberText(double value, int decimals);

signals:
    void edited(const QVariant& value);
    // A new gesture begins (slider pressed, field focused, dialog opened): edits after it are a new undo
    // step; edits within one gesture merge into one.
    void interactionStarted();

protected:
    explicit PropertyEditor(const document::PropertyInfo& info, QWidget* parent);
    void watchFocus(QWidget* widget); // emits interactionStarted() when it gains focus; guards the wheel
    // The wheel edits `widget` only while it has focus; otherwise it scrolls the panel around it.
    void guardWheel(QWidget* widget);
    bool eventFilter(QObject* watched, QEvent* event) override;

    document::PropertyInfo m_info;
};

} // namespace speculum::ui
