#pragma once

#include "render/image/Image.hpp"
#include "render/mesh/MeshData.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace speculum::render {

// A snapshot of everything one frame needs, in plain structs. Transforms are double precision world
// matrices; the renderer makes them camera-relative before converting to float.

// How the rasterizer approximates a rough (glossy) reflection; the exact answer is the tracer's.
// Mip: one lookup in the reflection's mip chain at a level set by the roughness alone (the cheap end).
// Footprint: planar mirrors sample their reflection texture over the GGX lobe's footprint, which grows with
// the distance from the mirror to what it reflects; the curved reflector reads the level of its
// GGX-convolved (pre-filtered) map chain that matches its roughness.
enum class GlossyFilter { Mip, Footprint };

struct Settings {
    glm::dvec3 background{0.1, 0.1, 0.12};
    int mirrorDepth = 3;
    double ambient = 0.2;
    // Reflected views and the environment map draw big meshes at their simplified level
    // (MeshData::coarse): an approximation the bench's reflected-detail family measures.
    bool simplifyReflections = true;
    GlossyFilter glossyFilter = GlossyFilter::Footprint;
    int glossyTaps = 16;       // lobe samples per pixel of a rough planar mirror (Footprint)
    int prefilterSamples = 64; // lobe samples per texel of the reflector's pre-filtered chain (Footprint)
};

struct Camera {
    glm::dvec3 position{0.0, 0.0, 1.0};
    glm::dvec3 target{0.0, 0.0, -3.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    double fovY = 65.0; // degrees, vertical
    double near = 0.1;
    double far = 10.0;
};

// How texture coordinates outside [0, 1] are read (glTF sampler wrapS / wrapT, Assimp's mapping modes).
enum class TextureWrap { Repeat, ClampToEdge, MirroredRepeat };

// One texture a material samples. Either a file (`path`, absolute) that the renderer loads itself, or an
// image already decoded (`image`: a model's embedded texture), in which case `path` is only its name for
// messages and caches ("/abs/model.glb#*0"). Both renderers read it with the same wrap modes.
struct TextureSource {
    std::string path;
    std::shared_ptr<const TextureImage> image;
    TextureWrap wrapS = TextureWrap::Repeat;
    TextureWrap wrapT = TextureWrap::Repeat;

