#pragma once

#include "editor/document/ModelImport.hpp"

#include <set>
#include <string>
#include <vector>

struct aiMaterial;
struct aiScene;

namespace speculum::document::detail {

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
// relative to the model's folder (absolute, regular files only; a missing one is a note, the material
// keeps no texture), embedded ones decoded once into model.embeddedTextures under
// "<modelPath>#<Assimp's name>". The conversion is documented in ModelMaterials.cpp.
class MaterialConverter {
public:
    MaterialConverter(const aiScene& scene, std::string absoluteModelPath, ImportedModel& model,
                      ImportNotes& notes);

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
};

} // namespace speculum::document::detail
