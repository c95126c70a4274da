#pragma once

#include "render/frame/FrameInput.hpp"
#include "render/mesh/Primitives.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <memory>

namespace speculum::test {

// Small FrameInputs for tracer tests, built in code so each test states its whole scene.
inline render::MeshHandle planeMesh() {
    return std::make_shared<const render::MeshData>(render::makePlane(1));
}

inline render::MeshHandle boxMesh() {
    return std::make_shared<const render::MeshData>(render::makeBox());
}

inline glm::dmat4 placed(glm::dvec3 translate, glm::dvec3 scale = glm::dvec3(1.0)) {
    return glm::scale(glm::translate(glm::dmat4(1.0), translate), scale);
}

// A flat, unlit colour: emission only.
inline render::Material emissive(glm::dvec3 colour) {
    render::Material m;
    m.color = glm::dvec3(0.0);
    m.specular = 0.0;
    m.emission = colour;
    return m;
}

inline render::DrawItem item(std::string name, render::MeshHandle mesh, glm::dmat4 world,
                             render::Material m) {
    render::DrawItem d;
    d.name = std::move(name);
    d.mesh = std::move(mesh);
    d.world = world;
    d.material = m;
    return d;
}

// A mirror whose reflective side faces `facing` (+Y, −Y or +Z), centred at `centre`.
inline render::Mirror mirror(glm::dvec3 centre, glm::dvec3 facing, glm::dvec2 size) {
    render::Mirror m;
    glm::dmat4 world = glm::translate(glm::dmat4(1.0), centre);
    if (facing.y < -0.5)
        world = glm::rotate(world, glm::radians(180.0), glm::dvec3(1, 0, 0));
    else if (facing.z > 0.5)
        world = glm::rotate(world, glm::radians(90.0), glm::dvec3(1, 0, 0));
    m.world = world;
    m.size = size;
    return m;
}

} // namespace speculum::test
