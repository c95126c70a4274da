// Material conversion from Assimp to speculum's Blinn-Phong (MaterialComponent).
//
// Every format:
//   base colour factor  AI_MATKEY_BASE_COLOR, else AI_MATKEY_COLOR_DIFFUSE (OBJ Kd, Collada/FBX diffuse;
//                       glTF factors are linear, and so are the others as speculum reads them) → color
//   base colour texture aiTextureType_BASE_COLOR, else DIFFUSE → texture
//   wrap modes          AI_MATKEY_MAPPINGMODE_U/V of the base colour texture → wrap (decal → clamp)
//   emissive            AI_MATKEY_COLOR_EMISSIVE (× glTF emissive_strength) → emission; EMISSIVE
//                       texture → emissionTexture (a textured emitter with a zero factor from a non-glTF
//                       file gets factor 1, glTF's zero default stays zero as the spec says)
//   normal map          aiTextureType_NORMALS (+ glTF normalTexture.scale) → normalTexture, normalScale
//   alpha               glTF: base colour alpha → opacity, alphaMode/alphaCutoff as given (BLEND is
//                       drawn as a cut-out and named); others: AI_MATKEY_OPACITY (OBJ d, FBX) → opacity,
//                       and opacity < 1 makes the material "blend" (drawn as a cut-out at the cutoff).
// glTF metallic/roughness (the material has AI_MATKEY_METALLIC_FACTOR), one conversion:
//   alpha = roughness², shininess = clamp(2/alpha² − 2, 1, 1024),
//   specular = clamp(mix(0.04, 1, metallic) · (shininess + 8)/8, 0, 1)   (energy-normalised Blinn-Phong),
//   specularColor = mix(white, baseColor, metallic), diffuse = 1 − metallic, ambient = 1.
// Phong files (OBJ, Collada, FBX): Ks → specular (its largest component) and specularColor (Ks divided by
//   it), Ns → shininess (clamped to 1..10000), Ke → emission, ambient = diffuse = 1.
// What is dropped is named once: metallic-roughness, occlusion, specular, opacity, height and other
// texture kinds, clearcoat / sheen / transmission / volume / specular-glossiness, texture transforms and
// textures on a second uv set.
#include "scene/import/ModelMaterials.hpp"

#include "render/imageio/TextureLoader.hpp"
#include "scene/import/ModelNodes.hpp"

#include <algorithm>
#include <assimp/GltfMaterial.h>
#include <assimp/material.h>
#include <assimp/scene.h>
#include <cmath>
#include <filesystem>
#include <glm/common.hpp>
#include <system_error>

