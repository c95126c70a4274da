#include "scene/import/ModelSerialization.hpp"

#include "render/imageio/TextureLoader.hpp"
#include "scene/import/ModelPrecheck.hpp"

#include <QJsonDocument>
#include <cmath>
#include <glm/gtc/type_ptr.hpp>
#include <utility>

namespace speculum::scene::detail {
namespace {

using base::Error;

// A field added to one of these types must be written and read here too; the sizes (x86-64, libstdc++)
// make the build say so rather than the child silently dropping it. Materials need no such check: they
// travel field by field as their declaration lists them (render/frame/Material.hpp).
static_assert(sizeof(render::MeshData) == 256, "MeshData changed: update writeMesh/readMesh");
static_assert(sizeof(ImportedPart) == 56, "ImportedPart changed: update the part serialization");
static_assert(sizeof(ImportedNode) == 208, "ImportedNode changed: update writeNodes/readNodes");
static_assert(sizeof(ImportedModel) == 336, "ImportedModel changed: update serializeChildImport");
static_assert(sizeof(render::TextureImage) == 64, "TextureImage changed: update writeTexture/readTexture");

constexpr std::uint64_t kMagic = 0x31544d49'4c554353ull; // "SCULIMT1"

void writeVec3(ByteWriter& out, const glm::dvec3& v) {
    out.raw(glm::value_ptr(v), sizeof(double) * 3);
}
glm::dvec3 readVec3(ByteReader& in) {
    glm::dvec3 v;
    v.x = in.f64();
    v.y = in.f64();
    v.z = in.f64();
    return v;
}

template <typename Enum>
bool readEnum(ByteReader& in, Enum& out, Enum last) {
    const std::int64_t value = in.i64();
    if (value < 0 || value > static_cast<std::int64_t>(last)) {
        in.fail();
        return false;
    }
    out = static_cast<Enum>(value);
    return true;
}

// The simplified level (MeshData::coarse) does not travel: the parent builds it when a reflection first
// needs it, which most imports never do.
void writeMesh(ByteWriter& out, const render::MeshData& mesh) {
    out.array(mesh.positions);
    out.array(mesh.normals);
    out.array(mesh.uvs);
    out.array(mesh.colors);
    out.array(mesh.tangents);
    out.array(mesh.indices);
}

// A mesh whose attributes do not match its vertex count, or with an index out of range, is refused: the
// renderer and the tracer trust both.
bool readMesh(ByteReader& in, render::MeshData& mesh) {
    mesh.positions = in.array<glm::vec3>();
    mesh.normals = in.array<glm::vec3>();
    mesh.uvs = in.array<glm::vec2>();
    mesh.colors = in.array<glm::vec4>();
    mesh.tangents = in.array<glm::vec4>();
    mesh.indices = in.array<std::uint32_t>();
    const std::size_t n = mesh.positions.size();
    const auto matches = [n](std::size_t size) { return size == 0 || size == n; };
    if (in.failed() || !matches(mesh.normals.size()) || !matches(mesh.uvs.size()) ||
        !matches(mesh.colors.size()) || !matches(mesh.tangents.size()) || mesh.indices.size() % 3 != 0) {
        return false;
    }
    for (const std::uint32_t index : mesh.indices) {
        if (index >= n) {
            return false;
        }
    }
    return true;
}

void writeTexture(ByteWriter& out, const render::TextureImage& image) {
    out.i64(image.width);
    out.i64(image.height);
    out.array(image.rgba8);
    out.array(image.linear);
    out.u64(image.decodedFromSrgb ? 1 : 0);
}

bool readTexture(ByteReader& in, render::TextureImage& image) {
    const std::int64_t width = in.i64(), height = in.i64();
    image.rgba8 = in.array<std::uint8_t>();
    image.linear = in.array<float>();
    image.decodedFromSrgb = in.u64() != 0;
    if (in.failed() || width < 0 || height < 0 || width > render::kMaxTextureSide ||
        height > render::kMaxTextureSide) {
        return false;
    }
    image.width = static_cast<int>(width);
    image.height = static_cast<int>(height);
    const std::size_t texels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4;
    return (image.rgba8.empty() || image.rgba8.size() == texels) &&
           (image.linear.empty() || image.linear.size() == texels);
}

// Pre-order, each node followed by its child count; an explicit stack so that the depth costs no native
// stack on either side.
void writeNodes(ByteWriter& out, const ImportedNode& root) {
    std::vector<const ImportedNode*> stack{&root};
    while (!stack.empty()) {
        const ImportedNode& node = *stack.back();
        stack.pop_back();
        out.string(node.name);
        out.raw(glm::value_ptr(node.local), sizeof(double) * 16);
        out.array(node.parts);
        out.u64(node.children.size());
        for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) {
            stack.push_back(&*child);
        }
    }
}

bool readNodes(ByteReader& in, ImportedNode& root, std::size_t partCount) {
    constexpr std::size_t kMinNodeBytes = 8 + 16 * 8 + 8 + 8;
    struct Item {
        ImportedNode* node;
        int depth;
    };
    std::vector<Item> stack{{&root, 0}};
    while (!stack.empty()) {
        const Item item = stack.back();
        stack.pop_back();
        if (item.depth > kMaxNodeDepth + 1) {
            return false;
        }
        ImportedNode& node = *item.node;
        node.name = in.string();
        for (int column = 0; column < 4; ++column) {
            for (int row = 0; row < 4; ++row) {
                node.local[column][row] = in.f64();
            }
        }
        node.parts = in.array<int>();
        for (const int part : node.parts) {
            if (part < 0 || static_cast<std::size_t>(part) >= partCount) {
                return false;
            }
        }
        node.children.resize(in.count(kMinNodeBytes)); // sized once: the pointers below stay valid
        if (in.failed()) {
            return false;
        }
        for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) {
            stack.push_back({&*child, item.depth + 1});
        }
    }
    return true;
}

} // namespace

