#pragma once

#include "base/Result.hpp"
#include "render/frame/FrameInput.hpp"

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace speculum::accuracy {

// What the sweep changes in a scene, in the scene's own terms: declared fields (render/frame/Field.hpp) set
// on every component of a kind, and the three settings that are not one field of one component.

// The components a declared field is set on: the scene's settings, every planar mirror, the reflector,
// every shadow-casting light's shadow map.
enum class Part { Settings, Mirrors, Reflector, Shadows };

// A declared field set to one value on every component of its part.
struct FieldAssignment {
    Part part = Part::Settings;
    std::string field; // its declared name: "technique"
    render::FieldValue value;
    bool operator==(const FieldAssignment&) const = default;
};

// What a configuration changes; anything it does not name keeps the scene's value.
struct Variation {
    std::vector<FieldAssignment> fields;
    std::optional<bool> parallax;    // the reflector's proxy (its own, or the box around the scene) on or off
    std::optional<int> tessellation; // the built-in teapots re-meshed at this tessellation
    std::optional<double> roughness; // every surface that is rough in the scene, at this roughness

    // Sets (or replaces) one field's value; returns *this for chaining.
    Variation& set(Part part, std::string_view field, const render::FieldValue& value);
    // The value this variation gives the field, or null.
    const render::FieldValue* find(Part part, std::string_view field) const;
    // `other`'s changes on top of these (its values win).
    void merge(const Variation& other);
    bool operator==(const Variation&) const = default;
};

// The proxy "parallax on" gives a reflector without one of its own: a box around the rest of the scene,
// when that box encloses the reflector; none otherwise.
std::optional<render::ParallaxParams> sceneProxy(const render::FrameInput& scene, int index = -1);

// Replaces a built-in teapot's mesh by the same teapot at another tessellation; returns other meshes as
// they are.
using TessellateTeapot = std::function<render::MeshHandle(const render::MeshHandle& mesh, int tessellation)>;

// The scene with a variation applied. `proxy` is what "parallax on" means for a reflector without a proxy
// of its own (sceneProxy).
render::FrameInput applyVariation(const render::FrameInput& scene, const Variation& variation,
                                  const std::optional<render::ParallaxParams>& proxy,
                                  const TessellateTeapot& tessellate);

// A bench results file's settings: (column, value) pairs as effectiveSettings writes them.
using Settings = std::vector<std::pair<std::string, std::string>>;

// The columns bench results have, in their order (the screen-space trace's last: only where a mirror is
// traced); declared fields swept on their own follow.
inline const std::vector<std::string> kSettingNames = {"map",
                                                       "resolution",
                                                       "fill",
                                                       "parallax",
                                                       "technique",
                                                       "mirrorDepth",
                                                       "pcf",
                                                       "tessellation",
                                                       "reflectedDetail",
                                                       "roughness",
                                                       "glossy",
                                                       "screenSteps",
                                                       "screenThickness",
                                                       "screenResolution",
                                                       "screenFallback",
                                                       "reflectorTechnique"};

// The effective value of every setting the scene has, whether a configuration swept it or not:
// ("map", "cube"), ("resolution", "128"), ... in the order of kSettingNames, then the declared fields that
// have sweep values of their own.
Settings effectiveSettings(const render::FrameInput& applied, const std::optional<int>& teapotTessellation,
                           bool simplifiableMeshes);

// What one setting of a results file asks of a scene, read back: "map" = "cube" is the reflector's map;
// "glossy" = "footprint 16 taps" the glossy filter and its taps. An error names what is wrong ("unknown
// map type", "this version does not know the setting").
base::Result<Variation> variationOf(std::string_view column, std::string_view value);

// The declared spec of a part's field, or null.
const render::FieldSpec* partField(Part part, std::string_view field);
// The column of a declared field in bench results: its sweep name, or its name.
std::string_view columnOf(const render::FieldSpec& spec);
// "settings", "mirror", "reflector", "shadows".
std::string_view partName(Part part);

// Every declared field with sweep values of its own (FieldSpec::sweep), by part.
std::vector<std::pair<Part, const render::FieldSpec*>> declaredSweeps();

// The glossy setting's text: "mip", or "footprint" and its quality ("16 taps / 64 samples").
std::string glossyText(const render::Settings& settings, bool roughMirrors, bool roughReflector);

} // namespace speculum::accuracy
