// Crash recovery as it really happens: an editor in a child process (this program started again with
// --edit-then-wait) opens a project, moves the teapot through the undo stack, and is killed with SIGKILL
// once its autosave (every second, by SPECULUM_AUTOSAVE_SECONDS) is on disk. The next editor offers the
// unsaved edit in a list of every document such editors left: restored, the edit is back; left for later,
// nothing is deleted; discarded by name, only that document goes; unreadable, it is kept aside. Both
// processes keep settings and recovery files in a temporary XDG home, never the user's.
#include "editor/document/Commands.hpp"
#include "editor/ui/Editor.hpp"
#include "editor/ui/RecoveryDialog.hpp"
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
        m_second = m_dir.filePath(QStringLiteral("second.speculum.json"));
        ASSERT_TRUE(QFile::copy(m_project, m_second));
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

    void TearDown() override {
        for (const qint64 pid : m_editorsStarted) {
            ::kill(static_cast<pid_t>(pid), SIGKILL);
        }
    }

    static QByteArray readAll(const QString& path) {
        QFile file(path);
        return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
    }

    QString recoveryFileOf(qint64 pid) const {
        return m_recovery + QStringLiteral("/recovery-%1.speculum.json").arg(pid);
    }

    // Starts an editor that edits `project`, waits until its autosave holds the edit, and kills it.
    // Returns the killed editor's recovery file.
    QString crashAfterAutosave(const QString& project) {
        QProcess child;
        QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
        environment.insert(QStringLiteral("SPECULUM_AUTOSAVE_SECONDS"), QStringLiteral("1"));
        child.setProcessEnvironment(environment);
        child.setProcessChannelMode(QProcess::ForwardedChannels);
        child.start(QCoreApplication::applicationFilePath(), {QString::fromLatin1(kChildArgument), project});
        EXPECT_TRUE(child.waitForStarted(10000)) << child.errorString().toStdString();
        const qint64 pid = child.processId();
        const QString scene = recoveryFileOf(pid);
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
        EXPECT_EQ(child.state(), QProcess::Running)
            << "the editor exited by itself, status " << child.exitCode();
        EXPECT_TRUE(saved) << "no autosave with the edit in " << m_recovery.toStdString();
        EXPECT_EQ(::kill(static_cast<pid_t>(pid), SIGKILL), 0);
        EXPECT_TRUE(child.waitForFinished(10000));
        EXPECT_EQ(child.exitStatus(), QProcess::CrashExit);
        EXPECT_EQ(readAll(project), m_original) << "the killed editor never saved the project";
        return scene;
    }

    // Runs `answer` on the recovery dialog once it is up (offerRecovery shows it modally).
    void answerRecovery(std::function<void(ui::RecoveryDialog&)> answer) {
        auto* timer = new QTimer(&m_answers);
        timer->setInterval(20);
        QObject::connect(timer, &QTimer::timeout, timer, [this, timer, answer] {
            if (auto* dialog = qobject_cast<ui::RecoveryDialog*>(QApplication::activeModalWidget())) {
                timer->deleteLater();
                timer->stop();
                for (const auto& r : dialog->offered()) {
                    m_offered << r.originalPath;
                    m_edits << r.changes;
                }
                m_unreadable = dialog->unreadableText();
                if (const QString dump = qEnvironmentVariable("SPECULUM_TEST_DUMP"); !dump.isEmpty()) {
                    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
                    dialog->grab().save(
                        dump + QStringLiteral("/recovery-%1.png").arg(QString::fromLatin1(test->name())));
                }
                answer(*dialog);
                if (dialog->isVisible()) {
                    dialog->reject(); // Decide Later: keeps what is left
                }
            }
        });
        timer->start();
    }

    // Answers the next message box with `button`, keeping its text.
    void answerNextQuestion(QMessageBox::StandardButton button) {
        auto* timer = new QTimer(&m_answers);
        timer->setInterval(20);
        QObject::connect(timer, &QTimer::timeout, timer, [this, timer, button] {
            if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
                m_question = box->text();
                timer->stop();
                timer->deleteLater();
                box->button(button)->click();
            }
        });
        timer->start();
    }

    static int rowOf(const ui::RecoveryDialog& dialog, const QString& project) {
        for (std::size_t i = 0; i < dialog.offered().size(); ++i) {
            if (dialog.offered()[i].originalPath == QFileInfo(project).absoluteFilePath()) {
                return int(i);
            }
        }
        return -1;
    }

    QTemporaryDir m_dir;
    QString m_project;
    QString m_second;
    QByteArray m_original;
    double m_height = 0.0;
    QString m_recovery;
    QString m_question;
    QStringList m_offered;
    QStringList m_edits;
    QString m_unreadable;
    std::vector<qint64> m_editorsStarted;
    QObject m_answers; // the timers that answer dialogs; one that found none goes with the test
};