namespace {

// One declared field's value in the stream: numbers as they are, an enumeration as its index (checked
// against its names on the way back), a texture as its path.
template <typename M>
void writeValue(ByteWriter& out, const M& value) {
    if constexpr (std::is_enum_v<M> || std::is_same_v<M, int> || std::is_same_v<M, bool>) {
        out.i64(static_cast<std::int64_t>(value));
    } else if constexpr (std::is_same_v<M, double>) {
        out.f64(value);
    } else if constexpr (std::is_same_v<M, glm::dvec3>) {
        writeVec3(out, value);
    } else if constexpr (std::is_same_v<M, render::TextureSource>) {
        out.string(value.path);
    } else {
        static_assert(std::is_same_v<M, std::array<TextureWrap, 2>>,
                      "a material field the stream cannot hold");
        writeValue(out, value[0]);
        writeValue(out, value[1]);
    }
}

template <typename M>
bool readValue(ByteReader& in, M& value, const render::FieldSpec& spec) {
    if constexpr (std::is_enum_v<M>) {
        const std::int64_t index = in.i64();
        if (index < 0 || index >= static_cast<std::int64_t>(spec.choices.size()))
            return false;
        value = static_cast<M>(index);
    } else if constexpr (std::is_same_v<M, int> || std::is_same_v<M, bool>) {
        value = static_cast<M>(in.i64());
    } else if constexpr (std::is_same_v<M, double>) {
        value = in.f64();
    } else if constexpr (std::is_same_v<M, glm::dvec3>) {
        value = readVec3(in);
    } else if constexpr (std::is_same_v<M, render::TextureSource>) {
        value = render::TextureSource{in.string(), nullptr};
    } else {
        return readValue(in, value[0], spec) && readValue(in, value[1], spec);
    }
    return true;
}

} // namespace

void writeMaterial(ByteWriter& out, const MaterialComponent& material) {
    render::forEachField<MaterialComponent>([&](const auto& f) { writeValue(out, material.*f.member); });
}

