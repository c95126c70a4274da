// The signatures that let the renderer reuse a map (envmapSignature for the reflector's environment map,
// shadowSignature for a light's shadow map) must change with every field the map draws and with nothing
// else. One table row per field of FrameInput's structs: how to perturb it, whether each signature must
// see it, and why. The field lists come from the declarations (fields()) and, for plain structs, from
// structured bindings, so a field added anywhere fails a test or the build until it has a row.
#include "render/imageio/TextureLoader.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/plan/Planner.hpp"

#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <set>
#include <sstream>

namespace speculum::render {
namespace {

// "a, b, c" → {"Type.a", "Type.b", "Type.c"}
std::vector<std::string> qualified(const std::string& type, const std::string& names) {
    std::vector<std::string> out;
    std::stringstream in(names);
    std::string name;
    while (std::getline(in, name, ',')) {
        name.erase(0, name.find_first_not_of(' '));
        out.push_back(type + "." + name);
    }
    return out;
}

// The fields of a plain struct, in order: the binding needs exactly as many names as Type has fields, so
// adding one to the struct breaks the build here.
#define SPECULUM_FIELDS(Type, ...)                                                                           \
    [] {                                                                                                     \
        [[maybe_unused]] const auto& [__VA_ARGS__] = Type{};                                                 \
        return qualified(#Type, #__VA_ARGS__);                                                               \
    }()

// The declared fields of Params (what a file stores), named as fields of Type: a field added to a
// declaration needs a row below without any edit here.
template <typename Params>
std::vector<std::string> declared(const std::string& type) {
    std::vector<std::string> out;
    Params::fields([&](const auto& field) { out.push_back(type + "." + std::string(field.spec.name)); });
    return out;
}

// What a light, mirror or reflector holds besides its declared parameters: where the scene put it and
// what it is made of. A structured binding cannot list a derived struct's members, so their sizes stand in.
static_assert(sizeof(Light) == sizeof(LightParams) + sizeof(std::string) + 2 * sizeof(glm::dvec3),
              "a member was added to Light: give it a row and list it in everyField()");
static_assert(sizeof(Mirror) == sizeof(MirrorParams) + sizeof(std::string) + sizeof(glm::dmat4) +
                                    sizeof(Material) + alignof(Mirror),
              "a member was added to Mirror: give it a row and list it in everyField()");
static_assert(sizeof(Reflector) == sizeof(ReflectorParams) + sizeof(std::string) + sizeof(glm::dmat4) +
                                       sizeof(MeshHandle) + sizeof(Material),
              "a member was added to Reflector: give it a row and list it in everyField()");

std::vector<std::string> everyField() {
    std::vector<std::vector<std::string>> lists = {
        declared<Settings>("Settings"),
        declared<Camera>("Camera"),
        SPECULUM_FIELDS(TextureSource, path, image),
        declared<Material>("Material"),
        SPECULUM_FIELDS(DrawItem, name, world, mesh, material, castsShadows),
        declared<ShadowParams>("ShadowParams"),
        declared<LightParams>("Light"),
        {"Light.name", "Light.position", "Light.direction"},
        declared<MirrorParams>("Mirror"),
        {"Mirror.name", "Mirror.world", "Mirror.material", "Mirror.hasMaterial"},
        declared<ParallaxParams>("ParallaxParams"),
        declared<ReflectorParams>("Reflector"),
        {"Reflector.name", "Reflector.world", "Reflector.mesh", "Reflector.material"},
        SPECULUM_FIELDS(FrameInput, settings, camera, items, lights, mirrors, reflectors, time),
    };
    std::vector<std::string> all;
    for (auto& list : lists)
        all.insert(all.end(), list.begin(), list.end());
    return all;
}

MeshHandle boxMesh() {
    static const auto mesh = std::make_shared<const MeshData>(makeBox());
    return mesh;
}
MeshHandle sphereMesh() {
    static const auto mesh = std::make_shared<const MeshData>(makeSphere(16));
    return mesh;
}
std::shared_ptr<const TextureImage> someImage() {
    static const auto image = std::make_shared<const TextureImage>(checkerTexture(4));
    return image;
}

// A chrome ball (dual-paraboloid, resampled) at the origin, seen by the camera; a masked, textured box
// casting the shadow of a spot light; a textured wall mirror the ball sees.
FrameInput baseScene() {
    FrameInput input;
    input.settings.background = {0.2, 0.2, 0.25};
    input.settings.ambient = 0.3;
    input.camera.position = {0.0, 0.0, 5.0};
    input.camera.target = {0.0, 0.0, 0.0};
    input.camera.far = 50.0;
    DrawItem box{"Box", glm::translate(glm::dmat4(1.0), glm::dvec3(2, 0, 0)), boxMesh(), {}, true};
    box.material.alphaMode = AlphaMode::Mask;
    box.material.alphaCutoff = 0.4;
    box.material.texture.path = "/abs/leaves.png";
    box.material.emissionTexture.path = "/abs/glow.png";
    box.material.normalTexture.path = "/abs/bumps.png";
    input.items.push_back(box);
    Light light;
    light.name = "Lamp";
    light.type = LightType::Spot;
    light.position = {0, 4, 0};
    light.direction = {0, -1, 0};
    light.spotAngle = 40.0;
    light.shadows = ShadowParams{};
    light.shadows->pcf = 3;
    input.lights.push_back(light);
    Mirror wall;
    wall.name = "Wall";
    wall.world = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, -3)), glm::radians(90.0),
                             glm::dvec3(1, 0, 0));
    wall.size = {3.0, 2.0};
    wall.reflectivity = 0.8;
    wall.hasMaterial = true;
    wall.material.texture.path = "/abs/frame.png";
    input.mirrors.push_back(wall);
    Reflector ball;
    ball.name = "Ball";
    ball.mesh = sphereMesh();
    ball.map = ReflectorMap::DualParaboloid;
    ball.fill = ReflectorFill::Resampled;
    ball.mirrorDepth = 1;
    ball.parallax =
        ParallaxParams{.shape = ParallaxShape::Box, .min = glm::dvec3(-4.0), .max = glm::dvec3(4.0)};
    input.reflectors = {ball};
    return input;
}

