#include "render/reference/SceneGeometry.hpp"

#include "render/mesh/Primitives.hpp"

#include <algorithm>
#include <cmath>
#include <embree3/rtcore.h>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

namespace speculum::render::reference {

struct SceneGeometry::Embree {
    RTCDevice device = nullptr;
    RTCScene all = nullptr;
    RTCScene casters = nullptr;

    ~Embree() {
        if (casters)
            rtcReleaseScene(casters);
        if (all)
            rtcReleaseScene(all);
        if (device)
            rtcReleaseDevice(device);
    }
};

namespace {

bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Finite, and still finite once rounded to float for Embree.
bool usable(const glm::dvec3& v) {
    return finite(v) && std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}) < 1e30;
}

// The mesh under `world` (already camera-relative), keeping only triangles Embree can take safely.
Surface makeSurface(const MeshData& mesh, const glm::dmat4& world, SurfaceKind kind, int index,
                    bool castsShadows, std::size_t& dropped) {
    Surface s;
    s.kind = kind;
    s.index = index;
    s.castsShadows = castsShadows;
    const glm::dmat3 linear(world);
    s.flipped = glm::determinant(linear) < 0.0;
    glm::dmat3 normalMatrix = glm::inverseTranspose(linear);
    const bool normalsUsable = std::abs(glm::determinant(linear)) > 1e-300;
    s.positions.reserve(mesh.positions.size());
    for (const glm::vec3& p : mesh.positions)
        s.positions.push_back(glm::dvec3(world * glm::dvec4(glm::dvec3(p), 1.0)));
    if (mesh.normals.size() == mesh.positions.size() && normalsUsable) {
        s.normals.reserve(mesh.normals.size());
        for (const glm::vec3& n : mesh.normals)
            s.normals.push_back(normalMatrix * glm::dvec3(n));
    }
    if (mesh.uvs.size() == mesh.positions.size())
        s.uvs = mesh.uvs;
    if (mesh.colors.size() == mesh.positions.size())
        s.colors = mesh.colors;
    if (mesh.tangents.size() == mesh.positions.size()) {
        // A tangent is a direction in the surface: it transforms like a position (mesh.vert does the same),
        // and a mirroring transform turns the frame's handedness round.
        s.tangents.reserve(mesh.tangents.size());
        for (const glm::vec4& t : mesh.tangents)
            s.tangents.emplace_back(linear * glm::dvec3(t), s.flipped ? -double(t.w) : double(t.w));
    }
    const std::size_t count = mesh.positions.size();
    s.indices.reserve(mesh.indices.size());
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        if (a >= count || b >= count || c >= count || !usable(s.positions[a]) || !usable(s.positions[b]) ||
            !usable(s.positions[c])) {
            ++dropped;
            continue;
        }
        s.indices.insert(s.indices.end(), {a, b, c});
    }
    return s;
}

// Embree's filter for masked surfaces: a hit where the material is cut away does not count, so the ray
// goes on to whatever lies behind (camera, mirror, reflection and shadow rays alike).
void alphaFilter(const RTCFilterFunctionNArguments* args) {
    const auto* s = static_cast<const Surface*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1)
            continue;
        const double u = RTCHitN_u(args->hit, args->N, i);
        const double v = RTCHitN_v(args->hit, args->N, i);
        const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
        if (s->alpha(prim, u, v) < s->mask->cutoff)
            args->valid[i] = 0;
    }
}

unsigned attach(RTCDevice device, RTCScene scene, const Surface& s) {
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (s.mask) {
        rtcSetGeometryUserData(g, const_cast<Surface*>(&s));
        rtcSetGeometryIntersectFilterFunction(g, alphaFilter);
        rtcSetGeometryOccludedFilterFunction(g, alphaFilter);
    }
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), s.positions.size()));
    for (std::size_t i = 0; i < s.positions.size(); ++i) {
        // Vertices no triangle uses may be anything; Embree only needs the used ones finite.
        const glm::dvec3 p = usable(s.positions[i]) ? s.positions[i] : glm::dvec3(0.0);
        v[i * 3 + 0] = static_cast<float>(p.x);
        v[i * 3 + 1] = static_cast<float>(p.y);
        v[i * 3 + 2] = static_cast<float>(p.z);
    }
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(unsigned), s.indices.size() / 3));
    std::copy(s.indices.begin(), s.indices.end(), idx);
    rtcCommitGeometry(g);
    const unsigned id = rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
    return id;
}

