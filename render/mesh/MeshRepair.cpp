#include "render/mesh/MeshRepair.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <optional>
#include <sstream>
#include <vector>

namespace speculum::render {
namespace {

bool isFinite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
bool isFinite(const glm::vec2& v) {
    return std::isfinite(v.x) && std::isfinite(v.y);
}

// Twice the triangle area, in double so that large coordinates don't cancel to zero.
glm::dvec3 areaVector(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::dvec3 da(a);
    return glm::cross(glm::dvec3(b) - da, glm::dvec3(c) - da);
}

// A triangle is degenerate when its area is negligible next to its longest edge: a needle or a collapsed
// triangle has no defined normal and only produces rasterisation and intersection noise.
bool isDegenerate(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const double twiceArea = glm::length(areaVector(a, b, c));
    const glm::dvec3 da(a), db(b), dc(c);
    const double longest = std::max({glm::length(db - da), glm::length(dc - db), glm::length(da - dc)});
    return !(twiceArea > 1e-12 * longest * longest) || longest == 0.0;
}

void appendCount(std::ostringstream& out, bool& first, std::size_t count, const char* what) {
    if (count == 0) {
        return;
    }
    out << (first ? "" : "; ") << what << ' ' << count;
    first = false;
}

// The size limits come first, before anything is allocated for a hostile mesh.
std::optional<base::Error> checkMeshSize(const MeshData& mesh, std::size_t maxTriangles) {
    if (mesh.indices.size() / 3 > maxTriangles || mesh.positions.size() / 3 > maxTriangles) {
        std::ostringstream out;
        out << "mesh too large (" << mesh.indices.size() / 3 << " triangles, " << mesh.positions.size()
            << " vertices; the limit is " << maxTriangles << " triangles)";
        return base::Error{out.str()};
    }
    if (mesh.positions.size() > std::numeric_limits<std::uint32_t>::max()) {
        return base::Error{"mesh too large (vertex count does not fit 32-bit indices)"};
    }
    return std::nullopt;
}

// Step 1: the indices of the triangles that make sense (in range, finite, not degenerate), in order;
// each dropped triangle is counted in the report under its reason.
std::vector<std::uint32_t> keepUsableTriangles(const MeshData& mesh, RepairReport& report) {
    const std::size_t vertexCount = mesh.positions.size();
    std::vector<std::uint32_t> kept;
    kept.reserve(mesh.indices.size());
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        const std::uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
        if (i0 >= vertexCount || i1 >= vertexCount || i2 >= vertexCount) {
            ++report.droppedOutOfRange;
            continue;
        }
        const glm::vec3 &a = mesh.positions[i0], &b = mesh.positions[i1], &c = mesh.positions[i2];
        if (!isFinite(a) || !isFinite(b) || !isFinite(c)) {
            ++report.droppedNonFinite;
            continue;
        }
        if (i0 == i1 || i1 == i2 || i2 == i0 || isDegenerate(a, b, c)) {
            ++report.droppedDegenerate;
            continue;
        }
        kept.insert(kept.end(), {i0, i1, i2});
    }
    return kept;
}

base::Error noUsableTriangles(const RepairReport& report) {
    std::ostringstream out;
    out << "no usable triangles";
    if (report.droppedTriangles() > 0) {
        out << " (" << report.droppedTriangles() << " dropped: " << report.summary() << ")";
    }
    return base::Error{out.str()};
}

// Which per-vertex arrays travel with the vertices: those whose count matches the positions' (the others
// are dropped).
struct VertexAttributes {
    bool normals = false;
    bool uvs = false;
    bool colors = false;
    bool tangents = false;
};

// Appends vertex `index` of `mesh` to `out`, with the attributes it has, made finite.
void appendVertex(const MeshData& mesh, std::uint32_t index, const VertexAttributes& has, MeshData& out,
                  RepairReport& report) {
    out.positions.push_back(mesh.positions[index]);
    out.normals.push_back(has.normals ? mesh.normals[index] : glm::vec3(0.0f));
    if (has.uvs) {
        glm::vec2 uv = mesh.uvs[index];
        if (!isFinite(uv)) {
            uv = glm::vec2(0.0f);
            ++report.fixedUvs;
        }
        out.uvs.push_back(uv);
    }
    if (has.colors) {
        // A non-finite colour would poison every pixel it touches: white (no tint) instead.
        const glm::vec4 c = mesh.colors[index];
        const bool finite =
            std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b) && std::isfinite(c.a);
        out.colors.push_back(finite ? c : glm::vec4(1.0f));
    }
    if (has.tangents) {
        // The shaders fall back to the plain normal where the tangent has no direction.
        const glm::vec4 t = mesh.tangents[index];
        const bool finite =
            std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z) && std::isfinite(t.w);
        out.tangents.push_back(finite ? t : glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    }
}

