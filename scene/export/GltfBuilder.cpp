#include "scene/export/GltfBuilder.hpp"

#include "render/mesh/Primitives.hpp"
#include "scene/model/NodeMath.hpp"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QUrl>
#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <limits>
#include <map>
#include <optional>
#include <set>

namespace speculum::scene {

namespace {

// glTF's enumerations (glTF 2.0 specification, section 5).
constexpr int kFloat = 5126;
constexpr int kUnsignedShort = 5123;
constexpr int kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;
constexpr int kLinear = 9729;
constexpr int kLinearMipmapLinear = 9987;

constexpr const char* kLights = "KHR_lights_punctual";
constexpr const char* kEmissiveStrength = "KHR_materials_emissive_strength";

QJsonArray numbers(std::initializer_list<double> values) {
    QJsonArray out;
    for (double v : values) {
        out.append(v);
    }
    return out;
}

QJsonArray vec3(const glm::dvec3& v) {
    return numbers({v.x, v.y, v.z});
}

double unit(double v) {
    return std::isfinite(v) ? std::clamp(v, 0.0, 1.0) : 0.0;
}

int wrapCode(TextureWrap wrap) {
    switch (wrap) {
    case TextureWrap::Repeat:
        return 10497;
    case TextureWrap::ClampToEdge:
        return 33071;
    case TextureWrap::MirroredRepeat:
        return 33648;
    }
    return 10497;
}

// The rotation part of a view-to-world matrix as a glTF quaternion [x, y, z, w].
QJsonArray quaternion(const glm::dmat3& rotation) {
    const glm::dquat q = glm::normalize(glm::quat_cast(rotation));
    return numbers({q.x, q.y, q.z, q.w});
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

class Builder {
public:
    Builder(MeshLibrary& meshes, const GltfLayout& layout, std::vector<std::string>& warnings)
        : m_library(meshes)
        , m_layout(layout)
        , m_warnings(warnings)
        , m_imageSource(meshes) {}

    GltfAsset build(const Scene& scene) {
        QJsonArray roots;
        for (const auto& node : scene.topLevelNodes()) {
            roots.append(addNode(*node));
        }
        roots.append(addCamera(scene.camera()));

        QJsonObject root;
        root["asset"] = QJsonObject{{"version", "2.0"}, {"generator", "speculum " SPECULUM_VERSION}};
        root["scene"] = 0;
        root["scenes"] = QJsonArray{QJsonObject{{"name", "Scene"}, {"nodes", roots}}};
        root["nodes"] = m_nodes;
        root["cameras"] = m_cameras;
        auto put = [&](const char* key, const QJsonArray& array) {
            if (!array.isEmpty()) {
                root[key] = array;
            }
        };
        put("meshes", m_meshes);
        put("materials", m_materials);
        put("textures", m_textures);
        put("samplers", m_samplers);
        put("images", m_images);
        put("accessors", m_accessors);
        put("bufferViews", m_bufferViews);
        if (!m_lights.isEmpty()) {
            root["extensions"] = QJsonObject{{kLights, QJsonObject{{"lights", m_lights}}}};
            m_used.insert(kLights);
        }
        if (!m_used.empty()) {
            QJsonArray used;
            for (const std::string& name : m_used) {
                used.append(QString::fromStdString(name));
            }
            root["extensionsUsed"] = used;
        }
        if (!m_bin.empty()) {
            QJsonObject buffer{{"byteLength", static_cast<double>(m_bin.size())}};
            if (!m_layout.binary) {
                buffer["uri"] =
                    QString::fromLatin1(QUrl::toPercentEncoding(QString::fromStdString(m_layout.binUri)));
            }
            root["buffers"] = QJsonArray{buffer};
        }

        GltfAsset asset;
        asset.json = QJsonDocument(root).toJson(QJsonDocument::Compact);
        asset.bin = std::move(m_bin);
        asset.imageFiles = std::move(m_imageFiles);
        return asset;
    }

private:
    // ---- binary data ----

    int addBufferView(const void* data, std::size_t size, int target) {
        while (m_bin.size() % 4 != 0) { // every view starts 4-byte aligned
            m_bin.push_back(0);
        }
        QJsonObject view{{"buffer", 0},
                         {"byteOffset", static_cast<double>(m_bin.size())},
                         {"byteLength", static_cast<double>(size)}};
        if (target != 0) {
            view["target"] = target;
        }
        const auto* bytes = static_cast<const unsigned char*>(data);
        m_bin.insert(m_bin.end(), bytes, bytes + size);
        m_bufferViews.append(view);
        return static_cast<int>(m_bufferViews.size() - 1);
    }

    template <typename Vec>
    int addFloatAccessor(const std::vector<Vec>& values, const char* type, bool bounds) {
        constexpr int n = Vec::length();
        const int view = addBufferView(values.data(), values.size() * sizeof(Vec), kArrayBuffer);
        QJsonObject accessor{{"bufferView", view},
                             {"componentType", kFloat},
                             {"count", static_cast<double>(values.size())},
                             {"type", type}};
        if (bounds) { // required for POSITION
            Vec lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
            for (const Vec& v : values) {
                lo = glm::min(lo, v);
                hi = glm::max(hi, v);
            }
            QJsonArray min, max;
            for (int i = 0; i < n; ++i) {
                min.append(static_cast<double>(lo[i]));
                max.append(static_cast<double>(hi[i]));
            }
            accessor["min"] = min;
            accessor["max"] = max;
        }
        m_accessors.append(accessor);
        return static_cast<int>(m_accessors.size() - 1);
    }

    int addIndices(const std::vector<std::uint32_t>& indices, std::size_t vertexCount) {
        int view = 0;
        int type = kUnsignedInt;
        if (vertexCount <= 0xffff) { // 0xffff itself is the restart value, never a valid index
            std::vector<std::uint16_t> shorts(indices.begin(), indices.end());
            view = addBufferView(shorts.data(), shorts.size() * 2, kElementArrayBuffer);
            type = kUnsignedShort;
        } else {
            view = addBufferView(indices.data(), indices.size() * 4, kElementArrayBuffer);
        }
        m_accessors.append(QJsonObject{{"bufferView", view},
                                       {"componentType", type},
                                       {"count", static_cast<double>(indices.size())},
                                       {"type", "SCALAR"}});
        return static_cast<int>(m_accessors.size() - 1);
    }

    // A primitive's attributes and indices, shared by every node that draws the same mesh.
    std::optional<QJsonObject> geometry(const render::MeshData& mesh) {
        if (auto found = m_geometry.find(&mesh); found != m_geometry.end()) {
            return found->second;
        }
        const std::size_t n = mesh.positions.size();
        if (n == 0 || mesh.indices.empty()) {
            return std::nullopt;
        }
        QJsonObject attributes;
        attributes["POSITION"] = addFloatAccessor(mesh.positions, "VEC3", true);
        if (mesh.normals.size() == n) {
            attributes["NORMAL"] = addFloatAccessor(mesh.normals, "VEC3", false);
        }
        if (mesh.uvs.size() == n) {
            // speculum's v = 0 is the bottom row of the image; glTF's v = 0 is the top row.
            std::vector<glm::vec2> uvs(mesh.uvs);
            for (glm::vec2& uv : uvs) {
                uv.y = 1.0f - uv.y;
            }
            attributes["TEXCOORD_0"] = addFloatAccessor(uvs, "VEC2", false);
        }
        if (mesh.colors.size() == n) {
            attributes["COLOR_0"] = addFloatAccessor(mesh.colors, "VEC4", false);
        }
        if (mesh.tangents.size() == n && mesh.normals.size() == n) {
            // Unchanged: speculum's bitangent w·(normal × tangent) points up the image (increasing v),
            // and so does glTF's (normal maps are +Y up; the Khronos sample viewer builds the same basis).
            const std::vector<glm::vec4>& tangents = mesh.tangents;
            attributes["TANGENT"] = addFloatAccessor(tangents, "VEC4", false);
        }
        QJsonObject primitive{
            {"attributes", attributes}, {"indices", addIndices(mesh.indices, n)}, {"mode", 4}};
        m_geometry.emplace(&mesh, primitive);
        return primitive;
    }

    // ---- textures ----

    std::optional<int> addTexture(const std::string& name, const MaterialComponent& m,
                                  const std::string& owner) {
        auto image = m_imageIndex.find(name);
        if (image == m_imageIndex.end()) {
            auto loaded = m_imageSource.load(name);
            if (!loaded) {
                m_warnings.push_back("node \"" + owner + "\": texture not exported: " + loaded.error());
                m_imageIndex.emplace(name, -1);
                return std::nullopt;
            }
            QJsonObject json;
            if (m_layout.binary) {
                json["bufferView"] = addBufferView(loaded->bytes.data(), loaded->bytes.size(), 0);
                json["mimeType"] = QString::fromStdString(loaded->mimeType);
            } else {
                const std::string file =
                    m_layout.imageStem + "_" + std::to_string(m_imageFiles.size()) + loaded->extension();
                json["uri"] = QString::fromLatin1(QUrl::toPercentEncoding(QString::fromStdString(file)));
                m_imageFiles.push_back({file, std::move(*loaded)});
            }
            m_images.append(json);
            image = m_imageIndex.emplace(name, static_cast<int>(m_images.size() - 1)).first;
        }
        if (image->second < 0) {
            return std::nullopt;
        }
        const auto samplerKey = std::make_pair(wrapCode(m.wrap[0]), wrapCode(m.wrap[1]));
        auto sampler = m_samplerIndex.find(samplerKey);
        if (sampler == m_samplerIndex.end()) {
            m_samplers.append(QJsonObject{{"magFilter", kLinear},
                                          {"minFilter", kLinearMipmapLinear},
                                          {"wrapS", samplerKey.first},
                                          {"wrapT", samplerKey.second}});
            sampler = m_samplerIndex.emplace(samplerKey, static_cast<int>(m_samplers.size() - 1)).first;
        }
        const auto key = std::make_pair(image->second, sampler->second);
        auto texture = m_textureIndex.find(key);
        if (texture == m_textureIndex.end()) {
            m_textures.append(QJsonObject{{"source", key.first}, {"sampler", key.second}});
            texture = m_textureIndex.emplace(key, static_cast<int>(m_textures.size() - 1)).first;
        }
        return texture->second;
    }

    // ---- materials ----

    // `metallic`/`roughness` given: a mirror or the reflector (their reflectivity and roughness); otherwise
    // metallic comes from the specular colour and roughness from the shininess, both by inverting the
    // importer's conversion (ModelMaterials.cpp).
    int addMaterial(const std::string& owner, const MaterialComponent& m, std::optional<double> metallic,
                    std::optional<double> roughness) {
        QJsonObject pbr;
        pbr["baseColorFactor"] =
            numbers({unit(m.color.r), unit(m.color.g), unit(m.color.b), unit(m.opacity)});
        pbr["metallicFactor"] = unit(metallic.value_or(metallicFromSpecularColor(m)));
        pbr["roughnessFactor"] = unit(roughness.value_or(roughnessFromShininess(m.shininess)));
        if (!m.texture.empty()) {
            if (auto t = addTexture(m.texture.path, m, owner)) {
                pbr["baseColorTexture"] = QJsonObject{{"index", *t}};
            }
        }
        QJsonObject material{{"name", QString::fromStdString(owner + " material")},
                             {"pbrMetallicRoughness", pbr}};

        // glTF's emissiveFactor is 0..1; brighter emission keeps its colour there and its strength in
        // KHR_materials_emissive_strength.
        const glm::dvec3 emission = glm::max(m.emission, glm::dvec3(0.0));
        const double strength = std::max({emission.r, emission.g, emission.b});
        if (strength > 0.0 && std::isfinite(strength)) {
            const double scale = strength > 1.0 ? strength : 1.0;
            material["emissiveFactor"] = vec3(emission / scale);
            if (strength > 1.0) {
                material["extensions"] =
                    QJsonObject{{kEmissiveStrength, QJsonObject{{"emissiveStrength", strength}}}};
                m_used.insert(kEmissiveStrength);
            }
        }
        if (!m.emissionTexture.empty()) {
            if (auto t = addTexture(m.emissionTexture.path, m, owner)) {
                material["emissiveTexture"] = QJsonObject{{"index", *t}};
                if (!material.contains("emissiveFactor")) {
                    material["emissiveFactor"] = numbers({0.0, 0.0, 0.0}); // as in speculum: factor × texture
                }
            }
        }
        if (!m.normalTexture.empty()) {
            if (auto t = addTexture(m.normalTexture.path, m, owner)) {
                material["normalTexture"] = QJsonObject{{"index", *t}, {"scale", m.normalScale}};
            }
        }
        switch (m.alphaMode) {
        case AlphaMode::Opaque:
            break;
        case AlphaMode::Mask:
            material["alphaMode"] = "MASK";
            material["alphaCutoff"] = std::max(0.0, m.alphaCutoff);
            break;
        case AlphaMode::Blend:
            material["alphaMode"] = "BLEND";
            break;
        }
        m_materials.append(material);
        return static_cast<int>(m_materials.size() - 1);
    }

    // ---- nodes ----

    int addNode(const Node& node) {
        const NodeData& d = node.data();
        const std::string name = d.name.empty() ? std::string("node") : d.name;
        QJsonObject json{{"name", QString::fromStdString(name)}};
        // The pose at t = 0 (animations are not exported): T × R × S of the node's transform.
        const glm::dvec3 translate = animatedTranslate(d, 0.0);
        if (translate != glm::dvec3(0.0)) {
            json["translation"] = vec3(translate);
        }
        const glm::dquat rotation =
            glm::normalize(glm::quat_cast(glm::dmat3(rotationMatrix(d.transform.rotate))));
        if (!isIdentity(rotation)) {
            json["rotation"] = numbers({rotation.x, rotation.y, rotation.z, rotation.w});
        }
        if (d.transform.scale != glm::dvec3(1.0)) {
            json["scale"] = vec3(d.transform.scale);
        }

        QJsonArray primitives;
        if (d.mesh) {
            std::vector<std::string> importWarnings;
            auto mesh = m_library.get(*d.mesh, importWarnings);
            if (!mesh) {
                m_warnings.push_back("node \"" + d.name + "\": mesh not exported: " + mesh.error());
            } else if (auto primitive = geometry(**mesh)) {
                std::optional<double> metallic, roughness;
                if (d.reflector) {
                    metallic = d.reflector->reflectivity;
                    roughness = d.reflector->roughness;
                }
                primitive->insert("material", addMaterial(name, d.material.value_or(MaterialComponent{}),
                                                          metallic, roughness));
                primitives.append(*primitive);
            } else {
                m_warnings.push_back("node \"" + d.name + "\": mesh not exported: it has no triangles");
            }
        }
        if (d.mirror) {
            primitives.append(mirrorQuad(d, name));
        }
        if (!primitives.isEmpty()) {
            m_meshes.append(QJsonObject{{"name", QString::fromStdString(name)}, {"primitives", primitives}});
            json["mesh"] = static_cast<int>(m_meshes.size() - 1);
        }

        // Reserve this node's index before its children take theirs.
        const int index = static_cast<int>(m_nodes.size());
        m_nodes.append(QJsonObject{});
        QJsonArray children;
        if (d.light) {
            const int light = addLight(*d.light, name);
            const QJsonObject extension{{kLights, QJsonObject{{"light", light}}}};
            if (d.light->type == LightType::Point) {
                json["extensions"] = extension;
            } else {
                // speculum's lights shine along local −Y, glTF's along −Z: a child turned −90° about X.
                const double h = std::sqrt(0.5);
                m_nodes.append(QJsonObject{{"name", QString::fromStdString(name + " (light)")},
                                           {"rotation", numbers({-h, 0.0, 0.0, h})},
                                           {"extensions", extension}});
                children.append(static_cast<int>(m_nodes.size() - 1));
            }
        }
        for (const auto& child : node.children()) {
            children.append(addNode(*child));
        }
        if (!children.isEmpty()) {
            json["children"] = children;
        }
        m_nodes[index] = json;
        return index;
    }

    // The mirror's rectangle as the renderer draws it: the unit plane scaled to its size, same uvs.
    QJsonObject mirrorQuad(const NodeData& d, const std::string& name) {
        auto quad = std::make_shared<render::MeshData>(render::makePlane(1));
        const glm::vec3 half(float(d.mirror->size.x * 0.5), 1.0f, float(d.mirror->size.y * 0.5));
        for (glm::vec3& p : quad->positions) {
            p *= half;
        }
        m_keepAlive.push_back(quad);
        QJsonObject primitive = *geometry(*quad);
        MaterialComponent look = d.material.value_or(MaterialComponent{});
        if (!d.material) {
            look.color = glm::dvec3(0.95);
        }
        primitive["material"] =
            addMaterial(name + " (mirror)", look, d.mirror->reflectivity, d.mirror->roughness);
        return primitive;
    }

    // KHR_lights_punctual: colour and intensity as speculum has them (its lights do not fall off with
    // distance; glTF's point and spot lights do, by the inverse square law, and are in candela).
    int addLight(const LightComponent& l, const std::string& name) {
        QJsonObject light{{"name", QString::fromStdString(name)},
                          {"color", numbers({unit(l.color.r), unit(l.color.g), unit(l.color.b)})},
                          {"intensity", std::max(0.0, l.intensity)}};
        switch (l.type) {
        case LightType::Point:
            light["type"] = "point";
            break;
        case LightType::Directional:
            light["type"] = "directional";
            break;
        case LightType::Spot: {
            light["type"] = "spot";
            const double outer = glm::radians(std::clamp(l.spotAngle, 1e-3, 90.0));
            // The edge fades over the outer `spotBlend` of the cone; glTF wants inner < outer.
            const double inner = std::min(outer * (1.0 - std::clamp(l.spotBlend, 0.0, 1.0)), outer * 0.9999);
            light["spot"] = QJsonObject{{"innerConeAngle", inner}, {"outerConeAngle", outer}};
            break;
        }
        }
        m_lights.append(light);
        return static_cast<int>(m_lights.size() - 1);
    }

    // The scene camera as a perspective camera on a top-level node "Camera", which glTF points along its
    // local −Z with +Y up: the node's matrix is the inverse of the view matrix.
    int addCamera(const CameraData& c) {
        QJsonObject perspective{{"yfov", glm::radians(std::clamp(c.fovY, 1e-3, 179.0))},
                                {"znear", std::max(c.near, 1e-6)}};
        if (c.far > c.near) {
            perspective["zfar"] = c.far;
        }
        m_cameras.append(
            QJsonObject{{"name", "Camera"}, {"type", "perspective"}, {"perspective", perspective}});

        QJsonObject node{{"name", "Camera"}, {"camera", static_cast<int>(m_cameras.size() - 1)}};
        node["translation"] = vec3(c.position);
        const glm::dvec3 forward = c.target - c.position;
        const glm::dvec3 side = glm::cross(forward, c.up);
        if (glm::length(forward) > 0.0 && glm::length(side) > 1e-12 * glm::length(forward)) {
            const glm::dmat4 view = glm::lookAt(c.position, c.target, c.up);
            node["rotation"] = quaternion(glm::dmat3(glm::inverse(view)));
        } else {
            m_warnings.push_back(
                "camera: its target or up direction is degenerate; exported looking along -Z");
        }
        m_nodes.append(node);
        return static_cast<int>(m_nodes.size() - 1);
    }

    MeshLibrary& m_library;
    GltfLayout m_layout;
    std::vector<std::string>& m_warnings;
    GltfImageSource m_imageSource;

    QJsonArray m_nodes, m_meshes, m_materials, m_textures, m_samplers, m_images, m_accessors, m_bufferViews,
        m_cameras, m_lights;
    std::set<std::string> m_used; // extensions actually written
    std::vector<unsigned char> m_bin;
    std::vector<GltfAsset::ImageFile> m_imageFiles;
    std::map<const render::MeshData*, QJsonObject> m_geometry;
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
