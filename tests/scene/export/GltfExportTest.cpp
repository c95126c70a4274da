// File ▸ Export Scene as glTF 2.0 (and `speculum export`): Assimp reads the file back with the same
// nodes, transforms and triangles, the mirror as a quad of its size; the .glb is self-contained (images
// inside it as PNG/JPEG, no path), the camera and the lights are there, extensionsUsed lists exactly what
// is used, and the uvs come back as they went out.
#include "scene/export/GltfExport.hpp"

#include "editor/document/Commands.hpp"
#include "editor/document/NodeFactory.hpp"
#include "render/imageio/TextureLoader.hpp"
#include "scene/evaluate/Snapshot.hpp"
#include "scene/import/ModelImport.hpp"
#include "scene/project/ProjectFile.hpp"
#include "support/FillingDisk.hpp"
#include "support/TestPaths.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QUndoStack>
#include <QUrl>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>
#include <iterator>
#include <map>
#include <set>

namespace {

using namespace speculum::document;
using namespace speculum::scene;

std::filesystem::path folder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const auto dir = std::filesystem::path(speculum::testDataPath()) / "editor_editing" / info->name();
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
    speculum::scene::Scene scene;
    std::vector<std::string> warnings;
    ASSERT_TRUE(speculum::scene::openProject(
                    scene,
                    QString::fromStdString(speculum::testSourcePath("resources/scenes/teapot.speculum.json")),
                    warnings)
                    .ok());
    QUndoStack stack;
    speculum::scene::NodeTree mirror = makeNode(NewNodeKind::Mirror, {0, 0, -4});
    mirror.data.mirror->size = {3.0, 1.5};
    mirror.children.push_back(makeNode(NewNodeKind::Sphere, {0, 1, 0}));
    stack.push(new AddNodeCommand(scene, mirror));

    for (const char* name : {"scene.gltf", "scene.glb"}) {
        const auto path = folder() / name;
        speculum::scene::MeshLibrary meshes;
        std::vector<std::string> exportWarnings;
        const auto status =
            speculum::scene::exportGltf(scene, QString::fromStdString(path.string()), meshes, exportWarnings);
        ASSERT_TRUE(status.ok()) << status.error();
        EXPECT_TRUE(exportWarnings.empty());
        ASSERT_TRUE(std::filesystem::exists(path));

        Assimp::Importer importer;
        const aiScene* read = importer.ReadFile(path.string(), 0);
        ASSERT_TRUE(read) << importer.GetErrorString();
        const aiNode* teapot = findNode(read->mRootNode, "Teapot");
        ASSERT_TRUE(teapot) << name;
        ASSERT_EQ(teapot->mNumMeshes, 1u);
        speculum::scene::MeshLibrary check;
        std::vector<speculum::scene::Warning> ignored;
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
    speculum::scene::Scene scene;
    speculum::scene::MeshLibrary meshes;
    std::vector<std::string> warnings;
    const auto dir = folder();
    EXPECT_FALSE(speculum::scene::exportGltf(scene, QString::fromStdString((dir / "scene.obj").string()),
                                             meshes, warnings)
                     .ok());
    const auto missing = speculum::scene::exportGltf(
        scene, QString::fromStdString((dir / "no" / "scene.gltf").string()), meshes, warnings);
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().find("does not exist"), std::string::npos);
    // An empty scene still exports.
    EXPECT_TRUE(speculum::scene::exportGltf(scene, QString::fromStdString((dir / "empty.gltf").string()),
                                            meshes, warnings)
                    .ok());
}

// ---- self-contained export: images, camera, lights, extensions, uvs ----

std::vector<unsigned char> readBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::uint32_t le32(const unsigned char* p) {
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 |
           std::uint32_t(p[3]) << 24;
}

struct Glb {
    QJsonObject json;
    std::vector<unsigned char> bin;
};

// Splits a GLB by the container rules, checking them on the way.
Glb parseGlb(const std::vector<unsigned char>& file) {
    Glb out;
    EXPECT_GE(file.size(), 20u);
    if (file.size() < 20) {
        return out;
    }
    EXPECT_EQ(std::memcmp(file.data(), "glTF", 4), 0);
    EXPECT_EQ(le32(&file[4]), 2u);
    EXPECT_EQ(le32(&file[8]), file.size());
    const std::uint32_t jsonLength = le32(&file[12]);
    EXPECT_EQ(jsonLength % 4, 0u);
    EXPECT_EQ(std::memcmp(&file[16], "JSON", 4), 0);
    QJsonParseError error;
    out.json =
        QJsonDocument::fromJson(QByteArray(reinterpret_cast<const char*>(&file[20]), int(jsonLength)), &error)
            .object();
    EXPECT_EQ(error.error, QJsonParseError::NoError) << error.errorString().toStdString();
    const std::size_t bin = 20 + jsonLength;
    if (bin + 8 <= file.size()) {
        const std::uint32_t binLength = le32(&file[bin]);
        EXPECT_EQ(std::memcmp(&file[bin + 4], "BIN\0", 4), 0);
        EXPECT_EQ(bin + 8 + binLength, file.size());
        out.bin.assign(file.begin() + std::ptrdiff_t(bin + 8), file.end());
    }
    return out;
}

