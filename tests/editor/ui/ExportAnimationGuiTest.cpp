// File ▸ Export Animation: the dialog's defaults (one loop of the scene, the viewport's size, the format
// by the file name, a turntable's frames) and remembered choices; a clip and a PNG sequence of the teapot
// demo exported through the menu while the editor's event loop keeps running; the progress dialog and its
// Cancel (a sequence keeps its finished frames, a clip is not written); exact frames; and the document
// left as it was. With SPECULUM_SHOTS_DIR set, pictures of the dialog and of the progress.
#include "editor/ui/ExportAnimationDialog.hpp"
#include "editor/view/AnimationClock.hpp"
#include "render/video/VideoWriter.hpp"
#include "scene/model/Scene.hpp"
#include "scene/model/SceneAnimation.hpp"
#include "support/GuiTestSupport.hpp"
#include "support/TestPaths.hpp"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QProgressDialog>
#include <QPushButton>
#include <QScreen>
#include <QSpinBox>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>
#include <QUndoStack>
#include <QWindow>
#include <cmath>
#include <gtest/gtest.h>

namespace {

using namespace speculum;
using namespace speculum::ui::test;
using ui::ExportAnimationDialog;
using ui::MainWindow;

const QString kTeapotProject =
    QString::fromStdString(speculum::testSourcePath("resources/scenes/teapot.speculum.json"));

// Counts the event loop's timer ticks and the longest wait between two: how responsive the editor is.
class Heartbeat {
public:
    Heartbeat() {
        m_timer.setInterval(10);
        QObject::connect(&m_timer, &QTimer::timeout, [this] {
            if (m_since.isValid()) {
                m_longestGapMs = std::max(m_longestGapMs, m_since.elapsed());
            }
            m_since.restart();
            ++m_ticks;
        });
        m_timer.start();
    }
    int ticks() const { return m_ticks; }
    qint64 longestGapMs() const { return m_longestGapMs; }

private:
    QTimer m_timer;
    QElapsedTimer m_since;
    int m_ticks = 0;
    qint64 m_longestGapMs = 0;
};

class ExportAnimation : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(m_dir.isValid());
        m_window = std::make_unique<MainWindow>();
        m_window->resize(1280, 800);
        m_window->show();
        ASSERT_TRUE(
            waitFor([&] { return m_window->windowHandle() && m_window->windowHandle()->isExposed(); }));
        m_window->clock().setPlaying(false);
        m_window->setOpensExports(false); // no player opens during the tests
        auto status = m_window->openProjectFile(kTeapotProject);
        ASSERT_TRUE(status.ok()) << status.error();
        ASSERT_TRUE(waitForFrames(*m_window));
        m_undoSteps = m_window->undoStack().count();
    }

    void TearDown() override {
        if (m_window) {
            EXPECT_FALSE(m_window->isModified()) << "an export is no edit";
            EXPECT_EQ(m_window->undoStack().count(), m_undoSteps) << "an export adds no undo step";
            m_window.reset();
        }
    }

    QProgressDialog* progressDialog() const {
        return m_window->findChild<QProgressDialog*>(QStringLiteral("animationProgress"));
    }

    static scene::AnimationSettings smallClip(int frames) {
        scene::AnimationSettings s;
        s.still.width = 160;
        s.still.height = 90;
        s.frames = {0, frames - 1};
        s.fps = 24;
        return s;
    }

    bool waitForExportEnd(int timeoutMs = 300000) {
        return waitFor([&] { return !m_window->animationExportRunning(); }, timeoutMs);
    }

    QString shotsDir() const { return qEnvironmentVariable("SPECULUM_SHOTS_DIR"); }

    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;
    int m_undoSteps = 0;
};

template <typename T>
T* child(QWidget& parent, const char* name) {
    auto* found = parent.findChild<T*>(QString::fromLatin1(name));
    EXPECT_NE(found, nullptr) << "no " << name;
    return found;
}

