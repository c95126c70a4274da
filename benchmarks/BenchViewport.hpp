#pragma once

// What the editor benchmarks share: waiting for the viewport's frames and driving it with the mouse, as a
// user's drag does.
#include "editor/ui/Viewport.hpp"

#include <QCoreApplication>
#include <QEventLoop>
#include <QMouseEvent>
#include <QTimer>

namespace speculum::bench {

// Sleeps in an event loop until the viewport has drawn frame `target`, as the editor waits for the next
// mouse event: a polling loop here would take a core from llvmpipe's rasterizer threads.
inline bool waitForFrame(ui::Viewport& viewport, int target, int timeoutMs = 30000) {
    if (viewport.framesRendered() >= target) {
        return true;
    }
    QEventLoop loop;
    QTimer timeout;
    timeout.setSingleShot(true);
    QObject::connect(&timeout, &QTimer::timeout, &loop, &QEventLoop::quit);
    QObject::connect(&viewport, &ui::Viewport::frameRendered, &loop, [&] {
        if (viewport.framesRendered() >= target) {
            loop.quit();
        }
    });
    timeout.start(timeoutMs);
    loop.exec();
    return viewport.framesRendered() >= target;
}

inline void sendMouse(ui::Viewport& viewport, QEvent::Type type, QPointF at, Qt::MouseButton button,
                      Qt::MouseButtons buttons) {
    QMouseEvent event(type, at, viewport.mapToGlobal(at), button, buttons, Qt::NoModifier);
    QCoreApplication::sendEvent(&viewport, &event);
}

} // namespace speculum::bench