// The floats of accessor `index` (float accessors only).
std::vector<float> accessorFloats(const QJsonObject& json, const std::vector<unsigned char>& bin, int index) {
    const QJsonObject accessor = json["accessors"].toArray()[index].toObject();
    const QJsonObject view = json["bufferViews"].toArray()[accessor["bufferView"].toInt()].toObject();
    EXPECT_EQ(accessor["componentType"].toInt(), 5126);
    const std::map<QString, int> sizes{{"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4}};
    const std::size_t count = std::size_t(accessor["count"].toInt()) * sizes.at(accessor["type"].toString());
    std::vector<float> values(count);
    const std::size_t offset = std::size_t(view["byteOffset"].toInt() + accessor["byteOffset"].toInt());
    EXPECT_LE(offset + count * 4, bin.size());
    std::memcpy(values.data(), bin.data() + offset, count * 4);
    return values;
}

// A 4×2 image, every pixel different, written top row first: the way up and the sides matter.
const unsigned char kTexels[2][4][4] = {
    {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 0, 255}},
    {{0, 255, 255, 255}, {255, 0, 255, 255}, {128, 128, 128, 255}, {255, 255, 255, 255}},
};

void writeTga(const std::filesystem::path& path) {
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out);
    OIIO::ImageSpec spec(4, 2, 4, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:UnassociatedAlpha", 1);
    ASSERT_TRUE(out->open(path.string(), spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, &kTexels[0][0][0]));
    ASSERT_TRUE(out->close());
}

// Reads a PNG/JPEG as stored (row 0 the top) and checks it holds kTexels.
void expectTexels(const std::string& label, std::unique_ptr<OIIO::ImageInput> in) {
    ASSERT_TRUE(in) << label << ": " << OIIO::geterror();
    ASSERT_EQ(in->spec().width, 4) << label;
    ASSERT_EQ(in->spec().height, 2) << label;
    std::vector<unsigned char> pixels(4 * 2 * 4);
    ASSERT_TRUE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, pixels.data()));
    EXPECT_EQ(std::memcmp(pixels.data(), &kTexels[0][0][0], pixels.size()), 0)
        << label << ": the image is not the texture as stored (flipped or mirrored?)";
}

// A scene with a TGA-textured plane, an emissive box, three kinds of light and a camera.
speculum::scene::SceneData exportScene(const std::filesystem::path& dir) {
    writeTga(dir / "checker.tga");
    speculum::scene::SceneData data;
    data.camera.position = {1.0, 2.0, 5.0};
    data.camera.target = {0.0, 0.5, 0.0};
    data.camera.fovY = 50.0;
    data.camera.near = 0.25;
    data.camera.far = 40.0;

    speculum::scene::NodeTree plane = makeNode(NewNodeKind::Plane);
    plane.data.name = "Floor";
    plane.data.material = speculum::scene::MaterialComponent{};
    plane.data.material->texture.path = (dir / "checker.tga").string();
    plane.data.material->wrap = {speculum::scene::TextureWrap::ClampToEdge,
                                 speculum::scene::TextureWrap::MirroredRepeat};
    plane.data.material->opacity = 0.5;
    plane.data.material->alphaMode = speculum::scene::AlphaMode::Mask;
    plane.data.material->alphaCutoff = 0.3;
    plane.data.material->shininess = 32.0;
    data.nodes.push_back(plane);

    speculum::scene::NodeTree point = makeNode(NewNodeKind::PointLight, {0, 3, 0});
    point.data.name = "Bulb";
    point.data.light->color = {1.0, 0.5, 0.25};
    point.data.light->intensity = 2.0;
    data.nodes.push_back(point);
    speculum::scene::NodeTree spot = makeNode(NewNodeKind::SpotLight, {2, 3, 0});
    spot.data.name = "Spot";
    spot.data.transform.rotate = {-30.0, 20.0, 0.0};
    spot.data.light->spotAngle = 40.0;
    spot.data.light->spotBlend = 0.25;
    data.nodes.push_back(spot);
    speculum::scene::NodeTree sun = makeNode(NewNodeKind::DirectionalLight, {0, 5, 0});
    sun.data.name = "Sun";
    data.nodes.push_back(sun);
    return data;
}

const aiNode* findNodeIn(const aiScene* scene, const char* name) {
    return findNode(scene->mRootNode, name);
}

aiMatrix4x4 globalTransform(const aiNode* node) {
    aiMatrix4x4 m = node->mTransformation;
    for (const aiNode* p = node->mParent; p; p = p->mParent) {
        m = p->mTransformation * m;
    }
    return m;
}

