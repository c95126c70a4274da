#include "editor/ui/Editor.hpp"

#include "editor/ui/AppIdentity.hpp"
#include "editor/ui/MainWindow.hpp"
#include "editor/ui/Screenshot.hpp"

#include <QApplication>
#include <QMessageBox>
#include <QSurfaceFormat>
#include <QTimer>

namespace speculum::ui {

void installDefaultSurfaceFormat() {
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(8); // mirror recursion masks
    QSurfaceFormat::setDefaultFormat(format);
}

int runEditor(int& argc, char** argv, const std::string& projectPath, const std::string& recoveryPath) {
    // Both must precede the QApplication: the format is read when the first context is made, and shared
    // contexts let the viewport survive being re-parented (docking) without losing its GL objects.
    installDefaultSurfaceFormat();
    QApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("speculum"));
    QApplication::setApplicationName(QStringLiteral("speculum"));
    QApplication::setApplicationVersion(QStringLiteral(SPECULUM_VERSION));
    // Wayland names a window's application by its desktop entry; X11 takes the icon from the window.
    QGuiApplication::setDesktopFileName(QString::fromLatin1(kApplicationId));
    QApplication::setWindowIcon(applicationIcon());

    const ScreenshotRequest screenshot = screenshotRequestFromEnvironment();

    MainWindow window;
    QString openError;
    const std::string& asked = projectPath.empty() ? recoveryPath : projectPath;
    if (!asked.empty()) {
        const QString path = QString::fromStdString(asked);
        base::Status status =
            projectPath.empty() ? window.restoreRecoveryFile(path) : window.openProjectFile(path);
        if (!status) {
            openError = QString::fromStdString(status.error());
        }
    }

    if (screenshot.enabled) {
        if (!openError.isEmpty()) {
            qCritical("speculum: %s", qPrintable(openError));
            return 1;
        }
        return takeScreenshot(window, screenshot);
    }

    window.restoreLayout();
    // Paused, as a project opened from the File menu is: Space plays it. A paused view draws nothing
    // until something changes.
    window.show();
    if (openError.isEmpty() && asked.empty()) {
        // A previous session that crashed left unsaved work: offer it (only when no file was asked for).
        QTimer::singleShot(0, &window, [&window] { window.offerRecovery(); });
    }
    if (!openError.isEmpty()) {
        // After the window is up, so the box has a parent on screen; the empty document stays open.
        QTimer::singleShot(0, &window, [&window, openError, asked] {
            QMessageBox::critical(
                &window, QObject::tr("Open Project"),
                QObject::tr("Could not open %1:\n\n%2").arg(QString::fromStdString(asked), openError));
        });
    }
    return app.exec();
}

} // namespace speculum::ui
