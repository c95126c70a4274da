#include "scene/import/ModelWeld.hpp"

#include <cmath>
#include <glm/geometric.hpp>
#include <meshoptimizer.h>
#include <vector>

namespace speculum::scene::detail {

namespace {

template <typename T>
void remapStream(std::vector<T>& stream, const std::vector<unsigned>& remap, std::size_t unique) {
    if (stream.empty()) {
        return;
    }
    std::vector<T> out(unique);
    meshopt_remapVertexBuffer(out.data(), stream.data(), stream.size(), sizeof(T), remap.data());
    stream = std::move(out);
}

} // namespace

void weldVertices(render::MeshData& mesh) {
    const std::size_t vertexCount = mesh.positions.size();
    if (vertexCount == 0 || mesh.indices.empty()) {
        return;
    }
    std::vector<meshopt_Stream> streams;
    streams.push_back({mesh.positions.data(), sizeof(glm::vec3), sizeof(glm::vec3)});
    if (mesh.normals.size() == vertexCount) {
        streams.push_back({mesh.normals.data(), sizeof(glm::vec3), sizeof(glm::vec3)});
    }
    if (mesh.uvs.size() == vertexCount) {
        streams.push_back({mesh.uvs.data(), sizeof(glm::vec2), sizeof(glm::vec2)});
    }
    if (mesh.colors.size() == vertexCount) {
        streams.push_back({mesh.colors.data(), sizeof(glm::vec4), sizeof(glm::vec4)});
    }
    if (mesh.tangents.size() == vertexCount) {
        streams.push_back({mesh.tangents.data(), sizeof(glm::vec4), sizeof(glm::vec4)});
    }
    std::vector<unsigned> remap(vertexCount);
    const std::size_t unique = meshopt_generateVertexRemapMulti(
        remap.data(), mesh.indices.data(), mesh.indices.size(), vertexCount, streams.data(), streams.size());
    if (unique == vertexCount) {
        return; // nothing shared; the order may still differ, but keeping it is cheaper and as good
    }
    meshopt_remapIndexBuffer(mesh.indices.data(), mesh.indices.data(), mesh.indices.size(), remap.data());
    remapStream(mesh.positions, remap, unique);
    remapStream(mesh.normals, remap, unique);
    remapStream(mesh.uvs, remap, unique);
    remapStream(mesh.colors, remap, unique);
    remapStream(mesh.tangents, remap, unique);
}

void computeTangents(render::MeshData& mesh) {
    const std::size_t n = mesh.positions.size();
    mesh.tangents.clear();
    if (n == 0 || mesh.uvs.size() != n || mesh.normals.size() != n) {
        return;
    }
    std::vector<glm::dvec3> tan(n, glm::dvec3(0.0)), bitan(n, glm::dvec3(0.0));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
        if (i0 >= n || i1 >= n || i2 >= n) {
            continue;
        }
        const glm::dvec3 e1 = glm::dvec3(mesh.positions[i1]) - glm::dvec3(mesh.positions[i0]);
        const glm::dvec3 e2 = glm::dvec3(mesh.positions[i2]) - glm::dvec3(mesh.positions[i0]);
        const glm::dvec2 d1 = glm::dvec2(mesh.uvs[i1]) - glm::dvec2(mesh.uvs[i0]);
        const glm::dvec2 d2 = glm::dvec2(mesh.uvs[i2]) - glm::dvec2(mesh.uvs[i0]);
        const double det = d1.x * d2.y - d2.x * d1.y;
        if (!std::isfinite(det) || std::abs(det) < 1e-20) {
            continue; // no uv gradient on this triangle
        }
        // Unnormalised by |det|'s magnitude, so larger triangles (in uv and space) weigh more; the sign
        // of det carries the uv mirroring.
        const double sign = det > 0.0 ? 1.0 : -1.0;
        const glm::dvec3 sdir = (e1 * d2.y - e2 * d1.y) * sign;
        const glm::dvec3 tdir = (e2 * d1.x - e1 * d2.x) * sign;
        for (std::uint32_t i : {i0, i1, i2}) {
            tan[i] += sdir;
            bitan[i] += tdir;
        }
    }
    mesh.tangents.resize(n);
    for (std::size_t v = 0; v < n; ++v) {
        const glm::dvec3 normal(mesh.normals[v]);
        glm::dvec3 t = tan[v] - normal * glm::dot(normal, tan[v]);
        if (!(glm::length(t) > 1e-20)) {
            // No gradient: any direction perpendicular to the normal.
            const glm::dvec3 axis = std::abs(normal.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
            t = glm::cross(axis, normal);
        }
        t = glm::normalize(t);
        const double w = glm::dot(glm::cross(normal, t), bitan[v]) < 0.0 ? -1.0 : 1.0;
        mesh.tangents[v] = glm::vec4(glm::vec3(t), static_cast<float>(w));
    }
}

} // namespace speculum::scene::detail
