#include "scene/evaluate/Picking.hpp"

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/trigonometric.hpp>
#include <limits>
#include <mutex>
#include <thread>
#include <unordered_map>

namespace speculum::scene {

namespace {

constexpr double kNone = std::numeric_limits<double>::infinity();

// Möller–Trumbore, both sides (a click on the inside of an open mesh still selects it).
double intersectTriangle(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& a, const glm::dvec3& b,
                         const glm::dvec3& c) {
    const glm::dvec3 e1 = b - a, e2 = c - a;
    const glm::dvec3 p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-300) {
        return kNone;
    }
    const double inv = 1.0 / det;
    const glm::dvec3 s = o - a;
    const double u = glm::dot(s, p) * inv;
    if (u < 0.0 || u > 1.0) {
        return kNone;
    }
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(d, q) * inv;
    if (v < 0.0 || u + v > 1.0) {
        return kNone;
    }
    return glm::dot(e2, q) * inv;
}

struct MirrorHit {
    double t = kNone;
    bool front = false;
};

MirrorHit intersectMirror(const PickMirror& mirror, const Ray& ray) {
    const glm::dmat4 inv = glm::inverse(mirror.world);
    const glm::dvec3 o = glm::dvec3(inv * glm::dvec4(ray.origin, 1.0));
    const glm::dvec3 d = glm::dvec3(inv * glm::dvec4(ray.direction, 0.0));
    if (std::abs(d.y) < 1e-300) {
        return {};
    }
    const double t = -o.y / d.y;
    if (!(t > 0.0)) {
        return {};
    }
    const glm::dvec3 p = o + d * t;
    if (std::abs(p.x) > mirror.size.x * 0.5 || std::abs(p.z) > mirror.size.y * 0.5) {
        return {};
    }
    return {t, o.y > 0.0};
}

} // namespace

// ---- the hierarchy ----

