#pragma once

#include <QPoint>
#include <QSize>
#include <QString>
#include <QStringList>
#include <optional>

namespace speculum::ui {

class MainWindow;

// A picture of the editor window for documentation and for checking the editor on machines without a
// desktop (scripts/screenshot-editor runs it under Xvfb).
struct ScreenshotRequest {
    bool enabled = false;
    QString outputPath;    // SPECULUM_SCREENSHOT
    double time = 0.0;     // SPECULUM_SCREENSHOT_TIME: animation frozen at this time
    QSize size{1280, 800}; // SPECULUM_SCREENSHOT_SIZE=WxH
    // SPECULUM_SCREENSHOT_IMPORT: model files (separated by ':') imported first, as File ▸ Import Model does
    // (worker thread, placement); the view then frames the last one.
    QStringList imports;
    // SPECULUM_SCREENSHOT_ACTIONS: the object names of the window's actions (separated by ':') triggered
    // first, as the menu would ("viewShowScreenSpaceSources" shows the screen-space debug view).
    QStringList actions;
    // SPECULUM_SCREENSHOT_CLICK=X,Y: a left click at this point of the viewport (its own coordinates) once it
    // has drawn, as a user's (with View ▸ Inspect Pixel on among the actions, it explains that pixel).
    std::optional<QPoint> click;
    // SPECULUM_SCREENSHOT_THEN: actions triggered after the click, as SPECULUM_SCREENSHOT_ACTIONS before it
    // (a view preset, to see the inspected path from the side).
    QStringList actionsAfterClick;
    int frames = 3;         // frames the viewport draws before the grab
    int timeoutMs = 120000; // give up (exit 1) if the viewport has not drawn by then
};

ScreenshotRequest screenshotRequestFromEnvironment();

// Shows the window, runs the event loop until the viewport has drawn `frames` frames, saves the whole
// window to the output path and returns 0; returns 1 (with a message on stderr) when the viewport cannot
// draw, the timeout passes or the image cannot be written. Needs a running QApplication.
int takeScreenshot(MainWindow& window, const ScreenshotRequest& request);

} // namespace speculum::ui