TEST(GltfExport, GlbIsSelfContainedWithCameraLightsAndOnlyUsedExtensions) {
    const auto dir = folder();
    speculum::scene::Scene scene;
    scene.reset(exportScene(dir));
    const auto path = dir / "scene.glb";
    speculum::scene::MeshLibrary meshes;
    std::vector<std::string> warnings;
    const auto status =
        speculum::scene::exportGltf(scene, QString::fromStdString(path.string()), meshes, warnings);
    ASSERT_TRUE(status.ok()) << status.error();
    EXPECT_TRUE(warnings.empty()) << warnings.front();

    const std::vector<unsigned char> file = readBytes(path);
    const std::string raw(file.begin(), file.end());
    EXPECT_EQ(raw.find(dir.string()), std::string::npos) << "no absolute path in the .glb";
    EXPECT_EQ(raw.find("checker.tga"), std::string::npos) << "no reference to the source file";
    const Glb glb = parseGlb(file);
    const QJsonObject& json = glb.json;
    EXPECT_EQ(json["asset"].toObject()["version"].toString(), "2.0");
    ASSERT_EQ(json["buffers"].toArray().size(), 1);
    EXPECT_FALSE(json["buffers"].toArray()[0].toObject().contains("uri"));
    const int byteLength = json["buffers"].toArray()[0].toObject()["byteLength"].toInt();
    EXPECT_LE(byteLength, int(glb.bin.size()));
    EXPECT_GT(byteLength + 4, int(glb.bin.size())) << "the BIN chunk pads the buffer by at most 3 bytes";

    // Images: inside the BIN chunk, PNG (the TGA converted), exactly the texture's pixels.
    const QJsonArray images = json["images"].toArray();
    ASSERT_EQ(images.size(), 1);
    for (const auto& value : images) {
        const QJsonObject image = value.toObject();
        EXPECT_FALSE(image.contains("uri"));
        ASSERT_TRUE(image.contains("bufferView"));
        EXPECT_EQ(image["mimeType"].toString(), "image/png");
        const QJsonObject view = json["bufferViews"].toArray()[image["bufferView"].toInt()].toObject();
        const auto* bytes = glb.bin.data() + view["byteOffset"].toInt();
        const std::size_t size = std::size_t(view["byteLength"].toInt());
        ASSERT_LE(view["byteOffset"].toInt() + size, glb.bin.size());
        OIIO::Filesystem::IOMemReader memory(bytes, size);
        expectTexels("embedded PNG", OIIO::ImageInput::open("image.png", nullptr, &memory));
    }

    // Material: texture with the wrap modes, alpha, roughness from shininess.
    const QJsonObject material = json["materials"].toArray()[0].toObject();
    const QJsonObject pbr = material["pbrMetallicRoughness"].toObject();
    EXPECT_DOUBLE_EQ(pbr["baseColorFactor"].toArray()[3].toDouble(), 0.5);
    EXPECT_NEAR(pbr["roughnessFactor"].toDouble(), std::pow(2.0 / 34.0, 0.25), 1e-9);
    EXPECT_EQ(material["alphaMode"].toString(), "MASK");
    EXPECT_DOUBLE_EQ(material["alphaCutoff"].toDouble(), 0.3);
    const QJsonObject texture =
        json["textures"].toArray()[pbr["baseColorTexture"].toObject()["index"].toInt()].toObject();
    const QJsonObject sampler = json["samplers"].toArray()[texture["sampler"].toInt()].toObject();
    EXPECT_EQ(sampler["wrapS"].toInt(), 33071); // clamp
    EXPECT_EQ(sampler["wrapT"].toInt(), 33648); // mirror

    // Camera: one perspective camera with the scene's field of view, looking at the target.
    ASSERT_EQ(json["cameras"].toArray().size(), 1);
    const QJsonObject perspective = json["cameras"].toArray()[0].toObject()["perspective"].toObject();
    EXPECT_NEAR(perspective["yfov"].toDouble(), 50.0 * M_PI / 180.0, 1e-12);
    EXPECT_DOUBLE_EQ(perspective["znear"].toDouble(), 0.25);
    EXPECT_DOUBLE_EQ(perspective["zfar"].toDouble(), 40.0);
    for (const auto& value : json["nodes"].toArray()) {
        const QJsonObject node = value.toObject();
        if (!node.contains("camera")) {
            continue;
        }
        const QJsonArray r = node["rotation"].toArray();
        const glm::dquat q(r[3].toDouble(), r[0].toDouble(), r[1].toDouble(), r[2].toDouble());
        const glm::dvec3 forward = q * glm::dvec3(0, 0, -1), up = q * glm::dvec3(0, 1, 0);
        const glm::dvec3 expected = glm::normalize(glm::dvec3(0.0, 0.5, 0.0) - glm::dvec3(1.0, 2.0, 5.0));
        EXPECT_NEAR(glm::length(forward - expected), 0.0, 1e-9);
        EXPECT_GT(up.y, 0.0);
        EXPECT_EQ(node["translation"].toArray()[2].toDouble(), 5.0);
    }

    // Lights: KHR_lights_punctual with the scene's three lights.
    const QJsonArray lights =
        json["extensions"].toObject()["KHR_lights_punctual"].toObject()["lights"].toArray();
    ASSERT_EQ(lights.size(), 3);
    std::map<QString, QJsonObject> byName;
    for (const auto& value : lights) {
        byName[value.toObject()["name"].toString()] = value.toObject();
    }
    EXPECT_EQ(byName["Bulb"]["type"].toString(), "point");
    EXPECT_DOUBLE_EQ(byName["Bulb"]["intensity"].toDouble(), 2.0);
    EXPECT_DOUBLE_EQ(byName["Bulb"]["color"].toArray()[1].toDouble(), 0.5);
    EXPECT_EQ(byName["Sun"]["type"].toString(), "directional");
    ASSERT_EQ(byName["Spot"]["type"].toString(), "spot");
    const QJsonObject cone = byName["Spot"]["spot"].toObject();
    EXPECT_NEAR(cone["outerConeAngle"].toDouble(), 40.0 * M_PI / 180.0, 1e-12);
    EXPECT_NEAR(cone["innerConeAngle"].toDouble(), 30.0 * M_PI / 180.0, 1e-12);

    // Exactly the extensions used; none required.
    const QJsonArray used = json["extensionsUsed"].toArray();
    ASSERT_EQ(used.size(), 1);
    EXPECT_EQ(used[0].toString(), "KHR_lights_punctual");
    EXPECT_FALSE(json.contains("extensionsRequired"));

    // The file's own uvs use glTF's top-left origin: the plane's corner at +Z (the bottom of the image
    // seen from above with -Z up) has v = 1.
    const QJsonObject floor = json["meshes"].toArray()[0].toObject()["primitives"].toArray()[0].toObject();
    const auto positions = accessorFloats(json, glb.bin, floor["attributes"].toObject()["POSITION"].toInt());
    const auto uvs = accessorFloats(json, glb.bin, floor["attributes"].toObject()["TEXCOORD_0"].toInt());
    ASSERT_EQ(positions.size() / 3, uvs.size() / 2);
    for (std::size_t i = 0; i < uvs.size() / 2; ++i) {
        EXPECT_NEAR(uvs[i * 2 + 1], (positions[i * 3 + 2] + 1.0f) / 2.0f, 1e-6f) << "vertex " << i;
        EXPECT_NEAR(uvs[i * 2], (positions[i * 3] + 1.0f) / 2.0f, 1e-6f) << "vertex " << i;
    }

    // Another reader: Assimp.
    Assimp::Importer importer;
    const aiScene* read = importer.ReadFile(path.string(), 0);
    ASSERT_TRUE(read) << importer.GetErrorString();
    EXPECT_EQ(read->mNumCameras, 1u);
    ASSERT_EQ(read->mNumTextures, 1u);
    EXPECT_EQ(read->mTextures[0]->mHeight, 0u) << "compressed (PNG) data";
    EXPECT_STREQ(read->mTextures[0]->achFormatHint, "png");
    aiString texturePath;
    ASSERT_EQ(read->mMaterials[read->mMeshes[0]->mMaterialIndex]->GetTexture(aiTextureType_DIFFUSE, 0,
                                                                             &texturePath),
              aiReturn_SUCCESS);
    EXPECT_STREQ(texturePath.C_Str(), "*0");

    // The uvs come back as speculum had them (Assimp turns glTF's v back on import).
    std::vector<speculum::scene::Warning> ignored;
    const auto planeMesh = meshes.get(*scene.topLevelNodes()[0]->data().mesh, ignored);
    ASSERT_TRUE(planeMesh.ok());
    const aiMesh* mesh = read->mMeshes[findNodeIn(read, "Floor")->mMeshes[0]];
    ASSERT_EQ(mesh->mNumVertices, (*planeMesh)->uvs.size());
    ASSERT_TRUE(mesh->HasTextureCoords(0));
    for (unsigned i = 0; i < mesh->mNumVertices; ++i) {
        EXPECT_NEAR(mesh->mTextureCoords[0][i].x, (*planeMesh)->uvs[i].x, 1e-6f) << i;
        EXPECT_NEAR(mesh->mTextureCoords[0][i].y, (*planeMesh)->uvs[i].y, 1e-6f) << i;
    }

    // Lights by type, each shining where speculum's does.
    ASSERT_EQ(read->mNumLights, 3u);
    std::vector<speculum::scene::Warning> snapshotWarnings;
    const auto frame = speculum::scene::snapshot(scene, 0.0, meshes, snapshotWarnings);
    std::set<aiLightSourceType> types;
    for (unsigned i = 0; i < read->mNumLights; ++i) {
        const aiLight* light = read->mLights[i];
        types.insert(light->mType);
        const aiNode* node = findNodeIn(read, light->mName.C_Str());
        ASSERT_TRUE(node) << light->mName.C_Str();
        const std::string name = light->mName.C_Str();
        const auto source = std::find_if(frame.lights.begin(), frame.lights.end(),
                                         [&](const auto& l) { return name.rfind(l.name, 0) == 0; });
        ASSERT_NE(source, frame.lights.end()) << name;
        const aiMatrix4x4 world = globalTransform(node);
        aiVector3D position = world * light->mPosition;
        EXPECT_NEAR(position.y, source->position.y, 1e-5) << name;
        if (light->mType != aiLightSource_POINT) {
            aiVector3D direction = aiMatrix3x3(world) * light->mDirection;
            direction.Normalize();
            EXPECT_NEAR(direction.x, source->direction.x, 1e-5) << name;
            EXPECT_NEAR(direction.y, source->direction.y, 1e-5) << name;
            EXPECT_NEAR(direction.z, source->direction.z, 1e-5) << name;
        }
    }
    EXPECT_EQ(types, (std::set<aiLightSourceType>{aiLightSource_POINT, aiLightSource_SPOT,
                                                  aiLightSource_DIRECTIONAL}));
}

