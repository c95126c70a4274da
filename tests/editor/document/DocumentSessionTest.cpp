// The open document as a session: New, Open and Restore replace the document, its history and its mesh
// library together (the library's address stays, so a viewport holding it keeps working); a failed Open
// changes none of them. And the placement of an imported model, which the import adds with addNodeTree.
#include "editor/document/DocumentSession.hpp"

#include "OperationsTestSupport.hpp"
#include "editor/document/EditOperations.hpp"
#include "editor/document/NodeFactory.hpp"
#include "render/math/Projection.hpp"
#include "support/TestPaths.hpp"

#include <QFile>
#include <QTemporaryDir>
#include <glm/mat4x4.hpp>

namespace speculum::document {
namespace {

QString demoScene() {
    return QString::fromStdString(speculum::testSourcePath("resources/scenes/teapot.speculum.json"));
}

std::string toyset() {
    return speculum::testSourcePath("resources/models/toyset.glb");
}

TEST(DocumentSession, OpenReplacesTheSceneTheHistoryAndTheMeshLibrary) {
    DocumentSession session;
    scene::MeshLibrary& library = session.meshes();
    const render::MeshHandle sphere = library.builtin(scene::BuiltinMesh::Sphere, 16);
    ASSERT_TRUE(addNodeTree(session.scene(), session.undoStack(), makeNode(NewNodeKind::Box)));
    ASSERT_TRUE(session.isModified());

    std::vector<std::string> warnings;
    ASSERT_TRUE(session.open(demoScene(), warnings));
    EXPECT_EQ(session.scene().projectPath(), demoScene());
    EXPECT_EQ(session.undoStack().count(), 0);
    EXPECT_FALSE(session.isModified());
    EXPECT_EQ(&session.meshes(), &library) << "the same library object: references stay valid";
    EXPECT_EQ(library.size(), 0u) << "the old document's meshes are let go";
    EXPECT_NE(library.builtin(scene::BuiltinMesh::Sphere, 16), sphere);
}

TEST(DocumentSession, AFailedOpenChangesNothing) {
    DocumentSession session;
    ASSERT_TRUE(addNodeTree(session.scene(), session.undoStack(), makeNode(NewNodeKind::Box)));
    const scene::SceneData before = session.scene().toData();
    const render::MeshHandle sphere = session.meshes().builtin(scene::BuiltinMesh::Sphere, 16);
    std::vector<std::string> warnings;
    EXPECT_FALSE(session.open(
        QString::fromStdString(speculum::testSourcePath("no/such/project.speculum.json")), warnings));
    EXPECT_EQ(session.scene().toData(), before);
    EXPECT_EQ(session.undoStack().count(), 1);
    EXPECT_TRUE(session.isModified());
    EXPECT_EQ(session.meshes().builtin(scene::BuiltinMesh::Sphere, 16), sphere) << "the library is kept";
}

TEST(DocumentSession, NewAndRestoreReplaceTheDocumentARestoredOneIsModifiedUntilSaved) {
    DocumentSession session;
    ASSERT_TRUE(addNodeTree(session.scene(), session.undoStack(), makeNode(NewNodeKind::Box)));
    scene::SceneData recovered = session.scene().toData();
    session.meshes().builtin(scene::BuiltinMesh::Box, 1);

    session.replace(scene::SceneData{}, QString());
    EXPECT_TRUE(session.scene().topLevelNodes().empty());
    EXPECT_EQ(session.undoStack().count(), 0);
    EXPECT_FALSE(session.isModified());
    EXPECT_EQ(session.meshes().size(), 0u);

    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("restored.speculum.json"));
    session.replace(std::move(recovered), path, true);
    EXPECT_EQ(session.scene().topLevelNodes().size(), 1u);
    EXPECT_EQ(session.scene().projectPath(), path);
    EXPECT_TRUE(session.isModified()) << "a restored document has unsaved changes";
    ASSERT_TRUE(session.save(path));
    EXPECT_FALSE(session.isModified());
}

QByteArray fileBytes(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// Two sessions on one project, as two editors: the later save over a file the other changed is refused
// until this session's user chose to overwrite it; saves of its own never count as someone else's.
TEST(DocumentSession, SavingOverAFileSomeoneElseChangedIsRefusedUntilOverwriteIsChosen) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("shared.speculum.json"));
    ASSERT_TRUE(QFile::copy(demoScene(), path));
    std::vector<std::string> warnings;
    DocumentSession first, second;
    ASSERT_TRUE(first.open(path, warnings));
    ASSERT_TRUE(second.open(path, warnings));

