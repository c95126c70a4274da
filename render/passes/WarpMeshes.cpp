#include "render/passes/WarpMeshes.hpp"

#include "render/envmap/Layout.hpp"
#include "render/plan/Hasher.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

namespace speculum::render::passes {

namespace {

// Angle between two directions, accurate for small angles too (acos of a dot product is not).
double angleBetween(const glm::dvec3& u, const glm::dvec3& v) {
    return std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v));
}

class Splitter {
public:
    Splitter(const MeshData& mesh, const glm::dmat4& world, const WarpTolerance& tolerance)
        : m_world(world)
        , m_tolerance(tolerance)
        , m_hasUv(mesh.uvs.size() == mesh.positions.size())
        , m_hasColors(mesh.colors.size() == mesh.positions.size())
        , m_hasTangents(mesh.tangents.size() == mesh.positions.size()) {
        m_out.positions = mesh.positions;
        m_out.normals = mesh.normals;
        if (m_hasUv)
            m_out.uvs = mesh.uvs;
        // Vertex colours and tangents are split like the uvs (the material shades with them).
        if (m_hasColors)
            m_out.colors = mesh.colors;
        if (m_hasTangents)
            m_out.tangents = mesh.tangents;
        m_relative.reserve(mesh.positions.size());
        for (const glm::vec3& p : mesh.positions)
            m_relative.push_back(relative(p));
    }

    // False when the triangle budget ran out.
    bool run(const MeshData& mesh, std::size_t maxTriangles) {
        std::vector<std::array<std::uint32_t, 3>> stack;
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            stack.push_back({mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]});
            while (!stack.empty()) {
                const auto [a, b, c] = stack.back();
                stack.pop_back();
                if (m_out.indices.size() / 3 + stack.size() > maxTriangles)
                    return false;
                split(a, b, c, stack);
            }
        }
        return true;
    }

    MeshData take() { return std::move(m_out); }

private:
    glm::dvec3 relative(const glm::vec3& p) const {
        return glm::dvec3(m_world * glm::dvec4(glm::dvec3(p), 1.0)) - m_tolerance.centre;
    }

    // Depends on the two end points' positions only, symmetrically (the cross product and the dot product
    // of swapped arguments round alike), so both triangles of an edge decide the same.
    bool needsSplit(std::uint32_t a, std::uint32_t b) const {
        const glm::dvec3& u = m_relative[a];
        const glm::dvec3& v = m_relative[b];
        return glm::length(u - v) > m_tolerance.minLength && angleBetween(u, v) > m_tolerance.maxAngle;
    }

    // The midpoint vertex of edge a-b, shared by both triangles of the edge.
    std::uint32_t midpoint(std::uint32_t a, std::uint32_t b) {
        const std::uint64_t key = (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
        const auto found = m_midpoints.find(key);
        if (found != m_midpoints.end())
            return found->second;
        const auto index = static_cast<std::uint32_t>(m_out.positions.size());
        // 0.5·(a + b) rounds the same for (b, a): vertices duplicated at one position (a box's corners, one
        // per face) get midpoints at one position too, so the faces stay closed.
        const glm::vec3 p = 0.5f * (m_out.positions[a] + m_out.positions[b]);
        const glm::vec3 n = m_out.normals[a] + m_out.normals[b];
        const float length = glm::length(n);
        m_out.positions.push_back(p);
        m_out.normals.push_back(length > 0.0f ? n / length : m_out.normals[a]);
        if (m_hasUv)
            m_out.uvs.push_back(0.5f * (m_out.uvs[a] + m_out.uvs[b]));
        if (m_hasColors)
            m_out.colors.push_back(0.5f * (m_out.colors[a] + m_out.colors[b]));
        if (m_hasTangents)
            m_out.tangents.push_back(glm::vec4(
                0.5f * (glm::vec3(m_out.tangents[a]) + glm::vec3(m_out.tangents[b])), m_out.tangents[a].w));
        m_relative.push_back(relative(p));
        m_midpoints.emplace(key, index);
        return index;
    }

    void split(std::uint32_t a, std::uint32_t b, std::uint32_t c,
               std::vector<std::array<std::uint32_t, 3>>& out) {
        // Rotate (keeping the winding) so that the split edges come first: ab, then bc.
        std::array<std::uint32_t, 3> v{a, b, c};
        std::array<bool, 3> s{needsSplit(a, b), needsSplit(b, c), needsSplit(c, a)};
        const int count = int(s[0]) + int(s[1]) + int(s[2]);
        if (count == 0) {
            m_out.indices.insert(m_out.indices.end(), {a, b, c});
            return;
        }
        for (int turn = 0; turn < 3; ++turn) {
            const bool canonical = count == 1 ? s[0] : count == 2 ? (s[0] && s[1]) : true;
            if (canonical)
                break;
            std::rotate(v.begin(), v.begin() + 1, v.end());
            std::rotate(s.begin(), s.begin() + 1, s.end());
        }
        const auto [p, q, r] = v;
        const std::uint32_t mpq = midpoint(p, q);
        if (count == 1) {
            out.push_back({p, mpq, r});
            out.push_back({mpq, q, r});
            return;
        }
        const std::uint32_t mqr = midpoint(q, r);
        if (count == 2) {
            out.push_back({mpq, q, mqr});
            // The quad p, mpq, mqr, r: cut along its shorter diagonal (in angle, the measure that matters).
            if (angleBetween(m_relative[p], m_relative[mqr]) <=
                angleBetween(m_relative[mpq], m_relative[r])) {
                out.push_back({p, mpq, mqr});
                out.push_back({p, mqr, r});
            } else {
                out.push_back({p, mpq, r});
                out.push_back({mpq, mqr, r});
            }
            return;
        }
        const std::uint32_t mrp = midpoint(r, p);
        out.push_back({p, mpq, mrp});
        out.push_back({mpq, q, mqr});
        out.push_back({mrp, mqr, r});
        out.push_back({mpq, mqr, mrp});
    }

    glm::dmat4 m_world;
    WarpTolerance m_tolerance;
    bool m_hasUv;
    bool m_hasColors;
    bool m_hasTangents;
    MeshData m_out;
    std::vector<glm::dvec3> m_relative; // per output vertex: world position − centre
    std::unordered_map<std::uint64_t, std::uint32_t> m_midpoints;
};