bool readMaterial(ByteReader& in, MaterialComponent& material) {
    bool ok = true;
    render::forEachField<MaterialComponent>(
        [&](const auto& f) { ok = readValue(in, material.*f.member, f.spec) && ok; });
    return ok && !in.failed();
}

std::string serializeChildImport(const ChildImport& result) {
    ByteWriter out;
    out.u64(kMagic);
    out.u64(result.notes.size());
    for (const std::string& note : result.notes) {
        out.string(note);
    }
    out.u64(result.ok ? 1 : 0);
    if (!result.ok) {
        out.string(result.error);
        out.u64(kMagic);
        return std::move(out.out);
    }
    const ImportedModel& model = result.model;
    out.u64(model.materials.size());
    for (const MaterialComponent& material : model.materials) {
        writeMaterial(out, material);
    }
    out.u64(model.parts.size());
    for (const ImportedPart& part : model.parts) {
        out.string(part.name);
        out.i64(part.material);
        out.u64(part.mesh ? 1 : 0);
        if (part.mesh) {
            writeMesh(out, *part.mesh);
        }
    }
    out.u64(model.embeddedTextures.size());
    for (const auto& [key, image] : model.embeddedTextures) {
        out.string(key);
        writeTexture(out, image ? *image : render::TextureImage{});
    }
    out.u64(result.compressedTextures.size());
    for (const auto& [key, texture] : result.compressedTextures) {
        out.string(key);
        out.string(texture.reference);
        out.string(texture.bytes);
    }
    writeNodes(out, model.root);
    out.f64(model.unitScale);
    out.raw(&model.bounds.min, sizeof model.bounds.min);
    out.raw(&model.bounds.max, sizeof model.bounds.max);
    out.u64(kMagic); // the end: a stream cut short lacks it
    return std::move(out.out);
}

base::Result<ChildImport> deserializeChildImport(std::string_view bytes) {
    const Error broken{"the model reader's answer was cut short or damaged"};
    ByteReader in(bytes);
    if (in.u64() != kMagic) {
        return broken;
    }
    ChildImport result;
    result.notes.resize(in.count(8));
    for (std::string& note : result.notes) {
        note = in.string();
    }
    result.ok = in.u64() == 1;
    if (!result.ok) {
        result.error = in.string();
        if (in.u64() != kMagic || in.failed() || !in.atEnd()) {
            return broken;
        }
        return result;
    }
    ImportedModel& model = result.model;
    model.materials.resize(in.count(8));
    for (MaterialComponent& material : model.materials) {
        if (!readMaterial(in, material)) {
            return broken;
        }
    }
    model.parts.resize(in.count(24));
    for (ImportedPart& part : model.parts) {
        part.name = in.string();
        const std::int64_t material = in.i64();
        if (material < -1 || material >= static_cast<std::int64_t>(model.materials.size())) {
            return broken;
        }
        part.material = static_cast<int>(material);
        if (in.u64() == 1) {
            render::MeshData mesh;
            if (!readMesh(in, mesh)) {
                return broken;
            }
            part.mesh = render::freezeMesh(std::move(mesh));
        }
    }
    for (std::uint64_t i = 0, n = in.count(8); i < n; ++i) {
        const std::string key = in.string();
        auto image = std::make_shared<render::TextureImage>();
        if (!readTexture(in, *image)) {
            return broken;
        }
        model.embeddedTextures[key] = std::move(image);
    }
    for (std::uint64_t i = 0, n = in.count(24); i < n; ++i) {
        const std::string key = in.string();
        EmbeddedBytes& texture = result.compressedTextures[key];
        texture.reference = in.string();
        texture.bytes = in.string();
    }
    if (in.failed() || !readNodes(in, model.root, model.parts.size())) {
        return broken;
    }
    model.unitScale = in.f64();
    in.raw(&model.bounds.min, sizeof model.bounds.min);
    in.raw(&model.bounds.max, sizeof model.bounds.max);
    if (in.u64() != kMagic || in.failed() || !in.atEnd()) {
        return broken;
    }
    return result;
}

} // namespace speculum::scene::detail
