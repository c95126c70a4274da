#include "editor/ui/KeypadKeys.hpp"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QKeyEvent>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QTextEdit>
#include <QWidget>

namespace speculum::ui {

namespace {

struct KeypadName {
    KeypadKey key;
    int numLockOn;  // the Qt key X delivers with NumLock on
    int numLockOff; // ... and with it off (the keypad's navigation keysym)
};

constexpr KeypadName kKeypad[] = {
    {KeypadKey::Digit0, Qt::Key_0, Qt::Key_Insert},       {KeypadKey::Digit1, Qt::Key_1, Qt::Key_End},
    {KeypadKey::Digit2, Qt::Key_2, Qt::Key_Down},         {KeypadKey::Digit3, Qt::Key_3, Qt::Key_PageDown},
    {KeypadKey::Digit4, Qt::Key_4, Qt::Key_Left},         {KeypadKey::Digit5, Qt::Key_5, Qt::Key_Clear},
    {KeypadKey::Digit6, Qt::Key_6, Qt::Key_Right},        {KeypadKey::Digit7, Qt::Key_7, Qt::Key_Home},
    {KeypadKey::Digit8, Qt::Key_8, Qt::Key_Up},           {KeypadKey::Digit9, Qt::Key_9, Qt::Key_PageUp},
    {KeypadKey::Decimal, Qt::Key_Period, Qt::Key_Delete}, {KeypadKey::Plus, Qt::Key_Plus, Qt::Key_Plus},
    {KeypadKey::Minus, Qt::Key_Minus, Qt::Key_Minus},
};

// Widgets that type what the keypad gives: they keep its keys.
bool takesText(const QWidget* focus) {
    return qobject_cast<const QLineEdit*>(focus) || qobject_cast<const QAbstractSpinBox*>(focus) ||
           qobject_cast<const QTextEdit*>(focus) || qobject_cast<const QPlainTextEdit*>(focus);
}

} // namespace

KeypadKeys::KeypadKeys(QWidget& window)
    : QObject(&window)
    , m_window(window) {
    qApp->installEventFilter(this);
}

void KeypadKeys::bind(KeypadKey key, bool ctrl, std::function<void()> run) {
    (ctrl ? m_ctrl : m_plain).at(static_cast<std::size_t>(key)) = std::move(run);
}

bool KeypadKeys::keypadKeyOf(const QKeyEvent& event, KeypadKey& key) {
    if (!(event.modifiers() & Qt::KeypadModifier))
        return false;
    // Locales whose decimal separator is a comma give the keypad's point as Key_Comma.
    const int pressed = event.key() == Qt::Key_Comma ? int(Qt::Key_Period) : event.key();
    for (const KeypadName& name : kKeypad) {
        if (pressed == name.numLockOn || pressed == name.numLockOff) {
            key = name.key;
            return true;
        }
    }
    return false;
}

const std::function<void()>* KeypadKeys::boundTo(QObject* watched, const QKeyEvent& event) const {
    auto* widget = qobject_cast<QWidget*>(watched);
    if (!widget || widget->window() != &m_window || takesText(QApplication::focusWidget()))
        return nullptr;
    KeypadKey key{};
    if (!keypadKeyOf(event, key))
        return nullptr;
    const Qt::KeyboardModifiers others = event.modifiers() & ~(Qt::KeypadModifier | Qt::ControlModifier);
    if (others != Qt::NoModifier)
        return nullptr;
    const auto& table = event.modifiers() & Qt::ControlModifier ? m_ctrl : m_plain;
    const std::function<void()>& run = table.at(static_cast<std::size_t>(key));
    return run ? &run : nullptr;
}

bool KeypadKeys::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() != QEvent::ShortcutOverride && event->type() != QEvent::KeyPress)
        return false;
    const std::function<void()>* run = boundTo(watched, *static_cast<QKeyEvent*>(event));
    if (!run)
        return false;
    // Taking the shortcut-override step keeps the shortcut map (Home's, Delete's) away from the key; the key
    // press that follows runs what is bound.
    event->accept();
    if (event->type() == QEvent::KeyPress)
        (*run)();
    return true;
}

} // namespace speculum::ui
