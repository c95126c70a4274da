#pragma once
// A room of flat-coloured tiles that the curved reflector tests draw and trace: sharp edges everywhere,
// which a coarse map blurs, and no texture (whose minification the tracer, without mipmaps, would alias).
#include "render/frame/FrameInput.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/reference/Tracer.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <memory>
#include <optional>

namespace speculum::test {

inline constexpr int kRoomTiles = 3; // per wall side

// A material that shows `colour` from every side and under any light: its emission alone.
inline render::Material flatColour(glm::dvec3 colour) {
    render::Material m;
    m.color = glm::dvec3(0.0);
    m.ambient = 0.0;
    m.diffuse = 0.0;
    m.emission = colour;
    return m;
}

// A room [−half, half]³ whose six walls are grids of flat-coloured tiles, on a black background.
inline render::FrameInput tiledRoom(double half) {
    static const auto plane = std::make_shared<const render::MeshData>(render::makePlane(1));
    static const glm::dvec3 palette[] = {{0.9, 0.1, 0.1},    {0.1, 0.8, 0.2},   {0.1, 0.2, 0.9},
                                         {0.9, 0.9, 0.1},    {0.9, 0.2, 0.9},   {0.1, 0.9, 0.9},
                                         {0.95, 0.95, 0.95}, {0.05, 0.05, 0.05}};
    render::FrameInput input;
    input.settings.background = {0.0, 0.0, 0.0};
    input.settings.ambient = 0.0;
    input.camera.far = 100.0;
    const double tile = 2.0 * half / kRoomTiles;
    int colour = 0;
    for (int wall = 0; wall < 6; ++wall) {
        const int axis = wall / 2;
        glm::dvec3 n(0.0);
        n[axis] = wall % 2 == 0 ? 1.0 : -1.0;
        // The unit plane lies in XZ facing +Y; turn +Y onto the wall's axis. Flat colours are two-sided.
        glm::dmat4 turn(1.0);
        if (axis == 0)
            turn = glm::rotate(glm::dmat4(1.0), glm::radians(90.0), glm::dvec3(0, 0, 1));
        else if (axis == 2)
            turn = glm::rotate(glm::dmat4(1.0), glm::radians(90.0), glm::dvec3(1, 0, 0));
        for (int i = 0; i < kRoomTiles; ++i)
            for (int j = 0; j < kRoomTiles; ++j) {
                const glm::dvec3 local(-half + (i + 0.5) * tile, 0.0, -half + (j + 0.5) * tile);
                const glm::dmat4 world = glm::translate(glm::dmat4(1.0), n * half) * turn *
                                         glm::translate(glm::dmat4(1.0), local) *
                                         glm::scale(glm::dmat4(1.0), glm::dvec3(tile * 0.5, 1.0, tile * 0.5));
                input.items.push_back({"tile", world, plane, flatColour(palette[colour++ % 8]), false});
            }
        ++colour; // neighbouring walls start on different colours
    }
    return input;
}

// The exact image of `input`, size² pixels of ssaa² samples, `paths` per sub-sample on a rough surface;
// none (with a test failure) where the tracer fails.
inline std::optional<render::reference::TraceResult> traceExact(const render::FrameInput& input, int size,
                                                                int ssaa, int paths = 16) {
    auto tracer = render::reference::Tracer::create(input);
    EXPECT_TRUE(tracer.ok()) << (tracer.ok() ? "" : tracer.error());
    if (!tracer.ok())
        return std::nullopt;
    render::reference::TraceSettings settings;
    settings.width = size;
    settings.height = size;
    settings.ssaa = ssaa;
    settings.samples = paths;
    auto traced = tracer->render(settings);
    EXPECT_TRUE(traced.ok()) << (traced.ok() ? "" : traced.error());
    if (!traced.ok())
        return std::nullopt;
    return std::move(*traced);
}

} // namespace speculum::test
