#pragma once

#include "render/frame/Light.hpp"
#include "render/frame/Material.hpp"
#include "render/frame/Mirror.hpp"
#include "render/frame/Reflector.hpp"
#include "render/frame/Settings.hpp"
#include "render/mesh/MeshData.hpp"

#include <glm/mat4x4.hpp>
#include <optional>
#include <string>
#include <vector>

namespace speculum::render {

// A snapshot of everything one frame needs, in plain structs. Transforms are double precision world
// matrices; the renderer makes them camera-relative before converting to float. The scene's settings,
// materials, lights, mirrors and reflectors are the structs the scene model holds (each declares its
// fields, Field.hpp), with where each is in the world.

struct DrawItem {
    std::string name;
    glm::dmat4 world{1.0};
    MeshHandle mesh;
    Material material;
    bool castsShadows = true;
};

struct FrameInput {
    Settings settings;
    Camera camera;
    std::vector<DrawItem> items;
    std::vector<Light> lights;
    std::vector<Mirror> mirrors;
    // The curved reflectors, each with its own environment map; no reflector is drawn into its own map.
    std::vector<Reflector> reflectors;
    double time = 0.0; // seconds, the time animations were evaluated at
};

} // namespace speculum::render
