// View ▸ Inspect Pixel as a user drives it: a click on the chrome ball explains that pixel in the Pixel
// Inspector (its exact path, the raster's recipe, why they differ), draws the path in the view where it stays
// while the view orbits, and a step selects the node it touched; turning the tool off clears the path.
#include "editor/ui/Viewport.hpp"
#include "editor/view/AnimationClock.hpp"
#include "editor/view/Selection.hpp"
#include "scene/model/Scene.hpp"
#include "support/GuiTestSupport.hpp"
#include "support/TestPaths.hpp"

#include <QAction>
#include <QTest>
#include <QTreeWidget>
#include <QWindow>
#include <gtest/gtest.h>

namespace {

using namespace speculum;
using namespace speculum::ui::test;

QTreeWidgetItem* topItem(QTreeWidget& tree, const QString& text) {
    for (int i = 0; i < tree.topLevelItemCount(); ++i)
        if (tree.topLevelItem(i)->text(0) == text)
            return tree.topLevelItem(i);
    return nullptr;
}

TEST(PixelInspector, AClickOnTheBallExplainsItsPixelAndDrawsItsPath) {
    ui::MainWindow window;
    window.resize(1400, 900);
    window.show();
    ASSERT_TRUE(waitFor([&] { return window.windowHandle() && window.windowHandle()->isExposed(); }));
    window.clock().setPlaying(false);
    const QString project = QString::fromStdString(testSourcePath("resources/scenes/chrome.speculum.json"));
    ASSERT_TRUE(window.openProjectFile(project).ok());
    ASSERT_TRUE(waitForFrames(window));

    auto* tool = window.findChild<QAction*>(QStringLiteral("inspectPixelAction"));
    ASSERT_NE(tool, nullptr);
    tool->trigger();
    ui::Viewport& viewport = window.viewport();
    EXPECT_TRUE(viewport.inspecting());
    // The chrome ball stands at the middle of the demo's view.
    QTest::mouseClick(&viewport, Qt::LeftButton, Qt::NoModifier, viewport.rect().center());
    auto* tree = window.findChild<QTreeWidget*>(QStringLiteral("inspectTree"));
    ASSERT_NE(tree, nullptr);
    ASSERT_TRUE(waitFor([&] { return topItem(*tree, "Exact path") != nullptr; }));
    QTreeWidgetItem* path = topItem(*tree, "Exact path");
    ASSERT_GT(path->childCount(), 1);
    EXPECT_EQ(path->child(0)->text(0), "reflector Chrome ball");
    QTreeWidgetItem* recipe = topItem(*tree, "Raster recipe");
    ASSERT_NE(recipe, nullptr);
    bool lookup = false, main = false;
    for (int i = 0; i < recipe->childCount(); ++i) {
        lookup = lookup || recipe->child(i)->text(0) == "map lookup";
        main = main || recipe->child(i)->text(0) == "main";
    }
    EXPECT_TRUE(lookup);
    EXPECT_TRUE(main);
    EXPECT_NE(topItem(*tree, "Why they differ"), nullptr);
    // The path is drawn: the camera ray first, from the camera to the ball; it stays while the view orbits.
    const std::vector<render::GuideLine> lines = viewport.inspectedPath();
    ASSERT_GE(lines.size(), 2u);
    EXPECT_LT(glm::length(lines[0].from - viewport.viewPositionTarget().first), 1e-6);
    viewport.orbitView(30.0, 0.0);
    ASSERT_TRUE(waitForFrames(window));
    EXPECT_EQ(viewport.inspectedPath().size(), lines.size());
    EXPECT_EQ(viewport.inspectedPath()[0].to, lines[0].to);
    // A step selects the node it touched, and its segment of the path is drawn wider.
    tree->setCurrentItem(path->child(0));
    EXPECT_GT(viewport.inspectedPath()[0].width, lines[0].width);
    const scene::Node* selected = window.selection().selectedNode();
    ASSERT_NE(selected, nullptr);
    EXPECT_EQ(selected->name(), "Chrome ball");
    // Off, the tool clicks select again and the path is gone.
    tool->trigger();
    EXPECT_FALSE(viewport.inspecting());
    EXPECT_TRUE(viewport.inspectedPath().empty());
}

} // namespace