namespace {

constexpr std::uint32_t kLeafSize = 4;
constexpr int kBins = 16;

struct Box3 {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{-std::numeric_limits<float>::max()};
    void add(const glm::vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void add(const Box3& b) {
        min = glm::min(min, b.min);
        max = glm::max(max, b.max);
    }
    bool empty() const { return min.x > max.x; }
    float area() const {
        if (empty()) {
            return 0.0f;
        }
        const glm::vec3 e = max - min;
        return e.x * e.y + e.y * e.z + e.z * e.x;
    }
};

// Entry parameter of the ray into [lo, hi] within [0, tMax], or infinity. invDir has no zeros (see below),
// so no 0·∞ appears.
double slab(const glm::dvec3& o, const glm::dvec3& invDir, const glm::vec3& lo, const glm::vec3& hi,
            double tMax) {
    double t0 = 0.0, t1 = tMax;
    for (int i = 0; i < 3; ++i) {
        double a = (double(lo[i]) - o[i]) * invDir[i], b = (double(hi[i]) - o[i]) * invDir[i];
        if (a > b) {
            std::swap(a, b);
        }
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
        if (t0 > t1) {
            return kNone;
        }
    }
    return t0;
}

// The triangles a ray can hit (every index in range, every corner finite), with the bounding box and
// its centre of each, in triangle order.
struct HittableTriangles {
    std::vector<std::uint32_t> numbers; // triangle numbers in the mesh
    std::vector<Box3> boxes;
    std::vector<glm::vec3> centroids;
};

HittableTriangles hittableTriangles(const render::MeshData& mesh) {
    const std::size_t triangles = mesh.indices.size() / 3;
    const std::size_t vertices = mesh.positions.size();
    HittableTriangles out;
    out.boxes.reserve(triangles);
    out.centroids.reserve(triangles);
    out.numbers.reserve(triangles);
    for (std::size_t t = 0; t < triangles; ++t) {
        Box3 box;
        bool valid = true;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = mesh.indices[3 * t + k];
            if (v >= vertices || !std::isfinite(mesh.positions[v].x) || !std::isfinite(mesh.positions[v].y) ||
                !std::isfinite(mesh.positions[v].z)) {
                valid = false;
                break;
            }
            box.add(mesh.positions[v]);
        }
        if (!valid) {
            continue;
        }
        out.numbers.push_back(std::uint32_t(t));
        out.boxes.push_back(box);
        out.centroids.push_back((box.min + box.max) * 0.5f);
    }
    return out;
}

// Which of kBins equal slices of the centroids' extent along `axis` a centroid falls in.
struct CentroidBins {
    int axis = 0;
    float min = 0.0f;
    float scale = 0.0f;
    int of(const glm::vec3& centroid) const {
        return std::min(kBins - 1, int((centroid[axis] - min) * scale));
    }
};

// The bin boundary b (1..kBins-1: bins below b go left) of least surface-area cost, or -1 where every
// triangle falls on one side.
int bestBinSplit(const Box3 (&binBox)[kBins], const std::uint32_t (&binCount)[kBins]) {
    float rightArea[kBins];
    std::uint32_t rightCount[kBins];
    Box3 acc;
    std::uint32_t n = 0;
    for (int b = kBins - 1; b > 0; --b) {
        acc.add(binBox[b]);
        n += binCount[b];
        rightArea[b] = acc.area();
        rightCount[b] = n;
    }
    float bestCost = std::numeric_limits<float>::max();
    int bestSplit = -1;
    acc = Box3{};
    n = 0;
    for (int b = 1; b < kBins; ++b) {
        acc.add(binBox[b - 1]);
        n += binCount[b - 1];
        if (n == 0 || rightCount[b] == 0) {
            continue;
        }
        const float cost = acc.area() * float(n) + rightArea[b] * float(rightCount[b]);
        if (cost < bestCost) {
            bestCost = cost;
            bestSplit = b;
        }
    }
    return bestSplit;
}

// Binned surface area heuristic along the widest axis of the centroids: partitions order[begin, end) and
// returns where its right part starts, or `begin` where it found no split (every centroid in one place).
std::uint32_t splitBySurfaceArea(const HittableTriangles& tris, const Box3& centres,
                                 std::vector<std::uint32_t>& order, std::uint32_t begin, std::uint32_t end) {
    const glm::vec3 extent = centres.max - centres.min;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    if (!(extent[axis] > 0.0f)) {
        return begin;
    }
    const CentroidBins bins{axis, centres.min[axis], float(kBins) / extent[axis] * 0.99999f};
    Box3 binBox[kBins];
    std::uint32_t binCount[kBins] = {};
    for (std::uint32_t i = begin; i < end; ++i) {
        const int b = bins.of(tris.centroids[order[i]]);
        binBox[b].add(tris.boxes[order[i]]);
        ++binCount[b];
    }
    const int bestSplit = bestBinSplit(binBox, binCount);
    if (bestSplit <= 0) {
        return begin;
    }
    return std::uint32_t(
        std::partition(order.begin() + begin, order.begin() + end,
                       [&](std::uint32_t i) { return bins.of(tris.centroids[i]) < bestSplit; }) -
        order.begin());
}

} // namespace

MeshPickAccel::MeshPickAccel(const render::MeshData& mesh) {
    // Triangles with an index out of range or a non-finite corner cannot be hit; leave them out.
    HittableTriangles tris = hittableTriangles(mesh);
    m_triangles = std::move(tris.numbers);
    // `tris.boxes` and `tris.centroids` are indexed by position in m_triangles before sorting; keep a
    // permutation.
    std::vector<std::uint32_t> order(m_triangles.size());
    for (std::uint32_t i = 0; i < order.size(); ++i) {
        order[i] = i;
    }
    if (order.empty()) {
        return;
    }
    m_nodes.reserve(2 * order.size() / kLeafSize + 1);
    m_nodes.push_back(BvhNode{});
    struct Task {
        std::uint32_t node, begin, end;
    };
    std::vector<Task> stack{{0, 0, std::uint32_t(order.size())}};
    while (!stack.empty()) {
        const Task task = stack.back();
        stack.pop_back();
        Box3 bounds, centres;
        for (std::uint32_t i = task.begin; i < task.end; ++i) {
            bounds.add(tris.boxes[order[i]]);
            centres.add(tris.centroids[order[i]]);
        }
        // A hair of padding: the double-precision triangle test may land a rounding error outside the box.
        const glm::vec3 pad = (glm::abs(bounds.min) + glm::abs(bounds.max) + glm::vec3(1e-3f)) * 1e-6f;
        m_nodes[task.node].min = bounds.min - pad;
        m_nodes[task.node].max = bounds.max + pad;
        const std::uint32_t count = task.end - task.begin;
        if (count <= kLeafSize) {
            m_nodes[task.node].first = task.begin;
            m_nodes[task.node].count = count;
            continue;
        }
        std::uint32_t middle = splitBySurfaceArea(tris, centres, order, task.begin, task.end);
        if (middle == task.begin || middle == task.end) {
            // Every centroid in one place (or one bin): halves by index still bound the work per ray.
            middle = task.begin + count / 2;
        }
        const std::uint32_t left = std::uint32_t(m_nodes.size());
        m_nodes.push_back(BvhNode{});
        m_nodes.push_back(BvhNode{});
        m_nodes[task.node].first = left;
        m_nodes[task.node].count = 0;
        stack.push_back({left + 1, middle, task.end});
        stack.push_back({left, task.begin, middle});
    }
    // Leaves index triangles through `order`; store the triangle numbers in leaf order directly.
    std::vector<std::uint32_t> sorted(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
        sorted[i] = m_triangles[order[i]];
    }
    m_triangles = std::move(sorted);
    m_bounds = render::Bounds{m_nodes[0].min, m_nodes[0].max};
}