TEST(GltfExport, GltfWritesItsImagesBesideItWithRelativeUris) {
    const auto dir = folder();
    speculum::scene::Scene scene;
    speculum::scene::SceneData data = exportScene(dir);
    // A PNG texture is copied byte for byte; the same texture twice is stored once.
    std::filesystem::create_directories(dir / "maps");
    {
        auto out = OIIO::ImageOutput::create((dir / "maps" / "glow.png").string());
        OIIO::ImageSpec spec(4, 2, 4, OIIO::TypeDesc::UINT8);
        ASSERT_TRUE(out->open((dir / "maps" / "glow.png").string(), spec));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, &kTexels[0][0][0]));
        ASSERT_TRUE(out->close());
    }
    speculum::scene::NodeTree box = makeNode(NewNodeKind::Box, {0, 1, 0});
    box.data.name = "Lamp";
    box.data.material = speculum::scene::MaterialComponent{};
    box.data.material->emission = {4.0, 2.0, 0.0};
    box.data.material->color = {0.8, 0.4, 0.2};
    box.data.material->specularColor = glm::mix(glm::dvec3(1.0), box.data.material->color, 0.75);
    box.data.material->emissionTexture.path = (dir / "maps" / "glow.png").string();
    box.data.material->texture.path = (dir / "maps" / "glow.png").string();
    data.nodes.push_back(box);
    scene.reset(data);

    const auto out = dir / "out";
    std::filesystem::create_directories(out);
    const auto path = out / "my scene.gltf";
    speculum::scene::MeshLibrary meshes;
    std::vector<std::string> warnings;
    const auto status =
        speculum::scene::exportGltf(scene, QString::fromStdString(path.string()), meshes, warnings);
    ASSERT_TRUE(status.ok()) << status.error();

    std::ifstream in(path);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text.find(dir.string()), std::string::npos) << "no absolute path";
    const QJsonObject json = QJsonDocument::fromJson(QByteArray::fromStdString(text)).object();
    const QString bufferUri = json["buffers"].toArray()[0].toObject()["uri"].toString();
    EXPECT_EQ(bufferUri, "my_scene.bin") << "companions are named without characters a URI must escape";
    EXPECT_TRUE(std::filesystem::exists(out / "my_scene.bin"));

    const QJsonArray images = json["images"].toArray();
    ASSERT_EQ(images.size(), 2);
    for (const auto& value : images) {
        const QJsonObject image = value.toObject();
        EXPECT_FALSE(image.contains("bufferView"));
        const std::string uri = image["uri"].toString().toStdString();
        ASSERT_FALSE(uri.empty());
        EXPECT_NE(uri.front(), '/');
        EXPECT_EQ(uri.find(':'), std::string::npos);
        const QString file = QUrl::fromPercentEncoding(QByteArray::fromStdString(uri));
        const auto beside = out / file.toStdString();
        ASSERT_TRUE(std::filesystem::exists(beside)) << uri;
        expectTexels(uri, OIIO::ImageInput::open(beside.string()));
    }
    // The PNG went through unchanged.
    const QString glowUri = QUrl::fromPercentEncoding(images[1].toObject()["uri"].toString().toUtf8());
    EXPECT_EQ(readBytes(out / glowUri.toStdString()), readBytes(dir / "maps" / "glow.png"));

    // Emission brighter than 1: factor scaled into 0..1, the strength in its extension, listed as used.
    const QJsonObject lamp = json["materials"].toArray()[1].toObject();
    // specularColor = mix(white, colour, metallic), as the importer makes it: metallic comes back.
    EXPECT_NEAR(lamp["pbrMetallicRoughness"].toObject()["metallicFactor"].toDouble(), 0.75, 1e-9);
    EXPECT_DOUBLE_EQ(json["materials"]
                         .toArray()[0]
                         .toObject()["pbrMetallicRoughness"]
                         .toObject()["metallicFactor"]
                         .toDouble(),
                     0.0)
        << "a white specular colour is a dielectric";
    EXPECT_DOUBLE_EQ(lamp["emissiveFactor"].toArray()[0].toDouble(), 1.0);
    EXPECT_DOUBLE_EQ(lamp["emissiveFactor"].toArray()[1].toDouble(), 0.5);
    EXPECT_DOUBLE_EQ(lamp["extensions"]
                         .toObject()["KHR_materials_emissive_strength"]
                         .toObject()["emissiveStrength"]
                         .toDouble(),
                     4.0);
    EXPECT_TRUE(lamp.contains("emissiveTexture"));
    std::set<QString> used;
    for (const auto& value : json["extensionsUsed"].toArray()) {
        used.insert(value.toString());
    }
    EXPECT_EQ(used, (std::set<QString>{"KHR_lights_punctual", "KHR_materials_emissive_strength"}));

    Assimp::Importer importer;
    const aiScene* read = importer.ReadFile(path.string(), 0);
    ASSERT_TRUE(read) << importer.GetErrorString();
    EXPECT_EQ(read->mNumCameras, 1u);
    EXPECT_EQ(read->mNumLights, 3u);
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(out)) {
        EXPECT_EQ(entry.path().filename().string().rfind(".", 0), std::string::npos) << "no temporary left";
        ++files;
    }
    EXPECT_EQ(files, 4u) << ".gltf, .bin and two images";
}

