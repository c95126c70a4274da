#pragma once

#include "render/frame/Field.hpp"
#include "render/frame/FrameInput.hpp"
#include "render/frame/SceneLimits.hpp"

#include <QJsonObject>
#include <array>
#include <glm/vec3.hpp>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace speculum::scene {

// Plain value types for everything a project file holds. The Scene (Scene.hpp) owns a tree of these; the
// project reader produces them and the writer consumes them, so "load → save → load" can be checked with ==.
//
// What the renderer draws (settings, camera, materials, lights, mirrors, the reflector) is held in the
// renderer's own structs (render/frame/), which declare their fields; what only the scene has (where a
// node is, its mesh's source, its animation, the editor's view) is declared here the same way. The project
// files, the inspector, the signatures, the import child and the sweep all walk those declarations.
//
// File paths (mesh file, texture) are held ABSOLUTE in memory: the reader resolves them against the project
// file's folder and the writer makes them relative to the folder it saves into. That keeps "Save As" into
// another folder and undo commands that hold old NodeData correct without any rebasing.

// The enumerations of the scene are the renderer's, defined once; the scene adds its built-in meshes.
using render::AlphaMode;
using render::GlossyFilter;
using render::LightType;
using render::MirrorTechnique;
using render::ParallaxShape;
using render::ReflectorFill;
using render::ReflectorMap;
using render::ReflectorTechnique;
using render::ReflectorUpdate;
using render::ScreenFallback;
using render::ScreenResolution;
using render::TextureWrap;

enum class BuiltinMesh { Teapot, Sphere, Box, Plane };
inline constexpr std::array<render::names::Name, 4> kBuiltinMeshNames{{
    {"teapot", "Teapot"},
    {"sphere", "Sphere"},
    {"box", "Box"},
    {"plane", "Plane"},
}};

using SceneSettings = render::Settings;
using CameraData = render::Camera;
using MaterialComponent = render::Material;
using ShadowComponent = render::ShadowParams;
using LightComponent = render::LightParams;
using MirrorComponent = render::MirrorParams;
using ReflectorParallax = render::ParallaxParams;
using ReflectorComponent = render::ReflectorParams;

// The fields of a file this version does not know, kept and written back so that saving a file from a newer
// speculum does not lose that version's data: per JSON object, by its path below its owner ("" the owner
// itself, "light.shadows", "reflector.parallax", ...).
using UnknownFields = std::map<std::string, QJsonObject>;

// Local transform: rotate is XYZ Euler degrees applied X, then Y, then Z (R = Rz·Ry·Rx).
// Local matrix = T × R × S; world = parent world × local.
struct Transform {
    glm::dvec3 translate{0.0};
    glm::dvec3 rotate{0.0};
    glm::dvec3 scale{1.0};
    bool operator==(const Transform&) const = default;

    template <typename Visit>
    static void fields(Visit&& visit);
};

struct MeshComponent {
    // Exactly one source: a built-in shape, or a file (absolute path in memory) that Assimp reads.
    std::optional<BuiltinMesh> builtin = BuiltinMesh::Teapot;
    int tessellation = 8; // built-ins only
    std::string file;     // used when builtin is empty
    // File meshes only: which of the file's meshes (Assimp's scene order, 0-based) this node draws, in
    // that mesh's own coordinates. Absent: every mesh of the file, flattened with the file's own node
    // transforms into one mesh (the whole model as one part).
    std::optional<int> part;
    bool operator==(const MeshComponent&) const = default;

    static MeshComponent fromBuiltin(BuiltinMesh kind, int tessellation = -1);
    static MeshComponent fromFile(std::string absolutePath);

    template <typename Visit>
    static void fields(Visit&& visit);
};

// Tessellation a built-in gets when the file gives none.
int defaultTessellation(BuiltinMesh kind);

// Bounce: the node's y is offset by height·|sin(π·t / period)| (one hop every `period` seconds, resting on
// its translate at t = 0, period, 2·period, ...).
struct BounceAnimation {
    double height = 1.0;
    double period = 2.0;
    bool operator==(const BounceAnimation&) const = default;

    template <typename Visit>
    static void fields(Visit&& visit);
};

// Orbit: the node's translate is replaced by center + radius·(cos 2πt/T, 0, sin 2πt/T), in the parent's
// space, so at t = 0 the node sits at center + (radius, 0, 0).
struct OrbitAnimation {
    glm::dvec3 center{0.0};
    double radius = 1.0;
    double period = 6.0;
    bool operator==(const OrbitAnimation&) const = default;

    template <typename Visit>
    static void fields(Visit&& visit);
};

