#pragma once

#include "support/GuiTestSupport.hpp"

#include <QGuiApplication>
#include <QProcess>
#include <QStandardPaths>
#include <QStringList>
#include <QWindow>
#include <memory>

namespace speculum::ui::test {

// Keys pressed on the test's X server through its XTEST extension (xdotool, installed by
// scripts/setup-deps): they reach Qt as a user's keyboard's do, through the xcb key map and Qt's shortcut
// map, which QTest's synthetic events skip. Each of `keys` is an xdotool key name ("KP_7", "ctrl+KP_Home",
// "Num_Lock"), pressed and released in turn. Goes to the window with X's input focus.
inline bool pressXKeys(const QStringList& keys) {
    QProcess xdotool;
    xdotool.start(QStringLiteral("xdotool"),
                  QStringList{QStringLiteral("key"), QStringLiteral("--delay"), QStringLiteral("30")} + keys);
    return xdotool.waitForFinished(10000) && xdotool.exitStatus() == QProcess::NormalExit &&
           xdotool.exitCode() == 0;
}

inline bool haveXKeyboard() {
    return !QStandardPaths::findExecutable(QStringLiteral("xdotool")).isEmpty();
}

// A main window at 1280×800, its animation stopped, with X's input focus (so that pressXKeys reaches it)
// and its first frames drawn; null where it never got there.
inline std::unique_ptr<MainWindow> mainWindowWithXFocus() {
    auto window = std::make_unique<MainWindow>();
    window->resize(1280, 800);
    window->show();
    if (!waitFor([&] { return window->windowHandle() && window->windowHandle()->isExposed(); }))
        return nullptr;
    window->clock().setPlaying(false);
    window->activateWindow();
    if (!waitFor([&] { return QGuiApplication::focusWindow() == window->windowHandle(); }) ||
        !waitForFrames(*window))
        return nullptr;
    return window;
}

} // namespace speculum::ui::test