TEST(GltfExport, MissingTexturesAreSkippedWithAWarning) {
    const auto dir = folder();
    speculum::scene::SceneData data;
    speculum::scene::NodeTree box = makeNode(NewNodeKind::Box);
    box.data.name = "Box";
    box.data.material = speculum::scene::MaterialComponent{};
    box.data.material->texture.path = (dir / "gone.png").string();
    data.nodes.push_back(box);
    speculum::scene::Scene scene;
    scene.reset(data);
    speculum::scene::MeshLibrary meshes;
    std::vector<std::string> warnings;
    const auto path = dir / "scene.glb";
    ASSERT_TRUE(
        speculum::scene::exportGltf(scene, QString::fromStdString(path.string()), meshes, warnings).ok());
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("gone.png"), std::string::npos) << warnings[0];
    const Glb glb = parseGlb(readBytes(path));
    EXPECT_FALSE(glb.json.contains("images"));
    EXPECT_FALSE(glb.json.contains("extensionsUsed")) << "no lights, nothing used";
}

// A texture embedded in an imported model ("<model>#*0") goes into the new .glb byte for byte; the model's
// vertex colours come out as COLOR_0 and read back as they were.
TEST(GltfExport, EmbeddedTexturesAndVertexColoursAreKept) {
    const auto dir = folder();
    // The model: our own .glb of the TGA-textured plane (its image is an embedded PNG).
    {
        speculum::scene::Scene source;
        speculum::scene::SceneData data = exportScene(dir);
        data.nodes.resize(1);
        source.reset(data);
        speculum::scene::MeshLibrary meshes;
        std::vector<std::string> warnings;
        ASSERT_TRUE(speculum::scene::exportGltf(source, QString::fromStdString((dir / "model.glb").string()),
                                                meshes, warnings)
                        .ok());
    }
    // A triangle with vertex colours.
    std::ofstream(dir / "colours.ply")
        << "ply\nformat ascii 1.0\nelement vertex 3\n"
           "property float x\nproperty float y\nproperty float z\n"
           "property uchar red\nproperty uchar green\nproperty uchar blue\n"
           "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
           "0 0 0 255 0 0\n1 0 0 0 255 0\n0 1 0 0 0 255\n3 0 1 2\n";
    speculum::scene::SceneData data;
    speculum::scene::NodeTree model;
    model.data.name = "Model";
    model.data.mesh = speculum::scene::MeshComponent::fromFile((dir / "model.glb").string());
    model.data.material = speculum::scene::MaterialComponent{};
    model.data.material->texture.path = (dir / "model.glb").string() + "#*0";
    data.nodes.push_back(model);
    speculum::scene::NodeTree colours;
    colours.data.name = "Colours";
    colours.data.mesh = speculum::scene::MeshComponent::fromFile((dir / "colours.ply").string());
    data.nodes.push_back(colours);
    speculum::scene::Scene scene;
    scene.reset(data);

    const auto path = dir / "again.glb";
    speculum::scene::MeshLibrary meshes;
    std::vector<std::string> warnings;
    const auto status =
        speculum::scene::exportGltf(scene, QString::fromStdString(path.string()), meshes, warnings);
    ASSERT_TRUE(status.ok()) << status.error();
    for (const std::string& w : warnings) {
        EXPECT_EQ(w.find("texture"), std::string::npos) << w;
    }

    const Glb original = parseGlb(readBytes(dir / "model.glb"));
    const Glb again = parseGlb(readBytes(path));
    auto imageBytes = [](const Glb& glb, int index) {
        const QJsonObject image = glb.json["images"].toArray()[index].toObject();
        const QJsonObject view = glb.json["bufferViews"].toArray()[image["bufferView"].toInt()].toObject();
        const auto begin = glb.bin.begin() + view["byteOffset"].toInt();
        return std::vector<unsigned char>(begin, begin + view["byteLength"].toInt());
    };
    ASSERT_EQ(again.json["images"].toArray().size(), 1);
    EXPECT_EQ(again.json["images"].toArray()[0].toObject()["mimeType"].toString(), "image/png");
    EXPECT_EQ(imageBytes(again, 0), imageBytes(original, 0)) << "the embedded PNG is copied as it is";
    const std::vector<unsigned char> file = readBytes(path);
    const std::string raw(file.begin(), file.end());
    EXPECT_EQ(raw.find(dir.string()), std::string::npos) << "no path to the model";

    // Vertex colours: what speculum has, in the file and back through Assimp.
    std::vector<speculum::scene::Warning> ignored;
    const auto triangle = meshes.get(*colours.data.mesh, ignored);
    ASSERT_TRUE(triangle.ok()) << triangle.error();
    ASSERT_EQ((*triangle)->colors.size(), 3u) << "the importer keeps PLY vertex colours";
    Assimp::Importer importer;
    const aiScene* read = importer.ReadFile(path.string(), 0);
    ASSERT_TRUE(read) << importer.GetErrorString();
    const aiNode* node = findNodeIn(read, "Colours");
    ASSERT_TRUE(node && node->mNumMeshes == 1);
    const aiMesh* mesh = read->mMeshes[node->mMeshes[0]];
    ASSERT_TRUE(mesh->HasVertexColors(0));
    ASSERT_EQ(mesh->mNumVertices, 3u);
    for (unsigned i = 0; i < 3; ++i) {
        const glm::vec4 c = (*triangle)->colors[i];
        EXPECT_NEAR(mesh->mColors[0][i].r, c.r, 1e-6f) << i;
        EXPECT_NEAR(mesh->mColors[0][i].g, c.g, 1e-6f) << i;
        EXPECT_NEAR(mesh->mColors[0][i].b, c.b, 1e-6f) << i;
        EXPECT_NEAR(mesh->mColors[0][i].a, c.a, 1e-6f) << i;
    }
    // Three different colours, not white: the data is real.
    EXPECT_GT((*triangle)->colors[0].r, (*triangle)->colors[0].g);
    EXPECT_GT((*triangle)->colors[1].g, (*triangle)->colors[1].r);
}

