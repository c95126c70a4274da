#include "render/reference/Tracer.hpp"

#include "render/frame/SceneLimits.hpp"
#include "render/math/Mirror.hpp"
#include "render/math/Projection.hpp"
#include "render/plan/Planner.hpp"
#include "render/plan/StillSize.hpp"
#include "render/reference/GlossySampling.hpp"
#include "render/reference/SceneGeometry.hpp"
#include "render/reference/Shading.hpp"
#include "render/reference/TextureSampler.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <functional>
#include <glm/trigonometric.hpp>
#include <limits>
#include <mutex>
#include <thread>

namespace speculum::render::reference {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The largest value of the rasterizer's half-float colour buffer (shaders/radiance.glsl): each sample is
// clamped to ±65504 and NaN becomes 0, as the GPU stores it, so both renderers show an over-bright
// surface alike and neither writes a non-finite pixel.
constexpr double kMaxRadiance = 65504.0;

glm::dvec3 storableRadiance(const glm::dvec3& c) {
    glm::dvec3 out;
    for (int i = 0; i < 3; ++i)
        out[i] = std::isnan(c[i]) ? 0.0 : std::clamp(c[i], -kMaxRadiance, kMaxRadiance);
    return out;
}

// A result with every buffer allocated (black, ids empty) for a width × height render.
TraceResult blankResult(int width, int height) {
    TraceResult result;
    result.image.width = result.ids.width = width;
    result.image.height = result.ids.height = height;
    result.image.rgba.assign(static_cast<std::size_t>(width) * height * 4, 0.0f);
    result.noise.width = width;
    result.noise.height = height;
    result.noise.rgba.assign(static_cast<std::size_t>(width) * height * 4, 0.0f);
    result.ids.ids.assign(static_cast<std::size_t>(width) * height, PixelId{});
    return result;
}

// Calls traceRow(y) for every row 0..height-1 on `threads` threads, each taking the next row as it is
// free, and reports progress from this (the caller's) thread a few times a second. False when progress
// cancelled it: the rows not yet started are then never traced.
bool traceRowsInParallel(int height, int threads, const TraceProgress& progress,
                         const std::function<void(int y)>& traceRow) {
    std::atomic<int> nextRow{0};
    std::atomic<int> rowsDone{0};
    std::atomic<bool> cancelled{false};
    std::mutex mutex;
    std::condition_variable finished;
    auto work = [&] {
        for (int y = nextRow++; y < height && !cancelled; y = nextRow++) {
            traceRow(y);
            if (++rowsDone == height) {
                std::lock_guard lock(mutex);
                finished.notify_all();
            }
        }
    };
    std::vector<std::thread> workers;
    workers.reserve(static_cast<std::size_t>(threads));
    for (int t = 0; t < threads; ++t)
        workers.emplace_back(work);
    {
        std::unique_lock lock(mutex);
        while (rowsDone < height && !cancelled) {
            finished.wait_for(lock, std::chrono::milliseconds(100));
            if (progress && rowsDone < height && !progress(double(rowsDone) / height))
                cancelled = true;
        }
    }
    for (std::thread& t : workers)
        t.join();
    return !cancelled;
}

} // namespace

struct Tracer::Impl {
    FrameInput input;
    std::unique_ptr<SceneGeometry> geometry;
    TextureSet textures;
    std::vector<ShadingLight> lights;
    std::vector<MaterialTextures> itemTexture;   // textures per item
    std::vector<MaterialTextures> mirrorTexture; // per mirror: its material's textures
    std::vector<std::optional<math::Plane>> mirrorPlanes;
    std::vector<MaterialTextures> reflectorTexture; // per reflector: its material's textures
    int maxMirrorDepth = 0;
    std::vector<std::string> warnings;
    glm::dvec3 cameraPosition{0.0}; // the world point that is (0,0,0) in the tracer

    struct PixelTracer;