TEST_F(ExportAnimation, DialogDefaultsFollowTheSceneAndTheTurntable) {
    const double loop = scene::animationLoopSeconds(m_window->scene());
    ExportAnimationDialog dialog(m_dir.filePath(QStringLiteral("teapot")), loop, QSize(641, 361),
                                 m_window.get());
    const int loopFrames = std::max(1, int(std::lround(loop * 24)));
    EXPECT_EQ(child<QSpinBox>(dialog, "animFirst")->value(), 0);
    EXPECT_EQ(child<QSpinBox>(dialog, "animLast")->value(), loopFrames - 1) << "one loop at 24 fps";
    EXPECT_EQ(child<QSpinBox>(dialog, "animFps")->value(), 24);
    EXPECT_EQ(child<QSpinBox>(dialog, "animWidth")->value(), 640) << "the viewport's size, made even";
    EXPECT_EQ(child<QSpinBox>(dialog, "animHeight")->value(), 360);
    EXPECT_TRUE(dialog.outputPath().endsWith(QStringLiteral("teapot.mp4")))
        << dialog.outputPath().toStdString();
    EXPECT_TRUE(dialog.framesNote().contains(QStringLiteral("one loop")))
        << dialog.framesNote().toStdString();

    // The format combo writes the name, and a typed name picks the format.
    auto* format = child<QComboBox>(dialog, "animFormat");
    format->setCurrentIndex(format->findData(QStringLiteral("png")));
    EXPECT_TRUE(dialog.outputPath().endsWith(QStringLiteral("teapot_%04d.png")))
        << dialog.outputPath().toStdString();
    format->setCurrentIndex(format->findData(QStringLiteral("gif")));
    EXPECT_TRUE(dialog.outputPath().endsWith(QStringLiteral("/teapot.gif")))
        << dialog.outputPath().toStdString();
    auto* path = child<QLineEdit>(dialog, "animPath");
    path->setText(m_dir.filePath(QStringLiteral("clip.webm")));
    emit path->textEdited(path->text());
    EXPECT_EQ(format->currentData().toString(), QStringLiteral("webm"));

    // A turntable of 2 s is 48 frames at 24 fps, 24 at 12.
    child<QCheckBox>(dialog, "animTurntable")->setChecked(true);
    child<QDoubleSpinBox>(dialog, "animTurnSeconds")->setValue(2.0);
    EXPECT_EQ(child<QSpinBox>(dialog, "animLast")->value(), 47);
    child<QSpinBox>(dialog, "animFps")->setValue(12);
    EXPECT_EQ(child<QSpinBox>(dialog, "animLast")->value(), 23);
    ASSERT_TRUE(dialog.settings().turntableSeconds.has_value());
    EXPECT_EQ(*dialog.settings().turntableSeconds, 2.0);

    // A bad name is refused in the dialog, with one line that names it.
    path->setText(m_dir.filePath(QStringLiteral("clip.xyz")));
    dialog.accept();
    EXPECT_EQ(dialog.result(), QDialog::Rejected);
    auto* error = child<QLabel>(dialog, "animError");
    EXPECT_FALSE(error->isHidden());
    EXPECT_TRUE(error->text().contains(QStringLiteral("clip.xyz"))) << error->text().toStdString();
    EXPECT_FALSE(error->text().contains(QLatin1Char('\n')));

    // A valid one is taken, and its choices are the next dialog's.
    path->setText(m_dir.filePath(QStringLiteral("clip.gif")));
    child<QSpinBox>(dialog, "animWidth")->setValue(320);
    dialog.accept();
    EXPECT_EQ(dialog.result(), QDialog::Accepted);
    ExportAnimationDialog next(m_dir.filePath(QStringLiteral("other")), loop, QSize(641, 361),
                               m_window.get());
    EXPECT_TRUE(next.outputPath().endsWith(QStringLiteral("other.gif"))) << next.outputPath().toStdString();
    EXPECT_EQ(next.settings().fps, 12);
    EXPECT_EQ(next.settings().still.width, 320);
    EXPECT_TRUE(next.settings().turntableSeconds.has_value());
    EXPECT_EQ(next.settings().frames.last, 23) << "the turntable's frames again";
}