struct Row {
    std::string field;   // "Struct.field" as in everyField()
    std::string context; // where in the scene it is perturbed, for nested structs seen in several places
    std::function<void(FrameInput&)> perturb;
    bool envmap; // the reflector's environment map draws it
    bool shadow; // light 0's shadow map draws it
    std::string why;
};

// A Material's rows, perturbed in one place of the scene. `envmap` and `shadow` say whether that place is
// drawn into the map at all and, for the shadow, whether its alpha is (a masked caster).
std::vector<Row> materialRows(const std::string& context, std::function<Material&(FrameInput&)> at,
                              bool envmap, bool shadowAlpha, const std::string& why) {
    auto row = [&](const std::string& field, std::function<void(Material&)> change, bool alpha) {
        return Row{"Material." + field,
                   context,
                   [at, change](FrameInput& f) { change(at(f)); },
                   envmap,
                   shadowAlpha && alpha,
                   why + (alpha ? "" : "; a shadow map holds depth, cut only by a masked caster's alpha")};
    };
    auto textureRows = [&](const std::string& name, std::function<TextureSource&(Material&)> texture,
                           bool alpha) {
        std::vector<Row> rows;
        auto one = [&](const std::string& field, std::function<void(TextureSource&)> change) {
            rows.push_back(Row{"TextureSource." + field, context + ".material." + name,
                               [at, texture, change](FrameInput& f) { change(texture(at(f))); }, envmap,
                               shadowAlpha && alpha,
                               why + (alpha ? "" : "; only the base texture's alpha masks a shadow")});
        };
        one("path", [](TextureSource& t) { t.path = "/abs/other.png"; });
        one("image", [](TextureSource& t) { t.image = someImage(); });
        rows.push_back(Row{"Material." + name, context,
                           [at, texture](FrameInput& f) {
                               TextureSource& t = texture(at(f));
                               t = t.empty() ? TextureSource{"/abs/added.png", nullptr} : TextureSource{};
                           },
                           envmap, shadowAlpha && alpha, why});
        return rows;
    };
    std::vector<Row> rows = {
        row(
            "color",
            [](Material& m) {
                m.color = {1.0, 0.0, 0.0};
            },
            false),
        row(
            "ambient", [](Material& m) { m.ambient = 0.5; }, false),
        row(
            "diffuse", [](Material& m) { m.diffuse = 0.5; }, false),
        row(
            "specular", [](Material& m) { m.specular = 0.7; }, false),
        row(
            "shininess", [](Material& m) { m.shininess = 8.0; }, false),
        row(
            "emission",
            [](Material& m) {
                m.emission = {0.2, 0.2, 0.0};
            },
            false),
        row(
            "specularColor",
            [](Material& m) {
                m.specularColor = {1.0, 0.5, 0.0};
            },
            false),
        row(
            "normalScale", [](Material& m) { m.normalScale = 0.5; }, false),
        row(
            "opacity", [](Material& m) { m.opacity = 0.5; }, true),
        row(
            "alphaMode",
            [](Material& m) {
                m.alphaMode = m.alphaMode == AlphaMode::Opaque ? AlphaMode::Mask : AlphaMode::Opaque;
            },
            true),
        row(
            "alphaCutoff", [](Material& m) { m.alphaCutoff = 0.7; }, true),
        row(
            "wrap",
            [](Material& m) {
                m.wrap = {TextureWrap::ClampToEdge, TextureWrap::MirroredRepeat};
            },
            true),
    };
    for (auto& r : textureRows(
             "texture", [](Material& m) -> TextureSource& { return m.texture; }, true))
        rows.push_back(std::move(r));
    for (auto& r : textureRows(
             "emissionTexture", [](Material& m) -> TextureSource& { return m.emissionTexture; }, false))
        rows.push_back(std::move(r));
    for (auto& r : textureRows(
             "normalTexture", [](Material& m) -> TextureSource& { return m.normalTexture; }, false))
        rows.push_back(std::move(r));
    return rows;
}

