// Crash recovery as it really happens: an editor in a child process (this program started again with
// --edit-then-wait) opens a project, moves the teapot through the undo stack, and is killed with SIGKILL
// once its autosave (every second, by SPECULUM_AUTOSAVE_SECONDS) is on disk. The next editor offers the
// unsaved edit: accepted, the edit is back; declined, the project file is as it was and nothing is
// offered again. Both processes keep settings and recovery files in a temporary XDG home, never the
// user's.
#include "editor/document/Commands.hpp"
#include "editor/ui/Editor.hpp"
#include "scene/project/ProjectFile.hpp"
#include "support/GuiTestSupport.hpp"
#include "support/TestPaths.hpp"

#include <QAbstractButton>
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QMessageBox>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>
#include <csignal>
#include <cstdio>
#include <gtest/gtest.h>
#include <optional>
#include <signal.h>

namespace {

using namespace speculum;
using namespace speculum::ui::test;

const char* kChildArgument = "--edit-then-wait";
constexpr double kMovedBy = 0.5; // how far the child moves the teapot up

void nameTheApplication() {
    // As the editor names itself, so recovery files and settings land where the editor's would.
    QApplication::setOrganizationName(QStringLiteral("speculum"));
    QApplication::setApplicationName(QStringLiteral("speculum"));
}

const speculum::scene::Node* teapot(const speculum::scene::Scene& scene) {
    for (const auto& node : scene.topLevelNodes()) {
        if (node->data().name == "Teapot") {
            return node.get();
        }
    }
    return nullptr;
}

std::optional<double> teapotHeight(const QString& projectPath) {
    std::vector<std::string> warnings;
    auto data = speculum::scene::loadProject(projectPath, warnings);
    if (!data) {
        return std::nullopt;
    }
    for (const auto& node : data->nodes) {
        if (node.data.name == "Teapot") {
            return node.data.transform.translate.y;
        }
    }
    return std::nullopt;
}

// The child: an editor that makes one edit and then runs until it is killed.
int editThenWait(int argc, char** argv, const QString& project) {
    ui::installDefaultSurfaceFormat();
    QApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    QApplication app(argc, argv);
    nameTheApplication();
    // Not shown: the viewport's first frame (shader compilation on llvmpipe) would only delay the
    // autosave, which works on the document whether or not it is on screen.
    ui::MainWindow window;
    if (!window.openProjectFile(project)) {
        return 2;
    }
    const speculum::scene::Node* node = teapot(window.scene());
    if (!node) {
        return 3;
    }
    speculum::scene::NodeData moved = node->data();
    moved.transform.translate.y += kMovedBy;
    window.undoStack().push(
        new document::SetNodeDataCommand(window.scene(), node->id(), moved, QStringLiteral("Move Teapot")));
    return app.exec(); // autosaving every SPECULUM_AUTOSAVE_SECONDS, until SIGKILL
}

class CrashRecovery : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(m_dir.isValid());
        // A copy of the demo project (and its texture): the file the user would have open.
        const QString scenes = QString::fromStdString(speculum::testSourcePath("resources/scenes"));
        m_project = m_dir.filePath(QStringLiteral("teapot.speculum.json"));
        ASSERT_TRUE(QFile::copy(scenes + QStringLiteral("/teapot.speculum.json"), m_project));
        ASSERT_TRUE(QDir(m_dir.path()).mkpath(QStringLiteral("textures")));
        ASSERT_TRUE(QFile::copy(scenes + QStringLiteral("/textures/marble.png"),
                                m_dir.filePath(QStringLiteral("textures/marble.png"))));
        m_original = readAll(m_project);
        m_height = teapotHeight(m_project).value_or(-1e9);
        ASSERT_NE(m_height, -1e9);
        // Where every editor keeps its recovery files (RecoveryStore::forThisProcess); empty to begin with.
        m_recovery = speculum::scene::RecoveryStore::forThisProcess().folder();
        ASSERT_TRUE(m_recovery.startsWith(qEnvironmentVariable("XDG_DATA_HOME"))) << m_recovery.toStdString();
        QDir(m_recovery).removeRecursively();
    }

    static QByteArray readAll(const QString& path) {
        QFile file(path);
        return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
    }

    // Starts an editor that edits the project, waits until its autosave holds the edit, and kills it.
    void crashAfterAutosave() {
        QProcess child;
        QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
        environment.insert(QStringLiteral("SPECULUM_AUTOSAVE_SECONDS"), QStringLiteral("1"));
        child.setProcessEnvironment(environment);
        child.setProcessChannelMode(QProcess::ForwardedChannels);
        child.start(QCoreApplication::applicationFilePath(),
                    {QString::fromLatin1(kChildArgument), m_project});
        ASSERT_TRUE(child.waitForStarted(10000)) << child.errorString().toStdString();
        const qint64 pid = child.processId();
        const QString scene = m_recovery + QStringLiteral("/recovery-%1.speculum.json").arg(pid);
        const QString note = m_recovery + QStringLiteral("/recovery-%1.note.json").arg(pid);
        // The note is written after the scene: once it is there, the scene is complete.
        const bool saved = waitFor(
            [&] {
                if (child.state() == QProcess::NotRunning || !QFile::exists(note)) {
                    return false;
                }
                const auto height = teapotHeight(scene);
                return height && std::abs(*height - (m_height + kMovedBy)) < 1e-9;
            },
            60000);
        ASSERT_EQ(child.state(), QProcess::Running)
            << "the editor exited by itself, status " << child.exitCode();
        ASSERT_TRUE(saved) << "no autosave with the edit in " << m_recovery.toStdString();
        ASSERT_EQ(::kill(static_cast<pid_t>(pid), SIGKILL), 0);
        ASSERT_TRUE(child.waitForFinished(10000));
        EXPECT_EQ(child.exitStatus(), QProcess::CrashExit);
        EXPECT_EQ(readAll(m_project), m_original) << "the killed editor never saved the project";
    }

    // Answers the next message box with `button`, keeping its text.
    void answerNextQuestion(QMessageBox::StandardButton button) {
        auto* timer = new QTimer(qApp);
        timer->setInterval(20);
        QObject::connect(timer, &QTimer::timeout, timer, [this, timer, button] {
            if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
                m_question = box->text();
                box->button(button)->click();
                timer->deleteLater();
            }
        });
        timer->start();
    }

    QTemporaryDir m_dir;
    QString m_project;
    QByteArray m_original;
    double m_height = 0.0;
    QString m_recovery;
    QString m_question;
};