    // Everything one ray needs to know about the path that led to it.
    struct Path {
        int mirrorLevel = 0; // planar reflections so far (since the last reflector bounce)
        int mirrorLimit = 0; // planar reflections allowed: the scene's depth, or the reflector's in its map
        int reflectorLevel = 0;     // bounces off reflectors so far
        int lastReflector = -1;     // the reflector it last left (-1: none)
        double farLeft = kInfinity; // what is left of the camera's far plane (in units of the direction)
        // Rough reflections: the path's random numbers, the lobe samples taken so far (their counter), and
        // whether it took any (set through the pointer, so the caller learns whether the pixel is exact).
        PathSeed seed;
        int bounce = 0;
        bool* rough = nullptr;
        // Explaining a pixel: every vertex the path meets is appended here. Null in renders.
        TracedPath* record = nullptr;
    };

    // Appends what the ray origin + t·direction met to the path's record (if it keeps one); returns the
    // vertex's index, -1 without a record.
    int record(const Path& path, PathEventKind kind, PixelId id, const glm::dvec3& origin,
               const glm::dvec3& direction, const Hit* hit) const {
        if (!path.record)
            return -1;
        PathVertex v;
        v.kind = kind;
        v.hit = id;
        v.from = origin + cameraPosition;
        v.incoming = glm::normalize(direction);
        const double t = hit ? hit->t : 1e3 / glm::length(direction);
        v.position = origin + direction * t + cameraPosition;
        v.distance = glm::length(direction) * t;
        if (hit)
            v.normal = hit->normal;
        v.mirrorLevel = path.mirrorLevel;
        v.reflectorLevel = path.reflectorLevel;
        path.record->vertices.push_back(v);
        return int(path.record->vertices.size()) - 1;
    }
    static PathVertex* vertex(const Path& path, int v) {
        return v >= 0 ? &path.record->vertices[std::size_t(v)] : nullptr;
    }
    // The shading terms of vertex v, for Shader::shade to fill (null without a record).
    static ShadingTerms* termsOf(const Path& path, int v) {
        PathVertex* p = vertex(path, v);
        if (!p)
            return nullptr;
        p->shaded = true;
        return &p->shading;
    }
    static glm::dvec3 recorded(const Path& path, int v, const glm::dvec3& colour) {
        if (PathVertex* p = vertex(path, v))
            p->colour = colour;
        return colour;
    }
    // A reflecting vertex's weights: R (Schlick's with fresnel) and tint.
    static void recordWeights(const Path& path, int v, double r, bool fresnel, const glm::dvec3& tint) {
        if (PathVertex* p = vertex(path, v)) {
            p->reflectivity = r;
            p->fresnel = fresnel;
            p->tint = tint;
        }
    }
    // The reflection it followed: the mirror direction of `direction` about `normal`, the direction taken
    // (a lobe sample where rough) and the sample's weight.
    static void recordReflection(const Path& path, int v, double roughness, const glm::dvec3& direction,
                                 const glm::dvec3& normal, const glm::dvec3& followed, double weight) {
        PathVertex* p = vertex(path, v);
        if (!p)
            return;
        p->roughness = roughness > 0.0 ? roughness : 0.0;
        p->mirrored = glm::normalize(direction - 2.0 * glm::dot(direction, normal) * normal);
        p->outgoing = glm::normalize(followed);
        p->lobeWeight = weight;
        if (weight <= 0.0)
            p->kind = PathEventKind::LostBelow;
    }

