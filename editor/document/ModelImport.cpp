#include "editor/document/ModelImport.hpp"

#include "editor/document/ModelMaterials.hpp"
#include "editor/document/ModelNodes.hpp"
#include "editor/document/ModelWeld.hpp"
#include "render/mesh/MeshRepair.hpp"

#include <assimp/Importer.hpp>
#include <assimp/ProgressHandler.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <cctype>
#include <cmath>
#include <exception>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <sstream>
#include <system_error>
#include <utility>

namespace speculum::document {
namespace {

namespace fs = std::filesystem;
using detail::ImportNotes;
using render::Error;
using render::MeshData;

// Deeper hierarchies than this are treated as broken (Assimp rejects cycles, but not absurd depth).
constexpr int kMaxNodeDepth = 1024;

glm::dmat4 toGlm(const aiMatrix4x4& m) {
    glm::dmat4 out(1.0);
    for (int row = 0; row < 4; ++row) {
        for (int col = 0; col < 4; ++col) {
            out[col][row] = m[row][col]; // Assimp is row-major, GLM column-major
        }
    }
    return out;
}

// A triangle mesh after SortByPType; meshes with only points or lines were removed by the importer, but
// a format may still hand over an empty one.
bool isTriangleMesh(const aiMesh* mesh) {
    return mesh != nullptr && mesh->mNumVertices > 0 && mesh->mNumFaces > 0 &&
           (mesh->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) != 0;
}

struct Progress {
    const ImportControl& control;
    bool cancelled() const { return control.cancel != nullptr && control.cancel->load(); }
    void operator()(double fraction, const char* phase) const {
        if (control.progress) {
            control.progress(fraction, phase);
        }
    }
};

// Assimp's own reading progress (most of a big file's time) and a way to stop it early.
class ReadProgress : public Assimp::ProgressHandler {
public:
    explicit ReadProgress(const Progress& progress)
        : m_progress(progress) {}
    bool Update(float percentage) override {
        // Reading and Assimp's post-processing each count 0..1; only ever report forward.
        if (percentage >= 0.0f && percentage <= 1.0f && 0.5 * percentage > m_reported) {
            m_reported = 0.5 * percentage;
            m_progress(m_reported, "reading");
        }
        return !m_progress.cancelled();
    }

private:
    Progress m_progress;
    double m_reported = 0.0;
};

// One aiMesh as a repaired, welded speculum mesh (tangents when `wantTangents` and it has uvs).
render::Result<MeshData> convertPart(const aiMesh& source, bool wantTangents, ImportNotes& notes,
                                     render::RepairReport& repairs, const Progress& progress,
                                     double fraction) {
    if (!isTriangleMesh(&source)) {
        return Error{"no triangles"};
    }
    if (source.mNumFaces > render::kMaxMeshTriangles || source.mNumVertices > render::kMaxMeshVertices) {
        std::ostringstream out;
        out << "too large (" << source.mNumFaces << " triangles, " << source.mNumVertices
            << " vertices; the limit is " << render::kMaxMeshTriangles << " triangles)";
        return Error{out.str()};
    }
    const unsigned n = source.mNumVertices;
    MeshData mesh;
    mesh.positions.resize(n);
    for (unsigned v = 0; v < n; ++v) {
        mesh.positions[v] = {source.mVertices[v].x, source.mVertices[v].y, source.mVertices[v].z};
    }
    if (source.HasNormals()) {
        mesh.normals.resize(n);
        for (unsigned v = 0; v < n; ++v) {
            mesh.normals[v] = {source.mNormals[v].x, source.mNormals[v].y, source.mNormals[v].z};
        }
    }
    if (source.HasTextureCoords(0)) {
        mesh.uvs.resize(n);
        for (unsigned v = 0; v < n; ++v) {
            mesh.uvs[v] = {source.mTextureCoords[0][v].x, source.mTextureCoords[0][v].y};
        }
    }
    if (source.GetNumUVChannels() > 1) {
        notes.add("only the first texture coordinate set is used");
    }
    if (source.HasVertexColors(0)) {
        mesh.colors.resize(n);
        for (unsigned v = 0; v < n; ++v) {
            const aiColor4D& c = source.mColors[0][v];
            mesh.colors[v] = {c.r, c.g, c.b, c.a};
        }
    }
    if (source.GetNumColorChannels() > 1) {
        notes.add("only the first vertex colour set is used");
    }
    std::size_t skippedFaces = 0, outOfRange = 0;
    mesh.indices.reserve(static_cast<std::size_t>(source.mNumFaces) * 3);
    for (unsigned f = 0; f < source.mNumFaces; ++f) {
        const aiFace& face = source.mFaces[f];
        if (face.mNumIndices != 3 || face.mIndices == nullptr) {
            ++skippedFaces;
            continue;
        }
        if (face.mIndices[0] >= n || face.mIndices[1] >= n || face.mIndices[2] >= n) {
            ++outOfRange; // the weld needs every index in range
            continue;
        }
        mesh.indices.insert(mesh.indices.end(), {face.mIndices[0], face.mIndices[1], face.mIndices[2]});
    }
    if (skippedFaces > 0) {
        notes.add("ignored point and line primitives");
    }
    repairs.droppedOutOfRange += outOfRange;
    if (mesh.indices.empty()) {
        return Error{"no triangles"};
    }
    progress(fraction, "welding");
    detail::weldVertices(mesh);
    progress(fraction, "repairing");
    render::RepairReport report;
    auto repaired = render::repairMesh(std::move(mesh), report);
    if (!repaired) {
        return Error{repaired.error()};
    }
    // Summed over the parts and told once for the file (importChecked).
    repairs.droppedOutOfRange += report.droppedOutOfRange;
    repairs.droppedNonFinite += report.droppedNonFinite;
    repairs.fixedUvs += report.fixedUvs;
    repairs.droppedUvs = repairs.droppedUvs || report.droppedUvs;
    if (wantTangents) {
        detail::computeTangents(repaired.value());
    }
    return repaired;
}

// The file's node tree, meshes referenced by index; deeper than kMaxNodeDepth is an error.
render::Status convertNode(const aiNode& node, const aiScene& scene, ImportedNode& out, int depth) {
    if (depth > kMaxNodeDepth) {
        return Error{"node hierarchy deeper than " + std::to_string(kMaxNodeDepth) + " levels"};
    }
    out.name = node.mName.C_Str();
    out.local = toGlm(node.mTransformation);
    for (unsigned i = 0; i < node.mNumMeshes; ++i) {
        if (node.mMeshes != nullptr && node.mMeshes[i] < scene.mNumMeshes) {
            out.parts.push_back(static_cast<int>(node.mMeshes[i]));
        }
    }
    out.children.reserve(node.mNumChildren);
    for (unsigned i = 0; i < node.mNumChildren; ++i) {
        if (node.mChildren == nullptr || node.mChildren[i] == nullptr) {
            continue;
        }
        out.children.emplace_back();
        if (const render::Status status =
                convertNode(*node.mChildren[i], scene, out.children.back(), depth + 1);
            !status) {
            return status;
        }
    }
    return render::Done{};
}

// FBX stores "UnitScaleFactor": centimetres per file unit (1 = cm, 100 = m). Assimp 5.2 reports it in
// the scene metadata (as a float) and does not apply it; speculum's unit is the metre.
double unitScaleOf(const aiScene& scene, const fs::path& file, ImportNotes& notes) {
    if (scene.mMetaData == nullptr) {
        return 1.0;
    }
    aiString format;
    const bool fbx = (scene.mMetaData->Get("SourceAsset_Format", format) &&
                      std::string(format.C_Str()).find("FBX") != std::string::npos);
    if (!fbx) {
        return 1.0;
    }
    double factor = 0.0;
    float asFloat = 0.0f;
    if (scene.mMetaData->Get("UnitScaleFactor", asFloat)) {
        factor = asFloat;
    } else if (!scene.mMetaData->Get("UnitScaleFactor", factor)) {
        return 0.01; // FBX's default unit is the centimetre
    }
    if (!std::isfinite(factor) || factor <= 0.0 || factor > 1e6) {
        notes.add("invalid FBX unit scale " + std::to_string(factor) + ", centimetres assumed");
        return 0.01;
    }
    (void)file;
    return factor / 100.0;
}

// Text formats that declare their element counts up front (OFF, PLY) make some Assimp readers reserve
// and loop over whatever the header says: invalid/OutOfMemory.off in Assimp's own test set declares
// 353535235358 faces and keeps the 5.2 reader busy for about a minute. Every element takes at least one
// byte, so a header that declares more elements than the file has bytes is refused before reading.
std::string lowerExtension(const fs::path& file) {
    std::string extension = file.extension().string();
    for (char& c : extension) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return extension;
}

render::Status checkDeclaredCounts(const fs::path& file, std::uintmax_t size) {
    std::ifstream in(file, std::ios::binary);
    std::string header(4096, '\0');
    in.read(header.data(), static_cast<std::streamsize>(header.size()));
    header.resize(static_cast<std::size_t>(in.gcount()));

    std::vector<unsigned long long> counts;
    const auto parseCount = [&](const std::string& token) {
        // Digits only; anything longer than 19 digits would not fit and is absurd anyway.
        if (token.empty() || token.size() > 19 ||
            token.find_first_not_of("0123456789") != std::string::npos) {
            return false;
        }
        counts.push_back(std::stoull(token));
        return true;
    };

    if (header.rfind("ply", 0) == 0) {
        // "element <name> <count>" lines up to "end_header".
        std::istringstream lines(header);
        std::string line;
        while (std::getline(lines, line) && line.rfind("end_header", 0) != 0) {
            std::istringstream words(line);
            std::string keyword, name, count;
            if (words >> keyword >> name >> count && keyword == "element" && !parseCount(count)) {
                return Error{"invalid element count '" + count + "' in the PLY header"};
            }
        }
    } else if (lowerExtension(file) == ".off") {
        // [ST][C][N][4][n]OFF, an optional dimension for nOFF, then vertex, face and edge counts; '#'
        // comments.
        std::istringstream lines(header);
        std::string line, all;
        while (std::getline(lines, line)) {
            all += line.substr(0, line.find('#')) + ' ';
        }
        std::istringstream words(all);
        std::string keyword, token;
        words >> keyword;
        if (keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0) {
            return render::Done{}; // counts on the keyword line or an unusual header: let Assimp judge
        }
        const bool hasDimension = keyword.find('n') != std::string::npos;
        if (hasDimension) {
            words >> token;
        }
        for (int i = 0; i < 2 && words >> token; ++i) {
            if (!parseCount(token)) {
                return Error{"invalid element count '" + token + "' in the OFF header"};
            }
        }
    }
    for (unsigned long long count : counts) {
        if (count > size || count > 3ull * render::kMaxMeshTriangles) {
            return Error{"the header declares " + std::to_string(count) + " elements but the file has only " +
                         std::to_string(size) + " bytes"};
        }
    }
    return render::Done{};
}

render::Result<ImportedModel> importChecked(const std::string& path, ImportNotes& notes,
                                            const Progress& progress) {
    std::error_code ec;
    const fs::path file(path);
    const fs::file_status status = fs::status(file, ec);
    if (ec || !fs::exists(status)) {
        return Error{"file not found"};
    }
    if (!fs::is_regular_file(status)) {
        return Error{"not a regular file"};
    }
    const auto size = fs::file_size(file, ec);
    if (ec) {
        return Error{"cannot read the file size: " + ec.message()};
    }
    if (size == 0) {
        return Error{"file is empty"};
    }
    if (const render::Status declared = checkDeclaredCounts(file, size); !declared) {
        return Error{declared.error()};
    }

    progress(0.0, "reading");
    Assimp::Importer importer;
    importer.SetProgressHandler(new ReadProgress(progress)); // the importer owns and deletes it
    // Drop points and lines entirely: the renderer and the tracer only know triangles.
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);