TEST_F(CrashRecovery, NextEditorOffersTheKilledEditorsEditAndRestoresIt) {
    crashAfterAutosave(m_project);
    ui::MainWindow window;
    answerRecovery([](ui::RecoveryDialog& dialog) {
        EXPECT_TRUE(dialog.restoreHere(0)) << dialog.lastError().toStdString();
    });
    window.offerRecovery();
    EXPECT_EQ(m_offered, QStringList{QFileInfo(m_project).absoluteFilePath()});
    EXPECT_EQ(m_edits, QStringList{QStringLiteral("Move Teapot")}) << "the row says what changed";

    const speculum::scene::Node* node = teapot(window.scene());
    ASSERT_NE(node, nullptr) << "the project is open again";
    EXPECT_NEAR(node->data().transform.translate.y, m_height + kMovedBy, 1e-9) << "with the edit";
    EXPECT_EQ(window.scene().projectPath(), QFileInfo(m_project).absoluteFilePath());
    EXPECT_TRUE(window.isModified()) << "unsaved, as it was when the editor died";
    EXPECT_EQ(readAll(m_project), m_original) << "restoring does not write the project";
    EXPECT_TRUE(window.recoveryStore().orphans().empty()) << "offered once";
    EXPECT_EQ(window.unsavedEdits(), QStringList{QStringLiteral("Move Teapot")}) << "and still named";

    // Saving makes it the project, and leaves nothing to recover.
    ASSERT_TRUE(window.saveProjectFile(m_project).ok());
    EXPECT_NEAR(teapotHeight(m_project).value_or(0.0), m_height + kMovedBy, 1e-9);
    EXPECT_TRUE(QDir(m_recovery).isEmpty(QDir::Files));
}

TEST_F(CrashRecovery, DecidingLaterKeepsEverythingAndAsksAgain) {
    const QString kept = crashAfterAutosave(m_project);
    const QByteArray bytes = readAll(kept);
    {
        ui::MainWindow window;
        answerRecovery([](ui::RecoveryDialog& dialog) { dialog.reject(); });
        window.offerRecovery();
        EXPECT_EQ(m_offered.size(), 1);
        EXPECT_EQ(teapot(window.scene()), nullptr) << "the editor starts with a new document";
        EXPECT_FALSE(window.isModified());
    } // a clean exit of that editor
    EXPECT_EQ(readAll(m_project), m_original);
    EXPECT_EQ(readAll(kept), bytes) << "closing the list deletes nothing";

    ui::MainWindow next;
    m_offered.clear();
    answerRecovery([](ui::RecoveryDialog& dialog) { EXPECT_TRUE(dialog.restoreHere(0)); });
    next.offerRecovery();
    EXPECT_EQ(m_offered.size(), 1) << "offered again";
    ASSERT_NE(teapot(next.scene()), nullptr);
    EXPECT_NEAR(teapot(next.scene())->data().transform.translate.y, m_height + kMovedBy, 1e-9);
}

TEST_F(CrashRecovery, DiscardingDeletesOnlyTheDocumentNamedAndOnlyOnceConfirmed) {
    const QString first = crashAfterAutosave(m_project);
    const QString second = crashAfterAutosave(m_second);
    ui::MainWindow window;
    answerRecovery([this](ui::RecoveryDialog& dialog) {
        const int row = rowOf(dialog, m_second);
        ASSERT_GE(row, 0);
        answerNextQuestion(QMessageBox::Cancel);
        EXPECT_FALSE(dialog.discard(row)) << "not confirmed";
        EXPECT_TRUE(m_question.contains(QStringLiteral("second.speculum.json"))) << m_question.toStdString();
        EXPECT_EQ(dialog.offered().size(), 2u);
        answerNextQuestion(QMessageBox::Discard);
        EXPECT_TRUE(dialog.discard(row));
        EXPECT_EQ(dialog.offered().size(), 1u);
    });
    window.offerRecovery();
    EXPECT_EQ(m_offered.size(), 2) << "both crashed editors' documents are listed";
    EXPECT_FALSE(QFile::exists(second)) << "the one discarded by name is gone";
    EXPECT_TRUE(QFile::exists(first)) << "the other is untouched";
    EXPECT_EQ(readAll(m_second), m_original);
}