std::optional<double> MeshPickAccel::intersect(const render::MeshData& mesh, const glm::dvec3& o,
                                               const glm::dvec3& d, double tMin) const {
    if (m_nodes.empty()) {
        return std::nullopt;
    }
    glm::dvec3 invDir;
    for (int i = 0; i < 3; ++i) {
        // A huge finite factor instead of 1/0: an axis-parallel ray then never produces 0·∞ = NaN.
        invDir[i] = std::abs(d[i]) > 1e-300 ? 1.0 / d[i] : std::copysign(1e300, d[i]);
    }
    double best = kNone;
    // A vector, not a fixed array: a lopsided hierarchy (very uneven triangle sizes) may be deep.
    std::vector<std::uint32_t> stack;
    stack.reserve(64);
    stack.push_back(0);
    while (!stack.empty()) {
        const BvhNode& node = m_nodes[stack.back()];
        stack.pop_back();
        if (slab(o, invDir, node.min, node.max, best) == kNone) {
            continue;
        }
        if (node.count > 0) {
            for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
                const std::size_t t = std::size_t(m_triangles[i]) * 3;
                const double hit = intersectTriangle(o, d, glm::dvec3(mesh.positions[mesh.indices[t]]),
                                                     glm::dvec3(mesh.positions[mesh.indices[t + 1]]),
                                                     glm::dvec3(mesh.positions[mesh.indices[t + 2]]));
                if (hit > tMin && hit < best) {
                    best = hit;
                }
            }
            continue;
        }
        // Nearer child last, so it is visited first and shrinks `best` for the other.
        const BvhNode& a = m_nodes[node.first];
        const BvhNode& b = m_nodes[node.first + 1];
        const double ta = slab(o, invDir, a.min, a.max, best), tb = slab(o, invDir, b.min, b.max, best);
        if (ta <= tb) {
            if (tb != kNone) {
                stack.push_back(node.first + 1);
            }
            if (ta != kNone) {
                stack.push_back(node.first);
            }
        } else {
            if (ta != kNone) {
                stack.push_back(node.first);
            }
            stack.push_back(node.first + 1);
        }
    }
    if (best == kNone) {
        return std::nullopt;
    }
    return best;
}

// ---- the per-mesh cache ----

namespace {

// Meshes this big get their hierarchy on a background thread when a click needs one: the click that
// finds none scans every triangle (~10 ms per million) instead of waiting for the build (~0.5 s per
// million), so no click is slower than before the hierarchy existed.
constexpr std::size_t kBackgroundBuildTriangles = 100000;

struct CacheEntry {
    std::weak_ptr<const render::MeshData> owner; // expired: the address may belong to another mesh now
    std::shared_ptr<const MeshPickAccel> accel;
    std::optional<render::Bounds> bounds;
    bool building = false; // a thread is building `accel`
};

struct PickCache {
    std::mutex mutex;
    std::condition_variable built;
    std::unordered_map<const render::MeshData*, CacheEntry> entries;
    std::size_t accelBuilds = 0;
    std::size_t boundsBuilds = 0;
    std::size_t pruneAt = 64;

