// main() for the GUI tests: a QApplication must exist before any widget, and the OpenGL surface format
// must be set before the QApplication, exactly as the editor does it.
#include "GuiTestSupport.hpp"
#include "editor/ui/Editor.hpp"

#include <QApplication>
#include <cstdio>
#include <gtest/gtest.h>

int main(int argc, char** argv) {
    // Settings (last folder, import options, layout) and recovery files must touch neither the user's
    // configuration nor another GUI test program running at the same time.
    QTemporaryDir home;
    if (!home.isValid()) {
        std::fprintf(stderr, "cannot create a temporary folder\n");
        return 1;
    }
    speculum::ui::test::useTemporaryUserFolders(home);
    speculum::ui::installDefaultSurfaceFormat();
    QApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("speculum"));
    QApplication::setApplicationName(QStringLiteral("speculum-gui-tests"));
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
