// Saving never loses the previous file: into a folder the user may not write, and when the disk fills
// up part-way through the write. Each case runs in a child process (a death test), so it can drop root
// privileges or lower its file-size limit without affecting the other tests.
#include "editor/document/ProjectFile.hpp"

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
SceneData bigScene() {
    SceneData data;
    for (int i = 0; i < 50; ++i) {
        NodeTree node;
        node.data.name = "Node " + std::to_string(i);
        node.data.mesh = MeshComponent::fromBuiltin(BuiltinMesh::Sphere);
        data.nodes.push_back(node);
    }
    return data;
}

// Child-process bodies: each exits 0 when the save failed as it should.
[[noreturn]] void saveAsOrdinaryUser(const QString& path) {
    // Root may write anywhere: become an ordinary user first, as a user of the editor would be.
    if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0))
        std::_Exit(3);
    const render::Status saved = saveProject(bigScene(), path);
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
    std::_Exit(saveProject(bigScene(), path).ok() ? 4 : 0);
}

class SaveFailures : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(m_dir.isValid());
        m_path = m_dir.filePath("scene.speculum.json");
        ASSERT_TRUE(saveProject(SceneData{}, m_path).ok());
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

} // namespace
} // namespace speculum::document
