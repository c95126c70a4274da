#include "editor/document/SceneData.hpp"

#include <array>
#include <utility>

namespace speculum::document {

namespace {

template <typename E>
using NameTable = std::array<std::pair<E, std::string_view>, 4>;

constexpr NameTable<BuiltinMesh> kBuiltinNames{{{BuiltinMesh::Teapot, "teapot"},
                                                {BuiltinMesh::Sphere, "sphere"},
                                                {BuiltinMesh::Box, "box"},
                                                {BuiltinMesh::Plane, "plane"}}};

template <typename E, std::size_t N>
std::string_view nameOf(const std::array<std::pair<E, std::string_view>, N>& table, E value) {
    for (const auto& [e, name] : table) {
        if (e == value) {
            return name;
        }
    }
    return "?";
}

template <typename E, std::size_t N>
std::optional<E> valueOf(const std::array<std::pair<E, std::string_view>, N>& table, std::string_view name) {
    for (const auto& [e, n] : table) {
        if (n == name) {
            return e;
        }
    }
    return std::nullopt;
}

constexpr std::array<std::pair<LightType, std::string_view>, 3> kLightNames{
    {{LightType::Point, "point"}, {LightType::Directional, "directional"}, {LightType::Spot, "spot"}}};

constexpr std::array<std::pair<MirrorTechnique, std::string_view>, 2> kTechniqueNames{
    {{MirrorTechnique::Stencil, "stencil"}, {MirrorTechnique::Texture, "texture"}}};

constexpr std::array<std::pair<ReflectorMap, std::string_view>, 3> kMapNames{
    {{ReflectorMap::Cube, "cube"},
     {ReflectorMap::DualParaboloid, "dual-paraboloid"},
     {ReflectorMap::TennisBall, "tennis-ball"}}};

constexpr std::array<std::pair<ReflectorFill, std::string_view>, 2> kFillNames{
    {{ReflectorFill::Direct, "direct"}, {ReflectorFill::Resampled, "resampled"}}};

constexpr std::array<std::pair<ReflectorUpdate, std::string_view>, 3> kUpdateNames{
    {{ReflectorUpdate::Always, "always"},
     {ReflectorUpdate::OnChange, "on-change"},
     {ReflectorUpdate::Once, "once"}}};

constexpr std::array<std::pair<ParallaxShape, std::string_view>, 2> kShapeNames{
    {{ParallaxShape::Sphere, "sphere"}, {ParallaxShape::Box, "box"}}};

constexpr std::array<std::pair<TextureWrap, std::string_view>, 3> kWrapNames{
    {{TextureWrap::Repeat, "repeat"}, {TextureWrap::Clamp, "clamp"}, {TextureWrap::Mirror, "mirror"}}};

constexpr std::array<std::pair<AlphaMode, std::string_view>, 3> kAlphaModeNames{
    {{AlphaMode::Opaque, "opaque"}, {AlphaMode::Mask, "mask"}, {AlphaMode::Blend, "blend"}}};

} // namespace

int defaultTessellation(BuiltinMesh kind) {
    switch (kind) {
    case BuiltinMesh::Teapot:
        return 8; // per Bézier patch edge: smooth enough for a hero object
    case BuiltinMesh::Sphere:
        return 32; // rings; render::kSphereDefaultTessellation

    case BuiltinMesh::Box:
    case BuiltinMesh::Plane:
        return 1; // flat faces need no subdivision
    }
    return 1;
}

MeshComponent MeshComponent::fromBuiltin(BuiltinMesh kind, int tessellation) {
    MeshComponent mesh;
    mesh.builtin = kind;
    mesh.tessellation = tessellation > 0 ? tessellation : defaultTessellation(kind);
    return mesh;
}

MeshComponent MeshComponent::fromFile(std::string absolutePath) {
    MeshComponent mesh;
    mesh.builtin.reset();
    mesh.tessellation = 1; // unused for files; fixed so that equality stays meaningful
    mesh.file = std::move(absolutePath);
    return mesh;
}

std::string_view toString(BuiltinMesh kind) {
    return nameOf(kBuiltinNames, kind);
}
std::string_view toString(LightType type) {
    return nameOf(kLightNames, type);
}
std::string_view toString(MirrorTechnique technique) {
    return nameOf(kTechniqueNames, technique);
}
std::string_view toString(ReflectorMap map) {
    return nameOf(kMapNames, map);
}

std::optional<BuiltinMesh> builtinMeshFromString(std::string_view name) {
    return valueOf(kBuiltinNames, name);
}
std::optional<LightType> lightTypeFromString(std::string_view name) {
    return valueOf(kLightNames, name);
}
std::optional<MirrorTechnique> mirrorTechniqueFromString(std::string_view name) {
    return valueOf(kTechniqueNames, name);
}
std::optional<ReflectorMap> reflectorMapFromString(std::string_view name) {
    return valueOf(kMapNames, name);
}
std::string_view toString(ReflectorFill fill) {
    return nameOf(kFillNames, fill);
}
std::string_view toString(ReflectorUpdate update) {
    return nameOf(kUpdateNames, update);
}
std::string_view toString(ParallaxShape shape) {
    return nameOf(kShapeNames, shape);
}
std::optional<ReflectorFill> reflectorFillFromString(std::string_view name) {
    return valueOf(kFillNames, name);
}
std::optional<ReflectorUpdate> reflectorUpdateFromString(std::string_view name) {
    return valueOf(kUpdateNames, name);
}
std::optional<ParallaxShape> parallaxShapeFromString(std::string_view name) {
    return valueOf(kShapeNames, name);
}
std::string_view toString(TextureWrap wrap) {
    return nameOf(kWrapNames, wrap);
}
std::string_view toString(AlphaMode mode) {
    return nameOf(kAlphaModeNames, mode);
}
std::optional<TextureWrap> textureWrapFromString(std::string_view name) {
    return valueOf(kWrapNames, name);
}
std::optional<AlphaMode> alphaModeFromString(std::string_view name) {
    return valueOf(kAlphaModeNames, name);
}

} // namespace speculum::document
