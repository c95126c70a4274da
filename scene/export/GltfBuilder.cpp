#include "scene/export/GltfBuilder.hpp"

#include "render/frame/SceneLimits.hpp"
#include "render/mesh/Primitives.hpp"
#include "scene/import/ModelNodes.hpp"
#include "scene/model/NodeMath.hpp"

#include <QString>
#include <QUrl>
#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <limits>
#include <map>
#include <optional>
#include <set>

namespace speculum::scene {

namespace {

constexpr const char* kLights = "KHR_lights_punctual";
constexpr const char* kEmissiveStrength = "KHR_materials_emissive_strength";

std::vector<double> vec3(const glm::dvec3& v) {
    return {v.x, v.y, v.z};
}

double unit(double v) {
    return std::isfinite(v) ? std::clamp(v, 0.0, 1.0) : 0.0;
}

// tinygltf's JSON library throws on text that is not UTF-8, and names from model files need not be:
// invalid sequences become U+FFFD, as Qt reads them.
std::string utf8(const std::string& text) {
    return QString::fromStdString(text).toStdString();
}

std::string uri(const std::string& fileName) {
    return QUrl::toPercentEncoding(QString::fromStdString(fileName)).toStdString();
}

// Appends `item` and returns its index, the way every glTF object is referred to.
template <typename T>
int push(std::vector<T>& list, T item) {
    list.push_back(std::move(item));
    return static_cast<int>(list.size() - 1);
}

tinygltf::Value object(const char* key, tinygltf::Value value) {
    return tinygltf::Value(tinygltf::Value::Object{{key, std::move(value)}});
}

int wrapCode(TextureWrap wrap) {
    switch (wrap) {
    case TextureWrap::Repeat:
        return TINYGLTF_TEXTURE_WRAP_REPEAT;
    case TextureWrap::ClampToEdge:
        return TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
    case TextureWrap::MirroredRepeat:
        return TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT;
    }
    return TINYGLTF_TEXTURE_WRAP_REPEAT;
}

// The rotation part of a view-to-world matrix as a glTF quaternion [x, y, z, w].
std::vector<double> quaternion(const glm::dmat3& rotation) {
    const glm::dquat q = glm::normalize(glm::quat_cast(rotation));
    return {q.x, q.y, q.z, q.w};
}

bool isIdentity(const glm::dquat& q) {
    return std::abs(q.x) < 1e-12 && std::abs(q.y) < 1e-12 && std::abs(q.z) < 1e-12;
}

// Inverts the importer's conversion (shininess = 2 / alpha² − 2 with alpha = roughness², the usual
// Blinn-Phong ↔ GGX correspondence): roughness = (2 / (shininess + 2))^(1/4).
double roughnessFromShininess(double shininess) {
    return std::pow(2.0 / (std::max(shininess, 0.0) + 2.0), 0.25);
}

// Inverts the importer's specularColor = mix(white, baseColor, metallic) by least squares over the colour
// channels (those where the base colour is not white say something). A white specular colour, the default
// of every hand-made material, gives 0: a dielectric.
double metallicFromSpecularColor(const MaterialComponent& m) {
    double num = 0.0, den = 0.0;
    for (int c = 0; c < 3; ++c) {
        const double base = 1.0 - unit(m.color[c]);
        num += (1.0 - unit(m.specularColor[c])) * base;
        den += base * base;
    }
    return den > 1e-4 ? unit(num / den) : 0.0;
}

// The pose at t = 0 (animations are not exported): T × R × S of the node's transform, each part left out
// when it does nothing.
void setPose(tinygltf::Node& out, const NodeData& d) {
    const glm::dvec3 translate = animatedTranslate(d, 0.0);
    if (translate != glm::dvec3(0.0)) {
        out.translation = vec3(translate);
    }
    const glm::dquat rotation =
        glm::normalize(glm::quat_cast(glm::dmat3(rotationMatrix(d.transform.rotate))));
    if (!isIdentity(rotation)) {
        out.rotation = {rotation.x, rotation.y, rotation.z, rotation.w};
    }
    if (d.transform.scale != glm::dvec3(1.0)) {
        out.scale = vec3(d.transform.scale);
    }
}

// KHR_lights_punctual: colour and intensity as speculum has them (its lights do not fall off with
// distance; glTF's point and spot lights do, by the inverse square law, and are in candela).
tinygltf::Light gltfLight(const LightComponent& l, const std::string& name) {
    tinygltf::Light light;
    light.name = utf8(name);
    light.color = {unit(l.color.r), unit(l.color.g), unit(l.color.b)};
    light.intensity = std::max(0.0, l.intensity);
    switch (l.type) {
    case LightType::Point:
        light.type = "point";
        break;
    case LightType::Directional:
        light.type = "directional";
        break;
    case LightType::Spot: {
        light.type = "spot";
        const double outer = glm::radians(std::clamp(l.spotAngle, 1e-3, 90.0));
        // The edge fades over the outer `spotBlend` of the cone; glTF wants inner < outer.
        light.spot.outerConeAngle = outer;
        light.spot.innerConeAngle =
            std::min(outer * (1.0 - std::clamp(l.spotBlend, 0.0, 1.0)), outer * 0.9999);
        break;
    }
    }
    return light;
}

// The scene camera's lens. tinygltf writes zfar whatever it is, and glTF wants it beyond znear: a far
// plane that is not (which project files and the editor refuse) becomes the farthest a scene may have.
tinygltf::Camera gltfCamera(const CameraData& c) {
    tinygltf::Camera camera;
    camera.name = "Camera";
    camera.type = "perspective";
    camera.perspective.yfov = glm::radians(std::clamp(c.fovY, 1e-3, 179.0));
    camera.perspective.znear = std::max(c.near, 1e-6);
    const bool farOk = std::isfinite(c.far) && c.far > camera.perspective.znear;
    camera.perspective.zfar = farOk ? c.far : camera.perspective.znear * render::kMaxFarNearRatio;
    return camera;
}

class Builder {
public:
    Builder(MeshLibrary& meshes, const GltfLayout& layout, std::vector<std::string>& warnings)
        : m_library(meshes)
        , m_layout(layout)
        , m_warnings(warnings)
        , m_imageSource(meshes) {}