std::vector<Row> table() {
    const std::string camera = "the map is captured from the reflector's centre, a shadow from its light";
    const std::string name = "names are for messages, nothing draws them";
    const std::string surface = "the reflector's own surface (pass 2) is not drawn into its map";
    const std::string notCast = "not a shadow caster and no part of the light's frustum";
    std::vector<Row> rows = {
        // Settings
        {"Settings.background", "",
         [](FrameInput& f) {
             f.settings.background = {1, 1, 1};
         },
         true, false, "the map's clear colour; " + notCast},
        {"Settings.mirrorDepth", "", [](FrameInput& f) { f.settings.mirrorDepth = 7; }, false, false,
         "the camera's nesting limit: the map nests to the reflector's own mirrorDepth"},
        {"Settings.ambient", "", [](FrameInput& f) { f.settings.ambient = 0.6; }, true, false,
         "lights the map's scene; " + notCast},
        {"Settings.simplifyReflections", "", [](FrameInput& f) { f.settings.simplifyReflections = false; },
         true, false, "the map may draw big meshes simplified; shadow maps always draw them whole"},
        {"Settings.glossyFilter", "", [](FrameInput& f) { f.settings.glossyFilter = GlossyFilter::Mip; },
         false, false, "how rough surfaces read the map, not what the map holds"},
        {"Settings.glossyTaps", "", [](FrameInput& f) { f.settings.glossyTaps = 4; }, false, false,
         "the camera's rough planar mirrors; the map's mirrors are sharp"},
        {"Settings.reflectorBounces", "", [](FrameInput& f) { f.settings.reflectorBounces = 2; }, true, false,
         "the other reflectors in the map are drawn with their maps, not their material"},
        {"Settings.prefilterSamples", "", [](FrameInput& f) { f.settings.prefilterSamples = 8; }, false,
         false, "filters the captured map again; it is not captured again"},
        {"Settings.screenSteps", "", [](FrameInput& f) { f.settings.screenSteps = 16; }, false, false,
         "the camera's screen-space mirrors; the map's mirrors use the stencil technique"},
        {"Settings.screenThickness", "", [](FrameInput& f) { f.settings.screenThickness = 0.2; }, false,
         false, "the camera's screen-space mirrors; the map's mirrors use the stencil technique"},
        {"Settings.screenFallback", "",
         [](FrameInput& f) { f.settings.screenFallback = ScreenFallback::Background; }, false, false,
         "what the camera's screen-space mirrors read where their rays miss, not what the map holds"},
        {"Settings.screenResolution", "",
         [](FrameInput& f) { f.settings.screenResolution = ScreenResolution::Half; }, false, false,
         "the camera's screen-space mirrors; the map's mirrors use the stencil technique"},
        // Camera
        {"Camera.position", "",
         [](FrameInput& f) {
             f.camera.position = {1, 2, 6};
         },
         false, false, camera},
        {"Camera.target", "",
         [](FrameInput& f) {
             f.camera.target = {1, 0, 0};
         },
         false, false, camera},
        {"Camera.up", "",
         [](FrameInput& f) {
             f.camera.up = {1, 0, 0};
         },
         false, false, camera},
        {"Camera.fovY", "", [](FrameInput& f) { f.camera.fovY = 30.0; }, false, false, camera},
        {"Camera.near", "", [](FrameInput& f) { f.camera.near = 0.5; }, false, false, camera},
        {"Camera.far", "", [](FrameInput& f) { f.camera.far = 80.0; }, false, false, camera},
        // DrawItem
        {"DrawItem.name", "", [](FrameInput& f) { f.items[0].name = "Crate"; }, false, false, name},
        {"DrawItem.world", "", [](FrameInput& f) { f.items[0].world[3].y += 0.1; }, true, true,
         "where it is drawn and where it casts from"},
        {"DrawItem.mesh", "", [](FrameInput& f) { f.items[0].mesh = sphereMesh(); }, true, true,
         "what is drawn and what casts"},
        {"DrawItem.material", "", [](FrameInput& f) { f.items[0].material = Material{}; }, true, true,
         "drawn lit; the masked caster becomes opaque"},
        {"DrawItem.castsShadows", "", [](FrameInput& f) { f.items[0].castsShadows = false; }, true, true,
         "its shadow falls in the map's scene and in the light's map"},
        // Light
        {"Light.name", "", [](FrameInput& f) { f.lights[0].name = "Sun"; }, false, false, name},
        {"Light.type", "", [](FrameInput& f) { f.lights[0].type = LightType::Point; }, true, true,
         "lights the map; a cube map instead of a perspective one"},
        {"Light.position", "", [](FrameInput& f) { f.lights[0].position.x += 0.5; }, true, true,
         "lights the map; moves the shadow frustum"},
        {"Light.direction", "",
         [](FrameInput& f) { f.lights[0].direction = glm::normalize(glm::dvec3(1, -2, 0)); }, true, true,
         "a spot light's cone and its frustum"},
        {"Light.color", "",
         [](FrameInput& f) {
             f.lights[0].color = {1.0, 0.5, 0.5};
         },
         true, false, "lights the map; a shadow map holds depth only"},
        {"Light.intensity", "", [](FrameInput& f) { f.lights[0].intensity = 2.0; }, true, false,
         "lights the map; a shadow map holds depth only"},
        {"Light.spotAngle", "", [](FrameInput& f) { f.lights[0].spotAngle = 25.0; }, true, true,
         "the cone lights the map and sets the frustum's angle"},
        {"Light.spotBlend", "", [](FrameInput& f) { f.lights[0].spotBlend = 0.5; }, true, false,
         "the cone's soft edge lights the map; the frustum covers the whole cone either way"},
        {"Light.shadows", "", [](FrameInput& f) { f.lights[0].shadows.reset(); }, true, false,
         "shadows off: the map is lit without them; whether a shadow map exists is the planner's decision, "
         "not part of what it holds"},
        // ShadowParams
        {"ShadowParams.mapSize", "", [](FrameInput& f) { f.lights[0].shadows->mapSize = 512; }, true, true,
         "the map samples a coarser shadow; the shadow map's own size"},
        {"ShadowParams.pcf", "", [](FrameInput& f) { f.lights[0].shadows->pcf = 5; }, true, false,
         "the map's shadow lookups filter wider; the kernel is sampling state, not map content"},
        // Mirror
        {"Mirror.name", "", [](FrameInput& f) { f.mirrors[0].name = "Glass"; }, false, false, name},
        {"Mirror.world", "", [](FrameInput& f) { f.mirrors[0].world[3].z -= 1.0; }, true, true,
         "seen in the map; a receiver the light's frustum reaches"},
        {"Mirror.size", "",
         [](FrameInput& f) {
             f.mirrors[0].size = {8.0, 2.0};
         },
         true, true, "seen in the map; a receiver the light's frustum reaches"},
        {"Mirror.reflectivity", "", [](FrameInput& f) { f.mirrors[0].reflectivity = 0.3; }, true, false,
         "its surface blends over its reflection in the map; " + notCast},
        {"Mirror.technique", "", [](FrameInput& f) { f.mirrors[0].technique = MirrorTechnique::Texture; },
         false, false, "the camera's choice: the map draws every mirror with the stencil technique"},
        {"Mirror.tint", "",
         [](FrameInput& f) {
             f.mirrors[0].tint = {1.0, 0.8, 0.6};
         },
         true, false, "tints its reflection in the map; " + notCast},
        {"Mirror.fresnel", "", [](FrameInput& f) { f.mirrors[0].fresnel = true; }, true, false,
         "Schlick's term on its surface in the map; " + notCast},
        {"Mirror.roughness", "", [](FrameInput& f) { f.mirrors[0].roughness = 0.5; }, false, false,
         "the map's stencil mirrors are sharp"},
        {"Mirror.material", "", [](FrameInput& f) { f.mirrors[0].material = Material{}; }, true, false,
         "its surface in the map; " + notCast},
        {"Mirror.hasMaterial", "", [](FrameInput& f) { f.mirrors[0].hasMaterial = false; }, true, false,
         "its surface in the map; " + notCast},
        // Reflector
        {"Reflector.name", "", [](FrameInput& f) { f.reflectors[0].name = "Globe"; }, false, false, name},
        {"Reflector.world", "", [](FrameInput& f) { f.reflectors[0].world[3].x += 0.1; }, true, true,
         "the capture point, and the shadow the reflector casts"},
        {"Reflector.mesh", "", [](FrameInput& f) { f.reflectors[0].mesh = boxMesh(); }, true, true,
         "its bounds place the capture point, its shape casts a shadow"},
        {"Reflector.material", "",
         [](FrameInput& f) {
             f.reflectors[0].material.color = {1, 0, 0};
         },
         false, false, surface},
        {"Reflector.map", "", [](FrameInput& f) { f.reflectors[0].map = ReflectorMap::TennisBall; }, true,
         false, "a map of another layout; not drawn by the shadow"},
        {"Reflector.resolution", "", [](FrameInput& f) { f.reflectors[0].resolution = 128; }, true, false,
         "the map's texels; not drawn by the shadow"},
        {"Reflector.reflectivity", "", [](FrameInput& f) { f.reflectors[0].reflectivity = 0.5; }, false,
         false, surface},
        {"Reflector.fresnel", "", [](FrameInput& f) { f.reflectors[0].fresnel = true; }, false, false,
         surface},
        {"Reflector.fill", "", [](FrameInput& f) { f.reflectors[0].fill = ReflectorFill::Direct; }, true,
         false, "how a non-linear map is filled; not drawn by the shadow"},
        {"Reflector.parallax", "", [](FrameInput& f) { f.reflectors[0].parallax = ParallaxParams{}; }, false,
         false, "the lookup's proxy in pass 2: " + surface},
        {"Reflector.update", "", [](FrameInput& f) { f.reflectors[0].update = ReflectorUpdate::Always; },
         false, false, "decides when the map is drawn, not what it holds"},
        {"Reflector.mirrorDepth", "", [](FrameInput& f) { f.reflectors[0].mirrorDepth = 2; }, true, false,
         "how deep the map's mirrors nest; not drawn by the shadow"},
        {"Reflector.roughness", "", [](FrameInput& f) { f.reflectors[0].roughness = 0.4; }, false, false,
         "chooses a level of the pre-filtered chain, which holds every roughness"},
        {"Reflector.technique", "",
         [](FrameInput& f) { f.reflectors[0].technique = ReflectorTechnique::ScreenSpace; }, false, false,
         "how the camera's view reads the reflection, not what the map holds"},
        // ParallaxParams, on a reflector that has a box proxy
        {"ParallaxParams.shape", "",
         [](FrameInput& f) { f.reflectors[0].parallax = ParallaxParams{.shape = ParallaxShape::Sphere}; },
         false, false, surface},
        {"ParallaxParams.radius", "", [](FrameInput& f) { f.reflectors[0].parallax->radius = 3.0; }, false,
         false, surface},
        {"ParallaxParams.min", "", [](FrameInput& f) { f.reflectors[0].parallax->min = glm::dvec3(-2.0); },
         false, false, surface},
        {"ParallaxParams.max", "", [](FrameInput& f) { f.reflectors[0].parallax->max = glm::dvec3(2.0); },
         false, false, surface},
        // FrameInput
        {"FrameInput.settings", "", [](FrameInput& f) { f.settings = Settings{}; }, true, false,
         "a default background and ambient"},
        {"FrameInput.camera", "", [](FrameInput& f) { f.camera = Camera{}; }, false, false, camera},
        {"FrameInput.items", "",
         [](FrameInput& f) {
             f.items.push_back(
                 {"Crate", glm::translate(glm::dmat4(1.0), glm::dvec3(-2, 0, 0)), boxMesh(), {}, true});
         },
         true, true, "one more object drawn and casting"},
        {"FrameInput.lights", "", [](FrameInput& f) { f.lights.push_back(Light{}); }, true, false,
         "one more light in the map; light 0's map does not see other lights"},
        {"FrameInput.mirrors", "",
         [](FrameInput& f) {
             Mirror far;
             far.world = glm::translate(glm::dmat4(1.0), glm::dvec3(0, -1, 9));
             f.mirrors.push_back(far);
         },
         true, true, "one more mirror in the map; a receiver that widens the light's frustum"},
        {"FrameInput.reflectors", "",
         [](FrameInput& f) {
             Reflector second = f.reflectors[0];
             second.world = glm::translate(glm::dmat4(1.0), glm::dvec3(2.5, 0.5, 0));
             f.reflectors.push_back(second);
         },
         true, true, "another reflector: in the first one's map, and another caster"},
        {"FrameInput.time", "", [](FrameInput& f) { f.time = 3.5; }, false, false,
         "animations are evaluated into the transforms before planning; the time itself draws nothing"},
    };
    auto add = [&](std::vector<Row> more) {
        for (Row& r : more)
            rows.push_back(std::move(r));
    };
    add(materialRows(
        "items[0]", [](FrameInput& f) -> Material& { return f.items[0].material; }, true, true,
        "the object is drawn lit into the map"));
    add(materialRows(
        "mirrors[0]", [](FrameInput& f) -> Material& { return f.mirrors[0].material; }, true, false,
        "the mirror's surface is drawn into the map; mirrors cast no shadow"));
    add(materialRows(
        "reflector", [](FrameInput& f) -> Material& { return f.reflectors[0].material; }, false, false,
        surface));
    return rows;
}

