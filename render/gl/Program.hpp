#pragma once

#include "base/Result.hpp"
#include "render/gl/Objects.hpp"

#include <array>
#include <cstdint>
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
base::Result<std::string> preprocessShader(std::string_view file, const std::string& defines,
                                           std::vector<std::string>& fileNumbers);

// Rewrites a driver's info log ("0:12(3): error ...", "0(12) : error ...") to name shader files.
std::string mapShaderLog(const std::string& log, const std::vector<std::string>& fileNumbers);

// A linked GLSL program built from embedded shader files, with cached uniform locations.
//
// A program can hold variants: the same files compiled with more `#define` lines, each linked once, the
// first time it is asked for. select() picks one for a frame (the lights); useWith() narrows it for a draw
// (an untextured material). Uniforms belong to the program, not to a variant: set() keeps every value,
// and use() brings a variant it switches to up to date.
class Program {
public:
    Program() = default;
    static base::Result<Program> build(std::string_view vertexFile, std::string_view fragmentFile,
                                       const std::string& defines = {});

    // Selects the variant built with `variantDefines` appended to the build's defines (empty: the program
    // as built), compiling and linking it the first time. On failure the selection is unchanged.
    // `drawVariants` false makes useWith() keep to the selected variant.
    base::Status select(const std::string& variantDefines, bool drawVariants = true);
    const std::string& selected() const { return m_selected; }

    // Binds the selected variant with `drawDefines` appended (empty: the selected variant), building it
    // the first time. The defines may only specialise the shader: if that variant does not build, the
    // selected one draws instead, the same image more slowly. Const like set(): variants are a cache.
    void useWith(const std::string& drawDefines) const;

    void use() const; // binds the current variant, with every uniform set so far
    GLuint id() const { return m_current ? m_current->program.id() : 0; }
    GLint location(const std::string& name) const;

    void set(const std::string& name, int v) const;
    void set(const std::string& name, float v) const;
    void set(const std::string& name, const glm::vec2& v) const;
    void set(const std::string& name, const glm::vec3& v) const;
    void set(const std::string& name, const glm::vec4& v) const;
    void set(const std::string& name, const glm::mat3& m) const;
    void set(const std::string& name, const glm::mat4& m) const;

private:
    struct Linked {
        ProgramHandle program;
        mutable std::unordered_map<std::string, GLint> locations;
        mutable std::uint64_t synced = 0; // every value up to this version is applied
    };
    enum class Kind { Int, Float, Vec2, Vec3, Vec4, Mat3, Mat4 };
    struct Value {
        Kind kind = Kind::Int;
        int i = 0;
        std::array<float, 16> f{};
        std::uint64_t version = 0;
    };
    static base::Result<Linked> link(std::string_view vertexFile, std::string_view fragmentFile,
                                     const std::string& defines);
    const Linked* variant(const std::string& defines) const; // nullptr: it does not build
    void store(const std::string& name, Value value) const;
    void storeFloats(const std::string& name, Kind kind, const float* data, std::size_t count) const;
    static void apply(GLint location, const Value& value);

    std::string m_vertexFile, m_fragmentFile, m_defines;
    // By variant defines; nodes stay put when the map moves.
    mutable std::map<std::string, Linked> m_variants;
    mutable std::map<std::string, std::string> m_failed; // variants that did not build: not retried
    mutable const Linked* m_current = nullptr;
    std::string m_selected;
    bool m_drawVariants = true;
    mutable std::unordered_map<std::string, Value> m_values; // every uniform set, by name
    mutable std::uint64_t m_version = 0;
};

} // namespace speculum::render::gl
