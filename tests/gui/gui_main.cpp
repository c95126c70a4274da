// main() for the GUI tests: a QApplication must exist before any widget, and the OpenGL surface format
// must be set before the QApplication, exactly as the editor does it.
#include "editor/ui/Editor.hpp"

#include <QApplication>
#include <QStandardPaths>
#include <gtest/gtest.h>

int main(int argc, char** argv) {
    speculum::ui::installDefaultSurfaceFormat();
    QApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("speculum"));
    QApplication::setApplicationName(QStringLiteral("speculum-gui-tests"));
    // QSettings (last folder) must not touch the user's configuration.
    QStandardPaths::setTestModeEnabled(true);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
