#pragma once
// Small scenes the planner tests share: mirrors facing a camera at the origin that looks down −Z.
#include "render/frame/FrameInput.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <string>

namespace speculum::render::test {

// A 2 × 2 (or size × size) mirror in the plane z = zPlane facing +Z (or −Z).
inline Mirror wall(const std::string& name, double zPlane, bool facingPlusZ = true, double size = 2.0) {
    Mirror m;
    m.name = name;
    m.world = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, zPlane)),
                          glm::radians(facingPlusZ ? 90.0 : -90.0), glm::dvec3(1, 0, 0));
    m.size = {size, size};
    return m;
}

inline FrameInput cameraAtOrigin() {
    FrameInput input;
    input.camera.position = {0, 0, 0};
    input.camera.target = {0, 0, -1};
    input.camera.far = 100.0;
    return input;
}

} // namespace speculum::render::test