    // The direction a reflection of `direction` about `normal` follows: the mirror direction for a
    // perfect mirror, a sample of the GGX lobe otherwise, with the sample's weight (0: nothing comes back).
    // `next` counts the bounce. The result keeps the length of `direction` (t stays in its units).
    static glm::dvec3 reflectedDirection(const glm::dvec3& direction, const glm::dvec3& normal,
                                         const glm::dvec3& viewDir, double roughness, const Path& path,
                                         Path& next, double& weight) {
        const glm::dvec3 mirrored = direction - 2.0 * glm::dot(direction, normal) * normal;
        weight = 1.0;
        if (!(roughness > 0.0))
            return mirrored;
        if (path.rough)
            *path.rough = true;
        next.bounce = path.bounce + 1;
        const auto bounce = static_cast<std::uint32_t>(path.bounce);
        const LobeSample lobe = sampleLobe(normal, viewDir, roughness, pathUniform(path.seed, bounce, 0),
                                           pathUniform(path.seed, bounce, 1));
        weight = lobe.weight;
        return lobe.direction * glm::length(direction);
    }

    // The colour seen along origin + t·direction, t ≥ tnear. `id`, if given, receives what was hit.
    glm::dvec3 radiance(const Shader& shader, const TraceSettings& settings, const glm::dvec3& origin,
                        const glm::dvec3& direction, double tnear, const Path& path, PixelId* id) const {
        const std::optional<Hit> hit = geometry->intersect(origin, direction, tnear, path.farLeft);
        if (!hit) {
            if (id)
                *id = {HitKind::Background, -1};
            const int v = record(path, PathEventKind::Background, {}, origin, direction, nullptr);
            return recorded(path, v, input.settings.background);
        }
        const glm::dvec3 viewDir = -glm::normalize(direction);
        const Surface& surface = *hit->surface;
        switch (surface.kind) {
        case SurfaceKind::Object: {
            if (id)
                *id = {HitKind::Object, surface.index};
            const DrawItem& item = input.items[static_cast<std::size_t>(surface.index)];
            const int v = record(path, PathEventKind::Surface, {HitKind::Object, surface.index}, origin,
                                 direction, &*hit);
            return recorded(path, v,
                            shader.shade(item.material, itemTexture[static_cast<std::size_t>(surface.index)],
                                         *hit, viewDir, termsOf(path, v)));
        }
        case SurfaceKind::Mirror: {
            const PixelId mirrorId{hit->frontFacing ? HitKind::Mirror : HitKind::MirrorBack, surface.index};
            if (id)
                *id = mirrorId;
            const int v = record(path, PathEventKind::Mirror, mirrorId, origin, direction, &*hit);
            return recorded(path, v, mirrorRadiance(shader, settings, direction, *hit, viewDir, path, v));
        }
        case SurfaceKind::Reflector: {
            if (id)
                *id = {HitKind::Reflector, surface.index};
            const int v = record(path, PathEventKind::Reflector, {HitKind::Reflector, surface.index}, origin,
                                 direction, &*hit);
            return recorded(path, v, reflectorRadiance(shader, settings, direction, *hit, viewDir, path, v));
        }
        }
        return input.settings.background;
    }

