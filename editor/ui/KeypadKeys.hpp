#pragma once

#include <QObject>
#include <array>
#include <functional>

class QKeyEvent;
class QWidget;

namespace speculum::ui {

// The numeric keypad's keys, whichever way the NumLock state delivers them.
enum class KeypadKey {
    Digit0,
    Digit1,
    Digit2,
    Digit3,
    Digit4,
    Digit5,
    Digit6,
    Digit7,
    Digit8,
    Digit9,
    Decimal,
    Plus,
    Minus
};

// The keypad as a Blender user's muscle memory expects it: keypad 7 is the top view whether NumLock is on
// or off, and never anything else.
//
// X delivers keypad 7 as Qt::Key_7 with Qt::KeypadModifier when NumLock is on and as Qt::Key_Home with
// Qt::KeypadModifier when it is off (and 1 as Key_End, 3 as Key_PageDown, the decimal point as Key_Delete,
// ...). Qt's shortcut map on X11 looks the key up without the keypad modifier, so a shortcut of
// KeypadModifier + Key_7 never fires, and with NumLock off the key fires Home's or Delete's shortcut instead.
// This filter takes every key event of `window` that carries the keypad modifier before the shortcut map
// sees it and runs what is bound to the key (with or without Ctrl), in either NumLock state. A text field
// with focus keeps the keypad (it types digits); unbound keypad keys go on as they came.
class KeypadKeys : public QObject {
public:
    // Watches the key events of `window` (installed on the application, so that the shortcut-override
    // step, which comes first, is seen too); owned by `window`.
    explicit KeypadKeys(QWidget& window);

    void bind(KeypadKey key, bool ctrl, std::function<void()> run);

    // The keypad key `event` is, in either NumLock state; false where it is not a keypad key.
    static bool keypadKeyOf(const QKeyEvent& event, KeypadKey& key);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    // What the event runs, or null: a keypad key of this window, bound, with no modifier but Ctrl, while no
    // text field has focus.
    const std::function<void()>* boundTo(QObject* watched, const QKeyEvent& event) const;

    static constexpr std::size_t kKeys = static_cast<std::size_t>(KeypadKey::Minus) + 1;
    QWidget& m_window;
    std::array<std::function<void()>, kKeys> m_plain;
    std::array<std::function<void()>, kKeys> m_ctrl;
};

} // namespace speculum::ui