// The ray's hit on triangle (a, b, c) in double (Möller–Trumbore): (t, u, v) with the barycentrics of b
// and c, whether or not they lie inside; nothing when the ray is parallel to the plane.
std::optional<glm::dvec3> exactHit(const glm::dvec3& origin, const glm::dvec3& direction, const glm::dvec3& a,
                                   const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 e1 = b - a, e2 = c - a;
    const glm::dvec3 p = glm::cross(direction, e2);
    const double det = glm::dot(e1, p);
    if (!(std::abs(det) > 0.0) || !std::isfinite(det))
        return std::nullopt;
    const double inv = 1.0 / det;
    const glm::dvec3 s = origin - a;
    const glm::dvec3 q = glm::cross(s, e1);
    const glm::dvec3 tuv(glm::dot(e2, q) * inv, glm::dot(s, p) * inv, glm::dot(direction, q) * inv);
    if (!finite(tuv))
        return std::nullopt;
    return tuv;
}

std::string deviceError(RTCDevice device) {
    switch (rtcGetDeviceError(device)) {
    case RTC_ERROR_NONE:
        return {};
    case RTC_ERROR_OUT_OF_MEMORY:
        return "Embree ran out of memory building the scene";
    case RTC_ERROR_UNSUPPORTED_CPU:
        return "Embree does not support this CPU";
    default:
        return "Embree failed to build the scene";
    }
}

} // namespace

SceneGeometry::~SceneGeometry() = default;

double Surface::alpha(std::size_t triangle, double u, double v) const {
    if (!mask)
        return 1.0;
    const std::size_t t = triangle * 3;
    if (t + 2 >= indices.size())
        return 1.0;
    u = std::clamp(u, 0.0, 1.0);
    v = std::clamp(v, 0.0, 1.0 - u);
    const double w = 1.0 - u - v;
    const std::uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
    double alpha = mask->opacity;
    if (mask->texture) {
        const glm::dvec2 uv = uvs.empty()
                                  ? glm::dvec2(0.0)
                                  : w * glm::dvec2(uvs[a]) + u * glm::dvec2(uvs[b]) + v * glm::dvec2(uvs[c]);
        alpha *= mask->texture->sample(uv, mask->wrapS, mask->wrapT).a;
    }
    if (!colors.empty())
        alpha *= w * double(colors[a].a) + u * double(colors[b].a) + v * double(colors[c].a);
    return alpha;
}

double SceneGeometry::offset(const glm::dvec3& p) {
    const double extent = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), 1.0});
    return 2e-5 * extent;
}

base::Result<std::unique_ptr<SceneGeometry>>
SceneGeometry::build(const FrameInput& input, const glm::dvec3& origin, std::vector<std::string>& warnings,
                     const TextureSet* textures, const std::vector<MaterialTextures>* itemTextures) {
    std::unique_ptr<SceneGeometry> geometry(new SceneGeometry);
    const glm::dmat4 toRelative = glm::translate(glm::dmat4(1.0), -origin);
    std::size_t dropped = 0;
    for (std::size_t i = 0; i < input.items.size(); ++i) {
        const DrawItem& item = input.items[i];
        if (!item.mesh)
            continue;
        geometry->m_surfaces.push_back(makeSurface(*item.mesh, toRelative * item.world, SurfaceKind::Object,
                                                   static_cast<int>(i), item.castsShadows, dropped));
        const Material& m = item.material;
        if (m.alphaMode != AlphaMode::Opaque) {
            Surface::AlphaMask mask;
            mask.opacity = m.opacity;
            // Blend is drawn as Mask at one half (passes::alphaCutoff).
            mask.cutoff = m.alphaMode == AlphaMode::Blend ? 0.5 : m.alphaCutoff;
            const int base =
                textures && itemTextures && i < itemTextures->size() ? (*itemTextures)[i].base : -1;
            mask.texture = base >= 0 ? &(*textures)[base] : nullptr;
            mask.wrapS = m.wrap[0];
            mask.wrapT = m.wrap[1];
            geometry->m_surfaces.back().mask = mask;
        }
    }
    // Mirrors are the renderer's unit plane scaled to their size: the same triangles, normals and uvs.
    const MeshData plane = makePlane(1);
    for (std::size_t i = 0; i < input.mirrors.size(); ++i) {
        const Mirror& m = input.mirrors[i];
        const glm::dmat4 rectangle =
            m.world * glm::scale(glm::dmat4(1.0), glm::dvec3(m.size.x * 0.5, 1.0, m.size.y * 0.5));
        geometry->m_surfaces.push_back(makeSurface(plane, toRelative * rectangle, SurfaceKind::Mirror,
                                                   static_cast<int>(i), false, dropped));
    }
    for (std::size_t i = 0; i < input.reflectors.size(); ++i) {
        const Reflector& reflector = input.reflectors[i];
        if (reflector.mesh)
            geometry->m_surfaces.push_back(makeSurface(*reflector.mesh, toRelative * reflector.world,
                                                       SurfaceKind::Reflector, static_cast<int>(i), true,
                                                       dropped));
    }
    if (dropped > 0)
        warnings.push_back("reference: " + std::to_string(dropped) +
                           " invalid triangles (indices out of range or non-finite positions) were left out");

    auto embree = std::make_unique<Embree>();
    embree->device = rtcNewDevice(nullptr);
    if (!embree->device)
        return base::Error{"cannot start Embree: " + deviceError(nullptr)};
    embree->all = rtcNewScene(embree->device);
    embree->casters = rtcNewScene(embree->device);
    for (RTCScene scene : {embree->all, embree->casters}) {
        rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
        rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
    }
    const bool exactMirrors = input.mirrors.size() <= kExactMirrors;
    for (std::size_t i = 0; i < geometry->m_surfaces.size(); ++i) {
        const Surface& s = geometry->m_surfaces[i];
        if (s.indices.empty())
            continue;
        if (exactMirrors && s.kind == SurfaceKind::Mirror) { // casts no shadow either
            geometry->m_exactSurface.push_back(static_cast<int>(i));
            continue;
        }
        // Each scene numbers its geometries from 0 in attach order.
        attach(embree->device, embree->all, s);
        geometry->m_allSurface.push_back(static_cast<int>(i));
        if (s.castsShadows) {
            attach(embree->device, embree->casters, s);
            geometry->m_shadowSurface.push_back(static_cast<int>(i));
        }
    }
    rtcCommitScene(embree->all);
    rtcCommitScene(embree->casters);
    if (const std::string error = deviceError(embree->device); !error.empty())
        return base::Error{error};
    geometry->m_embree = std::move(embree);
    return geometry;
}