    // A planar mirror's colour where the ray met it: its material from behind (or when it has no plane);
    // in front, mirror.frag's surface·(1−R) + reflection·R·tint, Schlick's R with fresnel.
    glm::dvec3 mirrorRadiance(const Shader& shader, const TraceSettings& settings,
                              const glm::dvec3& direction, const Hit& hit, const glm::dvec3& viewDir,
                              const Path& path, int v) const {
        const std::size_t m = static_cast<std::size_t>(hit.surface->index);
        const Mirror& mirror = input.mirrors[m];
        const MaterialTextures& texture = mirrorTexture[m];
        if (!hit.frontFacing || !mirrorPlanes[m]) {
            if (PathVertex* p = vertex(path, v))
                p->kind = PathEventKind::Surface;
            return shader.shade(mirror.material, texture, hit, viewDir, termsOf(path, v));
        }
        const glm::dvec3 normal = mirrorPlanes[m]->normal;
        double r = std::clamp(mirror.reflectivity, 0.0, 1.0);
        if (mirror.fresnel) {
            const double c = std::clamp(glm::dot(normal, viewDir), 0.0, 1.0);
            r = r + (1.0 - r) * std::pow(1.0 - c, 5.0);
        }
        glm::dvec3 result(0.0);
        if (r < 1.0) {
            Hit surfaceHit = hit;
            surfaceHit.normal = normal;
            result += shader.shade(mirror.hasMaterial ? mirror.material : Material{},
                                   mirror.hasMaterial ? texture : MaterialTextures{}, surfaceHit, viewDir,
                                   termsOf(path, v)) *
                      (1.0 - r);
        }
        recordWeights(path, v, r, mirror.fresnel, mirror.tint);
        // Beyond the depth limit the reflection is not followed and adds nothing (as a path tracer's
        // bounce limit ends a path): the last mirror of a corridor is dark, not lit like a wall.
        if (path.mirrorLevel + 1 > path.mirrorLimit) {
            if (PathVertex* p = vertex(path, v))
                p->kind = PathEventKind::DepthLimit;
            return result;
        }
        Path next = path;
        next.mirrorLevel += 1;
        next.farLeft = path.farLeft - hit.t;
        double weight = 1.0;
        const glm::dvec3 reflected =
            reflectedDirection(direction, normal, viewDir, mirror.roughness, path, next, weight);
        recordReflection(path, v, mirror.roughness, direction, normal, reflected, weight);
        if (weight <= 0.0) // a lobe sample lost below the mirror
            return result;
        const double eps = SceneGeometry::offset(hit.position);
        const glm::dvec3 seen =
            radiance(shader, settings, hit.position + normal * eps, reflected, 0.0, next, nullptr);
        // A perfect mirror's weight is exactly 1, and 1·x = x: its pixels do not change by a bit.
        result += mirror.tint * r * (weight * seen);
        return result;
    }

    // A curved reflector's colour where the ray met it: reflector.frag's surface·(1−R) + environment·R,
    // Schlick's R with fresnel; its material alone beyond the reflector depth, and where the ray left it
    // last (TraceSettings::reflectorDepth).
    glm::dvec3 reflectorRadiance(const Shader& shader, const TraceSettings& settings,
                                 const glm::dvec3& direction, const Hit& hit, const glm::dvec3& viewDir,
                                 const Path& path, int v) const {
        const auto index = static_cast<std::size_t>(hit.surface->index);
        const Reflector& reflector = input.reflectors[index];
        const MaterialTextures& texture = reflectorTexture[index];
        if (path.reflectorLevel >= settings.reflectorDepth || path.lastReflector == hit.surface->index) {
            if (PathVertex* p = vertex(path, v))
                p->kind = PathEventKind::Surface;
            return shader.shade(reflector.material, texture, hit, viewDir, termsOf(path, v));
        }
        double r = std::clamp(reflector.reflectivity, 0.0, 1.0);
        if (reflector.fresnel) {
            const double c = std::clamp(glm::dot(hit.normal, viewDir), 0.0, 1.0);
            r = r + (1.0 - r) * std::pow(1.0 - c, 5.0);
        }
        glm::dvec3 result(0.0);
        if (r < 1.0)
            result += shader.shade(reflector.material, texture, hit, viewDir, termsOf(path, v)) * (1.0 - r);
        // Reflected about the interpolated normal (what an environment-map lookup uses too); the new ray
        // leaves from the side the viewer is on. An environment map has no far plane, and shows planar
        // mirrors to the reflector's own mirror depth.
        Path next = path;
        next.reflectorLevel += 1;
        next.lastReflector = hit.surface->index;
        next.farLeft = kInfinity;
        next.mirrorLevel = 0;
        next.mirrorLimit = std::clamp(reflector.mirrorDepth, 0, kStencilLevels);
        const glm::dvec3 d = glm::normalize(direction);
        double weight = 1.0;
        const glm::dvec3 reflected =
            reflectedDirection(d, hit.normal, viewDir, reflector.roughness, path, next, weight);
        recordWeights(path, v, r, reflector.fresnel, glm::dvec3(1.0));
        recordReflection(path, v, reflector.roughness, d, hit.normal, reflected, weight);
        if (weight <= 0.0) // a lobe sample lost below the (interpolated) surface
            return result;
        const glm::dvec3 side =
            glm::dot(reflected, hit.geometricNormal) >= 0.0 ? hit.geometricNormal : -hit.geometricNormal;
        const double eps = SceneGeometry::offset(hit.position);
        const glm::dvec3 seen =
            radiance(shader, settings, hit.position + side * eps, reflected, 0.0, next, nullptr);
        result += r * (weight * seen);
        return result;
    }
};

