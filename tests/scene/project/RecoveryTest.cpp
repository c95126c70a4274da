// Crash recovery: an editor's autosave is invisible to itself, offered to the next editor once its process
// is gone, restores the same document (paths included), and a clean discard leaves nothing behind.
#include "scene/project/Recovery.hpp"

#include "editor/document/NodeFactory.hpp"
#include "scene/project/ProjectFile.hpp"
#include "support/TestPaths.hpp"

#include <QCoreApplication>
#include <QDir>
#include <filesystem>
#include <gtest/gtest.h>

namespace {

using namespace speculum::document;
using namespace speculum::scene;

QString folder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const auto dir = std::filesystem::path(speculum::testDataPath()) / "editor_recovery" / info->name();
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return QString::fromStdString(dir.string());
}

// A process id that is not running (pid_max on Linux is at most 2^22).
constexpr qint64 kDeadPid = 4194303 + 17;

TEST(Recovery, AnOrphanIsOfferedAndRestoresTheDocument) {
    const QString dir = folder();
    speculum::scene::SceneData data;
    std::vector<std::string> warnings;
    auto demo = speculum::scene::loadProject(
        QString::fromStdString(speculum::testSourcePath("resources/scenes/teapot.speculum.json")), warnings);
    ASSERT_TRUE(demo.ok());
    data = *demo;
    data.nodes.push_back(makeNode(NewNodeKind::Mirror));

    speculum::scene::RecoveryStore crashed(dir, kDeadPid);
    ASSERT_TRUE(crashed.write(data, QStringLiteral("/home/me/teapot.speculum.json")).ok());
    EXPECT_TRUE(crashed.orphans().empty()) << "a store never offers its own file";

    speculum::scene::RecoveryStore next(dir, QCoreApplication::applicationPid());
    const auto orphans = next.orphans();
    ASSERT_EQ(orphans.size(), 1u);
    EXPECT_EQ(orphans.front().originalPath, QStringLiteral("/home/me/teapot.speculum.json"));
    EXPECT_TRUE(orphans.front().savedAt.isValid());
    auto restored = speculum::scene::RecoveryStore::load(orphans.front(), warnings);
    ASSERT_TRUE(restored.ok()) << restored.error();
    EXPECT_TRUE(*restored == data) << "texture paths and nodes come back as they were";

    speculum::scene::RecoveryStore::remove(orphans.front());
    EXPECT_TRUE(next.orphans().empty());
    EXPECT_TRUE(QDir(dir).entryList(QDir::Files).isEmpty());
}

TEST(Recovery, RunningEditorsAreNotOrphansAndDiscardCleansUp) {
    const QString dir = folder();
    speculum::scene::RecoveryStore mine(dir, QCoreApplication::applicationPid());
    ASSERT_TRUE(mine.write(speculum::scene::SceneData{}, QString()).ok());
    speculum::scene::RecoveryStore other(dir, kDeadPid);
    EXPECT_TRUE(other.orphans().empty()) << "the writer is alive";
    mine.discard();
    EXPECT_TRUE(QDir(dir).entryList(QDir::Files).isEmpty());
}

} // namespace
