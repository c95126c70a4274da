#include "accuracy/run/Furnace.hpp"

#include "render/math/Ggx.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/reference/Tracer.hpp"
#include "render/renderer/StillRenderer.hpp"

#include <cmath>
#include <glm/trigonometric.hpp>
#include <memory>

namespace speculum::accuracy {

namespace {

constexpr int kPlanarSize = 9;        // every pixel sees about the same angle: the centre is measured
constexpr int kReflectorSize = 24;    // the centre pixel faces the camera
constexpr int kFurnaceSamples = 1024; // the tracer's paths per pixel: a standard error of ~0.5 %

render::FrameInput whiteSky() {
    render::FrameInput input;
    input.settings.background = {1.0, 1.0, 1.0};
    input.settings.ambient = 0.0;
    return input;
}

struct Traced {
    double value = 0.0, error = 0.0;
};

// The traced value averaged over the `window` × `window` pixels at the image's centre, which all see about
// the same angle, and its standard error. Averaging matters: a pixel's paths use the same random numbers
// at every roughness and view, so one pixel's chance deviation would repeat across the whole table.
base::Result<Traced> traceCentre(const render::FrameInput& input, int size, int window) {
    auto tracer = render::reference::Tracer::create(input);
    if (!tracer)
        return base::Error{tracer.error()};
    render::reference::TraceSettings settings;
    settings.width = settings.height = size;
    settings.samples = kFurnaceSamples;
    auto traced = tracer->render(settings);
    if (!traced)
        return base::Error{traced.error()};
    double sum = 0.0, variance = 0.0;
    const int from = size / 2 - window / 2;
    for (int y = from; y < from + window; ++y)
        for (int x = from; x < from + window; ++x) {
            sum += traced->image.at(x, y).g;
            variance += traced->noise.at(x, y).g;
        }
    const double count = double(window * window);
    return Traced{sum / count, std::sqrt(variance) / count};
}

base::Result<double> rasterCentre(render::Renderer& renderer, render::FrameInput input,
                                  render::GlossyFilter filter, int size) {
    input.settings.glossyFilter = filter;
    auto still = render::renderStill(renderer, input, render::StillSettings{size, size, 1});
    if (!still)
        return base::Error{still.error()};
    return double(still->image.at(size / 2, size / 2).g);
}

// E(μ_v, α = roughness²); a perfect mirror keeps everything.
double albedo(double cosView, double roughness) {
    return roughness > 0.0 ? render::math::ggxDirectionalAlbedo(cosView, roughness * roughness) : 1.0;
}

const char* pathName(render::GlossyFilter filter) {
    switch (filter) {
    case render::GlossyFilter::Mip:
        return "mip";
    case render::GlossyFilter::Chain:
        return "chain";
    default:
        return "footprint";
    }
}

// One surface at one roughness: the trace once, then each raster path.
base::Status measure(render::Renderer& renderer, const render::FrameInput& input, int size, FurnaceRow row,
                     std::vector<FurnaceRow>& rows) {
    // The planar furnace's narrow camera sees the same angle everywhere; the ball's centre only nearby.
    auto traced = traceCentre(input, size, size == kPlanarSize ? kPlanarSize : 3);
    if (!traced)
        return base::Error{"furnace: " + traced.error()};
    row.traced = traced->value;
    row.tracedError = traced->error;
    for (render::GlossyFilter filter :
         {render::GlossyFilter::Mip, render::GlossyFilter::Footprint, render::GlossyFilter::Chain}) {
        auto raster = rasterCentre(renderer, input, filter, size);
        if (!raster)
            return base::Error{"furnace: " + raster.error()};
        row.path = pathName(filter);
        row.raster = *raster;
        rows.push_back(row);
        if (row.roughness == 0.0)
            break; // a perfect mirror has no filter to choose
    }
    return base::Done{};
}

} // namespace

render::FrameInput planarFurnace(double roughness, double viewDegrees) {
    render::FrameInput input = whiteSky();
    const double theta = glm::radians(viewDegrees);
    input.camera.position = glm::dvec3(0.0, std::cos(theta), std::sin(theta)) * 3.0;
    input.camera.target = {0.0, 0.0, 0.0};
    input.camera.up = viewDegrees < 1.0 ? glm::dvec3(0, 0, -1) : glm::dvec3(0, 1, 0);
    input.camera.fovY = 2.0;
    input.camera.near = 0.1;
    input.camera.far = 1000.0;
    render::Mirror floor;
    floor.name = "Floor mirror";
    floor.world = glm::dmat4(1.0); // at the origin, facing +Y
    floor.size = {400.0, 400.0};
    floor.roughness = roughness;
    floor.technique = render::MirrorTechnique::Texture;
    input.mirrors.push_back(floor);
    return input;
}

render::FrameInput reflectorFurnace(double roughness) {
    render::FrameInput input = whiteSky();
    input.camera.position = {0.0, 0.0, 4.0};
    input.camera.target = {0.0, 0.0, 0.0};
    input.camera.fovY = 32.0;
    static const auto sphere = std::make_shared<const render::MeshData>(render::makeSphere(128));
    render::Reflector ball;
    ball.name = "Ball";
    ball.mesh = sphere;
    ball.world = glm::dmat4(1.0);
    ball.material.color = glm::dvec3(0.0);
    ball.material.specular = 0.0;
    ball.reflectivity = 1.0;
    ball.roughness = roughness;
    ball.resolution = 64;
    input.reflectors = {ball};
    return input;
}

const std::vector<double>& furnaceRoughnesses() {
    static const std::vector<double> values = {0.0, 0.1, 0.3, 0.6, 0.8, 1.0}; // with the glossy sweep's
    return values;
}

base::Result<std::vector<FurnaceRow>> runFurnace(render::Renderer& renderer,
                                                 const std::function<bool()>& stop) {
    std::vector<FurnaceRow> rows;
    for (double roughness : furnaceRoughnesses()) {
        for (double view : {0.0, 60.0}) {
            if (stop && stop())
                return base::Error{"stopped"};
            FurnaceRow row;
            row.surface = "planar mirror";
            row.roughness = roughness;
            row.viewDegrees = view;
            row.albedo = albedo(std::cos(glm::radians(view)), roughness);
            if (base::Status s = measure(renderer, planarFurnace(roughness, view), kPlanarSize, row, rows);
                !s)
                return base::Error{s.error()};
        }
        if (stop && stop())
            return base::Error{"stopped"};
        FurnaceRow row;
        row.surface = "reflector";
        row.roughness = roughness;
        row.albedo = albedo(1.0, roughness);
        if (base::Status s = measure(renderer, reflectorFurnace(roughness), kReflectorSize, row, rows); !s)
            return base::Error{s.error()};
    }
    return rows;
}

} // namespace speculum::accuracy