    GltfAsset build(const Scene& scene) {
        tinygltf::Scene root;
        root.name = "Scene";
        for (const auto& node : scene.topLevelNodes()) {
            root.nodes.push_back(addNode(*node));
        }
        root.nodes.push_back(addCamera(scene.camera()));
        m_model.defaultScene = push(m_model.scenes, std::move(root));
        m_model.asset.version = "2.0";
        m_model.asset.generator = "speculum " SPECULUM_VERSION;
        if (!m_model.lights.empty()) {
            m_used.insert(kLights);
        }
        m_model.extensionsUsed.assign(m_used.begin(), m_used.end());
        if (!m_bin.empty()) {
            tinygltf::Buffer buffer;
            buffer.data = std::move(m_bin);
            if (!m_layout.binary) {
                buffer.uri = uri(m_layout.binUri);
            }
            m_model.buffers.push_back(std::move(buffer));
        }
        return GltfAsset{std::move(m_model), std::move(m_imageFiles)};
    }

private:
    // ---- binary data ----

    int addBufferView(const void* data, std::size_t size, int target) {
        m_bin.resize((m_bin.size() + 3) & ~std::size_t(3), 0); // every view starts 4-byte aligned
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = m_bin.size();
        view.byteLength = size;
        view.target = target;
        const auto* bytes = static_cast<const unsigned char*>(data);
        m_bin.insert(m_bin.end(), bytes, bytes + size);
        return push(m_model.bufferViews, std::move(view));
    }

    template <typename Vec>
    int addFloatAccessor(const std::vector<Vec>& values, int type, bool bounds) {
        tinygltf::Accessor accessor;
        accessor.bufferView =
            addBufferView(values.data(), values.size() * sizeof(Vec), TINYGLTF_TARGET_ARRAY_BUFFER);
        accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        accessor.count = values.size();
        accessor.type = type;
        if (bounds) { // required for POSITION
            Vec lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
            for (const Vec& v : values) {
                lo = glm::min(lo, v);
                hi = glm::max(hi, v);
            }
            for (int i = 0; i < Vec::length(); ++i) {
                accessor.minValues.push_back(static_cast<double>(lo[i]));
                accessor.maxValues.push_back(static_cast<double>(hi[i]));
            }
        }
        return push(m_model.accessors, std::move(accessor));
    }