namespace speculum::scene::detail {
namespace {

namespace fs = std::filesystem;

glm::dvec3 rgb(const aiColor4D& c) {
    return {c.r, c.g, c.b};
}

glm::dvec3 clamp01(const glm::dvec3& c) {
    return glm::clamp(c, glm::dvec3(0.0), glm::dvec3(1.0));
}

bool finite(const glm::dvec3& c) {
    return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z);
}

double getFloat(const aiMaterial& material, const char* key, unsigned type, unsigned index, double fallback) {
    float value = 0.0f;
    if (material.Get(key, type, index, value) == AI_SUCCESS && std::isfinite(value)) {
        return value;
    }
    return fallback;
}

bool has(const aiMaterial& material, const char* key, unsigned type = 0, unsigned index = 0) {
    const aiMaterialProperty* property = nullptr;
    return aiGetMaterialProperty(&material, key, type, index, &property) == AI_SUCCESS;
}

TextureWrap wrapOf(const aiMaterial& material, int type, bool u) {
    int mode = aiTextureMapMode_Wrap;
    const aiReturn got = u ? material.Get(AI_MATKEY_MAPPINGMODE_U(type, 0), mode)
                           : material.Get(AI_MATKEY_MAPPINGMODE_V(type, 0), mode);
    if (got != AI_SUCCESS) {
        return TextureWrap::Repeat;
    }
    switch (mode) {
    case aiTextureMapMode_Clamp:
    case aiTextureMapMode_Decal:
        return TextureWrap::ClampToEdge;
    case aiTextureMapMode_Mirror:
        return TextureWrap::MirroredRepeat;
    default:
        return TextureWrap::Repeat;
    }
}

// Texture kinds speculum does not draw, with the name the user sees.
struct DroppedKind {
    aiTextureType type;
    const char* name;
};
constexpr DroppedKind kDroppedTextures[] = {
    {aiTextureType_UNKNOWN, "metallic-roughness texture"}, // glTF's metallicRoughnessTexture
    {aiTextureType_METALNESS, "metalness texture"},
    {aiTextureType_DIFFUSE_ROUGHNESS, "roughness texture"},
    {aiTextureType_LIGHTMAP, "occlusion texture"}, // glTF's occlusionTexture
    {aiTextureType_AMBIENT_OCCLUSION, "occlusion texture"},
    {aiTextureType_SPECULAR, "specular texture"},
    {aiTextureType_SHININESS, "shininess texture"},
    {aiTextureType_OPACITY, "opacity texture"},
    {aiTextureType_HEIGHT, "height (bump) texture"},
    {aiTextureType_DISPLACEMENT, "displacement texture"},
    {aiTextureType_REFLECTION, "reflection texture"},
    {aiTextureType_AMBIENT, "ambient texture"},
    {aiTextureType_SHEEN, "sheen texture"},
    {aiTextureType_CLEARCOAT, "clearcoat texture"},
    {aiTextureType_TRANSMISSION, "transmission texture"},
};

// glTF's alphaMode ("OPAQUE", "MASK", "BLEND"); empty for a material from any other format.
std::string gltfAlphaMode(const aiMaterial& material) {
    aiString mode;
    if (material.Get(AI_MATKEY_GLTF_ALPHAMODE, mode) == AI_SUCCESS) {
        return mode.C_Str();
    }
    return {};
}

void noteDroppedTextures(const aiMaterial& material, bool gltf, ImportNotes& notes) {
    for (const DroppedKind& kind : kDroppedTextures) {
        if (material.GetTextureCount(kind.type) > 0) {
            // Assimp reports glTF's one metallicRoughnessTexture under three types.
            const bool metallicRoughness = kind.type == aiTextureType_UNKNOWN ||
                                           kind.type == aiTextureType_METALNESS ||
                                           kind.type == aiTextureType_DIFFUSE_ROUGHNESS;
            notes.add(std::string(gltf && metallicRoughness ? "metallic-roughness texture" : kind.name) +
                      " ignored");
        }
    }
}

// The emission, clamped to 0..1 (with a note where it was brighter). A textured emitter with a zero
// factor from a non-glTF file gets factor 1; glTF's zero default stays zero, as the spec says.
glm::dvec3 emissionOf(const aiMaterial& material, bool textured, bool gltf, ImportNotes& notes) {
    aiColor4D emissive(0.0f, 0.0f, 0.0f, 1.0f);
    material.Get(AI_MATKEY_COLOR_EMISSIVE, emissive);
    glm::dvec3 emission = finite(rgb(emissive)) ? glm::max(rgb(emissive), glm::dvec3(0.0)) : glm::dvec3(0.0);
    emission *= std::max(0.0, getFloat(material, AI_MATKEY_EMISSIVE_INTENSITY, 1.0));
    if (textured && emission == glm::dvec3(0.0) && !gltf) {
        emission = glm::dvec3(1.0);
    }
    if (glm::any(glm::greaterThan(emission, glm::dvec3(1.0)))) {
        notes.add("emission brighter than 1 clamped");
    }
    return clamp01(emission);
}

// Specular, shininess (and for glTF metallic/roughness the diffuse weight): see the conversions at the
// top of the file. Needs m.color.
void convertSpecular(const aiMaterial& material, bool pbr, MaterialComponent& m, ImportNotes& notes) {
    if (pbr) {
        const double metallic = std::clamp(getFloat(material, AI_MATKEY_METALLIC_FACTOR, 1.0), 0.0, 1.0);
        const double roughness = std::clamp(getFloat(material, AI_MATKEY_ROUGHNESS_FACTOR, 1.0), 0.0, 1.0);
        const double alpha = std::max(roughness * roughness, 1e-4);
        m.shininess = std::clamp(2.0 / (alpha * alpha) - 2.0, 1.0, 1024.0);
        m.specular = std::clamp(glm::mix(0.04, 1.0, metallic) * (m.shininess + 8.0) / 8.0, 0.0, 1.0);
        m.specularColor = glm::mix(glm::dvec3(1.0), m.color, metallic);
        m.diffuse = 1.0 - metallic;
    } else {
        aiColor4D ks(0.0f, 0.0f, 0.0f, 1.0f);
        material.Get(AI_MATKEY_COLOR_SPECULAR, ks);
        const glm::dvec3 specular = finite(rgb(ks)) ? glm::max(rgb(ks), glm::dvec3(0.0)) : glm::dvec3(0.0);
        const double strongest = std::max({specular.x, specular.y, specular.z});
        m.specular = std::clamp(strongest, 0.0, 1.0);
        m.specularColor = strongest > 0.0 ? clamp01(specular / strongest) : glm::dvec3(1.0);
        m.shininess = std::clamp(getFloat(material, AI_MATKEY_SHININESS, 32.0), 1.0, 10000.0);
    }
    if (has(material, AI_MATKEY_GLOSSINESS_FACTOR)) {
        notes.add("KHR_materials_pbrSpecularGlossiness approximated by the base colour");
    }
}

// Opacity, alpha mode and cutoff: glTF's as given (BLEND drawn as a cut-out); other formats' opacity,
// below 1 making the material a cut-out at the cutoff.
void convertAlpha(const aiMaterial& material, const std::string& alphaMode, double baseAlpha,
                  MaterialComponent& m, ImportNotes& notes) {
    if (!alphaMode.empty()) {
        m.opacity = std::clamp(baseAlpha, 0.0, 1.0);
        if (alphaMode == "MASK") {
            m.alphaMode = AlphaMode::Mask;
        } else if (alphaMode == "BLEND") {
            m.alphaMode = AlphaMode::Blend;
            notes.add("alphaMode BLEND drawn as a cut-out");
        }
        m.alphaCutoff = std::clamp(getFloat(material, AI_MATKEY_GLTF_ALPHACUTOFF, 0.5), 0.0, 1.0);
    } else {
        m.opacity = std::clamp(getFloat(material, AI_MATKEY_OPACITY, 1.0), 0.0, 1.0);
        if (m.opacity < 1.0) {
            m.alphaMode = AlphaMode::Blend;
            notes.add("transparency drawn as a cut-out");
        }
    }
}

// glTF extensions Assimp reports that speculum cannot draw.
void noteUndrawnExtensions(const aiMaterial& material, ImportNotes& notes) {
    if (getFloat(material, AI_MATKEY_CLEARCOAT_FACTOR, 0.0) > 0.0) {
        notes.add("KHR_materials_clearcoat ignored");
    }
    if (has(material, AI_MATKEY_SHEEN_COLOR_FACTOR)) {
        notes.add("KHR_materials_sheen ignored");
    }
    if (getFloat(material, AI_MATKEY_TRANSMISSION_FACTOR, 0.0) > 0.0) {
        notes.add("KHR_materials_transmission ignored");
    }
    if (has(material, AI_MATKEY_VOLUME_THICKNESS_FACTOR)) {
        notes.add("KHR_materials_volume ignored");
    }
    int shading = 0;
    if (material.Get(AI_MATKEY_SHADING_MODEL, shading) == AI_SUCCESS && shading == aiShadingMode_Unlit) {
        notes.add("KHR_materials_unlit drawn lit");
    }
}

// Files hold floats: keep the project file's numbers as short as the file's own.
void shortenNumbers(MaterialComponent& m) {
    m.color = detail::shortestFloat(m.color);
    m.specularColor = detail::shortestFloat(m.specularColor);
    m.emission = detail::shortestFloat(m.emission);
    m.specular = detail::shortestFloat(m.specular);
    m.shininess = detail::shortestFloat(m.shininess);
    m.diffuse = detail::shortestFloat(m.diffuse);
    m.opacity = detail::shortestFloat(m.opacity);
    m.alphaCutoff = detail::shortestFloat(m.alphaCutoff);
    m.normalScale = detail::shortestFloat(m.normalScale);
}

} // namespace

