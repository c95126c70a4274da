#pragma once

#include <string_view>
#include <vector>

namespace speculum::render::gl {

struct EmbeddedShader {
    std::string_view name; // file name under shaders/, used in compile error messages
    std::string_view source;
};

// Generated at build time from shaders/ (see cmake/EmbedShaders.cmake).
const std::vector<EmbeddedShader>& embeddedShaders();

} // namespace speculum::render::gl
