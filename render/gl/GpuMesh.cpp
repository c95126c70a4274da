#include "render/gl/GpuMesh.hpp"

#include <cassert>
#include <vector>

namespace speculum::render::gl {

namespace {

// Interleaved position, normal, uv: one buffer, one attribute setup.
struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 uv;
};

GpuMesh upload(const MeshData& mesh) {
    std::vector<Vertex> vertices(mesh.positions.size());
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        vertices[i].position = mesh.positions[i];
        vertices[i].normal = i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0.0f, 1.0f, 0.0f);
        vertices[i].uv = i < mesh.uvs.size() ? mesh.uvs[i] : glm::vec2(0.0f);
    }
    GpuMesh gpu;
    gpu.vao = makeVertexArray();
    gpu.vertices = makeBuffer();
    gpu.indices = makeBuffer();
    gpu.indexCount = static_cast<GLsizei>(mesh.indices.size());
    glBindVertexArray(gpu.vao.id());
    glBindBuffer(GL_ARRAY_BUFFER, gpu.vertices.id());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)), vertices.data(),
                 GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.indices.id());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)), mesh.indices.data(),
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
    glBindVertexArray(0);
    return gpu;
}

} // namespace

void GpuMesh::draw() const {
    glBindVertexArray(vao.id());
    glDrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, nullptr);
}

const GpuMesh& MeshCache::get(const MeshHandle& mesh) {
    assert(mesh && "MeshCache::get(): null mesh");
    auto it = m_entries.find(mesh.get());
    // A new mesh may reuse the address of a freed one: only a live weak pointer to this very mesh counts.
    if (it != m_entries.end() && it->second.owner.lock() == mesh)
        return it->second.gpu;
    Entry entry{mesh, upload(*mesh)};
    entry.gpu.bounds = computeBounds(*mesh);
    auto [pos, inserted] = m_entries.insert_or_assign(mesh.get(), std::move(entry));
    return pos->second.gpu;
}

void MeshCache::purge() {
    std::erase_if(m_entries, [](const auto& kv) { return kv.second.owner.expired(); });
}

} // namespace speculum::render::gl