void ImportNotes::add(const std::string& note) {
    if (m_seen.insert(note).second) {
        m_notes.push_back(note);
    }
}

MaterialConverter::MaterialConverter(const aiScene& scene, std::string absoluteModelPath,
                                     ImportedModel& model, ImportNotes& notes,
                                     std::map<std::string, EmbeddedBytes>* compressedOut)
    : m_scene(scene)
    , m_modelPath(std::move(absoluteModelPath))
    , m_modelDir(fs::path(m_modelPath).parent_path().string())
    , m_model(model)
    , m_notes(notes)
    , m_compressed(compressedOut) {}

bool MaterialConverter::isPlaceholder(const aiMaterial& material) const {
    aiString name;
    return material.Get(AI_MATKEY_NAME, name) == AI_SUCCESS &&
           std::string(name.C_Str()) == AI_DEFAULT_MATERIAL_NAME &&
           material.GetTextureCount(aiTextureType_DIFFUSE) == 0;
}

MaterialComponent MaterialConverter::convert(const aiMaterial& material) {
    MaterialComponent m;
    m.ambient = 1.0;
    m.diffuse = 1.0;

    aiColor4D base(0.8f, 0.8f, 0.8f, 1.0f);
    if (material.Get(AI_MATKEY_BASE_COLOR, base) != AI_SUCCESS) {
        material.Get(AI_MATKEY_COLOR_DIFFUSE, base);
    }
    m.color = finite(rgb(base)) ? clamp01(rgb(base)) : glm::dvec3(0.8);

    const bool pbr = has(material, AI_MATKEY_METALLIC_FACTOR);
    const std::string alphaMode = gltfAlphaMode(material);
    const bool gltf = !alphaMode.empty();

    // Textures: base colour first (glTF reports it as both BASE_COLOR and DIFFUSE).
    const int baseType = material.GetTextureCount(aiTextureType_BASE_COLOR) > 0 ? aiTextureType_BASE_COLOR
                                                                                : aiTextureType_DIFFUSE;
    m.texture.path = texture(material, baseType, "base colour texture");
    if (!m.texture.empty()) {
        m.wrap = {wrapOf(material, baseType, true), wrapOf(material, baseType, false)};
    }
    m.emissionTexture.path = texture(material, aiTextureType_EMISSIVE, "emissive texture");
    m.normalTexture.path = texture(material, aiTextureType_NORMALS, "normal map");
    if (m.normalTexture.empty()) {
        m.normalTexture.path = texture(material, aiTextureType_NORMAL_CAMERA, "normal map");
    }
    if (!m.normalTexture.empty()) {
        m.normalScale = std::clamp(
            getFloat(material, AI_MATKEY_GLTF_TEXTURE_SCALE(aiTextureType_NORMALS, 0), 1.0), -100.0, 100.0);
    }
    noteDroppedTextures(material, gltf, m_notes);

    m.emission = emissionOf(material, !m.emissionTexture.empty(), gltf, m_notes);
    convertSpecular(material, pbr, m, m_notes);
    convertAlpha(material, alphaMode, static_cast<double>(base.a), m, m_notes);
    noteUndrawnExtensions(material, m_notes);
    shortenNumbers(m);
    return m;
}

