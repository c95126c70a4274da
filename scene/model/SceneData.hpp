#pragma once

#include "scene/model/EditorView.hpp"

#include <QJsonObject>
#include <array>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace speculum::scene {

// Plain value types for everything a project file holds. The Scene (Scene.hpp) owns a tree of these; the
// project reader produces them and the writer consumes them, so "load → save → load" can be checked with ==.
//
// Every struct that maps to a JSON object carries `extra`: the fields this version does not know. They are
// kept and written back so that saving a file from a newer speculum does not lose that version's data.
//
// File paths (mesh file, texture) are held ABSOLUTE in memory: the reader resolves them against the project
// file's folder and the writer makes them relative to the folder it saves into. That keeps "Save As" into
// another folder and undo commands that hold old NodeData correct without any rebasing.

// render::GlossyFilter, in the order of render::names::kGlossyFilters.
enum class GlossyFilter { Mip, Footprint };

struct SceneSettings {
    glm::dvec3 background{0.1, 0.1, 0.12};
    int mirrorDepth = 3;
    double ambient = 0.2;
    bool simplifyReflections = true; // render::Settings::simplifyReflections
    // How rough reflections are approximated (render::Settings, same names and defaults).
    GlossyFilter glossyFilter = GlossyFilter::Footprint;
    int glossyTaps = 16;
    int prefilterSamples = 64;
    QJsonObject extra;
    bool operator==(const SceneSettings&) const = default;
};

struct CameraData {
    glm::dvec3 position{0.0, 0.0, 1.0};
    glm::dvec3 target{0.0, 0.0, -3.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    double fovY = 65.0; // degrees, vertical
    double near = 0.1;
    double far = 10.0;
    QJsonObject extra;
    bool operator==(const CameraData&) const = default;
};

// Local transform: rotate is XYZ Euler degrees applied X, then Y, then Z (R = Rz·Ry·Rx).
// Local matrix = T × R × S; world = parent world × local.
struct Transform {
    glm::dvec3 translate{0.0};
    glm::dvec3 rotate{0.0};
    glm::dvec3 scale{1.0};
    QJsonObject extra;
    bool operator==(const Transform&) const = default;
};

enum class BuiltinMesh { Teapot, Sphere, Box, Plane };

struct MeshComponent {
    // Exactly one source: a built-in shape, or a file (absolute path in memory) that Assimp reads.
    std::optional<BuiltinMesh> builtin = BuiltinMesh::Teapot;
    int tessellation = 8; // built-ins only; 1..64
    std::string file;     // used when builtin is empty
    // File meshes only: which of the file's meshes (Assimp's scene order, 0-based) this node draws, in
    // that mesh's own coordinates. Absent: every mesh of the file, flattened with the file's own node
    // transforms into one mesh (the whole model as one part).
    std::optional<int> part;
    QJsonObject extra;
    bool operator==(const MeshComponent&) const = default;

