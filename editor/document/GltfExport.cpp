#include "editor/document/GltfExport.hpp"

#include "editor/document/NodeMath.hpp"

#include <QDir>
#include <QFileInfo>
#include <algorithm>
#include <assimp/Exporter.hpp>
#include <assimp/material.h>
#include <assimp/scene.h>
#include <cmath>
#include <memory>

namespace speculum::document {

namespace {

aiMatrix4x4 toAssimp(const glm::dmat4& m) {
    // glm is column-major (m[column][row]); aiMatrix4x4 is row-major (a1..a4 = first row).
    aiMatrix4x4 out;
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) {
            out[static_cast<unsigned>(r)][static_cast<unsigned>(c)] = static_cast<ai_real>(m[c][r]);
        }
    }
    return out;
}

aiString text(const std::string& s) {
    return aiString(s);
}

// Collects meshes and materials while the node tree is built; hands them to the aiScene at the end.
class SceneBuilder {
public:
    SceneBuilder(MeshLibrary& meshes, std::vector<std::string>& warnings, const QDir& outDir)
        : m_library(meshes)
        , m_warnings(warnings)
        , m_outDir(outDir) {}

    aiNode* build(const Node& node) {
        const NodeData& d = node.data();
        auto* out = new aiNode(d.name.empty() ? std::string("node") : d.name);
        out->mTransformation = toAssimp(localMatrix(d.transform));

        std::vector<unsigned> meshIndices;
        if (d.mesh) {
            std::vector<std::string> importWarnings;
            auto mesh = m_library.get(*d.mesh, importWarnings);
            if (mesh) {
                const unsigned material = addMaterial(d, d.reflector.has_value());
                meshIndices.push_back(addMesh(**mesh, material, d.name));
            } else {
                m_warnings.push_back("node \"" + d.name + "\": mesh not exported: " + mesh.error());
            }
        }
        if (d.mirror) {
            meshIndices.push_back(addMirrorQuad(d));
        }
        if (!meshIndices.empty()) {
            out->mNumMeshes = static_cast<unsigned>(meshIndices.size());
            out->mMeshes = new unsigned[meshIndices.size()];
            std::copy(meshIndices.begin(), meshIndices.end(), out->mMeshes);
        }
        if (!node.children().empty()) {
            out->mNumChildren = static_cast<unsigned>(node.children().size());
            out->mChildren = new aiNode*[out->mNumChildren];
            for (unsigned i = 0; i < out->mNumChildren; ++i) {
                out->mChildren[i] = build(*node.children()[i]);
                out->mChildren[i]->mParent = out;
            }
        }
        return out;
    }

    void finish(aiScene& scene) {
        if (m_materials.empty()) {
            addMaterial(NodeData{}, false); // glTF/Assimp want at least one
        }
        scene.mNumMeshes = static_cast<unsigned>(m_meshes.size());
        scene.mMeshes = new aiMesh*[std::max<std::size_t>(m_meshes.size(), 1)];
        for (std::size_t i = 0; i < m_meshes.size(); ++i) {
            scene.mMeshes[i] = m_meshes[i].release();
        }
        scene.mNumMaterials = static_cast<unsigned>(m_materials.size());
        scene.mMaterials = new aiMaterial*[m_materials.size()];
        for (std::size_t i = 0; i < m_materials.size(); ++i) {
            scene.mMaterials[i] = m_materials[i].release();
        }
    }

private:
    unsigned addMaterial(const NodeData& d, bool mirrorLike) {
        auto material = std::make_unique<aiMaterial>();
        const MaterialComponent m = d.material.value_or(MaterialComponent{});
        const aiString name = text((d.name.empty() ? std::string("material") : d.name) + " material");
        material->AddProperty(&name, AI_MATKEY_NAME);
        const aiColor4D base(float(m.color.r), float(m.color.g), float(m.color.b), 1.0f);
        material->AddProperty(&base, 1, AI_MATKEY_BASE_COLOR);
        const aiColor3D diffuse(float(m.color.r), float(m.color.g), float(m.color.b));
        material->AddProperty(&diffuse, 1, AI_MATKEY_COLOR_DIFFUSE);
        const aiColor3D emissive(float(m.emission.r), float(m.emission.g), float(m.emission.b));
        material->AddProperty(&emissive, 1, AI_MATKEY_COLOR_EMISSIVE);
        // Blinn-Phong has no metalness; a shininess s maps roughly to roughness sqrt(2 / (s + 2)).
        const float metallic = mirrorLike ? 1.0f : 0.0f;
        const float roughness =
            mirrorLike ? 0.0f : static_cast<float>(std::sqrt(2.0 / (std::max(m.shininess, 0.0) + 2.0)));
        material->AddProperty(&metallic, 1, AI_MATKEY_METALLIC_FACTOR);
        material->AddProperty(&roughness, 1, AI_MATKEY_ROUGHNESS_FACTOR);
        if (!m.texture.empty()) {
            const aiString texture =
                text(m_outDir.relativeFilePath(QString::fromStdString(m.texture)).toStdString());
            material->AddProperty(&texture, AI_MATKEY_TEXTURE(aiTextureType_DIFFUSE, 0));
            material->AddProperty(&texture, AI_MATKEY_TEXTURE(aiTextureType_BASE_COLOR, 0));
        }
        m_materials.push_back(std::move(material));
        return static_cast<unsigned>(m_materials.size() - 1);
    }