// One render's tracing of single pixels: the camera rays through them and the paths along those rays.
struct Tracer::Impl::PixelTracer {
    // One sub-sample: its first path, and only if that met a rough surface `paths` paths in all (the
    // first among them), averaged. The squared standard error of the average is the paths' sample
    // variance over their number (Welford's running sums, exact enough for nearly equal values); NaN
    // with a single path, which has no spread to measure.
    struct SubSample {
        glm::dvec3 value{0.0};
        glm::dvec3 error2{0.0};
        bool glossy = false;
    };
    // What one pixel shows: the average of its sub-samples, that average's variance, whether any of
    // them met a rough surface, and what its centre shows.
    struct Pixel {
        glm::dvec3 colour{0.0};
        glm::dvec3 variance{0.0};
        bool glossy = false;
        PixelId id;
    };

    const Impl& impl;
    const TraceSettings& settings;
    const int width, height;
    const int n;     // sub-samples per pixel along each axis
    const int paths; // paths per glossy sub-sample
    const Shader shader;
    const Camera& camera;
    // Camera rays in camera-relative world space. Directions have a view-depth component of exactly 1,
    // so a ray's t is the view depth and [near, far] clips like the projection does.
    const glm::dmat3 viewToWorld;
    const double tanHalf;
    const double aspect;
    Path primary;

    PixelTracer(const Impl& impl, const TraceSettings& settings)
        : impl(impl)
        , settings(settings)
        , width(settings.width)
        , height(settings.height)
        , n(std::clamp(settings.ssaa, kMinSsaa, kMaxSsaa))
        , paths(std::clamp(settings.samples, kMinTraceSamples, kMaxTraceSamples))
        , shader(impl.lights, *impl.geometry, impl.textures, impl.input.settings.ambient, settings.shadows)
        , camera(impl.input.camera)
        , viewToWorld(glm::transpose(glm::dmat3(math::viewRotation(camera))))
        , tanHalf(std::tan(glm::radians(camera.fovY) * 0.5))
        , aspect(double(width) / double(height)) {
        primary.farLeft = camera.far;
        primary.mirrorLimit = impl.maxMirrorDepth;
    }

    glm::dvec3 rayThrough(double px, double py) const {
        const double ndcX = 2.0 * px / width - 1.0;
        const double ndcY = 1.0 - 2.0 * py / height;
        return viewToWorld * glm::dvec3(ndcX * tanHalf * aspect, ndcY * tanHalf, -1.0);
    }