TEST(Signatures, EveryFieldOfFrameInputHasARow) {
    std::set<std::string> covered;
    for (const Row& row : table())
        covered.insert(row.field);
    for (const std::string& field : everyField())
        EXPECT_TRUE(covered.count(field)) << field << " has no row in the signature table";
    const std::vector<std::string> fields = everyField();
    const std::set<std::string> known(fields.begin(), fields.end());
    for (const std::string& field : covered)
        EXPECT_TRUE(known.count(field)) << field << " is not a field of FrameInput's structs";
}

TEST(Signatures, EachMapsSignatureChangesWithExactlyTheFieldsItDraws) {
    const FrameInput base = baseScene();
    const std::uint64_t envmap = envmapSignature(base, 0);
    const std::uint64_t shadow = shadowSignature(base, 0);
    for (const Row& row : table()) {
        FrameInput changed = base;
        row.perturb(changed);
        const std::string where =
            row.field + (row.context.empty() ? "" : " in " + row.context) + ": " + row.why;
        EXPECT_EQ(envmapSignature(changed, 0) != envmap, row.envmap) << "envmap signature, " << where;
        EXPECT_EQ(shadowSignature(changed, 0) != shadow, row.shadow) << "shadow signature, " << where;
    }
}

// The base scene's caster is masked, so its alpha shows in its shadow; an opaque caster's does not.
TEST(Signatures, AnOpaqueCastersAlphaIsNotInItsShadow) {
    FrameInput base = baseScene();
    base.items[0].material.alphaMode = AlphaMode::Opaque;
    const std::uint64_t shadow = shadowSignature(base, 0);
    FrameInput changed = base;
    changed.items[0].material.opacity = 0.2;
    changed.items[0].material.alphaCutoff = 0.9;
    changed.items[0].material.texture.path = "/abs/other.png";
    EXPECT_EQ(shadowSignature(changed, 0), shadow);
    // Blend is drawn as Mask at one half: the same cut as Mask with a cutoff of one half.
    FrameInput mask = base, blend = base;
    mask.items[0].material.alphaMode = AlphaMode::Mask;
    mask.items[0].material.alphaCutoff = 0.5;
    blend.items[0].material.alphaMode = AlphaMode::Blend;
    blend.items[0].material.alphaCutoff = 0.2;
    EXPECT_EQ(shadowSignature(mask, 0), shadowSignature(blend, 0));
}

