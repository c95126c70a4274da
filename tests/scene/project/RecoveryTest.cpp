// Crash recovery: an editor's autosave is invisible to itself, offered to the next editor once its process
// is gone, restores the same document (paths included), and a clean discard leaves nothing behind.
#include "scene/project/Recovery.hpp"

#include "editor/document/NodeFactory.hpp"
#include "scene/project/ProjectFile.hpp"
#include "support/TestPaths.hpp"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
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

QByteArray bytesOf(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

SceneData sceneWithMirrors(int mirrors) {
    SceneData data;
    for (int i = 0; i < mirrors; ++i) {
        data.nodes.push_back(makeNode(NewNodeKind::Mirror));
    }
    return data;
}

TEST(Recovery, EveryCrashedEditorsDocumentIsOfferedWithItsEdits) {
    const QString dir = folder();
    ASSERT_TRUE(
        RecoveryStore(dir, kDeadPid)
            .write(sceneWithMirrors(1), QStringLiteral("/p/a.speculum.json"), {QStringLiteral("Add Mirror")})
            .ok());
    ASSERT_TRUE(RecoveryStore(dir, kDeadPid + 1)
                    .write(sceneWithMirrors(2), QString(),
                           {QStringLiteral("Add Mirror"), QStringLiteral("Move Mirror")})
                    .ok());
    const RecoveryStore next(dir, QCoreApplication::applicationPid());
    const RecoveryStore::Scan scan = next.scan();
    ASSERT_EQ(scan.recoverable.size(), 2u) << "both documents, not only the newest";
    EXPECT_TRUE(scan.unreadable.empty());
    QStringList projects;
    for (const auto& r : scan.recoverable) {
        projects << r.originalPath;
        EXPECT_FALSE(r.changes.isEmpty());
    }
    EXPECT_TRUE(projects.contains(QStringLiteral("/p/a.speculum.json")));
    EXPECT_TRUE(projects.contains(QString())) << "the untitled one too";
    // Listing changes nothing: both are offered again, whatever the first list was answered with.
    EXPECT_EQ(next.scan().recoverable.size(), 2u);
    std::vector<std::string> warnings;
    for (const auto& r : scan.recoverable) {
        auto data = RecoveryStore::load(r, warnings);
        ASSERT_TRUE(data.ok()) << data.error();
        EXPECT_EQ(data->nodes.size(), r.originalPath.isEmpty() ? 2u : 1u);
        EXPECT_EQ(r.changes.size(), r.originalPath.isEmpty() ? 2 : 1);
    }
}

TEST(Recovery, AnUnreadableRecoveryIsKeptAsideNeverDeletedAndTheOthersStillOffered) {
    const QString dir = folder();
    RecoveryStore older(dir, kDeadPid);
    ASSERT_TRUE(older.write(sceneWithMirrors(1), QStringLiteral("/p/older.speculum.json")).ok());
    RecoveryStore newer(dir, kDeadPid + 1);
    ASSERT_TRUE(newer.write(sceneWithMirrors(3), QStringLiteral("/p/newer.speculum.json")).ok());
    // The newest recovery file cut short, as a crash during a write on a filesystem without rename
    // atomicity, or a full disk, can leave it.
    QByteArray truncated = bytesOf(newer.scenePath());
    truncated.truncate(truncated.size() / 2);
    {
        QFile cut(newer.scenePath());
        ASSERT_TRUE(cut.open(QIODevice::WriteOnly | QIODevice::Truncate));
        cut.write(truncated);
    }

    const RecoveryStore next(dir, QCoreApplication::applicationPid());
    const RecoveryStore::Scan scan = next.scan();
    ASSERT_EQ(scan.recoverable.size(), 1u) << "the older, valid one is still offered";
    EXPECT_EQ(scan.recoverable.front().originalPath, QStringLiteral("/p/older.speculum.json"));
    EXPECT_TRUE(QFile::exists(older.scenePath()));
    ASSERT_EQ(scan.unreadable.size(), 1u);
    const auto& bad = scan.unreadable.front();
    EXPECT_EQ(bad.recovered.originalPath, QStringLiteral("/p/newer.speculum.json"));
    EXPECT_NE(bad.reason.find("JSON"), std::string::npos) << bad.reason;
    EXPECT_TRUE(bad.keptAt.startsWith(next.quarantineFolder())) << bad.keptAt.toStdString();
    EXPECT_EQ(bytesOf(bad.keptAt), truncated) << "kept as it was, byte for byte";
    EXPECT_FALSE(QFile::exists(newer.scenePath()));

    // Not offered again, and still kept.
    const RecoveryStore::Scan again = next.scan();
    EXPECT_EQ(again.recoverable.size(), 1u);
    EXPECT_TRUE(again.unreadable.empty());
    EXPECT_TRUE(QFile::exists(bad.keptAt));
}

TEST(Recovery, AFileIsTakenOverOnlyWhenItIsAnOrphanOfThisFolder) {
    const QString dir = folder();
    RecoveryStore crashed(dir, kDeadPid);
    ASSERT_TRUE(crashed.write(sceneWithMirrors(1), QString(), {QStringLiteral("Add Mirror")}).ok());
    const RecoveryStore next(dir, QCoreApplication::applicationPid());
    const auto found = next.orphanAt(crashed.scenePath());
    ASSERT_TRUE(found.ok()) << found.error();
    EXPECT_EQ(found->changes, QStringList{QStringLiteral("Add Mirror")});

    RecoveryStore mine(dir, QCoreApplication::applicationPid());
    ASSERT_TRUE(mine.write(sceneWithMirrors(1), QString()).ok());
    EXPECT_FALSE(RecoveryStore(dir, kDeadPid + 5).orphanAt(mine.scenePath()).ok())
        << "a running editor's file is its own";
    EXPECT_FALSE(next.orphanAt(QStringLiteral("/etc/passwd")).ok());
}

} // namespace