    // Path k of sub-sample s is path number k·n² + s: a render with 2N paths repeats one with N, and
    // adds N more.
    SubSample traceSubSample(int x, int y, std::uint32_t sub, const glm::dvec3& dir, PixelId* id) const {
        const auto subSamples = static_cast<std::uint32_t>(n * n);
        SubSample s;
        bool rough = false;
        Path path = primary;
        path.seed = {static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), sub};
        path.rough = &rough;
        s.value =
            storableRadiance(impl.radiance(shader, settings, glm::dvec3(0.0), dir, camera.near, path, id));
        if (!rough)
            return s;
        s.glossy = true;
        glm::dvec3 mean = s.value, m2(0.0);
        for (int k = 1; k < paths; ++k) {
            path.seed.path = std::uint32_t(k) * subSamples + sub;
            const glm::dvec3 c = storableRadiance(
                impl.radiance(shader, settings, glm::dvec3(0.0), dir, camera.near, path, nullptr));
            const glm::dvec3 delta = c - mean;
            mean += delta / double(k + 1);
            m2 += delta * (c - mean);
        }
        s.value = mean;
        s.error2 = paths > 1 ? m2 / (double(paths - 1) * paths) : glm::dvec3(std::nan(""));
        return s;
    }

    // Path k through pixel (x, y)'s centre, recorded vertex by vertex: path 0 is the pixel's first path
    // (without SSAA, exactly the one the still traced first), k > 0 the k-th further lobe sample.
    TracedPath recordPath(int x, int y, int k) const {
        TracedPath traced;
        bool rough = false;
        Path path = primary;
        path.seed = {static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y),
                     std::uint32_t(k) * static_cast<std::uint32_t>(n * n)};
        path.rough = &rough;
        path.record = &traced;
        traced.colour = storableRadiance(impl.radiance(
            shader, settings, glm::dvec3(0.0), rayThrough(x + 0.5, y + 0.5), camera.near, path, nullptr));
        return traced;
    }

    Pixel tracePixel(int x, int y) const {
        glm::dvec3 sum(0.0), error2(0.0);
        Pixel pixel;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                // The ordered grid of renderStill: sample (i, j) at ((i + ½)/N, (j + ½)/N) in the
                // pixel.
                const glm::dvec3 dir = rayThrough(x + (i + 0.5) / n, y + (j + 0.5) / n);
                const SubSample s =
                    traceSubSample(x, y, std::uint32_t(j * n + i), dir, n == 1 ? &pixel.id : nullptr);
                sum += s.value;
                error2 += s.error2;
                pixel.glossy = pixel.glossy || s.glossy;
            }
        if (n > 1) // what the pixel's centre shows
            impl.radiance(shader, settings, glm::dvec3(0.0), rayThrough(x + 0.5, y + 0.5), camera.near,
                          primary, &pixel.id);
        pixel.colour = sum / double(n * n);
        // The mean of n² independent sub-sample means: its variance is their sum over n⁴.
        pixel.variance = error2 / double(n * n) / double(n * n);
        return pixel;
    }
};

Tracer::Tracer(std::unique_ptr<Impl> impl)
    : m_impl(std::move(impl)) {}
Tracer::Tracer(Tracer&&) noexcept = default;
Tracer& Tracer::operator=(Tracer&&) noexcept = default;
Tracer::~Tracer() = default;

const std::vector<std::string>& Tracer::warnings() const {
    return m_impl->warnings;
}

base::Result<Tracer> Tracer::create(const FrameInput& input) {
    auto impl = std::make_unique<Impl>();
    impl->input = input;
    const glm::dvec3 origin = input.camera.position;
    impl->cameraPosition = origin;
    // Every texture first: masked materials' alpha decides which hits count while the rays are traced,
    // and the geometry keeps pointers into the (then complete) set.
    for (const DrawItem& item : impl->input.items)
        impl->itemTexture.push_back(MaterialTextures::add(impl->textures, item.material));
    for (const Mirror& mirror : impl->input.mirrors)
        impl->mirrorTexture.push_back(MaterialTextures::add(impl->textures, mirror.material));
    for (const Reflector& reflector : impl->input.reflectors)
        impl->reflectorTexture.push_back(MaterialTextures::add(impl->textures, reflector.material));
    auto geometry =
        SceneGeometry::build(impl->input, origin, impl->warnings, &impl->textures, &impl->itemTexture);
    if (!geometry)
        return base::Error{geometry.error()};
    impl->geometry = std::move(*geometry);
    for (const Mirror& mirror : impl->input.mirrors) {
        // The plane in camera-relative coordinates; a collapsed rectangle has none and never reflects.
        glm::dmat4 world = mirror.world;
        world[3] -= glm::dvec4(origin, 0.0);
        auto plane = math::mirrorPlane(world);
        impl->mirrorPlanes.push_back(plane ? std::optional<math::Plane>(*plane) : std::nullopt);
    }
    impl->lights = shadingLights(impl->input, origin);
    impl->maxMirrorDepth = std::clamp(impl->input.settings.mirrorDepth, 0, kStencilLevels);
    impl->warnings.insert(impl->warnings.end(), impl->textures.warnings().begin(),
                          impl->textures.warnings().end());
    return Tracer(std::move(impl));
}