// Through the menu, as a user: the dialog, Export, the progress while the event loop keeps running, then
// the files and the status bar.
TEST_F(ExportAnimation, SequenceThroughTheMenuWhileTheEditorRuns) {
    const QString pattern = m_dir.filePath(QStringLiteral("frames/teapot_%04d.png"));
    ASSERT_TRUE(QDir(m_dir.path()).mkpath(QStringLiteral("frames")));
    bool dialogSeen = false;
    QTimer::singleShot(0, [&] {
        auto* dialog = qobject_cast<ExportAnimationDialog*>(QApplication::activeModalWidget());
        ASSERT_NE(dialog, nullptr) << "the Export Animation dialog is up";
        dialogSeen = true;
        child<QComboBox>(*dialog, "animFormat")->setCurrentIndex(3); // PNG sequence
        child<QLineEdit>(*dialog, "animPath")->setText(pattern);
        // Before the frames: the first test's turntable and fps are remembered, and they set the frames.
        child<QCheckBox>(*dialog, "animTurntable")->setChecked(false);
        child<QSpinBox>(*dialog, "animFps")->setValue(24);
        child<QSpinBox>(*dialog, "animFirst")->setValue(0);
        child<QSpinBox>(*dialog, "animLast")->setValue(5);
        child<QSpinBox>(*dialog, "animWidth")->setValue(160);
        child<QSpinBox>(*dialog, "animHeight")->setValue(90);
        if (!shotsDir().isEmpty()) {
            EXPECT_TRUE(dialog->grab().save(shotsDir() + QStringLiteral("/export-animation-dialog.png")));
        }
        dialog->accept();
    });
    Heartbeat heartbeat;
    m_window->findChild<QAction*>(QStringLiteral("actionExportAnimation"))->trigger();
    ASSERT_TRUE(dialogSeen);
    ASSERT_TRUE(m_window->animationExportRunning()) << "the export runs after the dialog closes";
    ASSERT_NE(progressDialog(), nullptr);
    EXPECT_TRUE(progressDialog()->isVisible()) << "the progress shows from the start";
    const int ticksBefore = heartbeat.ticks();
    ASSERT_TRUE(waitForExportEnd());
    EXPECT_GT(heartbeat.ticks(), ticksBefore) << "the event loop ran while the frames were drawn";
    EXPECT_FALSE(progressDialog()->isVisible());

    ASSERT_TRUE(m_window->lastAnimationExport().has_value());
    const scene::AnimationResult& result = *m_window->lastAnimationExport();
    ASSERT_TRUE(result.status.ok()) << result.status.error();
    EXPECT_EQ(result.files.size(), 6u);
    EXPECT_EQ(scene::framesOnDisk(pattern.toStdString()), (std::vector<int>{0, 1, 2, 3, 4, 5}));
    const QImage first(QString::fromStdString(scene::sequenceFramePath(pattern.toStdString(), 0)));
    EXPECT_EQ(first.size(), QSize(160, 90));
    EXPECT_TRUE(m_window->statusBar()->currentMessage().startsWith(QStringLiteral("Exported 6 frames")))
        << m_window->statusBar()->currentMessage().toStdString();
}

// A clip through the window's own function: every frame is in it, at its size.
TEST_F(ExportAnimation, GifClipHoldsEveryFrame) {
    const QString clip = m_dir.filePath(QStringLiteral("teapot.gif"));
    scene::AnimationSettings settings = smallClip(6);
    settings.turntableSeconds = 0.25;
    ASSERT_TRUE(m_window->startAnimationExport(clip, settings).ok());
    ASSERT_TRUE(waitForExportEnd());
    ASSERT_TRUE(m_window->lastAnimationExport()->status.ok())
        << m_window->lastAnimationExport()->status.error();
    auto decoded = render::video::decodeVideo(clip.toStdString());
    ASSERT_TRUE(decoded.ok()) << decoded.error();
    EXPECT_EQ(decoded->frames.size(), 6u);
    EXPECT_EQ(decoded->width, 160);
    EXPECT_EQ(decoded->height, 90);
    EXPECT_TRUE(m_window->statusBar()->currentMessage().contains(QStringLiteral("teapot.gif")));
    // A refusal comes at once, before any work, and writes nothing.
    settings.fps = 0;
    auto refused = m_window->startAnimationExport(m_dir.filePath(QStringLiteral("refused.gif")), settings);
    ASSERT_FALSE(refused.ok());
    EXPECT_TRUE(QString::fromStdString(refused.error()).contains(QStringLiteral("fps")));
    EXPECT_FALSE(m_window->animationExportRunning());
    EXPECT_FALSE(QFileInfo::exists(m_dir.filePath(QStringLiteral("refused.gif"))));
}

