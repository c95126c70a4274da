#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace speculum::render {

// A line the editor draws over the camera's view to help the eye (the ground grid, the scene camera's
// wireframe): not part of the scene. The renderer draws it after the camera's view and its mirrors, depth-
// tested against what they drew, so a guide never shows through an opaque object, never appears inside a
// reflection, and never reaches a still.
struct GuideLine {
    glm::dvec3 from{0.0};
    glm::dvec3 to{0.0};
    glm::vec4 color{1.0f}; // sRGB-encoded, with straight (not premultiplied) alpha
    float width = 1.0f;    // in output pixels
    // How strongly the parts behind the scene show, as a fraction of `color.a`: 0 hides them; a small value
    // keeps a faint see-through that still reads as a guide.
    float hiddenOpacity = 0.0f;
};

} // namespace speculum::render