    // The live entry of `mesh`, created if needed; the mutex is held.
    CacheEntry& entry(const render::MeshHandle& mesh) {
        auto it = entries.find(mesh.get());
        if (it != entries.end() && it->second.owner.expired() && !it->second.building) {
            entries.erase(it);
            it = entries.end();
        }
        if (it == entries.end()) {
            if (entries.size() >= pruneAt) {
                std::erase_if(entries,
                              [](const auto& e) { return e.second.owner.expired() && !e.second.building; });
                pruneAt = std::max<std::size_t>(64, entries.size() * 2);
            }
            it = entries.emplace(mesh.get(), CacheEntry{mesh, nullptr, std::nullopt, false}).first;
        }
        return it->second;
    }

    // Builds the hierarchy of `mesh` (whose entry is marked `building`) without the lock, then stores it.
    std::shared_ptr<const MeshPickAccel> build(const render::MeshHandle& mesh) {
        auto accel = std::make_shared<const MeshPickAccel>(*mesh);
        std::lock_guard lock(mutex);
        ++accelBuilds;
        CacheEntry& e = entry(mesh);
        e.accel = accel;
        e.building = false;
        if (!e.bounds) {
            e.bounds = render::computeBounds(*mesh);
            ++boundsBuilds;
        }
        built.notify_all();
        return accel;
    }
};

// Never destroyed: a background build may still be running when the process exits.
PickCache& pickCache() {
    static PickCache* cache = new PickCache;
    return *cache;
}

// The hierarchy if it is there; else, for a big mesh, null after starting a background build (or while
// one runs); a small one is built now.
std::shared_ptr<const MeshPickAccel> accelForClick(const render::MeshHandle& mesh) {
    PickCache& cache = pickCache();
    {
        std::lock_guard lock(cache.mutex);
        CacheEntry& e = cache.entry(mesh);
        if (e.accel) {
            return e.accel;
        }
        if (e.building) {
            return nullptr;
        }
        if (mesh->triangleCount() >= kBackgroundBuildTriangles) {
            e.building = true;
            std::thread([mesh] { pickCache().build(mesh); }).detach();
            return nullptr;
        }
    }
    return meshPickAccel(mesh);
}

// Every triangle tried, inside the mesh's (cached) bounds: a click on a big mesh whose hierarchy is not
// built yet.
std::optional<double> intersectEveryTriangle(const render::MeshHandle& mesh, const glm::dvec3& o,
                                             const glm::dvec3& d) {
    const render::Bounds b = meshBounds(mesh);
    glm::dvec3 invDir;
    for (int i = 0; i < 3; ++i) {
        invDir[i] = std::abs(d[i]) > 1e-300 ? 1.0 / d[i] : std::copysign(1e300, d[i]);
    }
    const glm::vec3 pad = (glm::abs(b.min) + glm::abs(b.max) + glm::vec3(1e-3f)) * 1e-6f;
    if (slab(o, invDir, b.min - pad, b.max + pad, kNone) == kNone) {
        return std::nullopt;
    }
    const render::MeshData& m = *mesh;
    double best = kNone;
    for (std::size_t i = 0; i + 2 < m.indices.size(); i += 3) {
        if (m.indices[i] >= m.positions.size() || m.indices[i + 1] >= m.positions.size() ||
            m.indices[i + 2] >= m.positions.size()) {
            continue;
        }
        const double t = intersectTriangle(o, d, glm::dvec3(m.positions[m.indices[i]]),
                                           glm::dvec3(m.positions[m.indices[i + 1]]),
                                           glm::dvec3(m.positions[m.indices[i + 2]]));
        if (t > 1e-9 && t < best) {
            best = t;
        }
    }
    if (best == kNone) {
        return std::nullopt;
    }
    return best;
}

} // namespace

std::shared_ptr<const MeshPickAccel> meshPickAccel(const render::MeshHandle& mesh) {
    PickCache& cache = pickCache();
    {
        std::unique_lock lock(cache.mutex);
        for (;;) {
            CacheEntry& e = cache.entry(mesh);
            if (e.accel) {
                return e.accel;
            }
            if (!e.building) {
                e.building = true;
                break;
            }
            cache.built.wait(lock); // someone else's build of this mesh: wait for it, do not build twice
        }
    }
    // Built without the lock: another mesh's build (the import worker's) must not wait on this one.
    return cache.build(mesh);
}

