#include "render/passes/GuidesPass.hpp"

#include <cmath>
#include <cstddef>
#include <glm/vec4.hpp>

namespace speculum::render::passes {

namespace {

// One line as the vertex shader reads it, per instance: its ends relative to the eye, its linear colour
// and its style.
struct LineVertex {
    glm::vec3 from;
    glm::vec3 to;
    glm::vec4 color; // linear, straight alpha
    glm::vec2 style; // width in drawn pixels, hidden opacity
};

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

std::vector<LineVertex> lineVertices(const std::vector<GuideLine>& lines, const GuidesView& view) {
    std::vector<LineVertex> vertices;
    vertices.reserve(lines.size());
    for (const GuideLine& line : lines) {
        const glm::vec4 color(srgbToLinear(line.color.r), srgbToLinear(line.color.g),
                              srgbToLinear(line.color.b), line.color.a);
        // Relative to the eye in double first: a grid far from the origin keeps its precision.
        vertices.push_back({glm::vec3(line.from - view.eye), glm::vec3(line.to - view.eye), color,
                            glm::vec2(float(line.width * view.pixelScale), line.hiddenOpacity)});
    }
    return vertices;
}

void describeAttributes() {
    const auto stride = static_cast<GLsizei>(sizeof(LineVertex));
    auto attribute = [stride](GLuint index, GLint count, std::size_t offset) {
        glEnableVertexAttribArray(index);
        glVertexAttribPointer(index, count, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void*>(offset));
        glVertexAttribDivisor(index, 1); // one line per instance: its six vertices share it
    };
    attribute(0, 3, offsetof(LineVertex, from));
    attribute(1, 3, offsetof(LineVertex, to));
    attribute(2, 4, offsetof(LineVertex, color));
    attribute(3, 2, offsetof(LineVertex, style));
}

} // namespace

base::Status GuidesPass::draw(const std::vector<GuideLine>& lines, const GuidesView& view) {
    if (!m_program) {
        auto program = gl::Program::build("guides.vert", "guides.frag");
        if (!program)
            return base::Error{program.error()};
        m_program = std::move(*program);
        m_vao = gl::makeVertexArray();
        m_buffer = gl::makeBuffer();
        glBindVertexArray(m_vao.id());
        glBindBuffer(GL_ARRAY_BUFFER, m_buffer.id());
        describeAttributes();
    }
    const std::vector<LineVertex> vertices = lineVertices(lines, view);
    glBindVertexArray(m_vao.id());
    glBindBuffer(GL_ARRAY_BUFFER, m_buffer.id());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(LineVertex)),
                 vertices.data(), GL_STREAM_DRAW);

    const gl::Program& program = *m_program;
    program.use();
    program.set("uViewProjection", glm::mat4(view.projection * view.rotation));
    program.set("uViewportSize", glm::vec2(view.size));
    program.set("uNearW", float(view.nearPlane * 1.01));
    glEnable(GL_BLEND);
    // Over the colour; the buffer's alpha (what the composite reads as coverage) stays as it is.
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    glDepthMask(GL_FALSE);
    const auto count = static_cast<GLsizei>(vertices.size());
    // In front of the scene (or on its surface); then, faintly, behind it where a line asks for that.
    glDepthFunc(GL_LEQUAL);
    program.set("uHiddenPass", 0);
    glDrawArraysInstanced(GL_TRIANGLES, 0, 6, count);
    bool seeThrough = false;
    for (const GuideLine& line : lines)
        seeThrough = seeThrough || line.hiddenOpacity > 0.0f;
    if (seeThrough) {
        glDepthFunc(GL_GREATER);
        program.set("uHiddenPass", 1);
        glDrawArraysInstanced(GL_TRIANGLES, 0, 6, count);
    }
    glBindVertexArray(0);
    return base::Status{base::Done{}};
}

} // namespace speculum::render::passes
