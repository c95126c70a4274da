// The demo projects shipped in resources/scenes: each loads without warnings, is already in the form
// speculum writes (so opening and saving one changes nothing), and snapshots into a renderable frame.
#include "scene/evaluate/Snapshot.hpp"
#include "scene/import/MeshLibrary.hpp"
#include "scene/project/ProjectFile.hpp"
#include "support/TestPaths.hpp"

#include <QDir>
#include <QFile>
#include <algorithm>
#include <gtest/gtest.h>

namespace speculum::document {
namespace {

QStringList demoScenes() {
    const QDir dir(QString::fromStdString(speculum::testSourcePath("resources/scenes")));
    QStringList paths;
    for (const QString& name : dir.entryList({"*.speculum.json"}, QDir::Files, QDir::Name))
        paths << dir.filePath(name);
    return paths;
}

TEST(DemoScenes, ThereAreDemoScenes) {
    EXPECT_TRUE(demoScenes().contains(
        QString::fromStdString(speculum::testSourcePath("resources/scenes/teapot.speculum.json"))));
    EXPECT_TRUE(demoScenes().contains(
        QString::fromStdString(speculum::testSourcePath("resources/scenes/mirrors.speculum.json"))));
}

TEST(DemoScenes, EachLoadsCleanlyAndIsInTheFormSpeculumWrites) {
    for (const QString& path : demoScenes()) {
        SCOPED_TRACE(path.toStdString());
        std::vector<std::string> warnings;
        auto data = scene::loadProject(path, warnings);
        ASSERT_TRUE(data.ok()) << data.error();
        EXPECT_TRUE(warnings.empty()) << warnings.front();
        QFile file(path);
        ASSERT_TRUE(file.open(QIODevice::ReadOnly));
        const std::string written = scene::serializeProject(*data, QFileInfo(path).dir()).toStdString();
        const std::string stored = file.readAll().toStdString();
        EXPECT_EQ(written, stored)
            << "first difference at byte "
            << std::mismatch(written.begin(), written.end(), stored.begin(), stored.end()).first -
                   written.begin();

        scene::Scene scene;
        ASSERT_TRUE(scene::openProject(scene, path, warnings).ok());
        scene::MeshLibrary meshes;
        std::vector<scene::Warning> snapshotWarnings;
        const render::FrameInput frame = scene::snapshot(scene, 0.0, meshes, snapshotWarnings);
        EXPECT_TRUE(snapshotWarnings.empty()) << ::testing::PrintToString(scene::messages(snapshotWarnings));
        EXPECT_FALSE(frame.items.empty() && frame.mirrors.empty());
        EXPECT_FALSE(frame.lights.empty());
    }
}

TEST(DemoScenes, MirrorRoomHasTwoFacingMirrorsAndObjectsBetween) {
    std::vector<std::string> warnings;
    scene::Scene scene;
    ASSERT_TRUE(
        scene::openProject(
            scene, QString::fromStdString(speculum::testSourcePath("resources/scenes/mirrors.speculum.json")),
            warnings)
            .ok());
    scene::MeshLibrary meshes;
    std::vector<scene::Warning> snapshotWarnings;
    const render::FrameInput frame = scene::snapshot(scene, 0.0, meshes, snapshotWarnings);
    ASSERT_GE(frame.mirrors.size(), 3u);
    // Two of them face each other: opposite normals, each in front of the other.
    auto normal = [](const render::Mirror& m) {
        return glm::normalize(glm::dvec3(m.world * glm::dvec4(0, 1, 0, 0)));
    };
    bool facing = false;
    for (const auto& a : frame.mirrors)
        for (const auto& b : frame.mirrors)
            if (&a != &b && glm::dot(normal(a), normal(b)) < -0.999) {
                const glm::dvec3 pa(a.world[3]), pb(b.world[3]);
                facing |= glm::dot(normal(a), pb - pa) > 0 && glm::dot(normal(b), pa - pb) > 0;
            }
    EXPECT_TRUE(facing);
    EXPECT_GE(frame.items.size(), 3u);
}

} // namespace
} // namespace speculum::document