    static MeshComponent fromBuiltin(BuiltinMesh kind, int tessellation = -1);
    static MeshComponent fromFile(std::string absolutePath);
};

// Tessellation a built-in gets when the file gives none.
int defaultTessellation(BuiltinMesh kind);

enum class TextureWrap { Repeat, Clamp, Mirror };
enum class AlphaMode { Opaque, Mask, Blend };

// Blinn-Phong; defaults are DESIGN.md's. render::Material documents the full formula.
//
// Texture paths are absolute in memory. A texture embedded in a model file is named by the model's path,
// '#', and Assimp's name for it: "/abs/models/duck.glb#*0" (written relative like any path).
struct MaterialComponent {
    glm::dvec3 color{0.8, 0.8, 0.8};
    double ambient = 1.0;
    double diffuse = 1.0;
    double specular = 0.0;
    double shininess = 32.0;
    glm::dvec3 emission{0.0};
    std::string texture; // base colour texture, empty for none
    // Fields for imported models (all optional: a file without them draws as before).
    glm::dvec3 specularColor{1.0};
    std::string emissionTexture; // multiplies emission
    std::string normalTexture;   // tangent-space normal map
    double normalScale = 1.0;
    std::array<TextureWrap, 2> wrap{TextureWrap::Repeat, TextureWrap::Repeat}; // u, v; every texture
    double opacity = 1.0;                                                      // base alpha, 0..1
    AlphaMode alphaMode = AlphaMode::Opaque;
    double alphaCutoff = 0.5;
    QJsonObject extra;
    bool operator==(const MaterialComponent&) const = default;
};

enum class LightType { Point, Directional, Spot };

struct ShadowComponent {
    int mapSize = 1024; // power of two, 16..16384
    int pcf = 1;        // odd kernel width in texels, 1..15 (1 = hard shadows)
    QJsonObject extra;
    bool operator==(const ShadowComponent&) const = default;
};

struct LightComponent {
    LightType type = LightType::Point;
    glm::dvec3 color{1.0};
    double intensity = 1.0;
    double spotAngle = 30.0;                // outer half angle, degrees, (0, 90]
    double spotBlend = 0.15;                // fraction of the cone over which the edge fades, 0..1
    std::optional<ShadowComponent> shadows; // present = the light casts shadows
    QJsonObject extra;
    bool operator==(const LightComponent&) const = default;
};

// Bounce: the node's y is offset by height·|sin(π·t / period)| (one hop every `period` seconds, resting on
// its translate at t = 0, period, 2·period, ...).
struct BounceAnimation {
    double height = 1.0;
    double period = 2.0;
    QJsonObject extra;
    bool operator==(const BounceAnimation&) const = default;
};

// Orbit: the node's translate is replaced by center + radius·(cos 2πt/T, 0, sin 2πt/T), in the parent's
// space, so at t = 0 the node sits at center + (radius, 0, 0).
struct OrbitAnimation {
    glm::dvec3 center{0.0};
    double radius = 1.0;
    double period = 6.0;
    QJsonObject extra;
    bool operator==(const OrbitAnimation&) const = default;
};

// Both may be present: orbit sets the position, then bounce lifts it.
struct AnimationComponent {
    std::optional<BounceAnimation> bounce;
    std::optional<OrbitAnimation> orbit;
    QJsonObject extra;
    bool operator==(const AnimationComponent&) const = default;
};

enum class MirrorTechnique { Stencil, Texture };

// A rectangle centred at the node origin in its local XZ plane, reflective side towards local +Y.
struct MirrorComponent {
    glm::dvec2 size{1.0, 1.0}; // [x extent, z extent]
    double reflectivity = 1.0; // 0..1
    MirrorTechnique technique = MirrorTechnique::Stencil;
    glm::dvec3 tint{1.0, 1.0, 1.0}; // multiplies the reflection, linear RGB 0..1
    bool fresnel = false;           // Schlick: `reflectivity` at normal incidence, rising to 1 at grazing
    // 0..1: GGX microfacet roughness of the reflection, α = roughness² (0: a perfect mirror). The file's
    // older `blur` field loads as this roughness, unchanged in value.
    double roughness = 0.0;
    QJsonObject extra;
    bool operator==(const MirrorComponent&) const = default;
};

enum class ReflectorMap { Cube, DualParaboloid, TennisBall };
// How the two non-linear maps are filled: warping the scene's vertices (the reference's method, needs fine
// tessellation) or resampling a cube map rendered first (exact up to the cube's resolution).
enum class ReflectorFill { Direct, Resampled };
// When the map is rendered again: every frame, when something it sees changed, or once.
enum class ReflectorUpdate { Always, OnChange, Once };
enum class ParallaxShape { Sphere, Box };

// Parallax correction: a proxy of the environment around the capture point (the reflector's centre),
// in world axes and units relative to that point. Lookups intersect the reflected ray with it.
struct ReflectorParallax {
    ParallaxShape shape = ParallaxShape::Sphere;
    double radius = 5.0;              // sphere
    glm::dvec3 min{-5.0, -5.0, -5.0}; // box, relative to the capture point
    glm::dvec3 max{5.0, 5.0, 5.0};
    QJsonObject extra;
    bool operator==(const ReflectorParallax&) const = default;
};

// The curved reflector (at most one per scene); its surface is the node's mesh.
struct ReflectorComponent {
    ReflectorMap map = ReflectorMap::Cube;
    int resolution = 256; // 8..8192
    double reflectivity = 1.0;
    bool fresnel = false; // Schlick: `reflectivity` at normal incidence, rising to 1 at grazing angles
    ReflectorFill fill = ReflectorFill::Resampled;
    std::optional<ReflectorParallax> parallax; // off when absent
    ReflectorUpdate update = ReflectorUpdate::OnChange;
    int mirrorDepth = 1;    // levels of planar mirrors inside the environment map, 0..16
    double roughness = 0.0; // 0..1, GGX roughness of the reflection, as a mirror's
    QJsonObject extra;
    bool operator==(const ReflectorComponent&) const = default;
};

// One node's own data, without its children: what SetNodeDataCommand replaces as a whole.
struct NodeData {
    std::string name;
    Transform transform;
    std::optional<MeshComponent> mesh;
    std::optional<MaterialComponent> material;
    std::optional<LightComponent> light;
    std::optional<MirrorComponent> mirror;
    std::optional<ReflectorComponent> reflector;
    std::optional<AnimationComponent> animation;
    QJsonObject extra;
    bool operator==(const NodeData&) const = default;
};

// A node with its subtree, as a value (file contents, clipboard, the payload of add/remove commands).
struct NodeTree {
    NodeData data;
    std::vector<NodeTree> children;
    bool operator==(const NodeTree&) const = default;
};

// A whole project as a value.
struct SceneData {
    SceneSettings settings;
    CameraData camera; // what `speculum render`, the exports and the sweep see
    // Where the editor last looked from: the editor's alone, never the scene camera. Absent in older files.
    std::optional<EditorView> editorView;
    std::vector<NodeTree> nodes;
    QJsonObject extra; // unknown top-level fields
    bool operator==(const SceneData&) const = default;
};

// Names as they appear in the file.
std::string_view toString(BuiltinMesh kind);
std::string_view toString(LightType type);
std::string_view toString(MirrorTechnique technique);
std::string_view toString(ReflectorMap map);
std::string_view toString(ReflectorFill fill);
std::string_view toString(ReflectorUpdate update);
std::string_view toString(ParallaxShape shape);
std::string_view toString(TextureWrap wrap);
std::string_view toString(AlphaMode mode);
std::optional<BuiltinMesh> builtinMeshFromString(std::string_view name);
std::optional<LightType> lightTypeFromString(std::string_view name);
std::optional<MirrorTechnique> mirrorTechniqueFromString(std::string_view name);
std::optional<ReflectorMap> reflectorMapFromString(std::string_view name);
std::optional<ReflectorFill> reflectorFillFromString(std::string_view name);
std::optional<ReflectorUpdate> reflectorUpdateFromString(std::string_view name);
std::optional<ParallaxShape> parallaxShapeFromString(std::string_view name);
std::optional<TextureWrap> textureWrapFromString(std::string_view name); // "repeat", "clamp", "mirror"
std::optional<AlphaMode> alphaModeFromString(std::string_view name);     // "opaque", "mask", "blend"

} // namespace speculum::scene
