#pragma once

#include "base/Result.hpp"
#include "render/frame/Guides.hpp"
#include "render/gl/Objects.hpp"
#include "render/gl/Program.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <optional>
#include <vector>

namespace speculum::render::passes {

// Where the guides are drawn: the camera's view, in the buffer its passes drew into (bound, with the depth
// they left), at `size` pixels, `pixelScale` of the output's (less for a preview drawn smaller).
struct GuidesView {
    glm::dmat4 projection{1.0}; // the camera's, as its main pass drew with it
    glm::dmat4 rotation{1.0};   // camera-relative world → eye
    glm::dvec3 eye{0.0};
    double nearPlane = 0.1;
    glm::ivec2 size{1, 1};
    double pixelScale = 1.0;
};

// The editor's guide lines (RenderOptions::guides) as thin anti-aliased quads, widened on screen: drawn
// where the depth buffer shows nothing in front of them and, where a line asks for it, faintly where
// something is. Lines lying on a surface (the grid on a floor at y = 0) are pulled a little toward the eye
// so that they are not lost in its depth. The program is built the first time guides are drawn: a frame
// without guides (every still, every CLI command) never builds it.
class GuidesPass {
public:
    base::Status draw(const std::vector<GuideLine>& lines, const GuidesView& view);

private:
    std::optional<gl::Program> m_program;
    gl::VertexArray m_vao;
    gl::Buffer m_buffer;
};

} // namespace speculum::render::passes
