#include "render/gl/Program.hpp"

#include "render/gl/EmbeddedShaders.hpp"

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

Status expand(std::string_view file, std::ostringstream& out, std::vector<std::string>& fileNumbers,
              int depth) {
    if (depth > 8)
        return Error{"shaders/" + std::string(file) + ": #include nested too deeply"};
    const EmbeddedShader* shader = findShader(file);
    if (!shader)
        return Error{"shaders/" + std::string(file) + ": no such embedded shader"};
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
            if (Status s = expand(match[1].str(), out, fileNumbers, depth + 1); !s)
                return s;
            out << "#line " << lineNo + 1 << " " << number << "\n";
        } else {
            out << line << "\n";
        }
    }
    return Done{};
}

Result<ShaderHandle> compile(GLenum stage, std::string_view file, const std::string& defines) {
    std::vector<std::string> fileNumbers;
    auto preprocessed = preprocessShader(file, defines, fileNumbers);
    if (!preprocessed)
        return Error{preprocessed.error()};
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
        return Error{"shader compile failed:\n" + mapShaderLog(log.c_str(), fileNumbers)};
    }
    return shader;
}

} // namespace

Result<std::string> preprocessShader(std::string_view file, const std::string& defines,
                                     std::vector<std::string>& fileNumbers) {
    std::ostringstream body;
    if (Status s = expand(file, body, fileNumbers, 0); !s)
        return Error{s.error()};
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

Result<Program::Linked> Program::link(std::string_view vertexFile, std::string_view fragmentFile,
                                      const std::string& defines) {
    auto vs = compile(GL_VERTEX_SHADER, vertexFile, defines);
    if (!vs)
        return Error{vs.error()};
    auto fs = compile(GL_FRAGMENT_SHADER, fragmentFile, defines);
    if (!fs)
        return Error{fs.error()};
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
        return Error{"shader link failed (shaders/" + std::string(vertexFile) + ", shaders/" +
                     std::string(fragmentFile) + "):\n" + log.c_str()};
    }
    glDetachShader(id, vs->id());
    glDetachShader(id, fs->id());
    return linked;
}

Result<Program> Program::build(std::string_view vertexFile, std::string_view fragmentFile,
                               const std::string& defines) {
    auto linked = link(vertexFile, fragmentFile, defines);
    if (!linked)
        return Error{linked.error()};
    Program program;
    program.m_vertexFile = vertexFile;
    program.m_fragmentFile = fragmentFile;
    program.m_defines = defines;
    program.m_current = &program.m_variants.emplace(std::string(), std::move(*linked)).first->second;
    return program;
}

Status Program::select(const std::string& variantDefines) {
    if (m_current && variantDefines == m_selected)
        return Done{};
    if (auto failed = m_failed.find(variantDefines); failed != m_failed.end())
        return Error{failed->second};
    auto it = m_variants.find(variantDefines);
    if (it == m_variants.end()) {
        auto linked = link(m_vertexFile, m_fragmentFile, m_defines + "\n" + variantDefines);
        if (!linked) {
            m_failed.emplace(variantDefines, linked.error());
            return Error{linked.error()};
        }
        it = m_variants.emplace(variantDefines, std::move(*linked)).first;
    }
    m_current = &it->second;
    m_selected = variantDefines;
    return Done{};
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

void Program::set(const std::string& name, const glm::mat3& m) const {
    glUniformMatrix3fv(location(name), 1, GL_FALSE, glm::value_ptr(m));
}

void Program::set(const std::string& name, const glm::mat4& m) const {
    glUniformMatrix4fv(location(name), 1, GL_FALSE, glm::value_ptr(m));
}

} // namespace speculum::render::gl