std::string MaterialConverter::texture(const aiMaterial& material, int type, const char* what) {
    const auto kind = static_cast<aiTextureType>(type);
    if (material.GetTextureCount(kind) == 0) {
        return {};
    }
    aiString reference;
    unsigned uvIndex = 0;
    if (material.GetTexture(kind, 0, &reference, nullptr, &uvIndex) != AI_SUCCESS) {
        return {};
    }
    if (uvIndex != 0) {
        m_notes.add(std::string(what) + " on the second uv set ignored");
        return {};
    }
    aiUVTransform transform;
    if (material.Get(AI_MATKEY_UVTRANSFORM(type, 0), transform) == AI_SUCCESS &&
        (transform.mTranslation != aiVector2D(0.0f, 0.0f) || transform.mScaling != aiVector2D(1.0f, 1.0f) ||
         transform.mRotation != 0.0f)) {
        m_notes.add("texture transform (KHR_texture_transform) ignored");
    }
    const std::string name = reference.C_Str();
    if (name.empty()) {
        return {};
    }
    if (name[0] == '*' || m_scene.GetEmbeddedTexture(name.c_str()) != nullptr) {
        return embedded(name);
    }
    return external(name);
}

std::string MaterialConverter::embedded(const std::string& reference) {
    const std::string key = m_modelPath + "#" + reference;
    if (m_model.embeddedTextures.count(key) != 0 ||
        (m_compressed != nullptr && m_compressed->count(key) != 0)) {
        return key;
    }
    const aiTexture* texture = m_scene.GetEmbeddedTexture(reference.c_str());
    if (texture == nullptr) {
        m_notes.add("embedded texture '" + reference + "' not found");
        return {};
    }
    auto image = std::make_shared<render::TextureImage>();
    if (texture->mHeight == 0 && m_compressed != nullptr) {
        const char* bytes = reinterpret_cast<const char*>(texture->pcData);
        (*m_compressed)[key] = {reference,
                                bytes != nullptr ? std::string(bytes, texture->mWidth) : std::string()};
        return key;
    }
    if (texture->mHeight == 0) {
        // Compressed (PNG, JPEG, ...): mWidth is the byte count.
        auto decoded = render::decodeTexture(texture->pcData, texture->mWidth, key);
        if (!decoded) {
            m_notes.add("embedded texture '" + reference + "' unreadable: " + decoded.error());
            return {};
        }
        *image = std::move(decoded).value();
    } else {
        // Raw BGRA texels, top row first; TextureImage wants the bottom row first.
        const unsigned width = texture->mWidth, height = texture->mHeight;
        if (width > static_cast<unsigned>(render::kMaxTextureSide) ||
            height > static_cast<unsigned>(render::kMaxTextureSide) || texture->pcData == nullptr) {
            m_notes.add("embedded texture '" + reference + "' too large, ignored");
            return {};
        }
        image->width = static_cast<int>(width);
        image->height = static_cast<int>(height);
        image->rgba8.resize(static_cast<std::size_t>(width) * height * 4);
        for (unsigned y = 0; y < height; ++y) {
            const aiTexel* row = texture->pcData + static_cast<std::size_t>(height - 1 - y) * width;
            std::uint8_t* out = image->rgba8.data() + static_cast<std::size_t>(y) * width * 4;
            for (unsigned x = 0; x < width; ++x) {
                out[4 * x + 0] = row[x].r;
                out[4 * x + 1] = row[x].g;
                out[4 * x + 2] = row[x].b;
                out[4 * x + 3] = row[x].a;
            }
        }
    }
    m_model.embeddedTextures.emplace(key, std::move(image));
    return key;
}

