#pragma once

#include "render/Result.hpp"
#include "render/gl/Objects.hpp"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <map>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace speculum::render::gl {

// Expands `#include "file.glsl"` in an embedded shader and inserts `#line` directives, so that compile
// errors can be reported as shaders/<file>:<line>. Returns the text and fills the file-number table.
Result<std::string> preprocessShader(std::string_view file, const std::string& defines,
                                     std::vector<std::string>& fileNumbers);

// Rewrites a driver's info log ("0:12(3): error ...", "0(12) : error ...") to name shader files.
std::string mapShaderLog(const std::string& log, const std::vector<std::string>& fileNumbers);

// A linked GLSL program built from embedded shader files, with cached uniform locations.
//
// A program can hold variants: the same files compiled with more `#define` lines, each linked once, on
// first selection. use(), id(), location() and set() act on the selected variant; uniforms are the
// variant's own, so select before setting them.
class Program {
public:
    Program() = default;
    static Result<Program> build(std::string_view vertexFile, std::string_view fragmentFile,
                                 const std::string& defines = {});

    // Selects the variant built with `variantDefines` appended to the build's defines (empty: the program
    // as built), compiling and linking it the first time. On failure the selection is unchanged.
    Status select(const std::string& variantDefines);
    const std::string& selected() const { return m_selected; }

    void use() const { glUseProgram(id()); }
    GLuint id() const { return m_current ? m_current->program.id() : 0; }
    GLint location(const std::string& name) const;

    void set(const std::string& name, int v) const { glUniform1i(location(name), v); }
    void set(const std::string& name, float v) const { glUniform1f(location(name), v); }
    void set(const std::string& name, const glm::vec2& v) const { glUniform2f(location(name), v.x, v.y); }
    void set(const std::string& name, const glm::vec3& v) const {
        glUniform3f(location(name), v.x, v.y, v.z);
    }
    void set(const std::string& name, const glm::vec4& v) const {
        glUniform4f(location(name), v.x, v.y, v.z, v.w);
    }
    void set(const std::string& name, const glm::mat3& m) const;
    void set(const std::string& name, const glm::mat4& m) const;

private:
    struct Linked {
        ProgramHandle program;
        mutable std::unordered_map<std::string, GLint> locations;
    };
    static Result<Linked> link(std::string_view vertexFile, std::string_view fragmentFile,
                               const std::string& defines);

    std::string m_vertexFile, m_fragmentFile, m_defines;
    std::map<std::string, Linked> m_variants;    // by variant defines; nodes stay put when the map moves
    std::map<std::string, std::string> m_failed; // variants that did not build, with the error: not retried
    const Linked* m_current = nullptr;
    std::string m_selected;
};

} // namespace speculum::render::gl