    ASSERT_TRUE(addNodeTree(first.scene(), first.undoStack(), makeNode(NewNodeKind::Box)));
    ASSERT_TRUE(first.save(path));
    ASSERT_TRUE(first.save(path)) << "its own save is not a change by someone else";
    EXPECT_FALSE(first.changedOnDisk());
    const QByteArray firstBytes = fileBytes(path);

    ASSERT_TRUE(addNodeTree(second.scene(), second.undoStack(), makeNode(NewNodeKind::Mirror)));
    EXPECT_TRUE(second.changedOnDisk());
    const base::Status refused = second.save(path);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().find("changed on disk"), std::string::npos) << refused.error();
    EXPECT_EQ(fileBytes(path), firstBytes) << "the other editor's save is intact";
    EXPECT_TRUE(second.isModified()) << "and this version is still unsaved, not lost";

    ASSERT_TRUE(second.save(path, DocumentSession::DiskChanges::Overwrite));
    EXPECT_NE(fileBytes(path), firstBytes);
    EXPECT_FALSE(second.changedOnDisk());
    EXPECT_TRUE(first.changedOnDisk()) << "now the first editor is the one to be asked";

    // Touching the file, or writing the same bytes again, is no change.
    const QByteArray now = fileBytes(path);
    {
        QFile same(path);
        ASSERT_TRUE(same.open(QIODevice::WriteOnly | QIODevice::Truncate));
        same.write(now);
    }
    EXPECT_FALSE(second.changedOnDisk());
}

TEST(PlaceImportedModel, StandsOnTheGroundWhereTheViewLooksBesideWhatIsThere) {
    std::vector<std::string> warnings;
    auto model = scene::importModelFile(toyset(), warnings);
    ASSERT_TRUE(model) << model.error();
    scene::Scene scene;
    QUndoStack undo;
    scene::MeshLibrary meshes;
    ImportPlacement placement;
    placement.focus = {3.0, 1.0, -2.0};

    const PlacedModel first = placeImportedModel(scene, meshes, *model, toyset(), placement);
    EXPECT_EQ(first.fit, 1.0) << "real size";
    EXPECT_FALSE(first.tree.children.empty()) << "the file's node tree";
    const render::math::Box box = render::math::worldBounds(model->bounds, glm::dmat4(1.0));
    // What placing added to the root's own transform: the box moves by that much.
    const glm::dvec3 at = first.tree.data.transform.translate -
                          scene::modelNodeTree(*model, toyset(), "toyset").data.transform.translate;
    EXPECT_NEAR(box.min.y + at.y, 0.0, 1e-9) << "on the ground: nothing is under it";
    EXPECT_NEAR((box.min.x + box.max.x) * 0.5 + at.x, 3.0, 1e-9);
    EXPECT_NEAR((box.min.z + box.max.z) * 0.5 + at.z, -2.0, 1e-9);
    EXPECT_NEAR(first.size.x, box.max.x - box.min.x, 1e-12);

    auto added = addNodeTree(scene, undo, first.tree);
    ASSERT_TRUE(added);
    EXPECT_EQ(undo.count(), 1);
    meshes.addModel(toyset(), std::make_shared<const scene::ImportedModel>(*model));
    const PlacedModel second = placeImportedModel(scene, meshes, *model, toyset(), placement);
    EXPECT_GE(second.tree.data.transform.translate.x,
              first.tree.data.transform.translate.x + (box.max.x - box.min.x) - 1e-9)
        << "moved along +X past the first";

    placement.fitToUnitBox = true;
    placement.asReflector = true;
    const PlacedModel fitted = placeImportedModel(scene, meshes, *model, toyset(), placement);
    EXPECT_LT(fitted.fit, 1.0);
    EXPECT_NEAR(std::max({fitted.size.x, fitted.size.y, fitted.size.z}), 1.0, 1e-9);
    EXPECT_TRUE(fitted.tree.data.reflector.has_value()) << "the whole file as the reflector's surface";
    EXPECT_TRUE(fitted.tree.children.empty());
}

} // namespace
} // namespace speculum::document