base::Result<PixelPaths> Tracer::explainPixel(const TraceSettings& settings, int x, int y, int windowRadius,
                                              int samplePaths) const {
    if (base::Status size = checkStillSize(settings.width, settings.height); !size)
        return base::Error{size.error()};
    if (x < 0 || y < 0 || x >= settings.width || y >= settings.height)
        return base::Error{"pixel " + std::to_string(x) + "," + std::to_string(y) + " is outside the " +
                           std::to_string(settings.width) + "x" + std::to_string(settings.height) + " image"};
    const Impl::PixelTracer tracer(*m_impl, settings);
    PixelPaths out;
    out.x = x;
    out.y = y;
    const Impl::PixelTracer::Pixel pixel = tracer.tracePixel(x, y);
    // As render() stores them: floats.
    out.colour = glm::dvec3(glm::vec3(pixel.colour));
    out.noise = glm::dvec3(glm::vec3(pixel.variance));
    out.glossy = pixel.glossy;
    out.id = pixel.id;
    out.centre = tracer.recordPath(x, y, 0);
    const bool rough = std::any_of(out.centre.vertices.begin(), out.centre.vertices.end(),
                                   [](const PathVertex& v) { return v.roughness > 0.0; });
    const int more = rough ? std::clamp(std::min(samplePaths, tracer.paths) - 1, 0, kMaxTraceSamples) : 0;
    for (int k = 1; k <= more; ++k)
        out.samples.push_back(tracer.recordPath(x, y, k));
    const int r = std::max(windowRadius, 0);
    out.windowX = std::max(x - r, 0);
    out.windowY = std::max(y - r, 0);
    out.windowWidth = std::min(x + r, settings.width - 1) - out.windowX + 1;
    out.windowHeight = std::min(y + r, settings.height - 1) - out.windowY + 1;
    for (int j = 0; j < out.windowHeight; ++j)
        for (int i = 0; i < out.windowWidth; ++i) {
            const Impl::PixelTracer::Pixel near = tracer.tracePixel(out.windowX + i, out.windowY + j);
            out.window.push_back(glm::dvec3(glm::vec3(near.colour)));
            out.windowIds.push_back(near.id);
        }
    return out;
}

RayHit Tracer::firstHit(const glm::dvec3& origin, const glm::dvec3& direction, int ignoreReflector) const {
    RayHit out;
    out.distance = kInfinity;
    const double length = glm::length(direction);
    if (!(length > 0.0) || !std::isfinite(length))
        return out;
    const glm::dvec3 d = direction / length;
    const glm::dvec3 start = origin - m_impl->cameraPosition;
    std::optional<Hit> hit;
    double t = 0.0;
    // Through the ignored reflector's own surface (in and out of it) and on; a few crossings at most.
    for (int crossing = 0; crossing < 16; ++crossing) {
        hit = m_impl->geometry->intersect(start, d, t, kInfinity);
        if (!hit || hit->surface->kind != SurfaceKind::Reflector || hit->surface->index != ignoreReflector)
            break;
        t = hit->t + SceneGeometry::offset(hit->position);
        hit.reset();
    }
    if (!hit)
        return out;
    const Surface& s = *hit->surface;
    HitKind kind = HitKind::Reflector;
    if (s.kind == SurfaceKind::Object)
        kind = HitKind::Object;
    else if (s.kind == SurfaceKind::Mirror)
        kind = hit->frontFacing ? HitKind::Mirror : HitKind::MirrorBack;
    out.id = {kind, s.index};
    out.distance = hit->t;
    out.position = hit->position + m_impl->cameraPosition;
    return out;
}

