#include "editor/ui/Screenshot.hpp"

#include "base/AtomicFile.hpp"
#include "base/Printable.hpp"
#include "editor/ui/MainWindow.hpp"
#include "editor/ui/Viewport.hpp"
#include "editor/view/AnimationClock.hpp"

#include <QAction>
#include <QApplication>
#include <QBuffer>
#include <QEventLoop>
#include <QFileInfo>
#include <QMouseEvent>
#include <QPixmap>
#include <QRegularExpression>
#include <QTimer>

namespace speculum::ui {

ScreenshotRequest screenshotRequestFromEnvironment() {
    ScreenshotRequest request;
    request.outputPath = qEnvironmentVariable("SPECULUM_SCREENSHOT");
    request.enabled = !request.outputPath.isEmpty();
    bool ok = false;
    const double time = qEnvironmentVariable("SPECULUM_SCREENSHOT_TIME").toDouble(&ok);
    if (ok) {
        request.time = time;
    }
    static const QRegularExpression sizePattern(QStringLiteral("^(\\d+)x(\\d+)$"));
    const auto match = sizePattern.match(qEnvironmentVariable("SPECULUM_SCREENSHOT_SIZE"));
    if (match.hasMatch()) {
        request.size = QSize(match.captured(1).toInt(), match.captured(2).toInt());
    }
    const QString actions = qEnvironmentVariable("SPECULUM_SCREENSHOT_ACTIONS");
    if (!actions.isEmpty())
        request.actions = actions.split(QLatin1Char(':'), Qt::SkipEmptyParts);
    const QStringList click = qEnvironmentVariable("SPECULUM_SCREENSHOT_CLICK").split(QLatin1Char(','));
    if (click.size() == 2)
        request.click = QPoint(click[0].toInt(), click[1].toInt());
    const QString then = qEnvironmentVariable("SPECULUM_SCREENSHOT_THEN");
    if (!then.isEmpty())
        request.actionsAfterClick = then.split(QLatin1Char(':'), Qt::SkipEmptyParts);
    const QString imports = qEnvironmentVariable("SPECULUM_SCREENSHOT_IMPORT");
    if (!imports.isEmpty()) {
        request.imports = imports.split(QLatin1Char(':'), Qt::SkipEmptyParts);
    }
    return request;
}

namespace {

void clickViewport(QWidget& viewport, QPoint at) {
    const QPointF local(at);
    const QPointF global(viewport.mapToGlobal(at));
    QMouseEvent press(QEvent::MouseButtonPress, local, global, Qt::LeftButton, Qt::LeftButton,
                      Qt::NoModifier);
    QCoreApplication::sendEvent(&viewport, &press);
    QMouseEvent release(QEvent::MouseButtonRelease, local, global, Qt::LeftButton, Qt::NoButton,
                        Qt::NoModifier);
    QCoreApplication::sendEvent(&viewport, &release);
}

} // namespace

int takeScreenshot(MainWindow& window, const ScreenshotRequest& request) {
    window.clock().setPlaying(false);
    window.clock().setTime(request.time);
    window.resize(request.size);
    window.show();
    for (const QString& path : request.imports) {
        if (auto status = window.importModelFile(path); !status) {
            qCritical("speculum: screenshot: could not import %s: %s", qPrintable(path),
                      status.error().c_str());
            return 1;
        }
    }
    if (!request.imports.isEmpty()) {
        window.viewport().frameSelected();
    }
    for (const QString& name : request.actions) {
        auto* action = window.findChild<QAction*>(name);
        if (!action) {
            qCritical("speculum: screenshot: the window has no action named %s", qPrintable(name));
            return 1;
        }
        action->trigger();
    }
    // The project's model files are read on workers: the picture shows them, not their stand-ins.
    window.viewport().waitForModels();
    window.viewport().update(); // the frames it drew meanwhile showed stand-ins: draw again
    int targetFrames = window.viewport().framesRendered() + request.frames;
    bool clickPending = request.click.has_value();

    QEventLoop loop;
    QString failure;
    auto finishWithFailure = [&](const QString& why) {
        failure = why;
        loop.quit();
    };
    QObject::connect(&window.viewport(), &Viewport::rendererFailed, &loop,
                     [&](const QString& message) { finishWithFailure(message); });
    QObject::connect(&window.viewport(), &Viewport::frameRendered, &loop, [&] {
        if (clickPending) { // once the viewport draws, it can be clicked; then the frames after it
            clickPending = false;
            QTimer::singleShot(0, &loop, [&] {
                clickViewport(window.viewport(), *request.click);
                for (const QString& name : request.actionsAfterClick)
                    if (auto* action = window.findChild<QAction*>(name))
                        action->trigger();
                targetFrames = window.viewport().framesRendered() + request.frames;
                window.viewport().update();
            });
            return;
        }
        if (window.viewport().framesRendered() < targetFrames) {
            // Paused, the viewport draws only on demand; ask for the next frame.
            window.viewport().update();
            return;
        }
        // Grab outside paintGL, from the event loop.
        QTimer::singleShot(0, &loop, &QEventLoop::quit);
    });
    QTimer::singleShot(request.timeoutMs, &loop, [&] {
        finishWithFailure(
            QStringLiteral("the viewport did not draw within %1 s").arg(request.timeoutMs / 1000));
    });
    loop.exec();

    if (!failure.isEmpty()) {
        qCritical("speculum: screenshot failed: %s", qPrintable(failure));
        return 1;
    }
    const QPixmap picture = window.grab();
    // Encoded in memory and written through a staged temporary: a full disk keeps the previous file.
    QByteArray encoded;
    QBuffer buffer(&encoded);
    buffer.open(QIODevice::WriteOnly);
    const QByteArray format = QFileInfo(request.outputPath).suffix().toLower().toLatin1();
    if (picture.isNull() || !picture.save(&buffer, format.isEmpty() ? "png" : format.constData())) {
        qCritical("speculum: could not encode %s", qPrintable(request.outputPath));
        return 1;
    }
    if (const base::Status written = base::writeFileAtomically(
            request.outputPath.toStdString(), std::string_view(encoded.constData(), encoded.size()));
        !written) {
        qCritical("speculum: %s", base::printable(written.error(), 400).c_str());
        return 1;
    }
    qInfo("speculum: wrote %s (%dx%d)", qPrintable(request.outputPath), picture.width(), picture.height());
    return 0;
}

} // namespace speculum::ui
