// Imports that keep the file's parts, materials, textures, node tree and units: real files
// from Debian's assimp-testmodels and a small glTF written here whose every value is known.
#include "render/imageio/TextureLoader.hpp"
#include "scene/import/MeshLibrary.hpp"
#include "scene/import/ModelImport.hpp"
#include "scene/import/ModelNodes.hpp"
#include "scene/model/NodeMath.hpp"
#include "support/TestPaths.hpp"

#include <QByteArray>
#include <QString>
#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <functional>
#include <gtest/gtest.h>
#include <random>
#include <set>
#include <vector>

namespace speculum::document {
namespace {

namespace fs = std::filesystem;

const fs::path kModels = "/usr/share/assimp/models";

#define REQUIRE_TEST_MODELS()                                                                                \
    if (!fs::is_directory(kModels)) {                                                                        \
        GTEST_SKIP() << kModels << " is missing; install the assimp-testmodels package";                     \
    }

fs::path freshFolder() {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const fs::path folder = fs::path(speculum::testDataPath()) / "editor_import" /
                            (std::string(info->test_suite_name()) + "." + info->name());
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

fs::path writeFile(const fs::path& path, const std::string& content) {
    std::ofstream(path, std::ios::binary) << content;
    return path;
}

scene::ImportedModel importOk(const fs::path& path, std::vector<std::string>* warningsOut = nullptr) {
    std::vector<std::string> warnings;
    auto model = scene::importModelFile(path.string(), warnings);
    EXPECT_TRUE(model.ok()) << path << ": " << (model.ok() ? "" : model.error());
    if (warningsOut != nullptr) {
        *warningsOut = warnings;
    }
    return model.ok() ? std::move(model).value() : scene::ImportedModel{};
}

void collectNames(const scene::NodeTree& tree, std::vector<std::string>& names) {
    names.push_back(tree.data.name);
    for (const scene::NodeTree& child : tree.children) {
        collectNames(child, names);
    }
}

void forEachNode(const scene::NodeTree& tree, const std::function<void(const scene::NodeTree&)>& visit) {
    visit(tree);
    for (const scene::NodeTree& child : tree.children) {
        forEachNode(child, visit);
    }
}

// --- a glTF quad written here ------------------------------------------------------------------------------

// Two primitives over the same unit quad in the XY plane (corners (0,0), (1,0), (1,1), (0,1)): the first
// with a red metallic material whose base colour texture (a copy of Assimp's CesiumLogoFlat.png beside
// the file) clamps in u and mirrors in v; the second blue, half transparent, MASK at 0.3, emissive, with
// clearcoat, and vertex colours. TEXCOORD_0 is glTF's, v = 0 at the TOP of the image: the bottom-left
// corner has (0, 1).
fs::path writeQuadGltf(const fs::path& folder) {
    std::vector<float> floats = {
        0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,                // positions
        0, 1, 1, 1, 1, 0, 0, 0,                            // uvs (glTF convention)
        1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1, 1, 1, 1, 0.5f, // colours
    };
    QByteArray buffer(reinterpret_cast<const char*>(floats.data()), static_cast<int>(floats.size() * 4));
    const std::uint16_t indices[6] = {0, 1, 2, 0, 2, 3};
    buffer.append(reinterpret_cast<const char*>(indices), sizeof(indices));
    const std::string data = buffer.toBase64().toStdString();
    fs::copy_file(kModels / "glTF2/BoxTextured-glTF/CesiumLogoFlat.png", folder / "logo.png");
    const std::string json = R"({
  "asset": {"version": "2.0"},
  "scene": 0,
  "scenes": [{"nodes": [0]}],
  "nodes": [{"name": "Quad", "mesh": 0, "translation": [0, 0, 2]}],
  "meshes": [{"name": "QuadMesh", "primitives": [
    {"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 3, "material": 0},
    {"attributes": {"POSITION": 0, "TEXCOORD_0": 1, "COLOR_0": 2}, "indices": 3, "material": 1}]}],
  "materials": [
    {"name": "RedMetal", "pbrMetallicRoughness": {"baseColorFactor": [1, 0, 0, 1], "metallicFactor": 1,
     "roughnessFactor": 0.5, "baseColorTexture": {"index": 0}}},
    {"name": "BlueMask", "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 1, 0.5], "metallicFactor": 0,
     "roughnessFactor": 1}, "alphaMode": "MASK", "alphaCutoff": 0.3, "emissiveFactor": [0.5, 0.25, 0],
     "extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 1}}}],
  "extensionsUsed": ["KHR_materials_clearcoat"],
  "textures": [{"source": 0, "sampler": 0}],
  "images": [{"uri": "logo.png"}],
  "samplers": [{"wrapS": 33071, "wrapT": 33648}],
  "buffers": [{"byteLength": )" +
                             std::to_string(buffer.size()) +
                             R"(, "uri": "data:application/octet-stream;base64,)" + data + R"("}],
  "bufferViews": [
    {"buffer": 0, "byteOffset": 0, "byteLength": 48},
    {"buffer": 0, "byteOffset": 48, "byteLength": 32},
    {"buffer": 0, "byteOffset": 80, "byteLength": 64},
    {"buffer": 0, "byteOffset": 144, "byteLength": 12}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
    {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
    {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC4"},
    {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"}]
})";
    return writeFile(folder / "quad.gltf", json);
}

TEST(ModelParts, GltfQuadKeepsUvsWithVAtTheBottom) {
    REQUIRE_TEST_MODELS();
    const fs::path file = writeQuadGltf(freshFolder());
    const scene::ImportedModel model = importOk(file);
    ASSERT_EQ(model.parts.size(), 2u);
    const render::MeshData& mesh = *model.parts[0].mesh;
    ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
    ASSERT_EQ(mesh.positions.size(), 4u);
    // speculum's convention: v = 0 is the bottom row of the image, so the corner at the quad's bottom-left
    // (where glTF says v = 1, the image's bottom row) has uv (0, 0), and the top-right has (1, 1).
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::vec3 p = mesh.positions[v];
        EXPECT_NEAR(mesh.uvs[v].x, p.x, 1e-6f) << "corner " << v;
        EXPECT_NEAR(mesh.uvs[v].y, p.y, 1e-6f) << "corner " << v;
    }
}

TEST(ModelParts, GltfMaterialsAreConvertedPerPart) {
    REQUIRE_TEST_MODELS();
    const fs::path folder = freshFolder();
    const fs::path file = writeQuadGltf(folder);
    std::vector<std::string> warnings;
    const scene::ImportedModel model = importOk(file, &warnings);
    ASSERT_EQ(model.parts.size(), 2u);
    ASSERT_GE(model.parts[0].material, 0);
    ASSERT_GE(model.parts[1].material, 0);
    ASSERT_NE(model.parts[0].material, model.parts[1].material);
    const scene::MaterialComponent& red = model.materials[model.parts[0].material];
    const scene::MaterialComponent& blue = model.materials[model.parts[1].material];

    // Metal, roughness 0.5: alpha 0.25, shininess 2/0.0625 − 2 = 30, specular min(1·38/8, 1).
    EXPECT_EQ(red.color, glm::dvec3(1, 0, 0));
    EXPECT_NEAR(red.shininess, 30.0, 1e-6);
    EXPECT_NEAR(red.specular, 1.0, 1e-9);
    EXPECT_EQ(red.specularColor, glm::dvec3(1, 0, 0)); // a metal's highlight takes its colour
    EXPECT_NEAR(red.diffuse, 0.0, 1e-9);
    EXPECT_EQ(fs::path(red.texture.path), fs::absolute(folder / "logo.png").lexically_normal());
    EXPECT_EQ(red.wrap[0], scene::TextureWrap::ClampToEdge);
    EXPECT_EQ(red.wrap[1], scene::TextureWrap::MirroredRepeat);
    EXPECT_EQ(red.alphaMode, scene::AlphaMode::Opaque);

    // Dielectric, roughness 1: shininess clamps to 1, specular 0.04·9/8, white highlight.
    EXPECT_EQ(blue.color, glm::dvec3(0, 0, 1));
    EXPECT_NEAR(blue.shininess, 1.0, 1e-9);
    EXPECT_NEAR(blue.specular, 0.045, 1e-6);
    EXPECT_EQ(blue.specularColor, glm::dvec3(1.0));
    EXPECT_NEAR(blue.diffuse, 1.0, 1e-9);
    EXPECT_NEAR(blue.opacity, 0.5, 1e-6);
    EXPECT_EQ(blue.alphaMode, scene::AlphaMode::Mask);
    EXPECT_NEAR(blue.alphaCutoff, 0.3, 1e-6);
    EXPECT_NEAR(blue.emission.x, 0.5, 1e-6);
    EXPECT_NEAR(blue.emission.y, 0.25, 1e-6);
    EXPECT_TRUE(blue.texture.empty());

    // Vertex colours of the second part, linear RGBA as written.
    const render::MeshData& colored = *model.parts[1].mesh;
    ASSERT_EQ(colored.colors.size(), colored.positions.size());
    std::set<std::vector<float>> colours;
    for (const glm::vec4& c : colored.colors) {
        colours.insert({c.r, c.g, c.b, c.a});
    }
    EXPECT_EQ(colours,
              (std::set<std::vector<float>>{{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 1, 0.5f}}));
    EXPECT_TRUE(model.parts[0].mesh->colors.empty());

    // Clearcoat is named once, with the file name.
    const auto clearcoat =
        std::count(warnings.begin(), warnings.end(), "quad.gltf: KHR_materials_clearcoat ignored");
    EXPECT_EQ(clearcoat, 1) << ::testing::PrintToString(warnings);
}

TEST(ModelParts, GltfQuadNodeTree) {
    REQUIRE_TEST_MODELS();
    const fs::path file = writeQuadGltf(freshFolder());
    const scene::ImportedModel model = importOk(file);
    EXPECT_EQ(model.unitScale, 1.0); // glTF is in metres
    // Placed by the node's translation.
    EXPECT_NEAR(model.bounds.min.z, 2.0f, 1e-6f);
    EXPECT_NEAR(model.bounds.max.x, 1.0f, 1e-6f);

    const scene::NodeTree tree = scene::modelNodeTree(model, file.string(), "quad");
    EXPECT_EQ(tree.data.name, "quad");
    std::vector<std::string> names;
    collectNames(tree, names);
    EXPECT_NE(std::find(names.begin(), names.end(), "Quad"), names.end()) << ::testing::PrintToString(names);
    std::vector<const scene::NodeTree*> meshes;
    forEachNode(tree, [&](const scene::NodeTree& node) {
        if (node.data.mesh) {
            meshes.push_back(&node);
        }
    });
    ASSERT_EQ(meshes.size(), 2u);
    std::set<int> parts;
    for (const scene::NodeTree* node : meshes) {
        EXPECT_EQ(node->data.mesh->file, file.string());
        ASSERT_TRUE(node->data.mesh->part.has_value());
        parts.insert(*node->data.mesh->part);
        ASSERT_TRUE(node->data.material.has_value());
        EXPECT_EQ(*node->data.material, model.materials[model.parts[*node->data.mesh->part].material]);
    }
    EXPECT_EQ(parts, (std::set<int>{0, 1}));
    // The "Quad" node carries the translation.
    forEachNode(tree, [&](const scene::NodeTree& node) {
        if (node.data.name == "Quad") {
            EXPECT_EQ(node.data.transform.translate, glm::dvec3(0, 0, 2));
        }
    });
}

// --- real files ------------------------------------------------------------------------------------------

TEST(ModelParts, MultiMaterialGlbKeepsDistinctMaterials) {
    REQUIRE_TEST_MODELS();
    const scene::ImportedModel model =
        importOk(kModels / "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
    ASSERT_GT(model.parts.size(), 10u);
    std::set<std::vector<double>> colours;
    for (const scene::ImportedPart& part : model.parts) {
        ASSERT_TRUE(part.mesh);
        ASSERT_GE(part.material, 0) << part.name;
        const glm::dvec3 c = model.materials[part.material].color;
        colours.insert({c.x, c.y, c.z});
    }
    // Blue body, orange and red lifters, grey rods, ...
    EXPECT_GE(colours.size(), 4u);
    // The file's float 0.85f comes in as the double 0.85, so the project file says what the model file says.
    EXPECT_EQ(model.materials[model.parts[0].material].color, glm::dvec3(0.0, 0.0, 0.85));
}

TEST(ModelParts, ObjMaterialsFindTheirTexturesBesideTheFile) {
    REQUIRE_TEST_MODELS();
    // spider.mtl names its textures ".\wal67ar_small.jpg" (Windows separators).
    const scene::ImportedModel model = importOk(kModels / "OBJ/spider.obj");
    ASSERT_GT(model.parts.size(), 4u);
    std::set<std::string> textures;
    for (const scene::ImportedPart& part : model.parts) {
        if (part.material >= 0 && !model.materials[part.material].texture.empty()) {
            const std::string& texture = model.materials[part.material].texture.path;
            EXPECT_TRUE(fs::path(texture).is_absolute()) << texture;
            EXPECT_TRUE(fs::is_regular_file(texture)) << texture;
            textures.insert(fs::path(texture).filename().string());
        }
    }
    EXPECT_TRUE(textures.count("wal67ar_small.jpg")) << ::testing::PrintToString(textures);
    EXPECT_TRUE(textures.count("SpiderTex.jpg")) << ::testing::PrintToString(textures);
}

TEST(ModelParts, ColladaVertexColoursAreKept) {
    REQUIRE_TEST_MODELS();
    const scene::ImportedModel model = importOk(kModels / "Collada/kwxport_test_vcolors.dae");
    ASSERT_FALSE(model.parts.empty());
    bool anyColoured = false;
    for (const scene::ImportedPart& part : model.parts) {
        ASSERT_TRUE(part.mesh);
        ASSERT_EQ(part.mesh->colors.size(), part.mesh->positions.size()) << part.name;
        for (const glm::vec4& c : part.mesh->colors) {
            anyColoured |= c.r != c.g || c.g != c.b;
        }
    }
    EXPECT_TRUE(anyColoured);
    // The flattened mesh carries them too.
    auto flat = scene::flattenModel(model);
    ASSERT_TRUE(flat.ok()) << flat.error();
    EXPECT_EQ(flat->colors.size(), flat->positions.size());
    EXPECT_EQ(flat->uvs.size(), flat->positions.size());
}

TEST(ModelParts, GlbEmbeddedTextureIsDecodedOnceAndMatchesTheExternalFile) {
    REQUIRE_TEST_MODELS();
    const fs::path glb = kModels / "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
    const scene::ImportedModel model = importOk(glb);
    ASSERT_EQ(model.parts.size(), 1u);
    ASSERT_GE(model.parts[0].material, 0);
    const std::string& name = model.materials[model.parts[0].material].texture.path;
    EXPECT_EQ(name, glb.string() + "#*0");
    ASSERT_EQ(model.embeddedTextures.count(name), 1u);
    const render::TextureImage& embedded = *model.embeddedTextures.at(name);
    // The same image as the .gltf variant's external PNG, decoded the same way up.
    auto external = render::loadTexture((kModels / "glTF2/BoxTextured-glTF/CesiumLogoFlat.png").string());
    ASSERT_TRUE(external.ok()) << external.error();
    EXPECT_EQ(embedded.width, external->width);
    EXPECT_EQ(embedded.height, external->height);
    EXPECT_TRUE(embedded.rgba8 == external->rgba8);

    // The library hands it out by name, and the part by index.
    scene::MeshLibrary library;
    std::vector<scene::Warning> warnings;
    const auto image = library.embeddedTexture(name, warnings);
    ASSERT_TRUE(image);
    EXPECT_EQ(image->width, embedded.width);
    EXPECT_FALSE(library.embeddedTexture(glb.string() + "#*7", warnings));
    EXPECT_FALSE(library.embeddedTexture(glb.string(), warnings));
}

TEST(ModelParts, FbxUnitScaleGivesMetres) {
    REQUIRE_TEST_MODELS();
    // The same two cubes, once in centimetres (UnitScaleFactor 1) and once in metres (100).
    const scene::ImportedModel cm = importOk(kModels / "FBX/cubes_with_names.fbx");
    const scene::ImportedModel m = importOk(kModels / "FBX/cubes_with_mirroring_and_pivot.fbx");
    EXPECT_DOUBLE_EQ(cm.unitScale, 0.01);
    EXPECT_DOUBLE_EQ(m.unitScale, 1.0);
    const glm::vec3 sizeCm = cm.bounds.max - cm.bounds.min;
    const glm::vec3 sizeM = m.bounds.max - m.bounds.min;
    EXPECT_NEAR(sizeCm.x, 0.209328f, 1e-4f);
    EXPECT_NEAR(sizeM.x, 0.209328f, 1e-4f);
    // The flattened mesh has the unit scale applied.
    auto flat = scene::flattenModel(cm);
    ASSERT_TRUE(flat.ok());
    const render::Bounds b = render::computeBounds(*flat);
    EXPECT_NEAR(b.max.x - b.min.x, sizeCm.x, 1e-5f);
}

TEST(ModelParts, FbxNodeTreeHasTheFileNames) {
    REQUIRE_TEST_MODELS();
    const fs::path file = kModels / "FBX/cubes_with_names.fbx";
    const scene::ImportedModel model = importOk(file);
    const scene::NodeTree tree = scene::modelNodeTree(model, file.string(), "cubes");
    std::vector<std::string> names;
    collectNames(tree, names);
    EXPECT_NE(std::find(names.begin(), names.end(), "Cube2"), names.end()) << ::testing::PrintToString(names);
    EXPECT_NE(std::find(names.begin(), names.end(), "Куб1"), names.end()) << ::testing::PrintToString(names);
    // The root carries the unit scale.
    EXPECT_NEAR(tree.data.transform.scale.x, 0.01, 1e-12);
}

// Drawing the node tree's parts with their node transforms gives the flattened model, vertex for vertex.
TEST(ModelParts, NodeTreeTransformsReproduceTheFlattenedModel) {
    REQUIRE_TEST_MODELS();
    for (const char* name :
         {"FBX/cubes_with_names.fbx", "FBX/spider.fbx", "Collada/teapot_instancenodes.DAE"}) {
        SCOPED_TRACE(name);
        const fs::path file = kModels / name;
        const scene::ImportedModel model = importOk(file);
        const scene::NodeTree tree = scene::modelNodeTree(model, file.string(), "root");
        render::Bounds fromTree{glm::vec3(1e30f), glm::vec3(-1e30f)};
        std::function<void(const scene::NodeTree&, const glm::dmat4&)> walk = [&](const scene::NodeTree& node,
                                                                                  const glm::dmat4& parent) {
            const glm::dmat4 world = parent * scene::localMatrix(node.data.transform);
            if (node.data.mesh && node.data.mesh->part) {
                for (const glm::vec3& p : model.parts[*node.data.mesh->part].mesh->positions) {
                    const glm::vec3 q(world * glm::dvec4(glm::dvec3(p), 1.0));
                    fromTree.min = glm::min(fromTree.min, q);
                    fromTree.max = glm::max(fromTree.max, q);
                }
            }
            for (const scene::NodeTree& child : node.children) {
                walk(child, world);
            }
        };
        walk(tree, glm::dmat4(1.0));
        const float scale = glm::length(model.bounds.max - model.bounds.min);
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(fromTree.min[k], model.bounds.min[k], 1e-4f * scale) << k;
            EXPECT_NEAR(fromTree.max[k], model.bounds.max[k], 1e-4f * scale) << k;
        }
    }
}

TEST(ModelParts, DecomposeRoundTripsTranslateRotateScale) {
    std::mt19937 random(13);
    std::uniform_real_distribution<double> angle(-179.0, 179.0), size(0.1, 3.0), offset(-5.0, 5.0);
    for (int i = 0; i < 200; ++i) {
        const glm::dvec3 t(offset(random), offset(random), offset(random));
        const glm::dvec3 r(angle(random), std::uniform_real_distribution<double>(-89.0, 89.0)(random),
                           angle(random));
        glm::dvec3 s(size(random), size(random), size(random));
        if (i % 5 == 0) {
            s.x = -s.x; // mirrored
        }
        const glm::dmat4 matrix = scene::localMatrix(t, r, s);
        scene::Transform out;
        ASSERT_TRUE(scene::detail::decomposeTransform(matrix, out)) << i;
        const glm::dmat4 back = scene::localMatrix(out);
        for (int c = 0; c < 4; ++c) {
            for (int k = 0; k < 4; ++k) {
                ASSERT_NEAR(back[c][k], matrix[c][k], 1e-9) << i;
            }
        }
    }
    // Shear cannot be expressed: reported.
    glm::dmat4 shear(1.0);
    shear[1][0] = 0.5;
    scene::Transform out;
    EXPECT_FALSE(scene::detail::decomposeTransform(shear, out));
}

// --- library, errors, control ----------------------------------------------------------------------------

TEST(ModelParts, LibraryServesPartsAndNamesABadPart) {
    REQUIRE_TEST_MODELS();
    const fs::path file = writeQuadGltf(freshFolder());
    scene::MeshLibrary library;
    std::vector<scene::Warning> warnings;
    scene::MeshComponent component = scene::MeshComponent::fromFile(file.string());
    component.part = 1;
    auto part = library.get(component, warnings);
    ASSERT_TRUE(part.ok()) << part.error();
    EXPECT_FALSE((*part)->colors.empty());
    auto again = library.get(component, warnings);
    ASSERT_TRUE(again.ok());
    EXPECT_EQ(part.value(), again.value()); // cached: the same handle frame after frame

    component.part = 5;
    auto bad = library.get(component, warnings);
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().find("part 5"), std::string::npos) << bad.error();
    EXPECT_NE(bad.error().find("2 parts"), std::string::npos) << bad.error();

    component.part.reset();
    auto whole = library.get(component, warnings);
    ASSERT_TRUE(whole.ok());
    EXPECT_EQ((*whole)->triangleCount(), 4u);
    const render::Bounds b = library.bounds(*whole);
    EXPECT_NEAR(b.min.z, 2.0f, 1e-6f);
}

TEST(ModelParts, ProgressAndCancel) {
    REQUIRE_TEST_MODELS();
    const fs::path file = kModels / "OBJ/spider.obj";
    std::vector<double> fractions;
    scene::ImportControl control;
    control.progress = [&](double fraction, const char*) { fractions.push_back(fraction); };
    std::vector<std::string> warnings;
    ASSERT_TRUE(scene::importModelFile(file.string(), warnings, control).ok());
    ASSERT_GE(fractions.size(), 3u);
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
    EXPECT_EQ(fractions.back(), 1.0);

    std::atomic<bool> cancel{true};
    control.cancel = &cancel;
    auto cancelled = scene::importModelFile(file.string(), warnings, control);
    ASSERT_FALSE(cancelled.ok());
    EXPECT_EQ(cancelled.error(), "cancelled");
}

TEST(ModelParts, SeparateVerticesAreWeldedAndSmoothed) {
    // Two triangles of a folded quad, each with its own copies of the shared edge's vertices and no
    // normals: the weld joins them, so the rebuilt normals are shared across the fold.
    const fs::path file = writeFile(freshFolder() / "fold.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\n"
                                                                "v 0 0 0\nv 1 1 0\nv 0 1 1\n"
                                                                "f 1 2 3\nf 4 5 6\n");
    const scene::ImportedModel model = importOk(file);
    ASSERT_EQ(model.parts.size(), 1u);
    const render::MeshData& mesh = *model.parts[0].mesh;
    EXPECT_EQ(mesh.vertexCount(), 4u);
    EXPECT_EQ(mesh.triangleCount(), 2u);
}

// A binary PLY grid (the benchmark's 4 M-triangle file, smaller): every triangle kept, shared vertices
// kept shared (no per-face copies), smooth normals rebuilt facing +y, one part at the file's root.
TEST(ModelParts, BinaryPlyGridKeepsItsTopology) {
    const int quads = 300, side = quads + 1;
    const fs::path file = freshFolder() / "grid.ply";
    {
        std::ofstream out(file, std::ios::binary);
        out << "ply\nformat binary_little_endian 1.0\nelement vertex " << side * side
            << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << 2 * quads * quads
            << "\nproperty list uchar int vertex_indices\nend_header\n";
        for (int j = 0; j < side; ++j) {
            for (int i = 0; i < side; ++i) {
                const float p[3] = {static_cast<float>(i) / quads, 0.0f, static_cast<float>(j) / quads};
                out.write(reinterpret_cast<const char*>(p), sizeof(p));
            }
        }
        const auto face = [&](std::int32_t a, std::int32_t b, std::int32_t c) {
            out.put(3);
            for (std::int32_t index : {a, b, c}) {
                out.write(reinterpret_cast<const char*>(&index), 4);
            }
        };
        for (int j = 0; j < quads; ++j) {
            for (int i = 0; i < quads; ++i) {
                const std::int32_t v = j * side + i;
                face(v, v + side, v + 1);
                face(v + 1, v + side, v + side + 1);
            }
        }
    }
    const scene::ImportedModel model = importOk(file);
    ASSERT_EQ(model.parts.size(), 1u);
    const render::MeshData& mesh = *model.parts[0].mesh;
    EXPECT_EQ(mesh.triangleCount(), static_cast<std::size_t>(2 * quads * quads));
    EXPECT_EQ(mesh.vertexCount(), static_cast<std::size_t>(side * side));
    for (const glm::vec3& n : mesh.normals) {
        ASSERT_NEAR(n.y, 1.0f, 1e-5f);
    }
    EXPECT_NEAR(model.bounds.max.x, 1.0f, 1e-6f);
    EXPECT_NEAR(model.bounds.max.z, 1.0f, 1e-6f);
    // The whole file drawn as one mesh is that part itself, not a copy.
    scene::MeshLibrary library;
    std::vector<scene::Warning> warnings;
    auto whole = library.file(file.string(), warnings);
    ASSERT_TRUE(whole.ok());
    auto part = library.part(file.string(), 0, warnings);
    ASSERT_TRUE(part.ok());
    EXPECT_EQ(whole.value(), part.value());
}

} // namespace
} // namespace speculum::document