    int addIndices(const std::vector<std::uint32_t>& indices, std::size_t vertexCount) {
        tinygltf::Accessor accessor;
        if (vertexCount <= 0xffff) { // 0xffff itself is the restart value, never a valid index
            const std::vector<std::uint16_t> shorts(indices.begin(), indices.end());
            accessor.bufferView =
                addBufferView(shorts.data(), shorts.size() * 2, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
            accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
        } else {
            accessor.bufferView =
                addBufferView(indices.data(), indices.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
            accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        }
        accessor.count = indices.size();
        accessor.type = TINYGLTF_TYPE_SCALAR;
        return push(m_model.accessors, std::move(accessor));
    }

    // A primitive's attributes and indices, shared by every node that draws the same mesh.
    std::optional<tinygltf::Primitive> geometry(const render::MeshData& mesh) {
        if (auto found = m_geometry.find(&mesh); found != m_geometry.end()) {
            return found->second;
        }
        const std::size_t n = mesh.positions.size();
        if (n == 0 || mesh.indices.empty()) {
            return std::nullopt;
        }
        tinygltf::Primitive primitive;
        primitive.mode = TINYGLTF_MODE_TRIANGLES;
        auto& attributes = primitive.attributes;
        attributes["POSITION"] = addFloatAccessor(mesh.positions, TINYGLTF_TYPE_VEC3, true);
        if (mesh.normals.size() == n) {
            attributes["NORMAL"] = addFloatAccessor(mesh.normals, TINYGLTF_TYPE_VEC3, false);
        }
        if (mesh.uvs.size() == n) {
            // speculum's v = 0 is the bottom row of the image; glTF's v = 0 is the top row.
            std::vector<glm::vec2> uvs(mesh.uvs);
            for (glm::vec2& uv : uvs) {
                uv.y = 1.0f - uv.y;
            }
            attributes["TEXCOORD_0"] = addFloatAccessor(uvs, TINYGLTF_TYPE_VEC2, false);
        }
        if (mesh.colors.size() == n) {
            attributes["COLOR_0"] = addFloatAccessor(mesh.colors, TINYGLTF_TYPE_VEC4, false);
        }
        if (mesh.tangents.size() == n && mesh.normals.size() == n) {
            // Unchanged: speculum's bitangent w·(normal × tangent) points up the image (increasing v),
            // and so does glTF's (normal maps are +Y up; the Khronos sample viewer builds the same basis).
            attributes["TANGENT"] = addFloatAccessor(mesh.tangents, TINYGLTF_TYPE_VEC4, false);
        }
        primitive.indices = addIndices(mesh.indices, n);
        m_geometry.emplace(&mesh, primitive);
        return primitive;
    }

    // ---- textures ----

    // The image of texture `name`, or -1 when it does not load (warned once).
    int addImage(const std::string& name, const std::string& owner) {
        if (auto found = m_imageIndex.find(name); found != m_imageIndex.end()) {
            return found->second;
        }
        auto loaded = m_imageSource.load(name);
        if (!loaded) {
            m_warnings.push_back("node \"" + owner + "\": texture not exported: " + loaded.error());
            m_imageIndex.emplace(name, -1);
            return -1;
        }
        tinygltf::Image image;
        if (m_layout.binary) {
            image.bufferView = addBufferView(loaded->bytes.data(), loaded->bytes.size(), 0);
            image.mimeType = loaded->mimeType;
        } else {
            const std::string file =
                m_layout.imageStem + "_" + std::to_string(m_imageFiles.size()) + loaded->extension();
            image.uri = uri(file);
            m_imageFiles.push_back({file, std::move(*loaded)});
        }
        const int index = push(m_model.images, std::move(image));
        m_imageIndex.emplace(name, index);
        return index;
    }

    std::optional<int> addTexture(const std::string& name, const MaterialComponent& m,
                                  const std::string& owner) {
        const int image = addImage(name, owner);
        if (image < 0) {
            return std::nullopt;
        }
        const auto samplerKey = std::make_pair(wrapCode(m.wrap[0]), wrapCode(m.wrap[1]));
        auto sampler = m_samplerIndex.find(samplerKey);
        if (sampler == m_samplerIndex.end()) {
            tinygltf::Sampler s;
            s.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
            s.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
            s.wrapS = samplerKey.first;
            s.wrapT = samplerKey.second;
            sampler = m_samplerIndex.emplace(samplerKey, push(m_model.samplers, std::move(s))).first;
        }
        const auto key = std::make_pair(image, sampler->second);
        auto texture = m_textureIndex.find(key);
        if (texture == m_textureIndex.end()) {
            tinygltf::Texture t;
            t.source = key.first;
            t.sampler = key.second;
            texture = m_textureIndex.emplace(key, push(m_model.textures, std::move(t))).first;
        }
        return texture->second;
    }

    // ---- materials ----

    // `metallic`/`roughness` given: a mirror or the reflector (their reflectivity and roughness); otherwise
    // metallic comes from the specular colour and roughness from the shininess, both by inverting the
    // importer's conversion (ModelMaterials.cpp). tinygltf leaves out the values that are glTF's defaults.
    int addMaterial(const std::string& owner, const MaterialComponent& m, std::optional<double> metallic,
                    std::optional<double> roughness) {
        tinygltf::Material material;
        material.name = utf8(owner + " material");
        tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;
        pbr.baseColorFactor = {unit(m.color.r), unit(m.color.g), unit(m.color.b), unit(m.opacity)};
        pbr.metallicFactor = unit(metallic.value_or(metallicFromSpecularColor(m)));
        pbr.roughnessFactor = unit(roughness.value_or(roughnessFromShininess(m.shininess)));
        if (!m.texture.empty()) {
            if (auto t = addTexture(m.texture.path, m, owner)) {
                pbr.baseColorTexture.index = *t;
            }
        }
        addEmission(material, m, owner);
        if (!m.normalTexture.empty()) {
            if (auto t = addTexture(m.normalTexture.path, m, owner)) {
                material.normalTexture.index = *t;
                material.normalTexture.scale = m.normalScale;
            }
        }
        switch (m.alphaMode) {
        case AlphaMode::Opaque:
            break;
        case AlphaMode::Mask:
            material.alphaMode = "MASK";
            material.alphaCutoff = std::max(0.0, m.alphaCutoff);
            break;
        case AlphaMode::Blend:
            material.alphaMode = "BLEND";
            break;
        }
        return push(m_model.materials, std::move(material));
    }

    // glTF's emissiveFactor is 0..1; brighter emission keeps its colour there and its strength in
    // KHR_materials_emissive_strength. An emission texture without emission stays dark, as in speculum
    // (factor × texture): glTF's default factor is 0.
    void addEmission(tinygltf::Material& material, const MaterialComponent& m, const std::string& owner) {
        const glm::dvec3 emission = glm::max(m.emission, glm::dvec3(0.0));
        const double strength = std::max({emission.r, emission.g, emission.b});
        if (strength > 0.0 && std::isfinite(strength)) {
            const double scale = strength > 1.0 ? strength : 1.0;
            material.emissiveFactor = vec3(emission / scale);
            if (strength > 1.0) {
                material.extensions[kEmissiveStrength] =
                    object("emissiveStrength", tinygltf::Value(strength));
                m_used.insert(kEmissiveStrength);
            }
        }
        if (!m.emissionTexture.empty()) {
            if (auto t = addTexture(m.emissionTexture.path, m, owner)) {
                material.emissiveTexture.index = *t;
            }
        }
    }

    // ---- nodes ----

    int addNode(const Node& node) {
        const NodeData& d = node.data();
        const std::string name = d.name.empty() ? std::string("node") : d.name;
        tinygltf::Node out;
        out.name = utf8(name);
        setPose(out, d);
        const bool parts = drawsModelParts(d);
        if (!parts) {
            out.mesh = addMesh(d, name);
        }

        // Reserve this node's index before its children take theirs.
        const int index = push(m_model.nodes, tinygltf::Node{});
        if (parts) {
            addModelParts(d, name, out);
        }
        if (d.light) {
            tinygltf::ExtensionMap extension{
                {kLights, object("light", tinygltf::Value(push(m_model.lights, gltfLight(*d.light, name))))}};
            if (d.light->type == LightType::Point) {
                out.extensions = std::move(extension);
            } else {
                // speculum's lights shine along local −Y, glTF's along −Z: a child turned −90° about X.
                const double h = std::sqrt(0.5);
                tinygltf::Node turned;
                turned.name = utf8(name + " (light)");
                turned.rotation = {-h, 0.0, 0.0, h};
                turned.extensions = std::move(extension);
                out.children.push_back(push(m_model.nodes, std::move(turned)));
            }
        }
        for (const auto& child : node.children()) {
            out.children.push_back(addNode(*child));
        }
        m_model.nodes[static_cast<std::size_t>(index)] = std::move(out);
        return index;
    }

    // As the renderer draws it: a whole model file on a plain node without a material of its own is every
    // part of the file with the file's own material, where the file's node tree places it.
    static bool drawsModelParts(const NodeData& d) {
        return d.mesh && !d.mesh->builtin && !d.mesh->part && !d.material && !d.reflector && !d.mirror;
    }

    // A child node per placed part, its matrix the file's placement of the part; a file of one part that
    // the file does not move has it on the node itself.
    void addModelParts(const NodeData& d, const std::string& name, tinygltf::Node& out) {
        std::vector<Warning> importWarnings;
        const auto model = m_library.model(d.mesh->file, importWarnings);
        if (!model) {
            m_warnings.push_back("node \"" + d.name + "\": mesh not exported: " + model.error());
            return;
        }
        const ImportedModel& m = **model;
        std::vector<std::pair<int, glm::dmat4>> placed;
        detail::forEachPlacedPart(m, [&](int index, const glm::dmat4& placement) {
            if (m.parts[static_cast<std::size_t>(index)].mesh) {
                placed.emplace_back(index, placement);
            }
        });
        if (placed.size() == 1 && placed.front().second == glm::dmat4(1.0)) {
            out.mesh = partMesh(d.mesh->file, m, placed.front().first, name);
            return;
        }
        for (const auto& [index, placement] : placed) {
            const int mesh = partMesh(d.mesh->file, m, index, name);
            if (mesh < 0) {
                continue;
            }
            const ImportedPart& part = m.parts[static_cast<std::size_t>(index)];
            tinygltf::Node child;
            child.name = utf8(name + "/" + (part.name.empty() ? "part " + std::to_string(index) : part.name));
            child.matrix.assign(glm::value_ptr(placement), glm::value_ptr(placement) + 16);
            child.mesh = mesh;
            out.children.push_back(push(m_model.nodes, std::move(child)));
        }
    }

    // The glTF mesh of a model file's part with the file's material for it: made once per part, however
    // often the file's node tree (or the scene) places it; -1 when it has no triangles.
    int partMesh(const std::string& file, const ImportedModel& m, int index, const std::string& owner) {
        const auto key = std::make_pair(file, index);
        if (const auto found = m_partMeshes.find(key); found != m_partMeshes.end()) {
            return found->second;
        }
        const ImportedPart& part = m.parts[static_cast<std::size_t>(index)];
        const std::string name =
            owner + "/" + (part.name.empty() ? "part " + std::to_string(index) : part.name);
        std::optional<tinygltf::Primitive> primitive = geometry(*part.mesh);
        int mesh = -1;
        if (primitive) {
            const bool hasMaterial =
                part.material >= 0 && part.material < static_cast<int>(m.materials.size());
            primitive->material = addMaterial(
                name,
                hasMaterial ? m.materials[static_cast<std::size_t>(part.material)] : MaterialComponent{},
                std::nullopt, std::nullopt);
            tinygltf::Mesh out;
            out.name = utf8(name);
            out.primitives.push_back(std::move(*primitive));
            mesh = push(m_model.meshes, std::move(out));
        }
        m_partMeshes.emplace(key, mesh);
        return mesh;
    }

    // The node's mesh (its shape or model, and a mirror's quad), or -1 when it has none.
    int addMesh(const NodeData& d, const std::string& name) {
        tinygltf::Mesh mesh;
        if (d.mesh) {
            std::vector<Warning> importWarnings;
            auto loaded = m_library.get(*d.mesh, importWarnings);
            if (!loaded) {
                m_warnings.push_back("node \"" + d.name + "\": mesh not exported: " + loaded.error());
            } else if (auto primitive = geometry(**loaded)) {
                std::optional<double> metallic, roughness;
                if (d.reflector) {
                    metallic = d.reflector->reflectivity;
                    roughness = d.reflector->roughness;
                }
                primitive->material =
                    addMaterial(name, d.material.value_or(MaterialComponent{}), metallic, roughness);
                mesh.primitives.push_back(std::move(*primitive));
            } else {
                m_warnings.push_back("node \"" + d.name + "\": mesh not exported: it has no triangles");
            }
        }
        if (d.mirror) {
            mesh.primitives.push_back(mirrorQuad(d, name));
        }
        if (mesh.primitives.empty()) {
            return -1;
        }
        mesh.name = utf8(name);
        return push(m_model.meshes, std::move(mesh));
    }

    // The mirror's rectangle as the renderer draws it: the unit plane scaled to its size, same uvs.
    tinygltf::Primitive mirrorQuad(const NodeData& d, const std::string& name) {
        auto quad = std::make_shared<render::MeshData>(render::makePlane(1));
        const glm::vec3 half(float(d.mirror->size.x * 0.5), 1.0f, float(d.mirror->size.y * 0.5));
        for (glm::vec3& p : quad->positions) {
            p *= half;
        }
        m_keepAlive.push_back(quad);
        tinygltf::Primitive primitive = *geometry(*quad);
        MaterialComponent look = d.material.value_or(MaterialComponent{});
        if (!d.material) {
            look.color = glm::dvec3(0.95);
        }
        primitive.material =
            addMaterial(name + " (mirror)", look, d.mirror->reflectivity, d.mirror->roughness);
        return primitive;
    }

    // The scene camera as a perspective camera on a top-level node "Camera", which glTF points along its
    // local −Z with +Y up: the node's matrix is the inverse of the view matrix.
    int addCamera(const CameraData& c) {
        tinygltf::Node node;
        node.name = "Camera";
        node.camera = push(m_model.cameras, gltfCamera(c));
        node.translation = vec3(c.position);
        const glm::dvec3 forward = c.target - c.position;
        const glm::dvec3 side = glm::cross(forward, c.up);
        if (glm::length(forward) > 0.0 && glm::length(side) > 1e-12 * glm::length(forward)) {
            const glm::dmat4 view = glm::lookAt(c.position, c.target, c.up);
            node.rotation = quaternion(glm::dmat3(glm::inverse(view)));
        } else {
            m_warnings.push_back(
                "camera: its target or up direction is degenerate; exported looking along -Z");
        }
        return push(m_model.nodes, std::move(node));
    }

    MeshLibrary& m_library;
    std::map<std::pair<std::string, int>, int> m_partMeshes; // (model file, part) → glTF mesh
    GltfLayout m_layout;
    std::vector<std::string>& m_warnings;
    GltfImageSource m_imageSource;

    tinygltf::Model m_model;
    std::set<std::string> m_used;     // extensions actually written
    std::vector<unsigned char> m_bin; // buffer 0, until build() hands it to the model
    std::vector<GltfAsset::ImageFile> m_imageFiles;
    std::map<const render::MeshData*, tinygltf::Primitive> m_geometry;
    std::vector<std::shared_ptr<render::MeshData>> m_keepAlive; // mirror quads keyed by address above
    std::map<std::string, int> m_imageIndex;                    // texture name → image, -1 when it failed
    std::map<std::pair<int, int>, int> m_samplerIndex;
    std::map<std::pair<int, int>, int> m_textureIndex;
};

} // namespace

GltfAsset buildGltf(const Scene& scene, MeshLibrary& meshes, const GltfLayout& layout,
                    std::vector<std::string>& warnings) {
    return Builder(meshes, layout, warnings).build(scene);
}

} // namespace speculum::scene
