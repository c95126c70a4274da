// Two editors on one project file: the one that saves second is told the file changed on disk (as it
// happens, and again before it saves) and chooses: Cancel keeps the other's save, Keep Mine overwrites it,
// Reload takes it in. Nothing is written over another editor's save without that question.
#include "editor/document/NodeFactory.hpp"
#include "editor/ui/MainWindow.hpp"
#include "scene/model/Scene.hpp"
#include "support/GuiTestSupport.hpp"
#include "support/TestPaths.hpp"

#include <QAbstractButton>
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QMessageBox>
#include <QTemporaryDir>
#include <QTimer>
#include <gtest/gtest.h>

namespace speculum::ui {
namespace {

using namespace speculum::ui::test;

QByteArray fileBytes(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

bool hasNodeNamed(const scene::Scene& scene, const std::string& name) {
    for (const auto& node : scene.topLevelNodes()) {
        if (node->data().name == name) {
            return true;
        }
    }
    return false;
}

class DiskChanges : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(m_dir.isValid());
        const QString scenes = QString::fromStdString(speculum::testSourcePath("resources/scenes"));
        m_project = m_dir.filePath(QStringLiteral("shared.speculum.json"));
        ASSERT_TRUE(QFile::copy(scenes + QStringLiteral("/teapot.speculum.json"), m_project));
        ASSERT_TRUE(QDir(m_dir.path()).mkpath(QStringLiteral("textures")));
        ASSERT_TRUE(QFile::copy(scenes + QStringLiteral("/textures/marble.png"),
                                m_dir.filePath(QStringLiteral("textures/marble.png"))));
    }

    // Clicks the button labelled `text` (without its & mark) on the next message box, keeping its text.
    void answerNextQuestion(const QString& text) {
        auto* timer = new QTimer(&m_answers);
        timer->setInterval(20);
        QObject::connect(timer, &QTimer::timeout, timer, [this, timer, text] {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (!box) {
                return;
            }
            m_question = box->text();
            timer->stop();
            for (QAbstractButton* button : box->buttons()) {
                if (button->text().remove(QLatin1Char('&')) == text) {
                    button->click();
                    return;
                }
            }
            ADD_FAILURE() << "no button " << text.toStdString();
            box->reject();
        });
        timer->start();
    }

    QTemporaryDir m_dir;
    QString m_project;
    QString m_question;
    QObject m_answers;
};

TEST_F(DiskChanges, TheSecondEditorToSaveIsAskedFirstAndItsAnswerIsKept) {
    MainWindow first, second;
    ASSERT_TRUE(first.openProjectFile(m_project).ok());
    ASSERT_TRUE(second.openProjectFile(m_project).ok());

    ASSERT_TRUE(first.addNode(document::NewNodeKind::Box).ok());
    first.action(QStringLiteral("actionSave"))->trigger();
    ASSERT_FALSE(first.isModified()) << "the first save asks nothing";
    const QByteArray firstSave = fileBytes(m_project);

    ASSERT_TRUE(second.addNode(document::NewNodeKind::Mirror).ok());
    EXPECT_TRUE(waitFor(
        [&] { return second.logLines().filter(QStringLiteral("changed on disk")).size() == 1; }, 20000))
        << "the second editor is told as it happens";

    answerNextQuestion(QStringLiteral("Cancel"));
    second.action(QStringLiteral("actionSave"))->trigger();
    EXPECT_TRUE(m_question.contains(QStringLiteral("shared.speculum.json changed on disk")))
        << m_question.toStdString();
    EXPECT_EQ(fileBytes(m_project), firstSave) << "Cancel: the first editor's save is intact";
    EXPECT_TRUE(second.isModified()) << "and the second's edits are still there, unsaved";

    m_question.clear();
    answerNextQuestion(QStringLiteral("Keep Mine"));
    second.action(QStringLiteral("actionSave"))->trigger();
    EXPECT_FALSE(m_question.isEmpty());
    EXPECT_FALSE(second.isModified());
    EXPECT_NE(fileBytes(m_project), firstSave) << "Keep Mine overwrites";

    // Now the first editor is the one whose file changed; it reloads instead of saving.
    ASSERT_TRUE(first.addNode(document::NewNodeKind::Box).ok());
    m_question.clear();
    answerNextQuestion(QStringLiteral("Reload"));
    first.action(QStringLiteral("actionSave"))->trigger();
    EXPECT_FALSE(m_question.isEmpty());
    EXPECT_FALSE(first.isModified()) << "reloaded";
    EXPECT_EQ(first.scene().toData(), second.scene().toData()) << "both hold the file as it is now";
    EXPECT_TRUE(hasNodeNamed(first.scene(), second.scene().topLevelNodes().back()->data().name));
}

TEST_F(DiskChanges, AFileSavedTwiceByItsOwnEditorAsksNothing) {
    MainWindow window;
    ASSERT_TRUE(window.openProjectFile(m_project).ok());
    for (int i = 0; i < 2; ++i) {
        ASSERT_TRUE(window.addNode(document::NewNodeKind::Box).ok());
        answerNextQuestion(QStringLiteral("Cancel")); // would record a question, if one came
        window.action(QStringLiteral("actionSave"))->trigger();
        EXPECT_FALSE(window.isModified());
        QCoreApplication::processEvents(); // the watcher's notice of this editor's own save
    }
    EXPECT_TRUE(m_question.isEmpty()) << m_question.toStdString();
    EXPECT_TRUE(window.logLines().filter(QStringLiteral("changed on disk")).isEmpty());
}

} // namespace
} // namespace speculum::ui