bool hasEnvmap(const FramePlan& plan) {
    for (const auto& p : plan.passes)
        if (p.kind == PassKind::Envmap)
            return true;
    return false;
}

// The bug this table guards against: a mirror's Fresnel is drawn into the map, so toggling it under
// update: on-change must draw the map again rather than keep the old reflection.
TEST(Signatures, TogglingAMirrorsFresnelRedrawsAnOnChangeMap) {
    FrameInput input = baseScene();
    ASSERT_EQ(input.reflectors[0].update, ReflectorUpdate::OnChange);
    PlannerState state; // what the renderer keeps after it rendered the map
    state.mapOf(0).signature = envmapSignature(input, 0);
    state.mapOf(0).reflector = input.reflectors[0].name;
    state.mapOf(0).settings = envmapSettingsKey(input.reflectors[0]);
    ASSERT_FALSE(hasEnvmap(planFrame(input, state))) << "nothing changed: the map is reused";

    input.mirrors[0].fresnel = true;
    const FramePlan toggled = planFrame(input, state);
    ASSERT_TRUE(hasEnvmap(toggled));
    for (const PlannedPass& pass : toggled.passes) {
        if (pass.kind == PassKind::Envmap) {
            EXPECT_EQ(pass.code, PlanReason::EnvmapChanged) << pass.reason();
        }
    }

    state.mapOf(0).signature = envmapSignature(input, 0);
    state.mapOf(0).reflector = input.reflectors[0].name;
    EXPECT_FALSE(hasEnvmap(planFrame(input, state))) << "redrawn once, then reused again";
}

} // namespace
} // namespace speculum::render