std::string MaterialConverter::external(const std::string& reference) {
    std::string cleaned = reference;
    std::replace(cleaned.begin(), cleaned.end(), '\\', '/'); // files written on Windows
    const fs::path given(cleaned);
    std::vector<fs::path> candidates;
    candidates.push_back(given.is_absolute() ? given : fs::path(m_modelDir) / given);
    // An absolute path from another machine ("D:/models/wood.jpg"): the file beside the model.
    candidates.push_back(fs::path(m_modelDir) / given.filename());
    for (const fs::path& candidate : candidates) {
        std::error_code ec;
        if (!candidate.filename().empty() && fs::is_regular_file(candidate, ec)) {
            return fs::absolute(candidate, ec).lexically_normal().string();
        }
    }
    // Kept, missing as it is: the material still names the file, so that everything that draws or checks
    // it reports it as it does a project's own missing texture (an error for the commands unless
    // --keep-going, the checker and a warning in the editor) instead of drawing the model untextured.
    std::error_code ec;
    const fs::path expected = fs::absolute(candidates.front(), ec);
    return (ec ? candidates.front() : expected).lexically_normal().string();
}

void decodeEmbeddedTextures(const std::map<std::string, EmbeddedBytes>& compressed, ImportedModel& model,
                            ImportNotes& notes) {
    for (const auto& [key, texture] : compressed) {
        std::string reduced;
        auto decoded = render::decodeTexture(texture.bytes.data(), texture.bytes.size(), key, {}, &reduced);
        if (decoded) {
            if (!reduced.empty())
                notes.add(reduced);
            model.embeddedTextures[key] = std::make_shared<render::TextureImage>(std::move(decoded).value());
            continue;
        }
        notes.add("embedded texture '" + texture.reference + "' unreadable: " + decoded.error());
        for (MaterialComponent& material : model.materials) {
            for (render::TextureSource* field :
                 {&material.texture, &material.emissionTexture, &material.normalTexture}) {
                if (field->path == key) {
                    *field = {};
                }
            }
        }
    }
    // Tangents were computed for parts whose material had a normal map; one that did not decode leaves none.
    for (ImportedPart& part : model.parts) {
        const bool normalMapped = part.material >= 0 && part.material < int(model.materials.size()) &&
                                  !model.materials[part.material].normalTexture.empty();
        if (part.mesh && !part.mesh->tangents.empty() && !normalMapped) {
            render::MeshData copy = *part.mesh;
            copy.tangents.clear();
            part.mesh = render::freezeMesh(std::move(copy));
        }
    }
}

} // namespace speculum::scene::detail