// All or nothing: when one of the .gltf's files cannot be put in place (here its .bin's name is taken by a
// folder), the existing .gltf is left as it was and no temporary remains.
TEST(GltfExport, AFailedExportLeavesNoPartialOutput) {
    const auto dir = folder();
    speculum::scene::Scene scene;
    scene.reset(exportScene(dir));
    std::filesystem::create_directories(dir / "scene.bin");
    std::ofstream(dir / "scene.gltf") << "precious";
    speculum::scene::MeshLibrary meshes;
    std::vector<std::string> warnings;
    const auto status = speculum::scene::exportGltf(
        scene, QString::fromStdString((dir / "scene.gltf").string()), meshes, warnings);
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find("scene.bin"), std::string::npos) << status.error();
    std::ifstream in(dir / "scene.gltf");
    EXPECT_EQ(std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()),
              "precious");
    std::set<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        names.insert(entry.path().filename().string());
    }
    EXPECT_EQ(names, (std::set<std::string>{"checker.tga", "scene.bin", "scene.gltf"}));
}

// A disk that fills up part-way through the export (a file-size limit in a child, EFBIG as a full disk's
// ENOSPC): the error names the file and the cause, and every file of the previous export, the .gltf and
// each companion, stays byte-identical, with no temporary left.
TEST(GltfExport, ADiskFillingUpKeepsEveryPreviousFile) {
    namespace fs = std::filesystem;
    const auto dir = folder();
    speculum::scene::Scene scene;
    scene.reset(exportScene(dir));
    speculum::scene::MeshLibrary meshes;
    std::vector<std::string> warnings;
    for (const char* name : {"scene.gltf", "scene.glb"}) {
        SCOPED_TRACE(name);
        const fs::path target = dir / name;
        ASSERT_TRUE(
            speculum::scene::exportGltf(scene, QString::fromStdString(target.string()), meshes, warnings)
                .ok());
        std::map<std::string, std::string> before;
        for (const auto& entry : fs::directory_iterator(dir)) {
            std::ifstream in(entry.path(), std::ios::binary);
            before[entry.path().filename().string()] = std::string(std::istreambuf_iterator<char>(in), {});
        }
        const speculum::render::test::ChildOutcome child =
            speculum::render::test::inChild([&](std::string& text) {
                speculum::render::test::limitFileSize(1024);
                const speculum::base::Status status = speculum::scene::exportGltf(
                    scene, QString::fromStdString(target.string()), meshes, warnings);
                text = status.ok() ? std::string("(exported)") : status.error();
                return status.ok() ? 1 : 0;
            });
        ASSERT_EQ(child.exitCode, 0) << child.text;
        EXPECT_EQ(child.text.find('\n'), std::string::npos) << child.text;
        EXPECT_NE(child.text.find("File too large"), std::string::npos) << child.text;
        EXPECT_NE(child.text.find("the previous file is unchanged"), std::string::npos) << child.text;
        std::map<std::string, std::string> after;
        for (const auto& entry : fs::directory_iterator(dir)) {
            std::ifstream in(entry.path(), std::ios::binary);
            after[entry.path().filename().string()] = std::string(std::istreambuf_iterator<char>(in), {});
        }
        EXPECT_EQ(after, before);
    }
}