    bool empty() const { return path.empty() && !image; }
};

// glTF's alphaMode: Opaque ignores alpha; Mask discards fragments whose alpha (opacity × texture alpha ×
// vertex alpha) is below alphaCutoff, in both renderers and in shadows; Blend is drawn as Mask at 0.5
// (a warned fallback: no sorted transparency yet).
enum class AlphaMode { Opaque, Mask, Blend };

// Blinn-Phong (DESIGN.md), with the additions model files need:
//   base     = color · baseTexture.rgb · vertexColor.rgb
//   emitted  = emission · emissionTexture.rgb
//   out      = emitted + base·(ambient·sceneAmbient + diffuse·Σ n·l·vis·L) + specular·specularColor·Σ
//   (n·h)^s·vis·L
// with n taken from the normal map (tangent space, scaled in xy by normalScale) when there is one and the
// mesh has tangents.
struct Material {
    glm::dvec3 color{0.8, 0.8, 0.8};
    double ambient = 1.0;
    double diffuse = 1.0;
    double specular = 0.0;
    double shininess = 32.0;
    glm::dvec3 emission{0.0, 0.0, 0.0};
    glm::dvec3 specularColor{1.0, 1.0, 1.0}; // tints highlights: metals' highlights take their colour
    TextureSource texture;                   // base colour (sRGB), alpha for Mask; empty for none
    TextureSource emissionTexture;           // multiplies emission (sRGB)
    TextureSource normalTexture;             // tangent-space normal map (linear)
    double normalScale = 1.0;
    double opacity = 1.0; // base alpha factor
    AlphaMode alphaMode = AlphaMode::Opaque;
    double alphaCutoff = 0.5;
};

// The alpha below which a masked material is cut away, in the lit passes and in shadows: its cutoff, or
// one half for Blend (no sorted transparency yet: drawn as Mask at one half, the importer warns).
inline double effectiveAlphaCutoff(const Material& m) {
    return m.alphaMode == AlphaMode::Blend ? 0.5 : m.alphaCutoff;
}

struct DrawItem {
    std::string name;
    glm::dmat4 world{1.0};
    MeshHandle mesh;
    Material material;
    bool castsShadows = true;
};

enum class LightType { Point, Directional, Spot };

struct ShadowSettings {
    bool enabled = false;
    int mapSize = 1024;
    int pcf = 1; // kernel width in texels; 1 = hard shadows
};

struct Light {
    std::string name;
    LightType type = LightType::Point;
    glm::dvec3 position{0.0};
    glm::dvec3 direction{0.0, -1.0, 0.0}; // unit; directional and spot lights
    glm::dvec3 color{1.0};
    double intensity = 1.0;
    double spotAngle = 30.0; // outer half angle, degrees
    double spotBlend = 0.15; // fraction of the cone over which the edge fades
    ShadowSettings shadows;
};

enum class MirrorTechnique { Stencil, Texture };

struct Mirror {
    std::string name;
    glm::dmat4 world{1.0};
    glm::dvec2 size{1.0, 1.0}; // local X and Z extents of the rectangle
    double reflectivity = 1.0; // at normal incidence when fresnel is on
    MirrorTechnique technique = MirrorTechnique::Stencil;
    glm::dvec3 tint{1.0, 1.0, 1.0}; // multiplies the reflected light
    bool fresnel = false;           // Schlick: reflectivity rises towards 1 at grazing angles
    // 0..1: GGX (Trowbridge–Reitz) microfacet roughness, α = roughness²; 0 is a perfect mirror.
    double roughness = 0.0;
    Material material;
    bool hasMaterial = false;
};

enum class ReflectorMap { Cube, DualParaboloid, TennisBall };

// The map type's name as the scene file spells it, for messages and plan reasons.
inline const char* reflectorMapName(ReflectorMap map) {
    switch (map) {
    case ReflectorMap::DualParaboloid:
        return "dual-paraboloid";
    case ReflectorMap::TennisBall:
        return "tennis-ball";
    case ReflectorMap::Cube:
        break;
    }
    return "cube";
}
enum class ReflectorFill { Direct, Resampled };
enum class ReflectorUpdate { Always, OnChange, Once };

// A proxy of the environment for parallax-corrected lookups, around the capture point (world axes).
struct ParallaxProxy {
    enum class Shape { None, Sphere, Box };
    Shape shape = Shape::None;
    double radius = 1.0;  // sphere
    glm::dvec3 min{-1.0}; // box, relative to the capture point
    glm::dvec3 max{1.0};
};

struct Reflector {
    std::string name;
    glm::dmat4 world{1.0};
    MeshHandle mesh;
    Material material;
    ReflectorMap map = ReflectorMap::Cube;
    int resolution = 256;
    double reflectivity = 1.0; // at normal incidence when fresnel is on
    bool fresnel = false;
    ReflectorFill fill = ReflectorFill::Resampled; // the non-linear maps only
    ParallaxProxy parallax;
    ReflectorUpdate update = ReflectorUpdate::OnChange;
    int mirrorDepth = 1;    // planar-mirror levels inside the environment map
    double roughness = 0.0; // 0..1, GGX roughness of the reflection as for Mirror
};

struct FrameInput {
    Settings settings;
    Camera camera;
    std::vector<DrawItem> items;
    std::vector<Light> lights;
    std::vector<Mirror> mirrors;
    std::optional<Reflector> reflector;
    double time = 0.0; // seconds, the time animations were evaluated at
};

} // namespace speculum::render