// Step 2: compacts the vertices to those the kept triangles still reference, in first-use order (this also
// removes non-finite positions, which would otherwise poison bounds and the tracer's acceleration
// structure). `kept` is renumbered in place and becomes the result's indices.
MeshData compactVertices(const MeshData& mesh, std::vector<std::uint32_t> kept, RepairReport& report) {
    const std::size_t vertexCount = mesh.positions.size();
    VertexAttributes has;
    has.normals = mesh.normals.size() == vertexCount;
    has.uvs = mesh.uvs.size() == vertexCount;
    report.droppedUvs = !mesh.uvs.empty() && !has.uvs;
    // Vertex colours and tangents travel with their vertices (dropped when their count does not match).
    has.colors = mesh.colors.size() == vertexCount;
    has.tangents = mesh.tangents.size() == vertexCount;
    constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> remap(vertexCount, kUnused);
    MeshData out;
    for (std::uint32_t& index : kept) {
        std::uint32_t& target = remap[index];
        if (target == kUnused) {
            target = static_cast<std::uint32_t>(out.positions.size());
            appendVertex(mesh, index, has, out, report);
        }
        index = target;
    }
    report.removedUnusedVertices = vertexCount - out.positions.size();
    out.indices = std::move(kept);
    return out;
}

// Step 3a: normalises the usable normals; returns which vertices need theirs rebuilt (missing, non-finite
// or zero).
std::vector<bool> normalizeNormals(MeshData& out, RepairReport& report) {
    std::vector<bool> rebuild(out.positions.size(), false);
    for (std::size_t v = 0; v < out.normals.size(); ++v) {
        const glm::vec3 n = out.normals[v];
        const float length = glm::length(n);
        if (!isFinite(n) || !std::isfinite(length) || length < 1e-20f) {
            rebuild[v] = true;
        } else if (std::abs(length - 1.0f) > 1e-4f) {
            out.normals[v] = n / length;
            ++report.renormalizedNormals;
        } else {
            out.normals[v] = n / length; // tidy the last bits too, silently
        }
    }
    return rebuild;
}

// Step 3b: rebuilds the flagged normals from the area-weighted face normals around them.
void rebuildNormals(MeshData& out, const std::vector<bool>& rebuild, RepairReport& report) {
    std::vector<glm::dvec3> sums(out.positions.size(), glm::dvec3(0.0));
    std::vector<glm::dvec3> fallback(out.positions.size(), glm::dvec3(0.0));
    for (std::size_t t = 0; t < out.indices.size(); t += 3) {
        const std::uint32_t i[3] = {out.indices[t], out.indices[t + 1], out.indices[t + 2]};
        // The cross product's length is twice the area: summing it weights each face by its area.
        const glm::dvec3 face = areaVector(out.positions[i[0]], out.positions[i[1]], out.positions[i[2]]);
        for (std::uint32_t v : i) {
            sums[v] += face;
            if (fallback[v] == glm::dvec3(0.0)) {
                fallback[v] = face;
            }
        }
    }
    for (std::size_t v = 0; v < out.normals.size(); ++v) {
        if (!rebuild[v]) {
            continue;
        }
        // Faces around a vertex can cancel (a paper-thin fin); then any one face is better than none.
        const glm::dvec3 sum =
            glm::length(sums[v]) > 1e-12 * glm::length(fallback[v]) ? sums[v] : fallback[v];
        out.normals[v] = glm::vec3(glm::normalize(sum));
        ++report.regeneratedNormals;
    }
}

} // namespace

bool RepairReport::clean() const {
    return droppedTrailingIndices == 0 && droppedTriangles() == 0 && removedUnusedVertices == 0 &&
           regeneratedNormals == 0 && renormalizedNormals == 0 && fixedUvs == 0 && !droppedUvs;
}

std::string RepairReport::summary() const {
    if (clean()) {
        return "no repairs needed";
    }
    std::ostringstream out;
    bool first = true;
    appendCount(out, first, droppedOutOfRange, "dropped triangles with out-of-range indices:");
    appendCount(out, first, droppedNonFinite, "dropped triangles with non-finite positions:");
    appendCount(out, first, droppedDegenerate, "dropped degenerate triangles:");
    appendCount(out, first, droppedTrailingIndices, "dropped trailing indices:");
    appendCount(out, first, removedUnusedVertices, "removed unused vertices:");
    appendCount(out, first, regeneratedNormals, "regenerated normals:");
    appendCount(out, first, renormalizedNormals, "renormalised normals:");
    appendCount(out, first, fixedUvs, "reset non-finite uvs:");
    if (droppedUvs) {
        out << (first ? "" : "; ") << "dropped uvs (count did not match the vertices)";
    }
    return out.str();
}

base::Result<MeshData> repairMesh(MeshData mesh, RepairReport& report, std::size_t maxTriangles) {
    report = RepairReport{};
    if (auto tooLarge = checkMeshSize(mesh, maxTriangles)) {
        return std::move(*tooLarge);
    }
    report.droppedTrailingIndices = mesh.indices.size() % 3;
    mesh.indices.resize(mesh.indices.size() - report.droppedTrailingIndices);

    // 1. Keep the triangles that make sense.
    std::vector<std::uint32_t> kept = keepUsableTriangles(mesh, report);
    if (kept.empty()) {
        return noUsableTriangles(report);
    }
    // 2. Compact the vertices to those still referenced.
    MeshData out = compactVertices(mesh, std::move(kept), report);
    mesh = MeshData{}; // release the input before the normal pass allocates

    // 3. Normals: keep the good ones, rebuild the rest from the area-weighted face normals around them.
    const std::vector<bool> rebuild = normalizeNormals(out, report);
    if (std::find(rebuild.begin(), rebuild.end(), true) != rebuild.end()) {
        rebuildNormals(out, rebuild, report);
    }
    return out;
}

} // namespace speculum::render