    // Not GenSmoothNormals, JoinIdenticalVertices or FindDegenerates: they took most of a big file's time,
    // and repairMesh() (normals, degenerate triangles) and the meshoptimizer weld do the same in linear
    // time. Not FindInvalidData: in Assimp 5.2 one NaN position makes it delete the whole mesh, while
    // repairMesh() drops just the triangles that touch it.
    constexpr unsigned kFlags =
        aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_ValidateDataStructure;
    const aiScene* scene = importer.ReadFile(path, kFlags);
    if (progress.cancelled()) {
        return Error{"cancelled"};
    }
    if (scene == nullptr) {
        std::string reason = importer.GetErrorString();
        if (reason.empty()) {
            reason = "Assimp could not read the file";
        }
        const std::string extension = file.extension().string();
        if (!extension.empty() && !importer.IsExtensionSupported(extension)) {
            reason = "unknown model format '" + extension + "' (" + reason + ")";
        } else if (reason.find("No meshes remaining") != std::string::npos ||
                   reason.find("contains no faces") != std::string::npos) {
            reason = "no triangles to import, points and lines are ignored (" + reason + ")";
        } else if (reason.find("bad_alloc") != std::string::npos) {
            reason = "out of memory while reading; the file is probably corrupt (" + reason + ")";
        }
        return Error{reason};
    }
    if ((scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0 || scene->mRootNode == nullptr) {
        return Error{"the file contains no complete scene (no meshes)"};
    }
    if (scene->mNumMeshes == 0 || scene->mMeshes == nullptr) {
        return Error{"the file contains no meshes"};
    }

    // Count first so that an absurd model is refused before anything big is allocated.
    std::size_t triangleCount = 0, vertexCount = 0;
    for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
        if (isTriangleMesh(scene->mMeshes[i])) {
            triangleCount += scene->mMeshes[i]->mNumFaces;
            vertexCount += scene->mMeshes[i]->mNumVertices;
        }
    }
    if (triangleCount == 0) {
        return Error{"the model contains no triangles"};
    }
    if (triangleCount > render::kMaxMeshTriangles || vertexCount > render::kMaxMeshVertices) {
        std::ostringstream out;
        out << "the model is too large (" << triangleCount << " triangles, " << vertexCount
            << " vertices; the limit is " << render::kMaxMeshTriangles << " triangles)";
        return Error{out.str()};
    }