std::optional<Hit> SceneGeometry::intersect(const glm::dvec3& origin, const glm::dvec3& direction,
                                            double tnear, double tfar) const {
    if (!finite(origin) || !finite(direction) || !(tfar > tnear))
        return std::nullopt;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh{};
    rh.ray.org_x = static_cast<float>(origin.x);
    rh.ray.org_y = static_cast<float>(origin.y);
    rh.ray.org_z = static_cast<float>(origin.z);
    rh.ray.dir_x = static_cast<float>(direction.x);
    rh.ray.dir_y = static_cast<float>(direction.y);
    rh.ray.dir_z = static_cast<float>(direction.z);
    rh.ray.tnear = static_cast<float>(std::max(tnear, 0.0));
    rh.ray.tfar = std::isfinite(tfar) ? static_cast<float>(tfar) : std::numeric_limits<float>::infinity();
    rh.ray.mask = 0xFFFFFFFFu;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    if (!m_allSurface.empty())
        rtcIntersect1(m_embree->all, &context, &rh);
    const Surface* best = nullptr;
    std::size_t bestTriangle = 0;
    double bestT = tfar, bestU = 0.0, bestV = 0.0;
    if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID && rh.hit.geomID < m_allSurface.size()) {
        const Surface& s = m_surfaces[static_cast<std::size_t>(m_allSurface[rh.hit.geomID])];
        const std::size_t tri = static_cast<std::size_t>(rh.hit.primID) * 3;
        if (tri + 2 < s.indices.size()) {
            best = &s;
            bestTriangle = rh.hit.primID;
            bestT = rh.ray.tfar;
            bestU = rh.hit.u;
            bestV = rh.hit.v;
            // Embree's t, u, v come from float arithmetic on a float copy: the barycentrics of a triangle
            // 1e9 wide are 1e-7 · 1e9 = 100 m off. Recomputed in double on the exact triangle.
            const auto exact = exactHit(origin, direction, s.positions[s.indices[tri]],
                                        s.positions[s.indices[tri + 1]], s.positions[s.indices[tri + 2]]);
            if (exact && (*exact)[0] >= 0.0) {
                bestT = (*exact)[0];
                bestU = (*exact)[1];
                bestV = (*exact)[2];
            }
        }
    }
    // Mirrors, exactly, in front of whatever Embree found.
    const double from = std::max(tnear, 0.0);
    for (const int index : m_exactSurface) {
        const Surface& s = m_surfaces[static_cast<std::size_t>(index)];
        for (std::size_t tri = 0; tri + 2 < s.indices.size(); tri += 3) {
            const auto exact = exactHit(origin, direction, s.positions[s.indices[tri]],
                                        s.positions[s.indices[tri + 1]], s.positions[s.indices[tri + 2]]);
            if (!exact)
                continue;
            const double t = (*exact)[0], u = (*exact)[1], v = (*exact)[2];
            // A hair of tolerance so no ray slips between the rectangle's two triangles.
            constexpr double kEdge = 1e-12;
            if (t >= from && t <= bestT && u >= -kEdge && v >= -kEdge && u + v <= 1.0 + kEdge) {
                best = &s;
                bestTriangle = tri / 3;
                bestT = t;
                bestU = u;
                bestV = v;
            }
        }
    }
    if (!best)
        return std::nullopt;
    return makeHit(*best, bestTriangle, bestU, bestV, bestT, direction);
}

