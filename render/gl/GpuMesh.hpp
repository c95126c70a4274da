#pragma once

#include "render/gl/Objects.hpp"
#include "render/mesh/MeshData.hpp"

#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace speculum::render::gl {

// Attribute locations: 0 position, 1 normal, 2 uv (one interleaved buffer), 3 colour and 4 tangent (a
// second buffer, only for meshes that have them; otherwise the attributes are disabled and draw() gives
// them the constant values white and (1, 0, 0, 1)).
inline constexpr GLuint kColorAttribute = 3;
inline constexpr GLuint kTangentAttribute = 4;

// Which of a mesh's triangle lists a draw uses: all of them, or the simplified level where the mesh has
// one built (MeshData::coarse; a mesh without one draws whole either way).
enum class Detail { Full, Coarse };

struct GpuMesh {
    VertexArray vao;
    Buffer vertices;
    Buffer extras; // colours then tangents, where the mesh has them; empty otherwise
    Buffer indices;
    GLsizei indexCount = 0;
    Buffer coarseIndices;         // the simplified level's, uploaded once it is built
    GLsizei coarseIndexCount = 0; // 0: no simplified level (yet)
    bool hasColors = false;
    bool hasTangents = false;
    Bounds bounds; // of the positions, in the mesh's own space: views cull with it

    void draw(Detail detail = Detail::Full) const;
};

// Uploads each MeshData once and keeps it while the mesh is alive; the shared pointer's address is the
// key, and a weak pointer tells when the CPU mesh is gone so its buffers can be freed.
class MeshCache {
public:
    // The mesh's buffers, uploaded on first use; its simplified level is added once it has been built.
    const GpuMesh& get(const MeshHandle& mesh);
    // Frees the GPU copies of meshes nobody holds any more.
    void purge();
    std::size_t size() const { return m_entries.size(); }
    // Meshes whose buffers did not fit in GPU memory since the last call (they draw nothing).
    std::vector<std::string> takeWarnings() { return std::exchange(m_warnings, {}); }

private:
    struct Entry {
        std::weak_ptr<const MeshData> owner;
        GpuMesh gpu;
        bool coarseTried = false; // the simplified level uploaded, or found empty, or did not fit
    };
    void addCoarseLevel(const MeshData& mesh, Entry& entry);
    std::unordered_map<const MeshData*, Entry> m_entries;
    std::vector<std::string> m_warnings;
};

} // namespace speculum::render::gl