    ImportedModel model;
    if (const render::Status walked = convertNode(*scene->mRootNode, *scene, model.root, 0); !walked) {
        return Error{walked.error()};
    }

    progress(0.5, "materials");
    const std::string absolutePath = fs::absolute(file, ec).lexically_normal().string();
    detail::MaterialConverter converter(*scene, absolutePath, model, notes);
    std::vector<int> materialIndex(scene->mNumMaterials, -1);
    for (unsigned i = 0; i < scene->mNumMaterials && scene->mMaterials != nullptr; ++i) {
        if (scene->mMaterials[i] == nullptr || converter.isPlaceholder(*scene->mMaterials[i])) {
            continue;
        }
        materialIndex[i] = static_cast<int>(model.materials.size());
        model.materials.push_back(converter.convert(*scene->mMaterials[i]));
    }

    model.parts.resize(scene->mNumMeshes);
    std::size_t failed = 0;
    render::RepairReport repairs; // what bad data cost, over every part
    std::string firstFailure;
    for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
        if (progress.cancelled()) {
            return Error{"cancelled"};
        }
        const double fraction = 0.55 + 0.4 * i / scene->mNumMeshes;
        progress(fraction, "converting");
        const aiMesh* source = scene->mMeshes[i];
        ImportedPart& part = model.parts[i];
        if (source == nullptr) {
            continue;
        }
        part.name = source->mName.C_Str();
        if (source->mMaterialIndex < materialIndex.size()) {
            part.material = materialIndex[source->mMaterialIndex];
        }
        const bool wantTangents = part.material >= 0 && !model.materials[part.material].normalTexture.empty();
        auto mesh = convertPart(*source, wantTangents, notes, repairs, progress, fraction);
        if (!mesh) {
            if (failed++ == 0) {
                firstFailure = "part " + std::to_string(i) + ": " + mesh.error();
            }
            continue;
        }
        part.mesh = render::freezeMesh(std::move(mesh).value());
    }
    if (failed == scene->mNumMeshes) {
        return Error{"no usable triangles (" + firstFailure + ")"};
    }
    // Regenerating normals and dropping zero-area triangles (cone tips, sphere poles: what Assimp's
    // FindDegenerates removed silently) are routine; losing geometry to bad data is worth telling, once
    // for the whole file rather than once per part.
    if (!repairs.clean()) {
        notes.add("repaired: " + repairs.summary());
    }
    if (failed > 0) {
        notes.add(std::to_string(failed) + " of " + std::to_string(scene->mNumMeshes) + " parts skipped (" +
                  firstFailure + ")");
    }