    unsigned addMesh(const render::MeshData& data, unsigned material, const std::string& name) {
        auto mesh = std::make_unique<aiMesh>();
        mesh->mName = text(name);
        mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
        mesh->mMaterialIndex = material;
        mesh->mNumVertices = static_cast<unsigned>(data.positions.size());
        mesh->mVertices = new aiVector3D[mesh->mNumVertices];
        mesh->mNormals = new aiVector3D[mesh->mNumVertices];
        const bool hasUv = data.uvs.size() == data.positions.size();
        if (hasUv) {
            mesh->mTextureCoords[0] = new aiVector3D[mesh->mNumVertices];
            mesh->mNumUVComponents[0] = 2;
        }
        for (unsigned i = 0; i < mesh->mNumVertices; ++i) {
            const auto& p = data.positions[i];
            mesh->mVertices[i] = aiVector3D(p.x, p.y, p.z);
            const glm::vec3 n = i < data.normals.size() ? data.normals[i] : glm::vec3(0.0f, 1.0f, 0.0f);
            mesh->mNormals[i] = aiVector3D(n.x, n.y, n.z);
            if (hasUv) {
                mesh->mTextureCoords[0][i] = aiVector3D(data.uvs[i].x, data.uvs[i].y, 0.0f);
            }
        }
        mesh->mNumFaces = static_cast<unsigned>(data.indices.size() / 3);
        mesh->mFaces = new aiFace[mesh->mNumFaces];
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
            aiFace& face = mesh->mFaces[f];
            face.mNumIndices = 3;
            face.mIndices = new unsigned[3];
            for (unsigned k = 0; k < 3; ++k) {
                face.mIndices[k] = data.indices[f * 3 + k];
            }
        }
        m_meshes.push_back(std::move(mesh));
        return static_cast<unsigned>(m_meshes.size() - 1);
    }

    // The mirror rectangle in the local XZ plane, facing +Y, with uvs over its area.
    unsigned addMirrorQuad(const NodeData& d) {
        render::MeshData quad;
        const float hx = float(d.mirror->size.x * 0.5), hz = float(d.mirror->size.y * 0.5);
        quad.positions = {{-hx, 0, -hz}, {-hx, 0, hz}, {hx, 0, hz}, {hx, 0, -hz}};
        quad.normals.assign(4, glm::vec3(0.0f, 1.0f, 0.0f));
        quad.uvs = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
        quad.indices = {0, 1, 2, 0, 2, 3}; // counter-clockwise seen from +Y
        NodeData look = d;
        if (!look.material) {
            look.material = MaterialComponent{};
            look.material->color = glm::dvec3(0.95);
        }
        const unsigned material = addMaterial(look, true);
        return addMesh(quad, material, d.name + " (mirror)");
    }

    MeshLibrary& m_library;
    std::vector<std::string>& m_warnings;
    QDir m_outDir;
    std::vector<std::unique_ptr<aiMesh>> m_meshes;
    std::vector<std::unique_ptr<aiMaterial>> m_materials;
};

} // namespace

render::Status exportGltf(const Scene& scene, const QString& path, MeshLibrary& meshes,
                          std::vector<std::string>& warnings) {
    const QFileInfo info(path);
    const QString suffix = info.suffix().toLower();
    if (suffix != QStringLiteral("gltf") && suffix != QStringLiteral("glb")) {
        return render::Error{path.toStdString() + ": expected a .gltf or .glb file name"};
    }
    if (!info.absoluteDir().exists()) {
        return render::Error{path.toStdString() + ": folder " + info.absolutePath().toStdString() +
                             " does not exist"};
    }

    auto out = std::make_unique<aiScene>();
    SceneBuilder builder(meshes, warnings, info.absoluteDir());
    auto* root = new aiNode("Scene");
    const auto& nodes = scene.topLevelNodes();
    root->mNumChildren = static_cast<unsigned>(nodes.size());
    root->mChildren = root->mNumChildren ? new aiNode*[root->mNumChildren] : nullptr;
    for (unsigned i = 0; i < root->mNumChildren; ++i) {
        root->mChildren[i] = builder.build(*nodes[i]);
        root->mChildren[i]->mParent = root;
    }
    out->mRootNode = root;
    builder.finish(*out);

    Assimp::Exporter exporter;
    const char* format = suffix == QStringLiteral("glb") ? "glb2" : "gltf2";
    if (exporter.Export(out.get(), format, info.absoluteFilePath().toStdString()) != AI_SUCCESS) {
        return render::Error{path.toStdString() + ": glTF export failed: " + exporter.GetErrorString()};
    }
    return render::Done{};
}

} // namespace speculum::document
