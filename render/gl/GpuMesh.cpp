#include "render/gl/GpuMesh.hpp"

#include "render/gl/Allocation.hpp"

#include <algorithm>
#include <cassert>
#include <glm/vec4.hpp>
#include <vector>

namespace speculum::render::gl {

namespace {

// Interleaved position, normal, uv: one buffer, one attribute setup.
struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 uv;
};

GpuMesh upload(const MeshData& mesh, std::string& failure) {
    std::vector<Vertex> vertices(mesh.positions.size());
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        vertices[i].position = mesh.positions[i];
        vertices[i].normal = i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0.0f, 1.0f, 0.0f);
        vertices[i].uv = i < mesh.uvs.size() ? mesh.uvs[i] : glm::vec2(0.0f);
    }
    GpuMesh gpu;
    // Checked: buffers that do not fit would draw nothing, or garbage, with no word said.
    const std::size_t extraBytes =
        mesh.positions.size() * sizeof(glm::vec4) *
        ((mesh.colors.size() == mesh.positions.size() && !mesh.colors.empty() ? 1 : 0) +
         (mesh.tangents.size() == mesh.positions.size() && !mesh.tangents.empty() ? 1 : 0));
    const std::size_t indexBytes = mesh.indices.size() * sizeof(std::uint32_t);
    const std::size_t bytes = std::max({vertices.size() * sizeof(Vertex), indexBytes, extraBytes});
    if (base::Status fits = beginAllocation(bytes); !fits) {
        failure = fits.error();
        return GpuMesh{};
    }
    gpu.vao = makeVertexArray();
    gpu.vertices = makeBuffer();
    gpu.indices = makeBuffer();
    gpu.indexCount = static_cast<GLsizei>(mesh.indices.size());
    glBindVertexArray(gpu.vao.id());
    glBindBuffer(GL_ARRAY_BUFFER, gpu.vertices.id());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)), vertices.data(),
                 GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.indices.id());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indexBytes), mesh.indices.data(),
                 GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<void*>(offsetof(Vertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<void*>(offsetof(Vertex, normal)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<void*>(offsetof(Vertex, uv)));
    // Colours and tangents go in a buffer of their own, so meshes without them (most) pay nothing.
    gpu.hasColors = mesh.colors.size() == mesh.positions.size() && !mesh.colors.empty();
    gpu.hasTangents = mesh.tangents.size() == mesh.positions.size() && !mesh.tangents.empty();
    if (gpu.hasColors || gpu.hasTangents) {
        const std::size_t block = mesh.positions.size() * sizeof(glm::vec4);
        const std::size_t colorBytes = gpu.hasColors ? block : 0;
        gpu.extras = makeBuffer();
        glBindBuffer(GL_ARRAY_BUFFER, gpu.extras.id());
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(colorBytes + (gpu.hasTangents ? block : 0)),
                     nullptr, GL_STATIC_DRAW);
        if (gpu.hasColors) {
            glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(block), mesh.colors.data());
            glEnableVertexAttribArray(kColorAttribute);
            glVertexAttribPointer(kColorAttribute, 4, GL_FLOAT, GL_FALSE, sizeof(glm::vec4), nullptr);
        }
        if (gpu.hasTangents) {
            glBufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(colorBytes),
                            static_cast<GLsizeiptr>(block), mesh.tangents.data());
            glEnableVertexAttribArray(kTangentAttribute);
            glVertexAttribPointer(kTangentAttribute, 4, GL_FLOAT, GL_FALSE, sizeof(glm::vec4),
                                  reinterpret_cast<void*>(colorBytes));
        }
    }
    glBindVertexArray(0);
    if (base::Status done = finishAllocation(); !done) {
        failure = done.error();
        return GpuMesh{}; // frees what was allocated
    }
    return gpu;
}

// The simplified level's indices, in a buffer of their own: the level is built after the mesh is first
// drawn (when a reflected view first needs it), and the full list stays as it was uploaded.
void uploadCoarseLevel(GpuMesh& gpu, const std::vector<std::uint32_t>& indices, std::string& failure) {
    if (base::Status fits = beginAllocation(indices.size() * sizeof(std::uint32_t)); !fits) {
        failure = fits.error();
        return;
    }
    Buffer buffer = makeBuffer();
    glBindBuffer(GL_COPY_WRITE_BUFFER, buffer.id());
    glBufferData(GL_COPY_WRITE_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)),
                 indices.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
    if (base::Status done = finishAllocation(); !done) {
        failure = done.error();
        return; // frees the buffer: the mesh draws whole
    }
    gpu.coarseIndices = std::move(buffer);
    gpu.coarseIndexCount = static_cast<GLsizei>(indices.size());
}

} // namespace

void GpuMesh::draw(Detail detail) const {
    if (!vao)
        return; // its buffers did not fit (MeshCache::takeWarnings)
    // A disabled attribute reads the context's current value, which is not part of the VAO: set here.
    if (!hasColors)
        glVertexAttrib4f(kColorAttribute, 1.0f, 1.0f, 1.0f, 1.0f);
    if (!hasTangents)
        glVertexAttrib4f(kTangentAttribute, 1.0f, 0.0f, 0.0f, 1.0f);
    glBindVertexArray(vao.id());
    if (detail == Detail::Coarse && coarseIndexCount > 0) {
        // The element buffer is the vertex array's state: swapped in for this draw, and back.
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, coarseIndices.id());
        glDrawElements(GL_TRIANGLES, coarseIndexCount, GL_UNSIGNED_INT, nullptr);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices.id());
    } else {
        glDrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, nullptr);
    }
}

const GpuMesh& MeshCache::get(const MeshHandle& mesh) {
    assert(mesh && "MeshCache::get(): null mesh");
    auto it = m_entries.find(mesh.get());
    // A new mesh may reuse the address of a freed one: only a live weak pointer to this very mesh counts.
    if (it != m_entries.end() && it->second.owner.lock() == mesh) {
        addCoarseLevel(*mesh, it->second);
        return it->second.gpu;
    }
    std::string failure;
    Entry entry{mesh, upload(*mesh, failure)};
    if (!failure.empty())
        m_warnings.push_back("a mesh of " + std::to_string(mesh->positions.size()) + " vertices and " +
                             std::to_string(mesh->indices.size() / 3) + " triangles " + failure +
                             "; it is not drawn");
    entry.gpu.bounds = computeBounds(*mesh);
    auto [pos, inserted] = m_entries.insert_or_assign(mesh.get(), std::move(entry));
    addCoarseLevel(*mesh, pos->second);
    return pos->second.gpu;
}

void MeshCache::addCoarseLevel(const MeshData& mesh, Entry& entry) {
    if (entry.coarseTried || !entry.gpu.vao)
        return;
    const std::vector<std::uint32_t>* coarse = mesh.coarse.indices();
    if (!coarse) {
        entry.coarseTried = mesh.coarse.ready() != nullptr; // built, and nothing gained: never asked again
        return;
    }
    entry.coarseTried = true;
    std::string failure;
    uploadCoarseLevel(entry.gpu, *coarse, failure);
    if (!failure.empty())
        m_warnings.push_back("the simplified level of a mesh of " + std::to_string(mesh.triangleCount()) +
                             " triangles " + failure + "; its reflections draw it whole");
}

void MeshCache::purge() {
    std::erase_if(m_entries, [](const auto& kv) { return kv.second.owner.expired(); });
}

} // namespace speculum::render::gl
