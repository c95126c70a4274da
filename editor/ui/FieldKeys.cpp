#include "editor/ui/FieldKeys.hpp"

#include <QAbstractItemView>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QDialog>
#include <QDoubleSpinBox>
#include <QKeyEvent>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QTimer>
#include <QWidget>

namespace speculum::ui {

namespace {

// Whether `widget` lies in `window` (its docks, floating or not, are its children), outside any dialog.
bool inWindow(const QWidget* widget, const QWidget& window) {
    for (const QWidget* w = widget; w; w = w->parentWidget()) {
        if (w == &window)
            return true;
        if (qobject_cast<const QDialog*>(w))
            return false;
    }
    return false;
}

// An item view's editor (the scene tree's rename field): its delegate commits on Enter and reverts on Esc.
bool editsAnItem(const QWidget* field) {
    for (const QWidget* w = field->parentWidget(); w; w = w->parentWidget())
        if (qobject_cast<const QAbstractItemView*>(w))
            return true;
    return false;
}

} // namespace

FieldKeys::FieldKeys(QWidget& window, QWidget& home)
    : QObject(&window)
    , m_window(window)
    , m_home(home) {
    qApp->installEventFilter(this);
}

QWidget* FieldKeys::fieldOf(QObject* watched) const {
    auto* widget = qobject_cast<QWidget*>(watched);
    if (!widget || (!qobject_cast<QLineEdit*>(widget) && !qobject_cast<QAbstractSpinBox*>(widget)))
        return nullptr;
    // A spin box's own line edit: the spin box is the field.
    if (auto* spin = qobject_cast<QAbstractSpinBox*>(widget->parentWidget()))
        widget = spin;
    return inWindow(widget, m_window) && widget != &m_home ? widget : nullptr;
}

bool FieldKeys::eventFilter(QObject* watched, QEvent* event) {
    const QEvent::Type type = event->type();
    if (type != QEvent::FocusIn && type != QEvent::KeyPress)
        return false;
    QWidget* field = fieldOf(watched);
    if (!field)
        return false;
    if (type == QEvent::FocusIn) {
        if (m_focused != field) {
            m_focused = field;
            auto* edit = qobject_cast<QLineEdit*>(field);
            m_textAtFocus = edit ? edit->text() : QString();
        }
        return false;
    }
    const int key = static_cast<QKeyEvent*>(event)->key();
    if (key == Qt::Key_Return || key == Qt::Key_Enter) {
        handBackAfter(field); // the field commits as it always does
        return false;
    }
    if (key == Qt::Key_Escape) {
        if (editsAnItem(field)) {
            handBackAfter(field); // the delegate reverts and closes its editor
            return false;
        }
        revert(field);
        m_home.setFocus(Qt::ShortcutFocusReason);
        return true;
    }
    return false;
}

void FieldKeys::handBackAfter(QWidget* field) {
    auto handBack = [this, guarded = QPointer<QWidget>(field)] {
        QWidget* focus = QApplication::focusWidget();
        const bool fieldDone = !guarded || !guarded->isVisible();
        const bool stillInField = guarded && (focus == guarded || guarded->isAncestorOf(focus));
        // A closed rename editor leaves the focus on its item view.
        const bool onItsView = fieldDone && focus && qobject_cast<QAbstractItemView*>(focus);
        if (stillInField || onItsView || (fieldDone && !focus))
            m_home.setFocus(Qt::ShortcutFocusReason);
    };
    if (!editsAnItem(field)) {
        QTimer::singleShot(0, this, handBack);
        return;
    }
    // An item view's delegate commits and closes its editor in a call it queues on this very key, after
    // this filter has seen it: hand the keyboard back after that call, not before (taking the focus first
    // would close the editor twice).
    QTimer::singleShot(0, this, [this, handBack] { QTimer::singleShot(0, this, handBack); });
}

void FieldKeys::revert(QWidget* field) {
    if (auto* edit = qobject_cast<QLineEdit*>(field)) {
        if (field == m_focused) {
            QSignalBlocker block(edit);
            edit->setText(m_textAtFocus);
        }
        edit->setModified(false); // leaving it then commits nothing
        return;
    }
    // A spin box commits on Enter or on leaving (no keyboard tracking): its value is still the committed
    // one, and setting it again puts its text back.
    if (auto* spin = qobject_cast<QDoubleSpinBox*>(field)) {
        QSignalBlocker block(spin);
        spin->setValue(spin->value());
    } else if (auto* spin = qobject_cast<QSpinBox*>(field)) {
        QSignalBlocker block(spin);
        spin->setValue(spin->value());
    }
}

} // namespace speculum::ui
