#include "render/gl/Program.hpp"

#include "render/gl/EmbeddedShaders.hpp"

#include <algorithm>
#include <glm/gtc/type_ptr.hpp>
#include <regex>
#include <sstream>

namespace speculum::render::gl {

namespace {

const EmbeddedShader* findShader(std::string_view name) {
    for (const EmbeddedShader& s : embeddedShaders())
        if (s.name == name)
            return &s;
    return nullptr;
}

int fileNumber(std::string_view file, std::vector<std::string>& fileNumbers) {
    for (std::size_t i = 0; i < fileNumbers.size(); ++i)
        if (fileNumbers[i] == file)
            return static_cast<int>(i);
    fileNumbers.emplace_back(file);
    return static_cast<int>(fileNumbers.size() - 1);
}

base::Status expand(std::string_view file, std::ostringstream& out, std::vector<std::string>& fileNumbers,
                    int depth) {
    if (depth > 8)
        return base::Error{"shaders/" + std::string(file) + ": #include nested too deeply"};
    const EmbeddedShader* shader = findShader(file);
    if (!shader)
        return base::Error{"shaders/" + std::string(file) + ": no such embedded shader"};
    const int number = fileNumber(file, fileNumbers);
    std::istringstream in{std::string(shader->source)};
    std::string line;
    int lineNo = 0;
    out << "#line 1 " << number << "\n";
    static const std::regex includeLine(R"(^\s*#include\s+"([^"]+)\"\s*$)");
    while (std::getline(in, line)) {
        ++lineNo;
        std::smatch match;
        if (std::regex_match(line, match, includeLine)) {
            if (base::Status s = expand(match[1].str(), out, fileNumbers, depth + 1); !s)
                return s;
            out << "#line " << lineNo + 1 << " " << number << "\n";
        } else {
            out << line << "\n";
        }
    }
    return base::Done{};
}

base::Result<ShaderHandle> compile(GLenum stage, std::string_view file, const std::string& defines) {
    std::vector<std::string> fileNumbers;
    auto preprocessed = preprocessShader(file, defines, fileNumbers);
    if (!preprocessed)
        return base::Error{preprocessed.error()};
    const std::string& text = *preprocessed;
    ShaderHandle shader(glCreateShader(stage));
    const char* src = text.c_str();
    glShaderSource(shader.id(), 1, &src, nullptr);
    glCompileShader(shader.id());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetShaderiv(shader.id(), GL_INFO_LOG_LENGTH, &length);
        std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
        glGetShaderInfoLog(shader.id(), length, nullptr, log.data());
        return base::Error{"shader compile failed:\n" + mapShaderLog(log.c_str(), fileNumbers)};
    }
    return shader;
}

} // namespace

base::Result<std::string> preprocessShader(std::string_view file, const std::string& defines,
                                           std::vector<std::string>& fileNumbers) {
    std::ostringstream body;
    if (base::Status s = expand(file, body, fileNumbers, 0); !s)
        return base::Error{s.error()};
    // ARB_gpu_shader5 where the driver has it: shaders test GL_ARB_gpu_shader5 and fall back to GLSL 3.30.
    return "#version 330 core\n#extension GL_ARB_gpu_shader5 : enable\n" + defines + "\n" + body.str();
}

std::string mapShaderLog(const std::string& log, const std::vector<std::string>& fileNumbers) {
    // Mesa: "0:12(3): error: ..."; NVIDIA: "0(12) : error ..."
    static const std::regex mesa(R"((\d+):(\d+)\((\d+)\))");
    static const std::regex nvidia(R"((\d+)\((\d+)\) ?:)");
    auto name = [&](const std::string& number) {
        const std::size_t i = std::stoul(number);
        return i < fileNumbers.size() ? "shaders/" + fileNumbers[i] : "source " + number;
    };
    std::istringstream in(log);
    std::ostringstream out;
    std::string line;
    while (std::getline(in, line)) {
        std::smatch m;
        if (std::regex_search(line, m, mesa))
            line = m.prefix().str() + name(m[1]) + ":" + m[2].str() + ":" + m[3].str() + m.suffix().str();
        else if (std::regex_search(line, m, nvidia))
            line = m.prefix().str() + name(m[1]) + ":" + m[2].str() + ":" + m.suffix().str();
        out << line << "\n";
    }
    return out.str();
}

base::Result<Program::Linked> Program::link(std::string_view vertexFile, std::string_view fragmentFile,
                                            const std::string& defines) {
    auto vs = compile(GL_VERTEX_SHADER, vertexFile, defines);
    if (!vs)
        return base::Error{vs.error()};
    auto fs = compile(GL_FRAGMENT_SHADER, fragmentFile, defines);
    if (!fs)
        return base::Error{fs.error()};
    Linked linked;
    linked.program = ProgramHandle(glCreateProgram());
    const GLuint id = linked.program.id();
    glAttachShader(id, vs->id());
    glAttachShader(id, fs->id());
    glLinkProgram(id);
    GLint ok = GL_FALSE;
    glGetProgramiv(id, GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetProgramiv(id, GL_INFO_LOG_LENGTH, &length);
        std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
        glGetProgramInfoLog(id, length, nullptr, log.data());
        return base::Error{"shader link failed (shaders/" + std::string(vertexFile) + ", shaders/" +
                           std::string(fragmentFile) + "):\n" + log.c_str()};
    }
    glDetachShader(id, vs->id());
    glDetachShader(id, fs->id());
    return linked;
}

base::Result<Program> Program::build(std::string_view vertexFile, std::string_view fragmentFile,
                                     const std::string& defines) {
    auto linked = link(vertexFile, fragmentFile, defines);
    if (!linked)
        return base::Error{linked.error()};
    Program program;
    program.m_vertexFile = vertexFile;
    program.m_fragmentFile = fragmentFile;
    program.m_defines = defines;
    program.m_current = &program.m_variants.emplace(std::string(), std::move(*linked)).first->second;
    return program;
}

const Program::Linked* Program::variant(const std::string& defines) const {
    if (auto it = m_variants.find(defines); it != m_variants.end())
        return &it->second;
    if (m_failed.count(defines))
        return nullptr;
    auto linked = link(m_vertexFile, m_fragmentFile, m_defines + "\n" + defines);
    if (!linked) {
        m_failed.emplace(defines, linked.error());
        return nullptr;
    }
    return &m_variants.emplace(defines, std::move(*linked)).first->second;
}

base::Status Program::select(const std::string& variantDefines, bool drawVariants) {
    m_drawVariants = drawVariants;
    if (m_current && variantDefines == m_selected)
        return base::Done{};
    const Linked* chosen = variant(variantDefines);
    if (!chosen)
        return base::Error{m_failed[variantDefines]};
    m_current = chosen;
    m_selected = variantDefines;
    return base::Done{};
}

void Program::useWith(const std::string& drawDefines) const {
    const Linked* chosen = nullptr;
    if (m_drawVariants && !drawDefines.empty())
        chosen = variant(m_selected + drawDefines);
    if (!chosen)
        chosen = variant(m_selected);
    if (chosen)
        m_current = chosen;
    use();
}

void Program::use() const {
    if (!m_current)
        return;
    glUseProgram(m_current->program.id());
    if (m_current->synced == m_version)
        return;
    for (const auto& [name, value] : m_values)
        if (value.version > m_current->synced)
            apply(location(name), value);
    m_current->synced = m_version;
}

GLint Program::location(const std::string& name) const {
    if (!m_current)
        return -1;
    auto& locations = m_current->locations;
    auto it = locations.find(name);
    if (it != locations.end())
        return it->second;
    const GLint loc = glGetUniformLocation(m_current->program.id(), name.c_str());
    locations.emplace(name, loc);
    return loc;
}

void Program::apply(GLint location, const Value& v) {
    switch (v.kind) {
    case Kind::Int:
        glUniform1i(location, v.i);
        break;
    case Kind::Float:
        glUniform1f(location, v.f[0]);
        break;
    case Kind::Vec2:
        glUniform2fv(location, 1, v.f.data());
        break;
    case Kind::Vec3:
        glUniform3fv(location, 1, v.f.data());
        break;
    case Kind::Vec4:
        glUniform4fv(location, 1, v.f.data());
        break;
    case Kind::Mat3:
        glUniformMatrix3fv(location, 1, GL_FALSE, v.f.data());
        break;
    case Kind::Mat4:
        glUniformMatrix4fv(location, 1, GL_FALSE, v.f.data());
        break;
    }
}

// Applies the value to the bound (current) variant and keeps it for the others. A variant that was up to
// date stays so.
void Program::store(const std::string& name, Value value) const {
    if (!m_current)
        return;
    const bool wasSynced = m_current->synced == m_version;
    value.version = ++m_version;
    apply(location(name), value);
    if (wasSynced)
        m_current->synced = m_version;
    m_values[name] = value;
}

void Program::set(const std::string& name, int v) const {
    Value value;
    value.i = v;
    store(name, value);
}

void Program::storeFloats(const std::string& name, Kind kind, const float* data, std::size_t count) const {
    Value value;
    value.kind = kind;
    std::copy(data, data + count, value.f.begin());
    store(name, value);
}

void Program::set(const std::string& name, float v) const {
    storeFloats(name, Kind::Float, &v, 1);
}
void Program::set(const std::string& name, const glm::vec2& v) const {
    storeFloats(name, Kind::Vec2, glm::value_ptr(v), 2);
}
void Program::set(const std::string& name, const glm::vec3& v) const {
    storeFloats(name, Kind::Vec3, glm::value_ptr(v), 3);
}
void Program::set(const std::string& name, const glm::vec4& v) const {
    storeFloats(name, Kind::Vec4, glm::value_ptr(v), 4);
}
void Program::set(const std::string& name, const glm::mat3& m) const {
    storeFloats(name, Kind::Mat3, glm::value_ptr(m), 9);
}
void Program::set(const std::string& name, const glm::mat4& m) const {
    storeFloats(name, Kind::Mat4, glm::value_ptr(m), 16);
}

} // namespace speculum::render::gl
