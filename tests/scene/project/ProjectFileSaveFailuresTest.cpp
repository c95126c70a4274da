// Saving never loses the previous file: into a folder the user may not write, and when the disk fills
// up part-way through the write. Each case runs in a child process (a death test), so it can drop root
// privileges or lower its file-size limit without affecting the other tests.
#include "scene/project/ProjectFile.hpp"
#include "scene/project/Recovery.hpp"
#include "support/FillingDisk.hpp"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <csignal>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

namespace speculum::document {
namespace {

QByteArray readAll(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// A scene big enough that saving it takes more than a few hundred bytes.
scene::SceneData bigScene() {
    scene::SceneData data;
    for (int i = 0; i < 50; ++i) {
        scene::NodeTree node;
        node.data.name = "Node " + std::to_string(i);
        node.data.mesh = scene::MeshComponent::fromBuiltin(scene::BuiltinMesh::Sphere);
        data.nodes.push_back(node);
    }
    return data;
}

// Child-process bodies: each exits 0 when the save failed as it should.
[[noreturn]] void saveAsOrdinaryUser(const QString& path) {
    // Root may write anywhere: become an ordinary user first, as a user of the editor would be.
    if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0))
        std::_Exit(3);
    const base::Status saved = scene::saveProject(bigScene(), path);
    if (saved.ok())
        std::_Exit(4);
    if (saved.error().find("scene.speculum.json") == std::string::npos)
        std::_Exit(5);
    std::_Exit(0);
}

[[noreturn]] void saveOntoAFillingDisk(const QString& path) {
    // The file-size limit makes writes past 256 bytes fail (EFBIG), as a full disk makes them fail
    // (ENOSPC) part-way through the new file.
    std::signal(SIGXFSZ, SIG_IGN);
    rlimit limit{};
    limit.rlim_cur = limit.rlim_max = 256;
    if (::setrlimit(RLIMIT_FSIZE, &limit) != 0)
        std::_Exit(3);
    std::_Exit(scene::saveProject(bigScene(), path).ok() ? 4 : 0);
}

class SaveFailures : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(m_dir.isValid());
        m_path = m_dir.filePath("scene.speculum.json");
        ASSERT_TRUE(scene::saveProject(scene::SceneData{}, m_path).ok());
        m_original = readAll(m_path);
        ASSERT_FALSE(m_original.isEmpty());
    }
    QTemporaryDir m_dir;
    QString m_path;
    QByteArray m_original;
};