// Both may be present: orbit sets the position, then bounce lifts it.
struct AnimationComponent {
    std::optional<BounceAnimation> bounce;
    std::optional<OrbitAnimation> orbit;
    bool operator==(const AnimationComponent&) const = default;

    template <typename Visit>
    static void fields(Visit&& visit);
};

// The editor's own view saved with a project: the optional top-level "editorView" of the file (older files
// have none and open in the scene camera). Where the editor looked from and at when the file was saved, so
// that it reopens there. Only the editor reads it: `speculum render`, the exports and the sweep use the
// scene camera. The rest of the view (up, field of view, near plane) is the scene camera's, as
// view::ViewCamera keeps it, and the far plane follows from the distance.
//
// Moving the view is not an edit: it pushes no undo step and does not mark the document modified; the
// editor puts its current view here when it saves (and autosaves).
struct EditorView {
    glm::dvec3 position{0.0, 0.0, 1.0};
    glm::dvec3 target{0.0, 0.0, -3.0};
    bool operator==(const EditorView&) const = default;

    template <typename Visit>
    static void fields(Visit&& visit);
};

// One node's own data, without its children: what SetNodeDataCommand replaces as a whole.
struct NodeData {
    std::string name;
    bool hidden = false; // left out of every picture, with the nodes under it; kept in the document
    Transform transform;
    std::optional<MeshComponent> mesh;
    std::optional<MaterialComponent> material;
    std::optional<LightComponent> light;
    std::optional<MirrorComponent> mirror;
    std::optional<ReflectorComponent> reflector;
    std::optional<AnimationComponent> animation;
    UnknownFields unknown;
    bool operator==(const NodeData&) const = default;

    template <typename Visit>
    static void fields(Visit&& visit);
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
    UnknownFields unknown; // "" for the top level, "settings", "camera", "editorView"
    bool operator==(const SceneData&) const = default;

    template <typename Visit>
    static void fields(Visit&& visit);
};

// ---- declarations ----

namespace spec {
using render::FieldSpec;
using render::FieldType;
using render::FieldWrite;
inline constexpr FieldSpec kPoint{.type = FieldType::Vector3,
                                  .min = -render::kMaxCoordinate,
                                  .max = render::kMaxCoordinate,
                                  .unit = " u",
                                  .noun = "coordinates"};
inline constexpr FieldSpec kPeriod{.min = render::kMinPeriod, .max = render::kMaxPeriod, .unit = " s"};
// `spec` with a name, a label and a meaning.
constexpr FieldSpec named(FieldSpec spec, std::string_view name, std::string_view label,
                          std::string_view meaning) {
    spec.name = name;
    spec.label = label;
    spec.meaning = meaning;
    return spec;
}
} // namespace spec

template <typename Visit>
void Transform::fields(Visit&& visit) {
    using namespace scene::spec;
    using render::field;
    visit(field(&Transform::translate, named(kPoint, "translate", "Translate",
                                             "Where the node's origin is, in "
                                             "its parent's space")));
    visit(field(&Transform::rotate, {.name = "rotate",
                                     .label = "Rotate",
                                     .meaning = "XYZ Euler angles in degrees, applied X, then Y, then Z",
                                     .type = FieldType::Vector3,
                                     .unit = "°",
                                     .step = 5.0}));
    visit(field(&Transform::scale, {.name = "scale",
                                    .label = "Scale",
                                    .meaning = "Along the node's own axes; a negative scale mirrors it",
                                    .type = FieldType::Vector3,
                                    .min = render::kMinScale,
                                    .max = render::kMaxScale,
                                    .rule = render::FieldRule::Magnitude}));
}

template <typename Visit>
void MeshComponent::fields(Visit&& visit) {
    using namespace scene::spec;
    using render::field;
    constexpr auto builtIn = [](const MeshComponent& m) { return m.builtin.has_value(); };
    constexpr auto fromFile = [](const MeshComponent& m) { return !m.builtin.has_value(); };
    visit(field(&MeshComponent::builtin,
                {.name = "builtin",
                 .label = "Shape",
                 .meaning = "A built-in shape (instead of a file)",
                 .type = FieldType::Choice,
                 .noun = "builtin mesh",
                 .choices = kBuiltinMeshNames,
                 .write = FieldWrite::WhenApplies},
                builtIn));
    visit(field(&MeshComponent::tessellation,
                {.name = "tessellation",
                 .label = "Tessellation",
                 .meaning = "Subdivisions of the built-in shape (teapot: per patch edge, sphere: rings)",
                 .type = FieldType::Integer,
                 .min = render::kMinTessellation,
                 .max = render::kMaxTessellation,
                 .write = FieldWrite::WhenApplies},
                builtIn));
    visit(field(&MeshComponent::file,
                {.name = "file",
                 .label = "File",
                 .meaning = "A model file Assimp reads (instead of a built-in shape)",
                 .type = FieldType::Path,
                 .write = FieldWrite::WhenApplies},
                fromFile));
    visit(field(
        &MeshComponent::part,
        {.name = "part",
         .label = "Part",
         .meaning = "Which mesh of the file this node draws, in its own coordinates; absent for all of it",
         .type = FieldType::Integer,
         .min = 0,
         .max = 1e9,
         .write = FieldWrite::WhenApplies},
        fromFile));
}

