// Which way up a texture shows on a model read from a file, in both renderers: a glTF quad written here,
// with glTF's own texture coordinates (v = 0 at the image's TOP), imported through the editor's model
// import. Seen from the front it must show the image as an image viewer shows the file, the way Blender
// and three.js put it; a flip anywhere between the file's uvs and the pixel fails it.
#include "render/reference/Tracer.hpp"
#include "scene/import/ModelImport.hpp"
#include "support/GlTest.hpp"
#include "support/MaterialScenes.hpp"

#include <QByteArray>
#include <fstream>

namespace speculum::test {
namespace {

namespace fs = std::filesystem;
using namespace materials;

// A unit quad in the XY plane facing +Z (corners (−1,−1) .. (1,1)) whose base colour texture is the
// quadrant image beside it. glTF uvs: the top-left corner of the quad takes (0, 0), the image's top left.
fs::path writeTexturedQuadGltf(const fs::path& folder) {
    writeQuadrantTexture(folder); // quadrants.png
    const float floats[] = {
        -1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0, // positions: bottom left, bottom right, top right, top left
        0,  0,  1, 0, 0,  1, 0, 0, 1, 0,  0, 1, // normals
        0,  1,  1, 1, 1,  0, 0, 0,              // uvs, glTF convention
    };
    QByteArray buffer(reinterpret_cast<const char*>(floats), sizeof(floats));
    const std::uint16_t indices[6] = {0, 1, 2, 0, 2, 3};
    buffer.append(reinterpret_cast<const char*>(indices), sizeof(indices));
    const std::string json = R"({
  "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"name": "Quad", "mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3,
                              "material": 0}]}],
  "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "metallicFactor": 0}}],
  "textures": [{"source": 0}], "images": [{"uri": "quadrants.png"}],
  "buffers": [{"byteLength": )" +
                             std::to_string(buffer.size()) +
                             R"(, "uri": "data:application/octet-stream;base64,)" +
                             buffer.toBase64().toStdString() + R"("}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 48},
                  {"buffer": 0, "byteOffset": 96, "byteLength": 32}, {"buffer": 0, "byteOffset": 128, "byteLength": 12}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 0]},
    {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
    {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
    {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"}]
})";
    const fs::path file = folder / "quad.gltf";
    std::ofstream(file) << json;
    return file;
}

// The imported quad alone, unlit (ambient 1, no lights: the texture as it is), seen from +Z with +Y up.
render::FrameInput importedQuadScene() {
    const fs::path file = writeTexturedQuadGltf(freshFolder());
    std::vector<std::string> warnings;
    auto model = scene::importModelFile(file.string(), warnings);
    EXPECT_TRUE(model.ok()) << (model.ok() ? "" : model.error());
    render::FrameInput input = orientationScene(View::BoxFromFront, render::Material{});
    if (!model.ok()) {
        return input;
    }
    EXPECT_EQ(model->parts.size(), 1u);
    EXPECT_GE(model->parts.front().material, 0);
    const scene::MaterialComponent& imported = model->materials.at(model->parts.front().material);
    EXPECT_EQ(fs::path(imported.texture.path).filename(), "quadrants.png");
    input.items.front().mesh = model->parts.front().mesh;
    input.items.front().material = showTexture(imported.texture.path);
    return input;
}

class ImportedOrientation : public GlTest {};

TEST_F(ImportedOrientation, GltfQuadShowsItsTextureUprightInTheRasterizer) {
    expectUprightQuadrants(renderImage(importedQuadScene(), 96, 96), "imported glTF quad, rasterizer");
}

TEST_F(ImportedOrientation, GltfQuadShowsItsTextureUprightInTheTracer) {
    auto tracer = render::reference::Tracer::create(importedQuadScene());
    ASSERT_TRUE(tracer.ok()) << tracer.error();
    render::reference::TraceSettings settings;
    settings.width = settings.height = 96;
    auto traced = tracer->render(settings);
    ASSERT_TRUE(traced.ok()) << traced.error();
    expectUprightQuadrants(traced->image, "imported glTF quad, tracer");
}

} // namespace
} // namespace speculum::test