// A whole model file on a node without a material of its own is exported as the viewport draws it: each
// part of the file with the file's own material (colours and textures), where the file places it, not as
// one grey primitive.
TEST(GltfExport, AWholeModelFileKeepsItsPartsAndTheirMaterials) {
    const auto dir = folder();
    const std::string toyset = speculum::testSourcePath("resources/models/toyset.glb");
    std::vector<std::string> importWarnings;
    const auto model = speculum::scene::importModelFile(toyset, importWarnings);
    ASSERT_TRUE(model.ok()) << model.error();
    ASSERT_GT(model->materials.size(), 1u) << "a file with materials of its own";

    speculum::scene::SceneData data;
    speculum::scene::NodeTree node = makeNode(NewNodeKind::Box);
    node.data.name = "Toys";
    node.data.mesh->builtin.reset();
    node.data.mesh->file = toyset;
    node.data.material.reset();
    data.nodes.push_back(node);
    speculum::scene::Scene scene;
    scene.reset(data);
    speculum::scene::MeshLibrary meshes;
    std::vector<std::string> warnings;
    const auto glb = dir / "toys.glb";
    ASSERT_TRUE(
        speculum::scene::exportGltf(scene, QString::fromStdString(glb.string()), meshes, warnings).ok());

    Assimp::Importer importer;
    const aiScene* back = importer.ReadFile(glb.string(), aiProcess_Triangulate);
    ASSERT_NE(back, nullptr) << importer.GetErrorString();
    std::set<std::string> colours;
    for (unsigned i = 0; i < back->mNumMaterials; ++i) {
        aiColor4D c;
        if (back->mMaterials[i]->Get(AI_MATKEY_BASE_COLOR, c) == AI_SUCCESS) {
            colours.insert(std::to_string(int(c.r * 100)) + "," + std::to_string(int(c.g * 100)) + "," +
                           std::to_string(int(c.b * 100)));
        }
    }
    EXPECT_GE(back->mNumMeshes, model->materials.size() > 1 ? 2u : 1u) << "a mesh per part, not one";
    EXPECT_GE(colours.size(), 2u) << "the file's materials, not one grey";
}

