#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace speculum::render::names {

// How each choice a scene makes is spelled: `file` in project files, on the command line and in bench
// results ("dual-paraboloid"), `label` for people (the inspector's options, reports: "Dual paraboloid").
// Each table is in the order of its enum, here (FrameInput.hpp) and in scene/model/SceneData.hpp
// alike: the index is the enum's value. Qt-free and GL-free, so every layer reads the same list.
struct Name {
    std::string_view file;
    std::string_view label;
};

inline constexpr std::array<Name, 3> kReflectorMaps{{
    {"cube", "Cube"},
    {"dual-paraboloid", "Dual paraboloid"},
    {"tennis-ball", "Tennis ball"},
}};
inline constexpr std::array<Name, 2> kReflectorFills{{
    {"direct", "Direct (vertex warp)"},
    {"resampled", "Resampled cube"},
}};
inline constexpr std::array<Name, 3> kReflectorUpdates{{
    {"always", "Always"},
    {"on-change", "When something it sees changes"},
    {"once", "Once"},
}};
inline constexpr std::array<Name, 2> kMirrorTechniques{{
    {"stencil", "Stencil"},
    {"texture", "Texture"},
}};
inline constexpr std::array<Name, 2> kGlossyFilters{{
    {"mip", "Mip level (cheap)"},
    {"footprint", "Lobe footprint / pre-filtered map"},
}};
inline constexpr std::array<Name, 3> kLightTypes{{
    {"point", "Point"},
    {"directional", "Directional"},
    {"spot", "Spot"},
}};
inline constexpr std::array<Name, 3> kTextureWraps{{
    {"repeat", "Repeat"},
    {"clamp", "Clamp"},
    {"mirror", "Mirror"},
}};
inline constexpr std::array<Name, 3> kAlphaModes{{
    {"opaque", "Opaque"},
    {"mask", "Mask"},
    {"blend", "Blend (drawn as mask)"},
}};
// The document's own enums (scene/model/SceneData.hpp): the built-in meshes, and a reflector's parallax
// proxy, which the frame input spells with a None first (FrameInput's ParallaxProxy::Shape).
inline constexpr std::array<Name, 4> kBuiltinMeshes{{
    {"teapot", "Teapot"},
    {"sphere", "Sphere"},
    {"box", "Box"},
    {"plane", "Plane"},
}};
inline constexpr std::array<Name, 2> kParallaxShapes{{
    {"sphere", "Sphere"},
    {"box", "Box"},
}};

// The file spelling of an enum value (an out-of-range value is a programmer error: "?").
template <typename E, std::size_t N>
constexpr std::string_view fileName(const std::array<Name, N>& names, E value) {
    const auto i = static_cast<std::size_t>(value);
    return i < N ? names[i].file : std::string_view("?");
}

// The enum value a file spelling names, or nothing.
template <typename E, std::size_t N>
constexpr std::optional<E> fromFileName(const std::array<Name, N>& names, std::string_view file) {
    for (std::size_t i = 0; i < N; ++i) {
        if (names[i].file == file) {
            return static_cast<E>(i);
        }
    }
    return std::nullopt;
}

// "cube, dual-paraboloid or tennis-ball": the file spellings for a message.
template <std::size_t N>
std::string choices(const std::array<Name, N>& names) {
    std::string out;
    for (std::size_t i = 0; i < N; ++i) {
        out += i == 0 ? "" : i + 1 == N ? " or " : ", ";
        out += names[i].file;
    }
    return out;
}

} // namespace speculum::render::names