double Tracer::footprintVisibility(int light, const glm::dvec3& position, const glm::dvec3& normal) const {
    const Impl& impl = *m_impl;
    if (light < 0 || std::size_t(light) >= impl.lights.size() || !impl.lights[std::size_t(light)].shadowed)
        return 1.0;
    const ShadingLight& l = impl.lights[std::size_t(light)];
    Hit hit;
    hit.position = position - impl.cameraPosition;
    hit.normal = hit.geometricNormal = hit.outwardNormal = normal;
    glm::dvec3 toLight = -l.direction;
    double distance = kInfinity;
    if (l.type != LightType::Directional) {
        const glm::dvec3 d = l.position - hit.position;
        distance = glm::length(d);
        if (!(distance > 0.0))
            return 1.0;
        toLight = d / distance;
    }
    if (glm::dot(normal, toLight) <= 0.0)
        return 1.0;
    const Shader shader(impl.lights, *impl.geometry, impl.textures, impl.input.settings.ambient,
                        ShadowMode::PcfFootprint);
    return shader.visibility(l, hit, toLight, distance);
}

base::Result<TraceResult> Tracer::render(const TraceSettings& settings, const TraceProgress& progress) const {
    const auto start = std::chrono::steady_clock::now();
    if (base::Status size = checkStillSize(settings.width, settings.height); !size)
        return base::Error{size.error()};
    const Impl& impl = *m_impl;
    const Impl::PixelTracer tracer(impl, settings);
    const int width = tracer.width, height = tracer.height;

    TraceResult result = blankResult(width, height);
    result.samples = tracer.n * tracer.n;
    result.paths = tracer.paths;
    result.warnings = impl.warnings;
    // Per row, summed in row order afterwards: the figures do not depend on which thread traced what.
    std::vector<double> rowNoise(static_cast<std::size_t>(height), 0.0);
    std::vector<int> rowGlossy(static_cast<std::size_t>(height), 0);
    auto traceRow = [&](int y) {
        for (int x = 0; x < width; ++x) {
            const Impl::PixelTracer::Pixel pixel = tracer.tracePixel(x, y);
            const glm::dvec3& c = pixel.colour;
            const glm::dvec3& e = pixel.variance;
            const std::size_t p = static_cast<std::size_t>(y) * width + x;
            result.image.rgba[p * 4 + 0] = static_cast<float>(c.r);
            result.image.rgba[p * 4 + 1] = static_cast<float>(c.g);
            result.image.rgba[p * 4 + 2] = static_cast<float>(c.b);
            result.image.rgba[p * 4 + 3] = 1.0f;
            result.ids.ids[p] = pixel.id;
            for (int k = 0; k < 3; ++k)
                result.noise.rgba[p * 4 + std::size_t(k)] = static_cast<float>(e[k]);
            result.noise.rgba[p * 4 + 3] = 1.0f;
            rowNoise[std::size_t(y)] += e.r + e.g + e.b;
            rowGlossy[std::size_t(y)] += pixel.glossy ? 1 : 0;
        }
    };

    // A first call before any work, so a caller can cancel at once.
    if (progress && !progress(0.0))
        return base::Error{"render cancelled"};
    const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
    const int threads =
        std::clamp(settings.threads > 0 ? settings.threads : int(hardware), 1, std::max(height, 1));
    if (!traceRowsInParallel(height, threads, progress, traceRow))
        return base::Error{"render cancelled"};
    if (progress)
        progress(1.0);
    double noise = 0.0;
    for (int y = 0; y < height; ++y) {
        noise += rowNoise[std::size_t(y)];
        result.glossyPixels += rowGlossy[std::size_t(y)];
    }
    result.noiseRms = std::sqrt(noise / (3.0 * double(width) * double(height)));
    result.totalMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return result;
}

} // namespace speculum::render::reference