render::Bounds meshBounds(const render::MeshHandle& mesh) {
    PickCache& cache = pickCache();
    {
        std::lock_guard lock(cache.mutex);
        if (const CacheEntry& e = cache.entry(mesh); e.bounds) {
            return *e.bounds;
        }
    }
    const render::Bounds b = render::computeBounds(*mesh);
    std::lock_guard lock(cache.mutex);
    ++cache.boundsBuilds;
    cache.entry(mesh).bounds = b;
    return b;
}

PickCacheStats pickCacheStats() {
    PickCache& cache = pickCache();
    std::lock_guard lock(cache.mutex);
    return PickCacheStats{cache.accelBuilds, cache.boundsBuilds, cache.entries.size()};
}

std::optional<double> intersectMesh(const PickMesh& mesh, const Ray& ray) {
    if (!mesh.mesh || mesh.mesh->indices.empty()) {
        return std::nullopt;
    }
    // In the mesh's local space with an unnormalised direction, t is the same parameter as in world space.
    const glm::dmat4 inv = glm::inverse(mesh.world);
    const glm::dvec3 o = glm::dvec3(inv * glm::dvec4(ray.origin, 1.0));
    const glm::dvec3 d = glm::dvec3(inv * glm::dvec4(ray.direction, 0.0));
    if (auto accel = accelForClick(mesh.mesh)) {
        return accel->intersect(*mesh.mesh, o, d);
    }
    return intersectEveryTriangle(mesh.mesh, o, d);
}

std::optional<PickHit> pick(const PickScene& scene, const Ray& start) {
    Ray ray = start;
    double travelled = 0.0;
    std::uint64_t firstMirror = 0;
    std::uint64_t lastMirror = 0;
    bool bounced = false;
    std::optional<PickHit>
        mirrorItself; // what a click on the first mirror selects if the reflection is empty
    for (int reflections = 0;; ++reflections) {
        const double length = glm::length(ray.direction);
        if (!(length > 0.0) || !std::isfinite(length)) {
            return mirrorItself;
        }
        double best = kNone;
        std::uint64_t bestId = 0;
        for (const PickMesh& m : scene.meshes) {
            if (auto t = intersectMesh(m, ray); t && *t < best) {
                best = *t;
                bestId = m.id;
            }
        }
        const PickMirror* mirror = nullptr;
        MirrorHit mirrorHit;
        for (const PickMirror& m : scene.mirrors) {
            // The mirror just left cannot be hit again at t ≈ 0 (a ray from a plane leaves it).
            if (bounced && m.id == lastMirror) {
                continue;
            }
            const MirrorHit h = intersectMirror(m, ray);
            if (h.t < best && h.t < mirrorHit.t) {
                mirrorHit = h;
                mirror = &m;
            }
        }
        if (mirror) {
            best = mirrorHit.t;
        }
        if (best == kNone) {
            return mirrorItself;
        }
        const glm::dvec3 point = ray.origin + ray.direction * best;
        const double distance = travelled + best * length;
        if (!mirror) {
            return PickHit{bestId, point, distance, reflections, firstMirror};
        }
        PickHit onMirror{mirror->id, point, distance, reflections, firstMirror};
        if (!mirrorHit.front || reflections >= scene.mirrorDepth) {
            return onMirror; // a mirror seen in a mirror is a real object too
        }
        if (reflections == 0) {
            firstMirror = mirror->id;
            mirrorItself = onMirror;
        }
        // Reflect about the mirror's world plane (normal = inverse-transpose of the local +Y).
        const glm::dvec3 n = glm::normalize(
            glm::dvec3(glm::inverseTranspose(glm::dmat3(mirror->world)) * glm::dvec3(0.0, 1.0, 0.0)));
        ray.direction = glm::reflect(ray.direction, n);
        ray.origin = point;
        travelled = distance;
        lastMirror = mirror->id;
        bounced = true;
    }
}

Ray cameraRay(const render::Camera& camera, double aspect, double ndcX, double ndcY) {
    const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::dvec3 up = glm::cross(right, forward);
    const double h = std::tan(glm::radians(camera.fovY) * 0.5);
    return Ray{camera.position, forward + right * (ndcX * h * aspect) + up * (ndcY * h)};
}

} // namespace speculum::scene
