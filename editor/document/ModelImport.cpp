#include "editor/document/ModelImport.hpp"

#include "render/mesh/MeshRepair.hpp"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <cctype>
#include <cmath>
#include <exception>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <limits>
#include <sstream>
#include <system_error>
#include <utility>

namespace speculum::document {
namespace {

namespace fs = std::filesystem;
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

struct Instance {
    const aiMesh* mesh;
    glm::dmat4 world;
};

// A triangle mesh after SortByPType; meshes with only points or lines were removed by the importer, but
// a format may still hand over an empty one.
bool isTriangleMesh(const aiMesh* mesh) {
    return mesh != nullptr && mesh->mNumVertices > 0 && mesh->mNumFaces > 0 &&
           (mesh->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) != 0;
}

// Depth-first walk of the node tree, collecting each mesh reference with its world transform.
render::Status collectInstances(const aiScene& scene, std::vector<Instance>& out) {
    struct Item {
        const aiNode* node;
        glm::dmat4 parent;
        int depth;
    };
    std::vector<Item> stack{{scene.mRootNode, glm::dmat4(1.0), 0}};
    while (!stack.empty()) {
        const Item item = stack.back();
        stack.pop_back();
        if (item.node == nullptr) {
            continue;
        }
        if (item.depth > kMaxNodeDepth) {
            return Error{"node hierarchy deeper than " + std::to_string(kMaxNodeDepth) + " levels"};
        }
        const glm::dmat4 world = item.parent * toGlm(item.node->mTransformation);
        for (unsigned i = 0; i < item.node->mNumMeshes; ++i) {
            const unsigned index = item.node->mMeshes[i];
            if (index < scene.mNumMeshes) {
                out.push_back({scene.mMeshes[index], world});
            }
        }
        for (unsigned i = 0; i < item.node->mNumChildren; ++i) {
            stack.push_back({item.node->mChildren[i], world, item.depth + 1});
        }
    }
    return render::Done{};
}

render::Result<MeshData> flatten(const std::vector<Instance>& instances, std::vector<std::string>& notes) {
    // Count first so that an absurd model is refused before anything big is allocated.
    std::size_t vertexCount = 0, triangleCount = 0, skippedFaces = 0;
    bool anyUvs = false, anyMissingUvs = false, extraUvChannels = false;
    for (const Instance& instance : instances) {
        if (!isTriangleMesh(instance.mesh)) {
            continue;
        }
        vertexCount += instance.mesh->mNumVertices;
        triangleCount += instance.mesh->mNumFaces;
        const bool hasUvs = instance.mesh->HasTextureCoords(0);
        anyUvs |= hasUvs;
        anyMissingUvs |= !hasUvs;
        extraUvChannels |= instance.mesh->GetNumUVChannels() > 1;
    }
    if (triangleCount == 0) {
        return Error{"the model contains no triangles"};
    }
    if (triangleCount > render::kMaxMeshTriangles || vertexCount > render::kMaxMeshVertices ||
        vertexCount > std::numeric_limits<std::uint32_t>::max()) {
        std::ostringstream out;
        out << "the model is too large (" << triangleCount << " triangles, " << vertexCount
            << " vertices; the limit is " << render::kMaxMeshTriangles << " triangles)";
        return Error{out.str()};
    }

    MeshData mesh;
    mesh.positions.reserve(vertexCount);
    mesh.normals.reserve(vertexCount);
    if (anyUvs) {
        mesh.uvs.reserve(vertexCount);
    }
    mesh.indices.reserve(triangleCount * 3);

    for (const Instance& instance : instances) {
        const aiMesh& source = *instance.mesh;
        if (!isTriangleMesh(&source)) {
            continue;
        }
        const glm::dmat3 linear(instance.world);
        const double determinant = glm::determinant(linear);
        // Normals transform by the inverse transpose; a singular transform has none (repair rebuilds them).
        const bool invertible = std::isfinite(determinant) && std::abs(determinant) > 1e-300;
        const glm::dmat3 normalMatrix = invertible ? glm::inverseTranspose(linear) : glm::dmat3(0.0);
        // A mirroring transform turns counter-clockwise triangles clockwise; swap two corners to undo it.
        const bool mirrored = determinant < 0.0;

        const auto base = static_cast<std::uint32_t>(mesh.positions.size());
        for (unsigned v = 0; v < source.mNumVertices; ++v) {
            const aiVector3D& p = source.mVertices[v];
            mesh.positions.emplace_back(instance.world * glm::dvec4(p.x, p.y, p.z, 1.0));
            glm::vec3 normal(0.0f);
            if (source.HasNormals() && invertible) {
                const aiVector3D& n = source.mNormals[v];
                normal = glm::vec3(normalMatrix * glm::dvec3(n.x, n.y, n.z)); // repair normalises
            }
            mesh.normals.push_back(normal);
            if (anyUvs) {
                const aiVector3D uv =
                    source.HasTextureCoords(0) ? source.mTextureCoords[0][v] : aiVector3D(0.0f);
                mesh.uvs.emplace_back(uv.x, uv.y);
            }
        }
        for (unsigned f = 0; f < source.mNumFaces; ++f) {
            const aiFace& face = source.mFaces[f];
            if (face.mNumIndices != 3) {
                ++skippedFaces;
                continue;
            }
            const std::uint32_t a = base + face.mIndices[0];
            const std::uint32_t b = base + face.mIndices[mirrored ? 2 : 1];
            const std::uint32_t c = base + face.mIndices[mirrored ? 1 : 2];
            // Indices past this mesh's vertices would alias the next mesh; make them out of range instead.
            const auto limit = static_cast<std::uint32_t>(base + source.mNumVertices);
            const auto guard = [&](std::uint32_t i) {
                return i < limit ? i : std::numeric_limits<std::uint32_t>::max();
            };
            mesh.indices.insert(mesh.indices.end(), {guard(a), guard(b), guard(c)});
        }
    }

    if (skippedFaces > 0) {
        notes.push_back("ignored " + std::to_string(skippedFaces) + " point and line primitives");
    }
    if (anyUvs && anyMissingUvs) {
        notes.push_back("some parts have no texture coordinates; they get uv (0, 0)");
    }
    if (extraUvChannels) {
        notes.push_back("only the first texture coordinate set is used");
    }
    return mesh;
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

render::Result<MeshData> importChecked(const std::string& path, std::vector<std::string>& notes) {
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

    Assimp::Importer importer;
    // Drop points and lines entirely: the renderer and the tracer only know triangles.
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    // Degenerate triangles become lines/points and are then removed by SortByPType.
    importer.SetPropertyBool(AI_CONFIG_PP_FD_REMOVE, true);

    // Not aiProcess_FindInvalidData: in Assimp 5.2 one NaN position makes it delete the whole mesh, while
    // repairMesh() drops just the triangles that touch it (and rebuilds bad normals, resets bad uvs).
    constexpr unsigned kFlags = aiProcess_Triangulate | aiProcess_GenSmoothNormals |
                                aiProcess_JoinIdenticalVertices | aiProcess_SortByPType |
                                aiProcess_FindDegenerates | aiProcess_ValidateDataStructure;
    const aiScene* scene = importer.ReadFile(path, kFlags);
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
    if (scene->mNumMeshes == 0) {
        return Error{"the file contains no meshes"};
    }

    std::vector<Instance> instances;
    if (const render::Status walked = collectInstances(*scene, instances); !walked) {
        return Error{walked.error()};
    }
    auto flat = flatten(instances, notes);
    if (!flat) {
        return flat;
    }

    render::RepairReport report;
    auto repaired = render::repairMesh(std::move(flat).value(), report);
    if (!repaired) {
        return Error{repaired.error()};
    }
    // Regenerating normals after a singular transform or for a format without them is routine, but
    // dropping geometry is worth telling the user.
    if (report.droppedTriangles() > 0 || report.droppedUvs || report.fixedUvs > 0) {
        notes.push_back("repaired: " + report.summary());
    }
    return repaired;
}

} // namespace

render::Result<MeshData> importModel(const std::string& path, std::vector<std::string>& warnings) {
    const std::string name =
        path.empty() ? std::string("(no file name)") : fs::path(path).filename().string();
    std::vector<std::string> notes;
    try {
        auto result = importChecked(path, notes);
        for (const std::string& note : notes) {
            warnings.push_back(name + ": " + note);
        }
        if (!result) {
            return Error{name + ": " + result.error()};
        }
        return result;
    } catch (const std::bad_alloc&) {
        return Error{name + ": out of memory while reading the model"};
    } catch (const std::exception& e) {
        return Error{name + ": " + e.what()};
    }
}

} // namespace speculum::document