// Cancel in the progress dialog: a sequence keeps the frames it finished, and says so.
TEST_F(ExportAnimation, CancelKeepsTheFinishedFramesOfASequence) {
    const std::string pattern = m_dir.filePath(QStringLiteral("long_%04d.png")).toStdString();
    scene::AnimationSettings settings = smallClip(400);
    settings.still.width = 320;
    settings.still.height = 180;
    Heartbeat heartbeat;
    ASSERT_TRUE(m_window->startAnimationExport(QString::fromStdString(pattern), settings).ok());
    ASSERT_TRUE(waitFor(
        [&] { return scene::framesOnDisk(pattern).size() >= 3 || !m_window->animationExportRunning(); }));
    ASSERT_TRUE(m_window->animationExportRunning()) << "400 frames take longer than 3";
    ASSERT_TRUE(waitFor([&] { return progressDialog()->labelText().contains(QStringLiteral("left")); }));
    if (!shotsDir().isEmpty()) {
        QApplication::processEvents();
        EXPECT_TRUE(QGuiApplication::primaryScreen()->grabWindow(0).save(
            shotsDir() + QStringLiteral("/export-animation-progress.png")));
    }
    EXPECT_TRUE(progressDialog()->labelText().contains(QStringLiteral(" of 400")))
        << progressDialog()->labelText().toStdString();
    progressDialog()->findChild<QPushButton*>()->click();
    ASSERT_TRUE(waitForExportEnd());
    EXPECT_GT(heartbeat.ticks(), 20);
    EXPECT_LT(heartbeat.longestGapMs(), 2000) << "the event loop never waits long for the export";

    const scene::AnimationResult& result = *m_window->lastAnimationExport();
    EXPECT_TRUE(result.cancelled);
    EXPECT_FALSE(result.status.ok());
    EXPECT_GE(result.written.size(), 3u);
    EXPECT_LT(result.written.size(), 400u);
    EXPECT_EQ(scene::framesOnDisk(pattern), result.written) << "the finished frames stay, none half-written";
    const QString message = m_window->statusBar()->currentMessage();
    EXPECT_TRUE(message.startsWith(QStringLiteral("Export cancelled; frames 0..")) &&
                message.contains(QStringLiteral("kept")))
        << message.toStdString();
}

// A cancelled clip leaves no file behind.
TEST_F(ExportAnimation, CancelWritesNoClip) {
    const QString clip = m_dir.filePath(QStringLiteral("long.gif"));
    scene::AnimationSettings settings = smallClip(400);
    ASSERT_TRUE(m_window->startAnimationExport(clip, settings).ok());
    ASSERT_TRUE(
        waitFor([&] { return progressDialog()->value() >= 10 || !m_window->animationExportRunning(); }));
    ASSERT_TRUE(m_window->animationExportRunning());
    m_window->cancelAnimationExport();
    ASSERT_TRUE(waitForExportEnd());
    EXPECT_TRUE(m_window->lastAnimationExport()->cancelled);
    EXPECT_FALSE(QFileInfo::exists(clip));
    EXPECT_EQ(QDir(m_dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList())
        << "no partial clip, no temporary file";
    EXPECT_EQ(m_window->statusBar()->currentMessage(),
              QStringLiteral("Export cancelled; no clip was written."));
}

// Exact frames are traced on the worker with no GL context.
TEST_F(ExportAnimation, ExactFramesAreTraced) {
    const std::string pattern = m_dir.filePath(QStringLiteral("exact_%02d.png")).toStdString();
    scene::AnimationSettings settings = smallClip(2);
    settings.still.width = 48;
    settings.still.height = 27;
    settings.still.reference = true;
    settings.still.samples = 1;
    ASSERT_TRUE(m_window->startAnimationExport(QString::fromStdString(pattern), settings).ok());
    ASSERT_TRUE(waitForExportEnd());
    const scene::AnimationResult& result = *m_window->lastAnimationExport();
    ASSERT_TRUE(result.status.ok()) << result.status.error();
    EXPECT_EQ(scene::framesOnDisk(pattern), (std::vector<int>{0, 1}));
    EXPECT_NE(result.renderer.find("reference"), std::string::npos) << result.renderer;
}

// Closing the editor during an export stops it (the worker waits on the GUI thread for its frames) and
// keeps what was finished.
TEST_F(ExportAnimation, ClosingTheEditorStopsAnExport) {
    const std::string pattern = m_dir.filePath(QStringLiteral("closed_%04d.png")).toStdString();
    ASSERT_TRUE(m_window->startAnimationExport(QString::fromStdString(pattern), smallClip(400)).ok());
    ASSERT_TRUE(waitFor([&] { return !scene::framesOnDisk(pattern).empty(); }));
    m_window.reset();
    const auto kept = scene::framesOnDisk(pattern);
    ASSERT_FALSE(kept.empty());
    EXPECT_LT(kept.size(), 400u);
    EXPECT_EQ(kept.back() + 1, int(kept.size())) << "the frames kept are the first ones, complete";
}

} // namespace
