#include "scene/model/SceneData.hpp"

#include "render/frame/SceneNames.hpp"

#include <utility>

namespace speculum::scene {

namespace {

namespace names = render::names;

// The spellings are render/frame/SceneNames.hpp's, indexed by the enum's value: each table has one name per
// value, in the enum's order.
static_assert(int(BuiltinMesh::Plane) + 1 == names::kBuiltinMeshes.size());
static_assert(int(LightType::Spot) + 1 == names::kLightTypes.size());
static_assert(int(MirrorTechnique::Texture) + 1 == names::kMirrorTechniques.size());
static_assert(int(ReflectorMap::TennisBall) + 1 == names::kReflectorMaps.size());
static_assert(int(ReflectorFill::Resampled) + 1 == names::kReflectorFills.size());
static_assert(int(ReflectorUpdate::Once) + 1 == names::kReflectorUpdates.size());
static_assert(int(ParallaxShape::Box) + 1 == names::kParallaxShapes.size());
static_assert(int(TextureWrap::Mirror) + 1 == names::kTextureWraps.size());
static_assert(int(AlphaMode::Blend) + 1 == names::kAlphaModes.size());

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
    return names::fileName(names::kBuiltinMeshes, kind);
}
std::string_view toString(LightType type) {
    return names::fileName(names::kLightTypes, type);
}
std::string_view toString(MirrorTechnique technique) {
    return names::fileName(names::kMirrorTechniques, technique);
}
std::string_view toString(ReflectorMap map) {
    return names::fileName(names::kReflectorMaps, map);
}

std::optional<BuiltinMesh> builtinMeshFromString(std::string_view name) {
    return names::fromFileName<BuiltinMesh>(names::kBuiltinMeshes, name);
}
std::optional<LightType> lightTypeFromString(std::string_view name) {
    return names::fromFileName<LightType>(names::kLightTypes, name);
}
std::optional<MirrorTechnique> mirrorTechniqueFromString(std::string_view name) {
    return names::fromFileName<MirrorTechnique>(names::kMirrorTechniques, name);
}
std::optional<ReflectorMap> reflectorMapFromString(std::string_view name) {
    return names::fromFileName<ReflectorMap>(names::kReflectorMaps, name);
}
std::string_view toString(ReflectorFill fill) {
    return names::fileName(names::kReflectorFills, fill);
}
std::string_view toString(ReflectorUpdate update) {
    return names::fileName(names::kReflectorUpdates, update);
}
std::string_view toString(ParallaxShape shape) {
    return names::fileName(names::kParallaxShapes, shape);
}
std::optional<ReflectorFill> reflectorFillFromString(std::string_view name) {
    return names::fromFileName<ReflectorFill>(names::kReflectorFills, name);
}
std::optional<ReflectorUpdate> reflectorUpdateFromString(std::string_view name) {
    return names::fromFileName<ReflectorUpdate>(names::kReflectorUpdates, name);
}
std::optional<ParallaxShape> parallaxShapeFromString(std::string_view name) {
    return names::fromFileName<ParallaxShape>(names::kParallaxShapes, name);
}
std::string_view toString(TextureWrap wrap) {
    return names::fileName(names::kTextureWraps, wrap);
}
std::string_view toString(AlphaMode mode) {
    return names::fileName(names::kAlphaModes, mode);
}
std::optional<TextureWrap> textureWrapFromString(std::string_view name) {
    return names::fromFileName<TextureWrap>(names::kTextureWraps, name);
}
std::optional<AlphaMode> alphaModeFromString(std::string_view name) {
    return names::fromFileName<AlphaMode>(names::kAlphaModes, name);
}

} // namespace speculum::scene