TEST_F(SaveFailures, ReadOnlyFolderReportsTheErrorAndKeepsThePreviousFile) {
    ASSERT_EQ(::chmod(QFile::encodeName(m_dir.path()).constData(), 0555), 0);
    EXPECT_EXIT(saveAsOrdinaryUser(m_path), ::testing::ExitedWithCode(0), "");
    ::chmod(QFile::encodeName(m_dir.path()).constData(), 0755);
    EXPECT_EQ(readAll(m_path), m_original);
    EXPECT_EQ(QDir(m_dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 1) << "no temporary file left";
}

TEST_F(SaveFailures, DiskFillingUpDuringTheWriteReportsTheErrorAndKeepsThePreviousFile) {
    EXPECT_EXIT(saveOntoAFillingDisk(m_path), ::testing::ExitedWithCode(0), "");
    EXPECT_EQ(readAll(m_path), m_original);
    EXPECT_EQ(QDir(m_dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 1) << "no temporary file left";
}

// The error a user sees for a save onto a full disk: one line, the file, the cause, the reassurance.
TEST_F(SaveFailures, DiskFullErrorIsOneLineNamingTheFileAndTheCause) {
    const render::test::ChildOutcome child = render::test::inChild([&](std::string& text) {
        render::test::limitFileSize(256);
        const base::Status saved = scene::saveProject(bigScene(), m_path);
        text = saved.ok() ? std::string("(saved)") : saved.error();
        return saved.ok() ? 1 : 0;
    });
    ASSERT_EQ(child.exitCode, 0) << child.text;
    EXPECT_EQ(child.text.find('\n'), std::string::npos) << child.text;
    EXPECT_NE(child.text.find("scene.speculum.json: the file is larger than"), std::string::npos)
        << child.text;
    EXPECT_NE(child.text.find("the previous file is unchanged"), std::string::npos) << child.text;
    EXPECT_EQ(readAll(m_path), m_original);
    EXPECT_EQ(QDir(m_dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 1) << "no temporary file left";
}

// A real full file system (ENOSPC) where the test may mount one: root, in a private mount namespace.
TEST(SaveFailuresOnASmallDisk, FullFileSystemKeepsThePreviousProject) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const std::string folder = QFile::encodeName(dir.path()).toStdString();
    const render::test::ChildOutcome child = render::test::inChild([&](std::string& text) {
        if (std::string why = render::test::mountSmallFileSystem(folder, "16k"); !why.empty()) {
            text = why;
            return 77;
        }
        const QString path = dir.filePath("scene.speculum.json");
        if (!scene::saveProject(scene::SceneData{}, path).ok())
            return 2;
        const QByteArray before = readAll(path);
        scene::SceneData huge;
        for (int i = 0; i < 400; ++i) {
            scene::NodeTree node;
            node.data.name = "A node with a long enough name " + std::to_string(i);
            node.data.mesh = scene::MeshComponent::fromBuiltin(scene::BuiltinMesh::Sphere);
            huge.nodes.push_back(node);
        }
        const base::Status saved = scene::saveProject(huge, path);
        text = saved.ok() ? std::string("(saved)") : saved.error();
        if (saved.ok())
            return 1;
        if (readAll(path) != before)
            return 4;
        if (QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).size() != 1)
            return 5;
        return 0;
    });
    if (child.exitCode == 77)
        GTEST_SKIP() << "no small file system to fill: " << child.text;
    EXPECT_EQ(child.exitCode, 0) << child.text;
    EXPECT_NE(child.text.find("the disk is full (No space left on device)"), std::string::npos) << child.text;
}

// Autosave onto a filling disk: the earlier recovery copy and its note stay as they were, nothing stray.
TEST(RecoveryFailures, AutosaveOntoAFillingDiskKeepsTheEarlierRecovery) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    scene::RecoveryStore store(dir.path(), 4242);
    ASSERT_TRUE(store.write(scene::SceneData{}, QStringLiteral("/projects/room.speculum.json")).ok());
    const QStringList before = QDir(dir.path()).entryList(QDir::Files | QDir::Hidden);
    ASSERT_EQ(before.size(), 2);
    std::vector<QByteArray> beforeBytes;
    for (const QString& name : before)
        beforeBytes.push_back(readAll(dir.filePath(name)));

    const render::test::ChildOutcome child = render::test::inChild([&](std::string& text) {
        render::test::limitFileSize(256);
        const base::Status written = store.write(bigScene(), QStringLiteral("/projects/room.speculum.json"));
        text = written.ok() ? std::string("(written)") : written.error();
        return written.ok() ? 1 : 0;
    });
    ASSERT_EQ(child.exitCode, 0) << child.text;
    EXPECT_NE(child.text.find("recovery-4242.speculum.json"), std::string::npos) << child.text;
    EXPECT_EQ(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), before) << "no temporary file left";
    for (qsizetype i = 0; i < before.size(); ++i)
        EXPECT_EQ(readAll(dir.filePath(before[i])), beforeBytes[std::size_t(i)]) << before[i].toStdString();
}

// The note alone failing (the scene fits, the note does not): the earlier note is kept whole.
TEST(RecoveryFailures, NoteThatDoesNotFitKeepsTheEarlierNote) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    scene::RecoveryStore store(dir.path(), 4243);
    ASSERT_TRUE(store.write(scene::SceneData{}, QStringLiteral("/a.speculum.json")).ok());
    const QString note = dir.filePath(QStringLiteral("recovery-4243.note.json"));
    const QByteArray beforeNote = readAll(note);
    ASSERT_FALSE(beforeNote.isEmpty());
    const QString longOriginal =
        QStringLiteral("/") + QString(3000, QLatin1Char('p')) + QStringLiteral(".speculum.json");
    const render::test::ChildOutcome child = render::test::inChild([&](std::string& text) {
        render::test::limitFileSize(2048); // an empty scene fits, a 3000-byte note does not
        const base::Status written = store.write(scene::SceneData{}, longOriginal);
        text = written.ok() ? std::string("(written)") : written.error();
        return written.ok() ? 1 : 0;
    });
    ASSERT_EQ(child.exitCode, 0) << child.text;
    EXPECT_NE(child.text.find("recovery-4243.note.json"), std::string::npos) << child.text;
    EXPECT_EQ(readAll(note), beforeNote);
    EXPECT_EQ(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 2) << "no temporary file left";
}

} // namespace
} // namespace speculum::document