std::uint64_t entryKey(const MeshData* mesh, const glm::dmat4& world, const WarpTolerance& t) {
    Hasher h;
    h.add(mesh);
    h.add(world);
    h.add(t.centre);
    h.add(t.maxAngle);
    h.add(t.minLength);
    return h.value;
}

} // namespace

double warpEdgeAngle(const envmap::MapLayout& layout) {
    // The largest texel angle: a paraboloid's centre (nominal radius 1 over (n − 2g)/2 texels, dθ/dr = 2
    // there), a tennis ball's equator (90° over n − 2g texels). A chord of an edge spanning θ strays
    // θ²/8; one texel allows θ = √(8 · texel angle). Half a texel (the rasterizer's own snapping) took
    // ~60% more triangles, and on llvmpipe a small triangle costs whole 4×4 blocks of fragments: split
    // that finely, the benchmark scene's floor shaded 2.4 fragments for each texel it covers at n = 128.
    const double inner = layout.width - 2.0 * layout.guard;
    const double texel = layout.type == envmap::MapType::DualParaboloid ? 4.0 / inner : 1.5707963 / inner;
    return std::min(kMaxWarpEdgeAngle, std::sqrt(8.0 * texel));
}

MeshData subdivideForWarp(const MeshData& mesh, const glm::dmat4& world, const WarpTolerance& tolerance,
                          std::size_t maxTriangles) {
    Splitter splitter(mesh, world, tolerance);
    if (splitter.run(mesh, maxTriangles))
        return splitter.take();
    // Geometry crowding the capture point would need more: split it to a coarser angle everywhere
    // rather than stop half way (which would leave cracks).
    WarpTolerance coarser = tolerance;
    coarser.maxAngle = tolerance.maxAngle * 2.0;
    if (coarser.maxAngle > 3.2)
        return mesh;
    return subdivideForWarp(mesh, world, coarser, maxTriangles);
}

MeshHandle WarpMeshes::get(const MeshHandle& mesh, const glm::dmat4& world, const WarpTolerance& tolerance,
                           gl::Detail detail) {
    if (!mesh)
        return mesh;
    const std::vector<std::uint32_t>* coarseIndices =
        detail == gl::Detail::Coarse ? mesh->coarse.indices() : nullptr;
    const bool coarse = coarseIndices != nullptr;
    const std::uint64_t key = entryKey(mesh.get(), world, tolerance) ^ (coarse ? 0x9e3779b97f4a7c15ull : 0);
    auto it = m_entries.find(key);
    if (it != m_entries.end() && it->second.owner.lock() == mesh && it->second.world == world &&
        it->second.tolerance.centre == tolerance.centre &&
        it->second.tolerance.maxAngle == tolerance.maxAngle &&
        it->second.tolerance.minLength == tolerance.minLength) {
        it->second.generation = m_generation;
        return it->second.fine ? it->second.fine : mesh;
    }
    MeshHandle handle;
    if (coarse) {
        // The simplified level is split: its copy holds the level's triangles as its whole list, so the
        // split mesh draws them whatever detail the view asks for.
        MeshData level;
        level.positions = mesh->positions;
        level.normals = mesh->normals;
        level.uvs = mesh->uvs;
        level.colors = mesh->colors;
        level.tangents = mesh->tangents;
        level.indices = *coarseIndices;
        handle = std::make_shared<const MeshData>(subdivideForWarp(level, world, tolerance));
    } else if (MeshData fine = subdivideForWarp(*mesh, world, tolerance);
               fine.triangleCount() != mesh->triangleCount()) {
        handle = std::make_shared<const MeshData>(std::move(fine));
    }
    // A copy that is the mesh itself must not keep it alive: hold it weakly through the owner only.
    m_entries[key] = {mesh, handle, world, tolerance, m_generation};
    return handle ? handle : mesh;
}

void WarpMeshes::purge() {
    std::erase_if(m_entries, [this](const auto& kv) {
        return kv.second.owner.expired() || kv.second.generation != m_generation;
    });
}

} // namespace speculum::render::passes
