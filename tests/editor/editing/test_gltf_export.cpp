// File ▸ Export Scene as glTF 2.0: Assimp reads the file back with the same nodes, transforms and
// triangles, the mirror as a quad of its size, and the texture referenced relative to the file.
#include "editor/document/Commands.hpp"
#include "editor/document/GltfExport.hpp"
#include "editor/document/NodeFactory.hpp"
#include "editor/document/ProjectFile.hpp"

#include <QDir>
#include <QUndoStack>
#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <filesystem>
#include <functional>
#include <gtest/gtest.h>

namespace {

using namespace speculum::document;

std::filesystem::path folder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const auto dir = std::filesystem::path(SPECULUM_TEST_DATA_DIR) / "editor_editing" / info->name();
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

const aiNode* findNode(const aiNode* node, const std::string& name) {
    if (name == node->mName.C_Str()) {
        return node;
    }
    for (unsigned i = 0; i < node->mNumChildren; ++i) {
        if (const aiNode* found = findNode(node->mChildren[i], name)) {
            return found;
        }
    }
    return nullptr;
}

TEST(GltfExport, TheDemoSceneReadsBackWithItsNodesAndMeshes) {
    Scene scene;
    std::vector<std::string> warnings;
    ASSERT_TRUE(openProject(scene,
                            QStringLiteral(SPECULUM_SOURCE_DIR "/resources/scenes/teapot.speculum.json"),
                            warnings)
                    .ok());
    QUndoStack stack;
    NodeTree mirror = makeNode(NewNodeKind::Mirror, {0, 0, -4});
    mirror.data.mirror->size = {3.0, 1.5};
    mirror.children.push_back(makeNode(NewNodeKind::Sphere, {0, 1, 0}));
    stack.push(new AddNodeCommand(scene, mirror));

    for (const char* name : {"scene.gltf", "scene.glb"}) {
        const auto path = folder() / name;
        MeshLibrary meshes;
        std::vector<std::string> exportWarnings;
        const auto status = exportGltf(scene, QString::fromStdString(path.string()), meshes, exportWarnings);
        ASSERT_TRUE(status.ok()) << status.error();
        EXPECT_TRUE(exportWarnings.empty());
        ASSERT_TRUE(std::filesystem::exists(path));

        Assimp::Importer importer;
        const aiScene* read = importer.ReadFile(path.string(), 0);
        ASSERT_TRUE(read) << importer.GetErrorString();
        const aiNode* teapot = findNode(read->mRootNode, "Teapot");
        ASSERT_TRUE(teapot) << name;
        ASSERT_EQ(teapot->mNumMeshes, 1u);
        MeshLibrary check;
        std::vector<std::string> ignored;
        const auto teapotMesh = check.get(*scene.topLevelNodes()[0]->data().mesh, ignored);
        ASSERT_TRUE(teapotMesh.ok());
        EXPECT_EQ(read->mMeshes[teapot->mMeshes[0]]->mNumFaces, (*teapotMesh)->triangleCount());
        // Its transform: translate (0,-1,-3), scale 0.25.
        aiVector3D scaling, position;
        aiQuaternion rotation;
        teapot->mTransformation.Decompose(scaling, rotation, position);
        EXPECT_NEAR(position.y, -1.0f, 1e-5f);
        EXPECT_NEAR(position.z, -3.0f, 1e-5f);
        EXPECT_NEAR(scaling.x, 0.25f, 1e-5f);

        const aiNode* m = findNode(read->mRootNode, "Mirror");
        ASSERT_TRUE(m);
        ASSERT_EQ(m->mNumMeshes, 1u);
        const aiMesh* quad = read->mMeshes[m->mMeshes[0]];
        EXPECT_EQ(quad->mNumFaces, 2u);
        float maxX = 0, maxZ = 0;
        for (unsigned i = 0; i < quad->mNumVertices; ++i) {
            maxX = std::max(maxX, quad->mVertices[i].x);
            maxZ = std::max(maxZ, quad->mVertices[i].z);
        }
        EXPECT_NEAR(maxX, 1.5f, 1e-6f);
        EXPECT_NEAR(maxZ, 0.75f, 1e-6f);
        ASSERT_TRUE(findNode(m, "Sphere")) << "children stay under their parent";
        EXPECT_TRUE(findNode(read->mRootNode, "Light")) << "lights are kept as nodes";
    }
}

TEST(GltfExport, BadNamesAreErrors) {
    Scene scene;
    MeshLibrary meshes;
    std::vector<std::string> warnings;
    const auto dir = folder();
    EXPECT_FALSE(
        exportGltf(scene, QString::fromStdString((dir / "scene.obj").string()), meshes, warnings).ok());
    const auto missing =
        exportGltf(scene, QString::fromStdString((dir / "no" / "scene.gltf").string()), meshes, warnings);
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().find("does not exist"), std::string::npos);
    // An empty scene still exports.
    EXPECT_TRUE(
        exportGltf(scene, QString::fromStdString((dir / "empty.gltf").string()), meshes, warnings).ok());
}

} // namespace
