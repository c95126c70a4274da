#include "GlslRunner.hpp"

#include <gtest/gtest.h>

namespace speculum::test {

namespace {

render::gl::ShaderHandle compileShader(GLenum stage, const std::string& text, std::string& error) {
    render::gl::ShaderHandle shader(glCreateShader(stage));
    const char* src = text.c_str();
    glShaderSource(shader.id(), 1, &src, nullptr);
    glCompileShader(shader.id());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096] = {};
        glGetShaderInfoLog(shader.id(), sizeof log, nullptr, log);
        error = log;
        return {};
    }
    return shader;
}

const char* kFragmentMain = R"(
uniform sampler2D uInput;
uniform int uMode;
uniform int uType;
uniform vec4 uLayout;
uniform sampler2DArray uMap;
uniform samplerCube uCube;
uniform float uGrad;
out vec4 result;

void main() {
    vec4 v = texelFetch(uInput, ivec2(gl_FragCoord.xy), 0);
    int component = int(v.w + 0.5);
    if (uMode == 0) {
        int c = envmapComponent(uType, v.xyz);
        result = vec4(float(c), envmapUv(uType, c, v.xyz), 0.0);
    } else if (uMode == 1) {
        result = vec4(envmapDirection(uType, component, v.xy), 0.0);
    } else if (uMode == 2 || uMode == 3) {
        mat3x2 j = envmapUvJacobian(uType, component, normalize(v.xyz));
        result = uMode == 2 ? vec4(j[0], j[1]) : vec4(j[2], 0.0, 0.0);
    } else if (uMode == 4) {
        result = texture(uCube, v.xyz);
    } else if (uMode == 5) {
        result = envmapWarp(v.xyz);
    } else {
        vec3 d = normalize(v.xyz);
        vec3 tx = normalize(cross(d, vec3(0.31, 0.77, 0.56)));
        vec3 gx = uGrad * tx;
        vec3 gy = uGrad * cross(d, tx);
        result = uType == ENVMAP_CUBE ? envmapLookupCube(uCube, d, gx, gy)
                                      : envmapLookup2D(uMap, uType, uLayout, d, gx, gy);
    }
}
)";

} // namespace

std::string shaderText(const std::string& file) {
    std::vector<std::string> numbers;
    auto text = render::gl::preprocessShader(file, "", numbers);
    EXPECT_TRUE(text.ok()) << (text.ok() ? "" : text.error());
    return text.ok() ? *text : std::string();
}

render::gl::ProgramHandle compileProgram(const std::string& vertex, const std::string& fragment,
                                         std::string& error) {
    auto vs = compileShader(GL_VERTEX_SHADER, vertex, error);
    if (!vs)
        return {};
    auto fs = compileShader(GL_FRAGMENT_SHADER, fragment, error);
    if (!fs)
        return {};
    render::gl::ProgramHandle program(glCreateProgram());
    glAttachShader(program.id(), vs.id());
    glAttachShader(program.id(), fs.id());
    glBindAttribLocation(program.id(), 0, "aPosition");
    glBindAttribLocation(program.id(), 1, "aColor");
    glLinkProgram(program.id());
    GLint ok = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[4096] = {};
        glGetProgramInfoLog(program.id(), sizeof log, nullptr, log);
        error = log;
        return {};
    }
    return program;
}

bool GlslRunner::build(std::string& error) {
    m_program =
        compileProgram(shaderText("fullscreen.vert"), shaderText("envmap_warp.glsl") + kFragmentMain, error);
    return bool(m_program);
}

std::vector<glm::vec4> GlslRunner::run(int mode, int type, const std::vector<glm::vec4>& inputs,
                                       const std::function<void()>& setUniforms) {
    constexpr int kWidth = 256;
    const int height = std::max<int>(1, int((inputs.size() + kWidth - 1) / kWidth));
    std::vector<glm::vec4> padded(std::size_t(kWidth) * height, glm::vec4(0.0f, 0.0f, 1.0f, 0.0f));
    std::copy(inputs.begin(), inputs.end(), padded.begin());

    render::gl::Texture input = render::gl::makeTexture();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, input.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, kWidth, height, 0, GL_RGBA, GL_FLOAT, padded.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    render::gl::Texture output = render::gl::makeTexture();
    glBindTexture(GL_TEXTURE_2D, output.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, kWidth, height, 0, GL_RGBA, GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, input.id());

    render::gl::FramebufferBinding keep;
    render::gl::Framebuffer fbo = render::gl::makeFramebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, output.id(), 0);
    EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
    glViewport(0, 0, kWidth, height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);

    glUseProgram(m_program.id());
    glUniform1i(glGetUniformLocation(m_program.id(), "uInput"), 0);
    glUniform1i(glGetUniformLocation(m_program.id(), "uMode"), mode);
    glUniform1i(glGetUniformLocation(m_program.id(), "uType"), type);
    glUniform1i(glGetUniformLocation(m_program.id(), "uMap"), 1);
    glUniform1i(glGetUniformLocation(m_program.id(), "uCube"), 2);
    if (setUniforms)
        setUniforms();
    render::gl::VertexArray vao = render::gl::makeVertexArray();
    glBindVertexArray(vao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);

    std::vector<glm::vec4> out(padded.size());
    glReadPixels(0, 0, kWidth, height, GL_RGBA, GL_FLOAT, out.data());
    out.resize(inputs.size());
    glUseProgram(0);
    return out;
}

} // namespace speculum::test