template <typename Visit>
void BounceAnimation::fields(Visit&& visit) {
    using namespace scene::spec;
    using render::field;
    FieldSpec height = named(kPoint, "height", "Bounce height", "How high each hop lifts the node");
    height.type = FieldType::Number;
    height.noun = {};
    visit(field(&BounceAnimation::height, height));
    visit(field(&BounceAnimation::period, named(kPeriod, "period", "Bounce period", "Seconds per hop")));
}

template <typename Visit>
void OrbitAnimation::fields(Visit&& visit) {
    using namespace scene::spec;
    using render::field;
    visit(field(&OrbitAnimation::center,
                named(kPoint, "center", "Orbit centre", "The point the node circles")));
    visit(field(&OrbitAnimation::radius, {.name = "radius",
                                          .label = "Orbit radius",
                                          .meaning = "The circle's radius",
                                          .min = 0,
                                          .max = render::kMaxCoordinate,
                                          .unit = " u"}));
    visit(field(&OrbitAnimation::period, named(kPeriod, "period", "Orbit period", "Seconds per turn")));
}

template <typename Visit>
void AnimationComponent::fields(Visit&& visit) {
    using namespace scene::spec;
    using render::field;
    visit(field(&AnimationComponent::bounce, {.name = "bounce",
                                              .label = "Bounce",
                                              .meaning = "Hops up and down on the node's own position",
                                              .type = FieldType::Object}));
    visit(field(&AnimationComponent::orbit, {.name = "orbit",
                                             .label = "Orbit",
                                             .meaning = "Circles a centre in the parent's XZ plane",
                                             .type = FieldType::Object}));
}

template <typename Visit>
void EditorView::fields(Visit&& visit) {
    using namespace scene::spec;
    using render::field;
    visit(field(&EditorView::position, named(kPoint, "position", "Position", "Where the editor's view was")));
    visit(field(&EditorView::target,
                named(kPoint, "target", "Target", "The point the editor's view looked at")));
}

template <typename Visit>
void NodeData::fields(Visit&& visit) {
    using namespace scene::spec;
    using render::field;
    const auto component = [](std::string_view name, std::string_view label, std::string_view meaning) {
        return FieldSpec{.name = name, .label = label, .meaning = meaning, .type = FieldType::Object};
    };
    visit(field(&NodeData::name,
                {.name = "name", .label = "Name", .meaning = "The node's name", .type = FieldType::Text}));
    visit(field(&NodeData::hidden, {.name = "hidden",
                                    .label = "Hidden",
                                    .meaning = "Left out of every picture (the viewport, stills, the bench, "
                                               "picking) with the nodes under it; kept in the document",
                                    .type = FieldType::Bool,
                                    .write = render::FieldWrite::UnlessDefault}));
    visit(field(&NodeData::transform, component("transform", "Transform", "Where the node is")));
    visit(field(&NodeData::mesh, component("mesh", "Mesh", "The node's shape: built in, or from a file")));
    visit(field(&NodeData::material, component("material", "Material", "How the node's surface is lit")));
    visit(field(&NodeData::light, component("light", "Light", "A light at the node's origin")));
    visit(field(&NodeData::mirror, component("mirror", "Planar mirror",
                                             "A mirror rectangle in the node's XZ "
                                             "plane")));
    visit(field(&NodeData::reflector, component("reflector", "Curved reflector",
                                                "The node's mesh reflects "
                                                "through an environment map")));
    visit(field(&NodeData::animation, component("animation", "Animation", "How the node moves with time")));
}

template <typename Visit>
void SceneData::fields(Visit&& visit) {
    using namespace scene::spec;
    using render::field;
    visit(field(&SceneData::settings, {.name = "settings",
                                       .label = "Scene",
                                       .meaning = "The scene's settings",
                                       .type = FieldType::Object}));
    visit(field(&SceneData::camera, {.name = "camera",
                                     .label = "Camera",
                                     .meaning = "The camera the scene is drawn from",
                                     .type = FieldType::Object}));
    visit(field(&SceneData::editorView, {.name = "editorView",
                                         .label = "Editor view",
                                         .meaning = "Where the editor last looked from (the editor's alone)",
                                         .type = FieldType::Object}));
}

} // namespace speculum::scene