TEST_F(CrashRecovery, NextEditorOffersTheKilledEditorsEditAndRestoresIt) {
    ASSERT_NO_FATAL_FAILURE(crashAfterAutosave());
    ui::MainWindow window;
    answerNextQuestion(QMessageBox::Yes);
    window.offerRecovery();
    EXPECT_TRUE(m_question.contains(QStringLiteral("teapot.speculum.json"))) << m_question.toStdString();

    const speculum::scene::Node* node = teapot(window.scene());
    ASSERT_NE(node, nullptr) << "the project is open again";
    EXPECT_NEAR(node->data().transform.translate.y, m_height + kMovedBy, 1e-9) << "with the edit";
    EXPECT_EQ(window.scene().projectPath(), QFileInfo(m_project).absoluteFilePath());
    EXPECT_TRUE(window.isModified()) << "unsaved, as it was when the editor died";
    EXPECT_EQ(readAll(m_project), m_original) << "restoring does not write the project";
    EXPECT_TRUE(window.recoveryStore().orphans().empty()) << "offered once";

    // Saving makes it the project, and leaves nothing to recover.
    ASSERT_TRUE(window.saveProjectFile(m_project).ok());
    EXPECT_NEAR(teapotHeight(m_project).value_or(0.0), m_height + kMovedBy, 1e-9);
    EXPECT_TRUE(QDir(m_recovery).isEmpty(QDir::Files));
}

TEST_F(CrashRecovery, DecliningKeepsTheProjectFileAsItWasAndAsksNoMore) {
    ASSERT_NO_FATAL_FAILURE(crashAfterAutosave());
    {
        ui::MainWindow window;
        answerNextQuestion(QMessageBox::No);
        window.offerRecovery();
        EXPECT_TRUE(m_question.contains(QStringLiteral("teapot.speculum.json"))) << m_question.toStdString();
        EXPECT_EQ(teapot(window.scene()), nullptr) << "the editor starts with a new document";
        EXPECT_FALSE(window.isModified());
    }
    EXPECT_EQ(readAll(m_project), m_original);
    EXPECT_TRUE(QDir(m_recovery).isEmpty(QDir::Files)) << "the declined edit is gone";

    ui::MainWindow next;
    EXPECT_TRUE(next.recoveryStore().orphans().empty()) << "a later editor is not asked again";
    EXPECT_TRUE(next.openProjectFile(m_project).ok());
    EXPECT_NEAR(teapot(next.scene())->data().transform.translate.y, m_height, 1e-9);
}

} // namespace

int main(int argc, char** argv) {
    if (argc == 3 && std::string(argv[1]) == kChildArgument) {
        return editThenWait(argc, argv, QString::fromLocal8Bit(argv[2]));
    }
    // Settings and recovery files of this process and its children go to a temporary home.
    QTemporaryDir home;
    if (!home.isValid()) {
        std::fprintf(stderr, "cannot create a temporary folder\n");
        return 1;
    }
    useTemporaryUserFolders(home);
    ui::installDefaultSurfaceFormat();
    QApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    QApplication app(argc, argv);
    nameTheApplication();
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