std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// A .gltf export writes <name>.bin and <name>_<n>.png beside it. It replaces those of an earlier export
// to the same file without asking, but never an unrelated file of such a name: without leave it refuses
// with one line naming the file and writes nothing; with leave (the editor asks) it replaces it.
TEST(GltfExport, FilesBesideItThatNoEarlierExportWroteAreNeverReplacedUnasked) {
    namespace fs = std::filesystem;
    const auto dir = folder();
    speculum::scene::Scene scene;
    scene.reset(exportScene(dir));
    speculum::scene::MeshLibrary meshes;
    std::vector<std::string> warnings;
    const QString target = QString::fromStdString((dir / "b.gltf").string());
    std::ofstream(dir / "b.bin") << "someone else's buffer";
    std::ofstream(dir / "b_0.png") << "someone else's picture";
    std::vector<std::string> asked;
    const auto refuse = [&](const std::vector<std::string>& paths) {
        asked = paths;
        return false;
    };
    const auto status = speculum::scene::exportGltf(scene, target, meshes, warnings, refuse);
    ASSERT_FALSE(status.ok());
    EXPECT_EQ(status.error().find('\n'), std::string::npos);
    EXPECT_NE(status.error().find("b.bin exists and is not part of an earlier export to b.gltf"),
              std::string::npos)
        << status.error();
    EXPECT_EQ(asked.size(), 2u) << "both files were named to the one asked";
    EXPECT_EQ(readText(dir / "b.bin"), "someone else's buffer");
    EXPECT_EQ(readText(dir / "b_0.png"), "someone else's picture");
    EXPECT_FALSE(fs::exists(dir / "b.gltf")) << "nothing was written";
    EXPECT_FALSE(speculum::scene::exportGltf(scene, target, meshes, warnings).ok())
        << "no one to ask: refused";

    // Given leave, the export replaces them; after that they are its own, and a new export asks nothing.
    ASSERT_TRUE(
        speculum::scene::exportGltf(scene, target, meshes, warnings, [](const auto&) { return true; }).ok());
    EXPECT_NE(readText(dir / "b.bin"), "someone else's buffer");
    asked.clear();
    ASSERT_TRUE(speculum::scene::exportGltf(scene, target, meshes, warnings, refuse).ok());
    EXPECT_TRUE(asked.empty());
}

} // namespace
