#pragma once

#include "render/gl/Objects.hpp"
#include "render/gl/Program.hpp"

#include <functional>
#include <glm/vec4.hpp>
#include <string>
#include <vector>

namespace speculum::test {

// Compiles a program from source text (e.g. preprocessShader() output followed by a main()); attribute 0
// is aPosition and 1 is aColor. Empty handle and `error` set on failure.
render::gl::ProgramHandle compileProgram(const std::string& vertex, const std::string& fragment,
                                         std::string& error);

// The text of an embedded shader with its includes expanded, #version line first.
std::string shaderText(const std::string& file);

// Runs the GLSL functions of envmap_lookup.glsl / envmap_warp.glsl once per input in a fragment shader
// (one fragment per input, RGBA32F in and out). Modes:
//   0: (component, uv, 0) of direction in.xyz for uType
//   1: direction of (component in.w, uv in.xy)
//   2: Jacobian columns 0 and 1 (∂uv/∂x, ∂uv/∂y) of direction in.xyz, component in.w; 3: column 2
//   4: texture(uCube, in.xyz)
//   5: envmapWarp(in.xyz) with the uEnvWarp* uniforms
//   6: envmapLookupCube / envmapLookup2D of direction in.xyz, direction gradients of length uGrad
class GlslRunner {
public:
    bool build(std::string& error);
    GLuint program() const { return m_program.id(); }
    // setUniforms runs with the program bound, before drawing.
    std::vector<glm::vec4> run(int mode, int type, const std::vector<glm::vec4>& inputs,
                               const std::function<void()>& setUniforms = {});

private:
    render::gl::ProgramHandle m_program;
};

} // namespace speculum::test
