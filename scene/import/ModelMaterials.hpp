#pragma once

#include "scene/import/ModelImport.hpp"

#include <map>
#include <set>
#include <string>
#include <vector>

struct aiMaterial;
struct aiScene;

namespace speculum::scene::detail {

// A compressed embedded texture as the file holds it, and the name the file gives it ("*0").
struct EmbeddedBytes {
    std::string reference;
    std::string bytes;
    bool operator==(const EmbeddedBytes&) const = default;
};

// Notes for the user, each text kept once ("KHR_materials_clearcoat ignored" for twenty materials is one
// line). ModelImport prefixes them with the file name.
class ImportNotes {
public:
    void add(const std::string& note);
    const std::vector<std::string>& all() const { return m_notes; }

private:
    std::set<std::string> m_seen;
    std::vector<std::string> m_notes;
};

// Converts Assimp's materials of one scene into speculum's, resolving their textures: external files
// relative to the model's folder (absolute; a missing one keeps the path it was expected at, so that the
// commands refuse it and the renderer shows it as missing, as they do a project's own textures), embedded
// ones decoded once into model.embeddedTextures under
// "<modelPath>#<Assimp's name>". The conversion is documented in ModelMaterials.cpp.
// Given `compressedOut`, compressed embedded textures (PNG, JPEG, ...) are not decoded but handed over as
// their file bytes under the same key: the import child leaves decoding (OpenImageIO, whose thread pool is
// not fork-safe) to the editor process, see decodeEmbeddedTextures.
class MaterialConverter {
public:
    MaterialConverter(const aiScene& scene, std::string absoluteModelPath, ImportedModel& model,
                      ImportNotes& notes, std::map<std::string, EmbeddedBytes>* compressedOut = nullptr);

    MaterialComponent convert(const aiMaterial& material);
    // Whether Assimp's material `index` is its placeholder for "the file gave no material" (PLY, STL):
    // such parts get speculum's default material instead.
    bool isPlaceholder(const aiMaterial& material) const;

private:
    std::string texture(const aiMaterial& material, int type, const char* what);
    std::string embedded(const std::string& reference);
    std::string external(const std::string& reference);

    const aiScene& m_scene;
    std::string m_modelPath;
    std::string m_modelDir;
    ImportedModel& m_model;
    ImportNotes& m_notes;
    std::map<std::string, EmbeddedBytes>* m_compressed;
};

// Decodes what a MaterialConverter with `compressedOut` handed over into model.embeddedTextures. A texture
// that cannot be decoded is a note and leaves the materials that named it without that texture (and a part
// whose normal map went without its tangents), as an in-process conversion would have.
void decodeEmbeddedTextures(const std::map<std::string, EmbeddedBytes>& compressed, ImportedModel& model,
                            ImportNotes& notes);

} // namespace speculum::scene::detail
