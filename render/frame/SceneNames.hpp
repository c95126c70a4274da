#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace speculum::render::names {

// How each choice a scene makes is spelled: `file` in project files, on the command line and in bench
// results ("dual-paraboloid"), `label` for people (the inspector's options, reports: "Dual paraboloid").
// Each table is in the order of its enum (render/frame/, scene/model/SceneData.hpp for the built-in
// meshes): the index is the enum's value. Qt-free and GL-free, so every layer reads the same list.
struct Name {
    std::string_view file;
    std::string_view label;
};

inline constexpr std::array<Name, 4> kReflectorMaps{{
    {"cube", "Cube"},
    {"dual-paraboloid", "Dual paraboloid"},
    {"tennis-ball", "Tennis ball"},
    {"octahedral", "Octahedral"},
}};
inline constexpr std::array<Name, 2> kReflectorFills{{
    {"direct", "Direct (vertex warp)"},
    {"resampled", "Resampled cube"},
}};
inline constexpr std::array<Name, 4> kReflectorUpdates{{
    {"always", "Always"},
    {"on-change", "When something it sees changes"},
    {"once", "Once"},
    {"time-sliced", "One face a frame, while any is out of date"},
}};
// How the curved reflector's reflection is drawn: its environment map alone, or traced in the camera's
// image first with the map where the trace finds nothing.
inline constexpr std::array<Name, 2> kReflectorTechniques{{
    {"map", "Environment map"},
    {"screen-space", "Screen space, then the map"},
}};
inline constexpr std::array<Name, 3> kMirrorTechniques{{
    {"stencil", "Stencil"},
    {"texture", "Texture"},
    {"screen-space", "Screen space (traced in the image)"},
}};
inline constexpr std::array<Name, 3> kGlossyFilters{{
    {"mip", "Mip level (cheap)"},
    {"footprint", "Lobe footprint / pre-filtered map"},
    {"chain", "Convolved chain / pre-filtered map"},
}};
// Where a screen-space mirror's ray that finds nothing in the camera's image takes its reflection from.
inline constexpr std::array<Name, 2> kScreenFallbacks{{
    {"map", "The reflector's map, then the background"},
    {"background", "The background"},
}};
// The resolution a screen-space mirror's reflection is traced at, against the camera's image.
inline constexpr std::array<Name, 2> kScreenResolutions{{
    {"full", "Full"},
    {"half", "Half (a quarter of the rays, scaled up)"},
}};
// A true-or-false setting as bench results spell it: settings.simplifyReflections.
inline constexpr std::array<Name, 2> kReflectedDetail{{
    {"full", "Full"},
    {"simplified", "Simplified"},
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
inline constexpr std::array<Name, 2> kParallaxShapes{{
    {"sphere", "Sphere"},
    {"box", "Box"},
}};

// The file spelling of an enum value (an out-of-range value is a programmer error: "?").
template <typename E>
constexpr std::string_view fileName(std::span<const Name> names, E value) {
    const auto i = static_cast<std::size_t>(value);
    return i < names.size() ? names[i].file : std::string_view("?");
}

// The enum value a file spelling names, or nothing.
template <typename E>
constexpr std::optional<E> fromFileName(std::span<const Name> names, std::string_view file) {
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (names[i].file == file) {
            return static_cast<E>(i);
        }
    }
    return std::nullopt;
}

// "cube, dual-paraboloid or tennis-ball": the file spellings for a message.
inline std::string choices(std::span<const Name> names) {
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i) {
        out += i == 0 ? "" : i + 1 == names.size() ? " or " : ", ";
        out += names[i].file;
    }
    return out;
}

} // namespace speculum::render::names
