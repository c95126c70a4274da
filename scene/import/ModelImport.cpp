#include "scene/import/ModelImport.hpp"

#include "base/FileKind.hpp"
#include "render/mesh/MeshRepair.hpp"
#include "scene/import/ModelImportProcess.hpp"
#include "scene/import/ModelIoSystem.hpp"
#include "scene/import/ModelMaterials.hpp"
#include "scene/import/ModelNodes.hpp"
#include "scene/import/ModelPrecheck.hpp"
#include "scene/import/ModelSerialization.hpp"
#include "scene/import/ModelWeld.hpp"

#include <algorithm>
#include <assimp/Importer.hpp>
#include <assimp/ProgressHandler.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <cmath>
#include <exception>
#include <filesystem>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <map>
#include <pthread.h>
#include <sstream>
#include <system_error>
#include <utility>

namespace speculum::scene {
namespace {

namespace fs = std::filesystem;
using base::Error;
using detail::ImportNotes;
using detail::kMaxNodeDepth;
using render::MeshData;

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
base::Result<MeshData> convertPart(const aiMesh& source, bool wantTangents, ImportNotes& notes,
                                   render::RepairReport& repairs, const Progress& progress, double fraction) {
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

// The file's node tree, meshes referenced by index; deeper than kMaxNodeDepth is an error. An explicit
// stack, so that the depth costs no native stack.
base::Status convertNode(const aiNode& root, const aiScene& scene, ImportedNode& rootOut) {
    struct Item {
        const aiNode* node;
        ImportedNode* out;
        int depth;
    };
    std::vector<Item> stack{{&root, &rootOut, 0}};
    while (!stack.empty()) {
        const Item item = stack.back();
        stack.pop_back();
        if (item.depth > kMaxNodeDepth) {
            return Error{"node hierarchy deeper than " + std::to_string(kMaxNodeDepth) + " levels"};
        }
        const aiNode& node = *item.node;
        ImportedNode& out = *item.out;
        out.name = node.mName.C_Str();
        out.local = toGlm(node.mTransformation);
        for (unsigned i = 0; i < node.mNumMeshes; ++i) {
            if (node.mMeshes != nullptr && node.mMeshes[i] < scene.mNumMeshes) {
                out.parts.push_back(static_cast<int>(node.mMeshes[i]));
            }
        }
        if (node.mChildren == nullptr) {
            continue;
        }
        std::size_t valid = 0;
        for (unsigned i = 0; i < node.mNumChildren; ++i) {
            valid += node.mChildren[i] != nullptr ? 1 : 0;
        }
        out.children.resize(valid); // sized once: the pointers pushed below stay valid
        std::size_t next = valid;
        for (unsigned i = node.mNumChildren; i-- > 0;) { // reversed: children come off in file order
            if (node.mChildren[i] != nullptr) {
                stack.push_back({node.mChildren[i], &out.children[--next], item.depth + 1});
            }
        }
    }
    return base::Done{};
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

// What the editor process checks itself before any reader runs.
base::Status checkBeforeReading(const fs::path& file) {
    std::error_code ec;
    if (const base::Status regular = base::requireRegularFile(file); !regular) {
        if (regular.error().find("folder") != std::string::npos) {
            return Error{"it is a folder, not a regular file"};
        }
        return Error{regular.error()};
    }
    const auto size = fs::file_size(file, ec);
    if (ec) {
        return Error{"cannot read the file size: " + ec.message()};
    }
    if (size == 0) {
        return Error{"file is empty"};
    }
    // What would exhaust memory, time or the stack inside Assimp is refused before it reads anything.
    if (const base::Status checked = detail::precheckModel(file); !checked) {
        return Error{checked.error()};
    }
    return base::Done{};
}

// Why Assimp read no scene, in the user's terms where its message is known.
std::string readFailure(const Assimp::Importer& importer, const fs::path& file) {
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
    return reason;
}

// A scene read is worth converting: complete, with meshes, with triangles and within the size limits.
// Counted first so that an absurd model is refused before anything big is allocated.
base::Status checkReadScene(const aiScene& scene) {
    if ((scene.mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0 || scene.mRootNode == nullptr) {
        return Error{"the file contains no complete scene (no meshes)"};
    }
    if (scene.mNumMeshes == 0 || scene.mMeshes == nullptr) {
        return Error{"the file contains no meshes"};
    }
    std::size_t triangleCount = 0, vertexCount = 0;
    for (unsigned i = 0; i < scene.mNumMeshes; ++i) {
        if (isTriangleMesh(scene.mMeshes[i])) {
            triangleCount += scene.mMeshes[i]->mNumFaces;
            vertexCount += scene.mMeshes[i]->mNumVertices;
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
    return base::Done{};
}

// The scene's materials into model.materials, placeholders left out; returns each Assimp material's
// index there (-1: none).
std::vector<int> convertMaterials(const aiScene& scene, const std::string& absolutePath, ImportedModel& model,
                                  ImportNotes& notes,
                                  std::map<std::string, detail::EmbeddedBytes>* compressedOut) {
    detail::MaterialConverter converter(scene, absolutePath, model, notes, compressedOut);
    std::vector<int> materialIndex(scene.mNumMaterials, -1);
    for (unsigned i = 0; i < scene.mNumMaterials && scene.mMaterials != nullptr; ++i) {
        if (scene.mMaterials[i] == nullptr || converter.isPlaceholder(*scene.mMaterials[i])) {
            continue;
        }
        materialIndex[i] = static_cast<int>(model.materials.size());
        model.materials.push_back(converter.convert(*scene.mMaterials[i]));
    }
    return materialIndex;
}

// Every mesh of the scene into model.parts (same indices). A part that fails is skipped, with a note;
// fails only when every part did (or when cancelled). What bad data cost is told once for the file.
base::Status convertParts(const aiScene& scene, const std::vector<int>& materialIndex, ImportedModel& model,
                          ImportNotes& notes, const Progress& progress) {
    model.parts.resize(scene.mNumMeshes);
    std::size_t failed = 0;
    render::RepairReport repairs; // what bad data cost, over every part
    std::string firstFailure;
    for (unsigned i = 0; i < scene.mNumMeshes; ++i) {
        if (progress.cancelled()) {
            return Error{"cancelled"};
        }
        const double fraction = 0.55 + 0.4 * i / scene.mNumMeshes;
        progress(fraction, "converting");
        const aiMesh* source = scene.mMeshes[i];
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
    if (failed == scene.mNumMeshes) {
        return Error{"no usable triangles (" + firstFailure + ")"};
    }
    // Regenerating normals and dropping zero-area triangles (cone tips, sphere poles: what Assimp's
    // FindDegenerates removed silently) are routine; losing geometry to bad data is worth telling, once
    // for the whole file rather than once per part.
    if (!repairs.clean()) {
        notes.add("repaired: " + repairs.summary());
    }
    if (failed > 0) {
        notes.add(std::to_string(failed) + " of " + std::to_string(scene.mNumMeshes) + " parts skipped (" +
                  firstFailure + ")");
    }
    return base::Done{};
}

// The Assimp read and the conversion, after checkBeforeReading. With `compressedOut` (the import child),
// compressed embedded textures are handed over undecoded.
base::Result<ImportedModel> importChecked(const std::string& path, ImportNotes& notes,
                                          const Progress& progress,
                                          std::map<std::string, detail::EmbeddedBytes>* compressedOut) {
    std::error_code ec;
    const fs::path file(path);
    progress(0.0, "reading");
    Assimp::Importer importer;
    importer.SetProgressHandler(new ReadProgress(progress)); // the importer owns and deletes it
    auto* io = new detail::ModelIoSystem(path);              // likewise
    importer.SetIOHandler(io);
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
    if (!io->refusal().empty()) {
        // A FIFO or device among the files the model references: refused even where the reader would
        // have gone on without it, and named rather than Assimp's "cannot open".
        return Error{io->refusal()};
    }
    if (scene == nullptr) {
        return Error{readFailure(importer, file)};
    }
    if (const base::Status usable = checkReadScene(*scene); !usable) {
        return Error{usable.error()};
    }

    ImportedModel model;
    if (const base::Status walked = convertNode(*scene->mRootNode, *scene, model.root); !walked) {
        return Error{walked.error()};
    }
    progress(0.5, "materials");
    const std::string absolutePath = fs::absolute(file, ec).lexically_normal().string();
    const std::vector<int> materialIndex =
        convertMaterials(*scene, absolutePath, model, notes, compressedOut);
    if (const base::Status converted = convertParts(*scene, materialIndex, model, notes, progress);
        !converted) {
        return Error{converted.error()};
    }

    model.unitScale = unitScaleOf(*scene, file, notes);
    model.root.local = glm::scale(glm::dmat4(1.0), glm::dvec3(model.unitScale)) * model.root.local;
    progress(0.95, "bounds");
    model.bounds = detail::placedBounds(model);
    progress(1.0, "done");
    return model;
}

// Assimp's readers and its scene destructor recurse once per nesting level of the file, for formats no
// precheck covers too (3DS and B3D chunks, AC3D kids, binary .x, ...). The whole import runs on a thread
// with a large stack so that the nesting a file of plausible size can hold does not overflow it; the
// stack is only reserved address space, pages are touched only as deep as a file goes.
constexpr std::size_t kImportStackBytes = std::size_t(512) << 20;

void* runBody(void* body) {
    (*static_cast<std::function<void()>*>(body))();
    return nullptr;
}

void runOnLargeStack(std::function<void()> body) {
    for (const std::size_t bytes : {kImportStackBytes, kImportStackBytes / 8}) {
        pthread_attr_t attributes;
        if (pthread_attr_init(&attributes) != 0) {
            break;
        }
        pthread_t thread;
        const bool started = pthread_attr_setstacksize(&attributes, bytes) == 0 &&
                             pthread_create(&thread, &attributes, &runBody, &body) == 0;
        pthread_attr_destroy(&attributes);
        if (started) {
            pthread_join(thread, nullptr);
            return;
        }
    }
    body(); // no thread to be had (address space limit): the caller's stack it is
}

std::string displayName(const std::string& path) {
    return path.empty() ? std::string("(no file name)") : fs::path(path).filename().string();
}

std::atomic<int> g_cpuLimitSeconds{kDefaultModelImportCpuSeconds};

// `body` on the large stack (the readers and the prechecks recurse per nesting level of the file), every
// exception an error.
template <typename R, typename Body>
R onLargeStackGuarded(Body body) {
    R result = Error{"the import did not run"};
    runOnLargeStack([&] {
        try {
            result = body();
        } catch (const std::bad_alloc&) {
            result = Error{"out of memory while reading the model"};
        } catch (const std::exception& e) {
            result = Error{e.what()};
        } catch (...) {
            result = Error{"unexpected failure while reading the model"};
        }
    });
    return result;
}

base::Result<ImportedModel> importGuarded(const std::string& path, ImportNotes& notes,
                                          const ImportControl& control,
                                          std::map<std::string, detail::EmbeddedBytes>* compressedOut) {
    return onLargeStackGuarded<base::Result<ImportedModel>>(
        [&] { return importChecked(path, notes, Progress{control}, compressedOut); });
}

// checkBeforeReading as the read was run before the child existed.
base::Status checkGuarded(const std::string& path) {
    return onLargeStackGuarded<base::Status>([&] { return checkBeforeReading(path); });
}

base::Result<ImportedModel> named(const std::string& name, base::Result<ImportedModel> result) {
    if (!result && result.error() != "cancelled") {
        return Error{name + ": " + result.error()};
    }
    return result;
}

void tell(const std::string& name, const std::vector<std::string>& notes,
          std::vector<std::string>& warnings) {
    for (const std::string& note : notes) {
        warnings.push_back(name + ": " + note);
    }
}

// The child's answer as the model importModelFile returns: notes told, embedded textures decoded here.
base::Result<ImportedModel> receive(const std::string& name, std::string& bytes,
                                    std::vector<std::string>& warnings) {
    auto answer = detail::deserializeChildImport(bytes);
    bytes = {};
    if (!answer) {
        return Error{name + ": " + answer.error()};
    }
    detail::ChildImport& child = answer.value();
    ImportNotes notes;
    for (const std::string& note : child.notes) {
        notes.add(note);
    }
    if (child.ok) {
        detail::decodeEmbeddedTextures(child.compressedTextures, child.model, notes);
    }
    tell(name, notes.all(), warnings);
    if (!child.ok) {
        return named(name, Error{child.error});
    }
    return std::move(child.model);
}

} // namespace

void setModelImportCpuLimit(int seconds) {
    g_cpuLimitSeconds.store(std::max(1, seconds));
}

int modelImportCpuLimit() {
    return g_cpuLimitSeconds.load();
}

namespace detail {

base::Result<ImportedModel> importModelFileInProcess(const std::string& path,
                                                     std::vector<std::string>& warnings,
                                                     const ImportControl& control) {
    const std::string name = displayName(path);
    if (const base::Status checked = checkGuarded(path); !checked) {
        return Error{name + ": " + checked.error()};
    }
    ImportNotes notes;
    auto result = importGuarded(path, notes, control, nullptr);
    tell(name, notes.all(), warnings);
    return named(name, std::move(result));
}

} // namespace detail

// The checks here; the read in a child process (ModelImportProcess), so that a crash, a hang or a memory
// blow-up inside Assimp costs the child, not the editor and its open document.
base::Result<ImportedModel> importModelFile(const std::string& path, std::vector<std::string>& warnings,
                                            const ImportControl& control) {
    const std::string name = displayName(path);
    if (const base::Status checked = checkGuarded(path); !checked) {
        return Error{name + ": " + checked.error()};
    }
    const auto body = [&path](const detail::ChildProgress& progress) {
        detail::ChildImport answer;
        ImportNotes notes;
        ImportControl childControl;
        childControl.progress = progress;
        auto result = importGuarded(path, notes, childControl, &answer.compressedTextures);
        answer.notes = notes.all();
        answer.ok = result.ok();
        if (result) {
            answer.model = std::move(result).value();
        } else {
            answer.error = result.error();
        }
        return detail::serializeChildImport(answer);
    };
    const int cpuSeconds = modelImportCpuLimit();
    detail::ChildRun run = detail::runInChildProcess(body, control, cpuSeconds);
    switch (run.outcome) {
    case detail::ChildRun::Outcome::NotStarted:
        return detail::importModelFileInProcess(path, warnings, control); // no process to be had
    case detail::ChildRun::Outcome::Cancelled:
        return Error{"cancelled"};
    case detail::ChildRun::Outcome::Failed:
        return Error{name + ": " + run.error};
    case detail::ChildRun::Outcome::Answered:
        break;
    }
    try {
        return receive(name, run.answer, warnings);
    } catch (const std::bad_alloc&) {
        return Error{name + ": out of memory while reading the model"};
    }
}

base::Result<MeshData> importModel(const std::string& path, std::vector<std::string>& warnings) {
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

} // namespace speculum::scene