// Two editors killed with unsaved work: both documents are offered, one restored in this window and the
// other in a new editor (the real speculum binary, started as Restore in New Window starts it).
TEST_F(CrashRecovery, TwoKilledEditorsAreBothOfferedAndBothRestored) {
    crashAfterAutosave(m_project);
    const QString second = crashAfterAutosave(m_second);
    ui::MainWindow window;
    window.setNewEditorProgram(QString::fromStdString(speculum::testCliBinary()));
    answerRecovery([this](ui::RecoveryDialog& dialog) {
        ASSERT_EQ(dialog.offered().size(), 2u);
        EXPECT_TRUE(dialog.restoreHere(rowOf(dialog, m_project))) << dialog.lastError().toStdString();
        EXPECT_TRUE(dialog.restoreInNewWindow(rowOf(dialog, m_second))) << dialog.lastError().toStdString();
        EXPECT_FALSE(dialog.isVisible()) << "nothing left to decide";
    });
    window.offerRecovery();
    ASSERT_NE(teapot(window.scene()), nullptr);
    EXPECT_EQ(window.scene().projectPath(), QFileInfo(m_project).absoluteFilePath());
    EXPECT_NEAR(teapot(window.scene())->data().transform.translate.y, m_height + kMovedBy, 1e-9);

    // The new editor takes the second document over: its own recovery file holds it (with the edit),
    // then the crashed editor's file goes.
    qint64 newEditor = 0;
    const bool takenOver = waitFor(
        [&] {
            for (const QFileInfo& f :
                 QDir(m_recovery).entryInfoList({QStringLiteral("recovery-*.speculum.json")})) {
                const qint64 pid =
                    f.fileName().section(QLatin1Char('-'), 1).section(QLatin1Char('.'), 0, 0).toLongLong();
                if (pid == QCoreApplication::applicationPid() || ::kill(static_cast<pid_t>(pid), 0) != 0) {
                    continue;
                }
                std::vector<std::string> warnings;
                const auto data = speculum::scene::loadProject(f.absoluteFilePath(), warnings);
                if (data && !QFile::exists(second)) {
                    newEditor = pid;
                    return true;
                }
            }
            return false;
        },
        120000);
    if (newEditor) {
        m_editorsStarted.push_back(newEditor);
    }
    ASSERT_TRUE(takenOver) << "no new editor restored " << second.toStdString();
    EXPECT_NEAR(teapotHeight(recoveryFileOf(newEditor)).value_or(0.0), m_height + kMovedBy, 1e-9);
    EXPECT_TRUE(window.recoveryStore().scan().recoverable.empty()) << "nothing is offered twice";
}

TEST_F(CrashRecovery, AnUnreadableNewestRecoveryIsKeptAsideAndTheOlderOneRestored) {
    crashAfterAutosave(m_project);
    const QString newest = crashAfterAutosave(m_second);
    QByteArray cut = readAll(newest);
    cut.truncate(cut.size() / 3);
    {
        QFile file(newest);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        file.write(cut);
    }
    ui::MainWindow window;
    answerRecovery([](ui::RecoveryDialog& dialog) { EXPECT_TRUE(dialog.restoreHere(0)); });
    window.offerRecovery();
    EXPECT_EQ(m_offered, QStringList{QFileInfo(m_project).absoluteFilePath()}) << "the older, valid one";
    ASSERT_NE(teapot(window.scene()), nullptr) << "and it is restored";
    const QString quarantine = window.recoveryStore().quarantineFolder();
    EXPECT_TRUE(m_unreadable.contains(QStringLiteral("second.speculum.json"))) << m_unreadable.toStdString();
    EXPECT_TRUE(m_unreadable.contains(quarantine)) << "the dialog says where it is kept";
    const QStringList kept = QDir(quarantine).entryList({QStringLiteral("*.speculum.json")});
    ASSERT_EQ(kept.size(), 1);
    EXPECT_EQ(readAll(quarantine + QLatin1Char('/') + kept.front()), cut) << "kept, byte for byte";

    m_offered.clear();
    m_unreadable.clear();
    ui::MainWindow next;
    answerRecovery([](ui::RecoveryDialog&) {});
    next.offerRecovery();
    EXPECT_TRUE(m_offered.isEmpty()) << "nothing left to offer, so no list";
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