Hit SceneGeometry::makeHit(const Surface& s, std::size_t triangle, double uIn, double vIn, double t,
                           const glm::dvec3& direction) const {
    const std::size_t tri = triangle * 3;
    const std::uint32_t a = s.indices[tri], b = s.indices[tri + 1], c = s.indices[tri + 2];
    const double u = std::clamp(uIn, 0.0, 1.0);
    const double v = std::clamp(vIn, 0.0, 1.0 - u);
    const double w = 1.0 - u - v;

    Hit hit;
    hit.surface = &s;
    hit.t = t;
    // Interpolated in double on the exact triangle: lies on the surface, not a float step off it.
    hit.position = w * s.positions[a] + u * s.positions[b] + v * s.positions[c];
    const double dirLength = glm::length(direction);
    const glm::dvec3 unitDir = direction / dirLength;

    glm::dvec3 outward = glm::cross(s.positions[b] - s.positions[a], s.positions[c] - s.positions[a]);
    if (s.flipped)
        outward = -outward;
    const double outwardLength = glm::length(outward);
    // A degenerate (or float-degenerate) triangle has no plane: face the viewer.
    outward = outwardLength > 0.0 && std::isfinite(outwardLength) ? outward / outwardLength : -unitDir;
    hit.outwardNormal = outward;
    hit.frontFacing = glm::dot(outward, unitDir) <= 0.0;
    hit.geometricNormal = hit.frontFacing ? outward : -outward;

    glm::dvec3 n(0.0);
    if (!s.normals.empty())
        n = w * s.normals[a] + u * s.normals[b] + v * s.normals[c];
    const double nLength = glm::length(n);
    n = nLength > 1e-12 && std::isfinite(nLength) ? n / nLength : outward;
    // Two-sided like mesh.frag: the back of a face is lit with the normal turned round.
    hit.normal = hit.frontFacing ? n : -n;

    if (!s.uvs.empty())
        hit.uv = w * glm::dvec2(s.uvs[a]) + u * glm::dvec2(s.uvs[b]) + v * glm::dvec2(s.uvs[c]);
    if (!s.colors.empty())
        hit.color = w * glm::dvec4(s.colors[a]) + u * glm::dvec4(s.colors[b]) + v * glm::dvec4(s.colors[c]);
    if (!s.tangents.empty()) {
        hit.tangent = w * s.tangents[a] + u * s.tangents[b] + v * s.tangents[c];
        hit.tangent.w = hit.tangent.w < 0.0 ? -1.0 : 1.0; // as mesh.frag reads the interpolated sign
    }
    return hit;
}

bool SceneGeometry::occluded(const glm::dvec3& origin, const glm::dvec3& direction, double tnear,
                             double tfar) const {
    if (m_shadowSurface.empty() || !finite(origin) || !finite(direction) || !(tfar > tnear))
        return false;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray{};
    ray.org_x = static_cast<float>(origin.x);
    ray.org_y = static_cast<float>(origin.y);
    ray.org_z = static_cast<float>(origin.z);
    ray.dir_x = static_cast<float>(direction.x);
    ray.dir_y = static_cast<float>(direction.y);
    ray.dir_z = static_cast<float>(direction.z);
    ray.tnear = static_cast<float>(std::max(tnear, 0.0));
    ray.tfar = std::isfinite(tfar) ? static_cast<float>(tfar) : std::numeric_limits<float>::infinity();
    ray.mask = 0xFFFFFFFFu;
    ray.flags = 0;
    rtcOccluded1(m_embree->casters, &context, &ray);
    // Embree marks an occluded ray by setting tfar to -inf.
    return ray.tfar < 0.0f;
}

} // namespace speculum::render::reference
