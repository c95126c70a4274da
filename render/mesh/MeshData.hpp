#pragma once

#include <atomic>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace speculum::render {

struct Bounds {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
};

// The bounds of a mesh that will not change any more (see freezeMesh). A copy or move starts empty, so
// a mesh copied and then edited can never carry its original's bounds.
class KnownBounds {
public:
    KnownBounds() = default;
    KnownBounds(const KnownBounds&) {}
    KnownBounds& operator=(const KnownBounds&) {
        m_set = false;
        return *this;
    }
    void set(const Bounds& bounds) {
        m_bounds = bounds;
        m_set = true;
    }
    const Bounds* get() const { return m_set ? &m_bounds : nullptr; }

private:
    Bounds m_bounds;
    bool m_set = false;
};

// A simplified triangle list over a mesh's own vertices.
struct CoarseLevel {
    std::vector<std::uint32_t> indices; // three per triangle; empty: the mesh is drawn whole
    float error = 0.0f; // the largest deviation the simplification allowed, as a share of the mesh's size

    std::size_t triangleCount() const { return indices.size() / 3; }
};

// Where a mesh keeps its simplified level. Building one costs seconds for a multi-million-triangle mesh,
// so it is built only when a reflected view first needs it (coarseLevel() in Simplify.hpp), once, by
// whichever thread asks first, while other threads read ready() without waiting. Like KnownBounds, a
// copy starts without one (a mesh copied and then edited must not draw its original's triangles); a move
// keeps it.
class CoarseLevelSlot {
public:
    CoarseLevelSlot() = default;
    CoarseLevelSlot(const CoarseLevelSlot&) {}
    CoarseLevelSlot& operator=(const CoarseLevelSlot&) {
        m_level = {};
        m_built.store(false, std::memory_order_release);
        return *this;
    }
    CoarseLevelSlot(CoarseLevelSlot&& other) noexcept
        : m_level(std::move(other.m_level))
        , m_built(other.m_built.load(std::memory_order_acquire)) {}
    CoarseLevelSlot& operator=(CoarseLevelSlot&& other) noexcept {
        m_level = std::move(other.m_level);
        m_built.store(other.m_built.load(std::memory_order_acquire), std::memory_order_release);
        return *this;
    }

    // The level once built (its indices empty where simplifying gained too little); null before.
    const CoarseLevel* ready() const { return m_built.load(std::memory_order_acquire) ? &m_level : nullptr; }
    // The built level's indices, or none: what a draw of the simplified level uses.
    const std::vector<std::uint32_t>* indices() const {
        const CoarseLevel* level = ready();
        return level && !level->indices.empty() ? &level->indices : nullptr;
    }
    // Builds the level with `build` unless it is built already; threads asking meanwhile wait for it.
    template <typename Build>
    const CoarseLevel& ensure(Build&& build) const {
        if (const CoarseLevel* level = ready())
            return *level;
        const std::lock_guard lock(m_building);
        if (!m_built.load(std::memory_order_acquire)) {
            m_level = build();
            m_built.store(true, std::memory_order_release);
        }
        return m_level;
    }
    // A level known before the mesh is shared (a mesh that must not be simplified: an empty one).
    void set(CoarseLevel level) {
        m_level = std::move(level);
        m_built.store(true, std::memory_order_release);
    }

private:
    mutable std::mutex m_building;
    mutable CoarseLevel m_level;
    mutable std::atomic<bool> m_built{false};
};

// CPU-side triangle mesh: what the GL layer uploads and the reference tracer intersects.
// Counter-clockwise triangles seen from outside; normals unit length. uvs, colors and tangents are
// optional: each is empty or holds one entry per vertex.
struct MeshData {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
    // Linear RGBA vertex colours (glTF COLOR_0, OBJ/PLY/Collada colours); they multiply the material's
    // base colour. Empty: white.
    std::vector<glm::vec4> colors;
    // Tangent-space basis for normal maps: xyz the unit tangent (direction of increasing u), w = ±1 the
    // handedness, bitangent = w · cross(normal, tangent). Empty: the mesh cannot take a normal map.
    std::vector<glm::vec4> tangents;
    std::vector<std::uint32_t> indices; // three per triangle
    KnownBounds knownBounds;            // set by freezeMesh: computeBounds() then costs nothing
    // A simplified level over the same vertices, for the reflected views of a big mesh (coarseLevel() in
    // Simplify.hpp builds it when one first needs it).
    CoarseLevelSlot coarse;

    std::size_t vertexCount() const { return positions.size(); }
    std::size_t triangleCount() const { return indices.size() / 3; }
};

// Meshes are shared and immutable once built: the pointer is their identity for GPU caches.
using MeshHandle = std::shared_ptr<const MeshData>;

// Of the finite positions; a frozen mesh answers from its known bounds (the planner, shadow frusta and
// culling ask every frame, and a multi-million-vertex scan each time would cost milliseconds).
Bounds computeBounds(const MeshData& mesh);

// The shared, immutable handle of a finished mesh, with its bounds computed once. Its simplified level,
// for a big mesh, is built later, when a reflected view first needs it.
MeshHandle freezeMesh(MeshData&& mesh);

// Whether the mesh is a closed, consistently and outward wound surface: every edge, by the positions of
// its end points (vertices duplicated for normals or uvs count as one), is run once in each direction by
// exactly two triangles, and its triangles enclose a positive volume. Seen from outside, such a mesh never
// shows a back face. A mesh of more than kMaxClosureCheckIndices indices counts as open: the check's edge
// table would cost hundreds of megabytes (open is the safe way to be wrong).
inline constexpr std::size_t kMaxClosureCheckIndices = 3 * 1'000'000;
bool isClosed(const MeshData& mesh);

} // namespace speculum::render