    model.unitScale = unitScaleOf(*scene, file, notes);
    model.root.local = glm::scale(glm::dmat4(1.0), glm::dvec3(model.unitScale)) * model.root.local;
    progress(0.95, "bounds");
    model.bounds = detail::placedBounds(model);
    progress(1.0, "done");
    return model;
}

std::string displayName(const std::string& path) {
    return path.empty() ? std::string("(no file name)") : fs::path(path).filename().string();
}

} // namespace

render::Result<ImportedModel> importModelFile(const std::string& path, std::vector<std::string>& warnings,
                                              const ImportControl& control) {
    const std::string name = displayName(path);
    ImportNotes notes;
    try {
        auto result = importChecked(path, notes, Progress{control});
        for (const std::string& note : notes.all()) {
            warnings.push_back(name + ": " + note);
        }
        if (!result) {
            if (result.error() == "cancelled") {
                return Error{"cancelled"};
            }
            return Error{name + ": " + result.error()};
        }
        return result;
    } catch (const std::bad_alloc&) {
        return Error{name + ": out of memory while reading the model"};
    } catch (const std::exception& e) {
        return Error{name + ": " + e.what()};
    }
}

render::Result<MeshData> importModel(const std::string& path, std::vector<std::string>& warnings) {
    auto model = importModelFile(path, warnings);
    if (!model) {
        return Error{model.error()};
    }
    auto flat = flattenModel(model.value());
    if (!flat) {
        return Error{displayName(path) + ": " + flat.error()};
    }
    return flat;
}

} // namespace speculum::document
