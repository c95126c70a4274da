// The wheel never edits an unfocused field (the Properties panel scrolls
// instead, no undo step); a tiny scale shows as itself and can be edited; the reflector's parallax proxy is
// in the inspector and round-trips through the project file; Export Still's exact reference writes an
// image and a cancelled one writes nothing; the Accuracy panel explains its numbers, labels chart points
// with their settings and forgets the previous document on New.
#include "editor/ui/AccuracyPanel.hpp"
#include "editor/ui/Inspector.hpp"
#include "editor/ui/PropertyEditors.hpp"
#include "editor/ui/SweepChart.hpp"
#include "editor/view/Selection.hpp"
#include "scene/model/Scene.hpp"
#include "support/GuiTestSupport.hpp"
#include "support/TestPaths.hpp"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QScrollArea>
#include <QScrollBar>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>
#include <QWheelEvent>
#include <QtTest/qtestspontaneevent.h>
#include <gtest/gtest.h>

namespace speculum::ui {
namespace {

using test::waitFor;
using test::waitForFrames;

const QString kChrome =
    QString::fromStdString(speculum::testSourcePath("resources/scenes/chrome.speculum.json"));

scene::NodeId findNode(const scene::Scene& scene, bool (*pick)(const scene::NodeData&)) {
    scene::NodeId found = scene::kNoNode;
    scene.forEachNode([&](const scene::Node& node) {
        if (found == scene::kNoNode && pick(node.data())) {
            found = node.id();
        }
    });
    return found;
}

bool isReflector(const scene::NodeData& d) {
    return d.reflector.has_value();
}

void wheelOver(QWidget* widget) {
    const QPointF local(widget->width() / 2.0, widget->height() / 2.0);
    QWheelEvent event(local, widget->mapToGlobal(local), QPoint(), QPoint(0, -120), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    // As from the window system: only such wheel events travel on to the parent when ignored.
    QSpontaneKeyEvent::setSpontaneous(&event);
    qApp->notify(widget, &event); // sendEvent would clear the spontaneous flag
}

class InspectorInputTest : public ::testing::Test {
protected:
    void SetUp() override {
        m_window = std::make_unique<MainWindow>();
        m_window->resize(1200, 500); // short: the Properties panel has to scroll
        m_window->show();
        ASSERT_TRUE(m_window->openProjectFile(kChrome).ok());
        ASSERT_TRUE(waitForFrames(*m_window, 1));
    }
    scene::Scene& scene() { return m_window->scene(); }
    template <typename W>
    W* field(const char* name) {
        return m_window->inspector().findChild<W*>(QString::fromLatin1(name));
    }

    std::unique_ptr<MainWindow> m_window;
};

TEST_F(InspectorInputTest, WheelOverAnUnfocusedFieldScrollsThePanelAndEditsNothing) {
    const scene::NodeId id = findNode(scene(), isReflector);
    ASSERT_NE(id, scene::kNoNode);
    m_window->selection().selectNode(id);
    QCoreApplication::processEvents();
    auto* scroll = m_window->inspector().findChild<QScrollArea*>();
    ASSERT_NE(scroll, nullptr);
    ASSERT_GT(scroll->verticalScrollBar()->maximum(), 0) << "the panel should be taller than the window";
    const int undoBefore = m_window->undoStack().count();
    const scene::NodeData before = scene().findNode(id)->data();
    m_window->viewport().setFocus();
    for (const char* name : {"reflector.resolution", "reflector.map", "reflector.reflectivity.slider",
                             "transform.translate.x"}) {
        QWidget* w = field<QWidget>(name);
        ASSERT_NE(w, nullptr) << name;
        ASSERT_FALSE(w->hasFocus());
        const int scrolled = scroll->verticalScrollBar()->value();
        wheelOver(w);
        QCoreApplication::processEvents();
        EXPECT_EQ(scene().findNode(id)->data(), before) << name;
        EXPECT_EQ(m_window->undoStack().count(), undoBefore) << name;
        if (scrolled < scroll->verticalScrollBar()->maximum()) {
            EXPECT_GT(scroll->verticalScrollBar()->value(), scrolled) << name << ": the panel should scroll";
        }
    }
    // Focused, the wheel edits as before (where the display lets the window take the focus).
    m_window->activateWindow();
    if (!QTest::qWaitForWindowActive(m_window.get(), 2000)) {
        return;
    }
    auto* resolution = field<QDoubleSpinBox>("reflector.resolution");
    resolution->setFocus();
    ASSERT_TRUE(waitFor([&] { return resolution->hasFocus(); }, 2000));
    wheelOver(resolution);
    QCoreApplication::processEvents();
    EXPECT_NE(scene().findNode(id)->data(), before);
}

TEST_F(InspectorInputTest, ATinyScaleShowsAsItselfAndEditsInOneStep) {
    const scene::NodeId id = findNode(scene(), isReflector);
    scene::NodeData data = scene().findNode(id)->data();
    data.transform.scale = glm::dvec3(5e-5);
    scene().setNodeData(id, data);
    m_window->selection().selectNode(id);
    QCoreApplication::processEvents();
    auto* x = field<QDoubleSpinBox>("transform.scale.x");
    ASSERT_NE(x, nullptr);
    EXPECT_DOUBLE_EQ(x->value(), 5e-5);
    EXPECT_NE(x->text(), QStringLiteral("X 0.000"));
    EXPECT_TRUE(x->text().contains(QStringLiteral("5e-05"))) << x->text().toStdString();
    EXPECT_EQ(PropertyEditor::numberText(0.25, 3), QStringLiteral("0.250"));

    const int undoBefore = m_window->undoStack().count();
    x->setFocus();
    x->selectAll();
    QTest::keyClicks(x, QStringLiteral("6e-05"));
    QTest::keyClick(x, Qt::Key_Return);
    QCoreApplication::processEvents();
    EXPECT_TRUE(m_window->inspector().errorText().isEmpty())
        << m_window->inspector().errorText().toStdString();
    EXPECT_DOUBLE_EQ(scene().findNode(id)->data().transform.scale.x, 6e-5);
    EXPECT_DOUBLE_EQ(scene().findNode(id)->data().transform.scale.y, 5e-5); // only x was edited
    EXPECT_EQ(m_window->undoStack().count(), undoBefore + 1);
    x = field<QDoubleSpinBox>("transform.scale.x"); // the inspector may have rebuilt its editors
    ASSERT_NE(x, nullptr);
    EXPECT_TRUE(x->text().contains(QStringLiteral("6e-05"))) << x->text().toStdString();
    // One step back is the value before the edit.
    m_window->undoStack().undo();
    EXPECT_DOUBLE_EQ(scene().findNode(id)->data().transform.scale.x, 5e-5);
    EXPECT_EQ(m_window->undoStack().count(), undoBefore + 1);
    EXPECT_EQ(m_window->undoStack().index(), undoBefore);
    // Numbers that fit three decimals keep showing that way; the typed forms parse either way.
    EXPECT_EQ(PropertyEditor::numberText(1.5, 3), QStringLiteral("1.500"));
    EXPECT_EQ(PropertyEditor::numberText(5e-5, 3), QStringLiteral("5e-05"));
    EXPECT_EQ(PropertyEditor::numberText(0.0, 3), QStringLiteral("0.000"));
}

TEST_F(InspectorInputTest, ParallaxProxyIsEditableAndRoundTrips) {
    const scene::NodeId id = findNode(scene(), isReflector);
    m_window->selection().selectNode(id);
    QCoreApplication::processEvents();
    ASSERT_NE(m_window->inspector().editor(QStringLiteral("reflector.parallax")), nullptr);
    const int undoBefore = m_window->undoStack().count();
    ASSERT_TRUE(m_window->inspector().applyValue(QStringLiteral("reflector.parallax"), 2).ok());
    EXPECT_EQ(m_window->undoStack().count(), undoBefore + 1);
    QCoreApplication::processEvents();
    ASSERT_NE(m_window->inspector().editor(QStringLiteral("reflector.parallax.max")), nullptr);
    EXPECT_FALSE(m_window->inspector()
                     .applyValue(QStringLiteral("reflector.parallax.min"), QVariantList{1.0, -1.0, -1.0})
                     .ok()); // the box must contain the capture point
    ASSERT_TRUE(m_window->inspector()
                    .applyValue(QStringLiteral("reflector.parallax.max"), QVariantList{3.0, 4.0, 5.0})
                    .ok());
    const auto proxy = scene().findNode(id)->data().reflector->parallax;
    ASSERT_TRUE(proxy.has_value());
    EXPECT_EQ(proxy->shape, scene::ParallaxShape::Box);

    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("proxy.speculum.json"));
    ASSERT_TRUE(m_window->saveProjectFile(path).ok());
    ASSERT_TRUE(m_window->openProjectFile(path).ok());
    const scene::NodeId again = findNode(scene(), isReflector);
    const auto loaded = scene().findNode(again)->data().reflector->parallax;
    ASSERT_TRUE(loaded.has_value());
    EXPECT_EQ(loaded->shape, scene::ParallaxShape::Box);
    EXPECT_EQ(loaded->max, glm::dvec3(3.0, 4.0, 5.0));
    m_window->undoStack().clear();
}

// A choice that adds rows (the parallax proxy's box fields) rebuilds the panel: it stays scrolled where it
// was, not back at the top.
TEST_F(InspectorInputTest, AChoiceThatAddsRowsKeepsTheScrollPosition) {
    const scene::NodeId id = findNode(scene(), isReflector);
    m_window->selection().selectNode(id);
    QCoreApplication::processEvents();
    auto* scroll = m_window->inspector().findChild<QScrollArea*>();
    ASSERT_NE(scroll, nullptr);
    ASSERT_GT(scroll->verticalScrollBar()->maximum(), 0) << "the panel should be taller than the window";
    // Off first, so that choosing a box adds rows.
    ASSERT_TRUE(m_window->inspector().applyValue(QStringLiteral("reflector.parallax"), 0).ok());
    QCoreApplication::processEvents();
    const int scrolled = scroll->verticalScrollBar()->maximum() * 2 / 3;
    scroll->verticalScrollBar()->setValue(scrolled);
    ASSERT_TRUE(m_window->inspector().applyValue(QStringLiteral("reflector.parallax"), 2).ok());
    QCoreApplication::processEvents();
    ASSERT_NE(m_window->inspector().editor(QStringLiteral("reflector.parallax.max")), nullptr)
        << "rows added";
    EXPECT_EQ(scroll->verticalScrollBar()->value(), scrolled);
    // Another node starts at the top.
    m_window->selection().selectNode(
        findNode(scene(), [](const scene::NodeData& d) { return d.light.has_value(); }));
    QCoreApplication::processEvents();
    EXPECT_EQ(scroll->verticalScrollBar()->value(), 0);
    m_window->undoStack().clear();
}

// A rough mirror set to the stencil technique is drawn with the texture technique: its Technique field
// says so, and stops saying it when it is no longer true.
TEST_F(InspectorInputTest, ARoughMirrorsTechniqueSaysHowItIsDrawn) {
    ASSERT_TRUE(m_window
                    ->openProjectFile(QString::fromStdString(
                        speculum::testSourcePath("resources/scenes/mirrors.speculum.json")))
                    .ok());
    const scene::NodeId mirror = findNode(
        scene(), [](const scene::NodeData& d) { return d.mirror.has_value() && d.mirror->roughness > 0.0; });
    ASSERT_NE(mirror, scene::kNoNode) << "the mirrors demo has a rough mirror";
    m_window->selection().selectNode(mirror);
    QCoreApplication::processEvents();
    Inspector& inspector = m_window->inspector();
    ASSERT_TRUE(inspector.applyValue(QStringLiteral("mirror.technique"), 0).ok()); // stencil
    QCoreApplication::processEvents();
    auto* note = inspector.findChild<QLabel*>(QStringLiteral("mirror.technique.note"));
    ASSERT_NE(note, nullptr);
    EXPECT_TRUE(note->isVisibleTo(&inspector));
    EXPECT_TRUE(note->text().contains(QStringLiteral("texture technique"))) << note->text().toStdString();
    ASSERT_TRUE(inspector.applyValue(QStringLiteral("mirror.technique"), 1).ok()); // texture
    QCoreApplication::processEvents();
    EXPECT_FALSE(note->isVisibleTo(&inspector)) << "drawn as it says";
    ASSERT_TRUE(inspector.applyValue(QStringLiteral("mirror.technique"), 0).ok());
    ASSERT_TRUE(inspector.applyValue(QStringLiteral("mirror.roughness"), 0.0).ok());
    QCoreApplication::processEvents();
    EXPECT_FALSE(note->isVisibleTo(&inspector)) << "a sharp mirror is drawn with the stencil technique";
    m_window->undoStack().clear();
}

TEST_F(InspectorInputTest, ExportStillExactReferenceWritesAndCancelWritesNothing) {
    QTemporaryDir dir;
    scene::StillExportSettings settings;
    settings.width = 48;
    settings.height = 32;
    settings.reference = true;
    const QString path = dir.filePath(QStringLiteral("exact.png"));
    double lastFraction = -1.0;
    auto done = m_window->exportStillFile(path, settings, [&](double f, const std::string&) {
        lastFraction = f;
        return true;
    });
    ASSERT_TRUE(done.ok()) << done.error();
    EXPECT_TRUE(QFile::exists(path));
    EXPECT_GE(lastFraction, 0.0);
    EXPECT_EQ(done->still.image.width, 48);

    const QString cancelled = dir.filePath(QStringLiteral("cancelled.png"));
    auto stopped =
        m_window->exportStillFile(cancelled, settings, [](double, const std::string&) { return false; });
    EXPECT_FALSE(stopped.ok());
    EXPECT_FALSE(QFile::exists(cancelled));
}

TEST_F(InspectorInputTest, AccuracyPanelExplainsLabelsAndClearsOnNew) {
    AccuracyPanel& panel = m_window->accuracyPanel();
    EXPECT_TRUE(panel.explanationText().contains(QStringLiteral("PSNR")));
    EXPECT_TRUE(panel.explanationText().contains(QStringLiteral("RMSE")));

    accuracy::ResultsFile results;
    accuracy::Record record;
    record.config.family = accuracy::Family::Envmap;
    record.config.label = "64";
    record.settings = {{"map", "cube"}, {"resolution", "64"}};
    record.gpuMs = 2.0;
    record.cpuMs = 3.0;
    record.psnr = 31.0;
    results.records.push_back(record);
    panel.chart().setResults(results);
    panel.chart().hoverRecord(0);
    EXPECT_TRUE(panel.chart().hoverText().contains(QStringLiteral("resolution 64")))
        << panel.chart().hoverText().toStdString();
    panel.chart().hoverRecord(-1);
    EXPECT_TRUE(panel.chart().hoverText().isEmpty());

    panel.chart().setResults(results);
    ASSERT_EQ(panel.chart().pointCount(), 1);
    m_window->newProject();
    QCoreApplication::processEvents();
    EXPECT_EQ(panel.chart().pointCount(), 0);
    EXPECT_FALSE(panel.lastComparison().has_value());
    EXPECT_EQ(panel.findChild<QLabel*>(QStringLiteral("accuracyPsnr"))->text(), QStringLiteral("—"));
}

// A picture of the Accuracy panel after a comparison, for people to look at (SPECULUM_SHOTS_DIR set).
TEST_F(InspectorInputTest, AccuracyPanelScreenshotAfterAComparison) {
    const QString shots = qEnvironmentVariable("SPECULUM_SHOTS_DIR");
    if (shots.isEmpty()) {
        GTEST_SKIP() << "set SPECULUM_SHOTS_DIR to write the screenshot";
    }
    m_window->resize(1600, 950);
    auto* dock = m_window->findChild<QDockWidget*>(QStringLiteral("accuracyDock"));
    ASSERT_NE(dock, nullptr);
    dock->toggleViewAction()->trigger();
    ASSERT_TRUE(waitForFrames(*m_window, 2));
    EXPECT_TRUE(m_window->inspector().isVisible()) << "the Accuracy dock must not hide the Properties";
    m_window->accuracyPanel().setPreviewWidth(240);
    m_window->accuracyPanel().compareWithExact();
    ASSERT_TRUE(waitFor([&] { return m_window->accuracyPanel().lastComparison().has_value(); }, 300000));
    QCoreApplication::processEvents();
    ASSERT_TRUE(waitForFrames(*m_window, 1));
    EXPECT_TRUE(m_window->grab().save(shots + QStringLiteral("/accuracy-panel.png")));
}

// The Properties dock at the window's first size and at a laptop's: every number field is shown whole
// (a vector's three, with their text), opening the Accuracy panel beside it does not squeeze it, and
// closing that panel gives its room back to the viewport, not to the Properties.
class InspectorLayoutTest : public ::testing::TestWithParam<QSize> {};

// Fields of the inspector cut off on the right or narrower than their text needs, by name.
QStringList cutFields(Inspector& inspector) {
    QStringList cut;
    auto* scroll = inspector.findChild<QScrollArea*>();
    for (QDoubleSpinBox* spin : inspector.findChildren<QDoubleSpinBox*>()) {
        if (!spin->isVisibleTo(&inspector))
            continue;
        const int right = spin->mapTo(scroll->viewport(), QPoint(spin->width(), 0)).x();
        if (spin->width() < spin->minimumSizeHint().width() || right > scroll->viewport()->width())
            cut.append(spin->objectName());
    }
    return cut;
}

TEST_P(InspectorLayoutTest, VectorsFitAndTheAccuracyPanelGivesItsRoomBack) {
    MainWindow window;
    if (GetParam().isValid())
        window.resize(GetParam());
    window.show();
    ASSERT_TRUE(window
                    .openProjectFile(QString::fromStdString(
                        speculum::testSourcePath("resources/scenes/teapot.speculum.json")))
                    .ok());
    ASSERT_TRUE(waitForFrames(window, 1));
    // Nothing selected: the scene's settings and its camera, whose position is a vector.
    window.selection().clear();
    QCoreApplication::processEvents();
    ASSERT_NE(window.inspector().findChild<QDoubleSpinBox*>(QStringLiteral("camera.position.z")), nullptr);
    EXPECT_EQ(cutFields(window.inspector()), QStringList{}) << "at the first layout";

    auto* properties = window.findChild<QDockWidget*>(QStringLiteral("inspectorDock"));
    auto* accuracy = window.findChild<QDockWidget*>(QStringLiteral("accuracyDock"));
    ASSERT_NE(properties, nullptr);
    ASSERT_NE(accuracy, nullptr);
    const int propertiesWidth = properties->width();
    const int viewportWidth = window.viewport().width();
    const int windowWidth = window.width();
    accuracy->toggleViewAction()->trigger();
    ASSERT_TRUE(waitFor([&] { return accuracy->isVisible(); }));
    waitFor([] { return false; }, 300); // its layout settles
    EXPECT_EQ(window.width(), windowWidth) << "the window does not grow to make room";
    const bool tabbed = window.tabifiedDockWidgets(properties).contains(accuracy);
    EXPECT_EQ(tabbed, GetParam().width() < 1600) << "beside the Properties only where there is room";
    if (tabbed) {
        EXPECT_EQ(window.viewport().width(), viewportWidth) << "tabbed with the Properties: no room taken";
    } else {
        EXPECT_GE(window.viewport().width(), 480) << "beside them, where the viewport keeps 480 pixels";
        EXPECT_EQ(cutFields(window.inspector()), QStringList{}) << "beside the Accuracy panel";
        EXPECT_GE(properties->width(), propertiesWidth - 2) << "its room came from the viewport";
    }

    accuracy->toggleViewAction()->trigger();
    ASSERT_TRUE(waitFor([&] { return !accuracy->isVisible(); }));
    ASSERT_TRUE(waitFor([&] { return std::abs(window.viewport().width() - viewportWidth) <= 2; }, 5000))
        << "closed, its room goes back to the viewport: " << window.viewport().width() << " against "
        << viewportWidth;
    EXPECT_LE(std::abs(properties->width() - propertiesWidth), 2);
    window.undoStack().setClean();
}

// The window's first size and a laptop's tab the Accuracy panel with the Properties; a wide screen's has
// room for it beside them.
INSTANTIATE_TEST_SUITE_P(WindowSizes, InspectorLayoutTest,
                         ::testing::Values(QSize(), QSize(1280, 800), QSize(1900, 1000)),
                         [](const auto& info) {
                             return !info.param.isValid()       ? "FirstSize"
                                    : info.param.width() < 1600 ? "Laptop"
                                                                : "WideScreen";
                         });

} // namespace
} // namespace speculum::ui
