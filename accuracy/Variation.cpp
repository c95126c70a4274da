#include "accuracy/Variation.hpp"

#include "render/math/Projection.hpp"
#include "render/plan/Planner.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <set>

namespace speculum::accuracy {

namespace {

using render::FieldValue;

// Calls f(spec) for every declared field of a part's struct.
template <typename F>
void forEachPartField(Part part, F&& f) {
    const auto each = [&](const auto& field) { f(field.spec); };
    switch (part) {
    case Part::Settings:
        render::forEachField<render::Settings>(each);
        break;
    case Part::Mirrors:
        render::forEachField<render::MirrorParams>(each);
        break;
    case Part::Reflector:
        render::forEachField<render::ReflectorParams>(each);
        break;
    case Part::Shadows:
        render::forEachField<render::ShadowParams>(each);
        break;
    }
}

constexpr Part kParts[] = {Part::Settings, Part::Mirrors, Part::Reflector, Part::Shadows};

// Sets one assignment on every component of its part; a value the declaration refuses leaves it alone.
void applyField(render::FrameInput& frame, const FieldAssignment& a) {
    switch (a.part) {
    case Part::Settings:
        (void)render::setField(frame.settings, a.field, a.value);
        break;
    case Part::Mirrors:
        for (render::Mirror& mirror : frame.mirrors)
            (void)render::setField(static_cast<render::MirrorParams&>(mirror), a.field, a.value);
        break;
    case Part::Reflector:
        for (render::Reflector& reflector : frame.reflectors)
            (void)render::setField(static_cast<render::ReflectorParams&>(reflector), a.field, a.value);
        break;
    case Part::Shadows:
        for (render::Light& light : frame.lights)
            if (light.shadows)
                (void)render::setField(*light.shadows, a.field, a.value);
        break;
    }
}

std::string roughnessText(double roughness) {
    char text[16];
    std::snprintf(text, sizeof text, "%.1f", roughness);
    return text;
}

bool parseInt(std::string_view text, int& out) {
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), out);
    return error == std::errc() && end == text.data() + text.size();
}

// "footprint 16 taps / 64 samples", "footprint 16 taps", "footprint 64 samples", "chain", "chain 64
// samples", "mip".
base::Result<Variation> glossyVariation(std::string_view text) {
    Variation v;
    if (text == "mip")
        return v.set(Part::Settings, "glossyFilter", int(render::GlossyFilter::Mip));
    constexpr std::string_view footprint = "footprint", chain = "chain";
    const bool isChain = text.starts_with(chain);
    if (!isChain && !text.starts_with(footprint))
        return base::Error{"expected mip, footprint or chain"};
    v.set(Part::Settings, "glossyFilter",
          int(isChain ? render::GlossyFilter::Chain : render::GlossyFilter::Footprint));
    std::string_view rest = text.substr(isChain ? chain.size() : footprint.size());
    while (!rest.empty()) {
        rest.remove_prefix(std::min(rest.find_first_not_of(" /"), rest.size()));
        const std::size_t space = rest.find(' ');
        if (rest.empty() || space == std::string_view::npos)
            break;
        int count = 0;
        if (!parseInt(rest.substr(0, space), count))
            return base::Error{"expected a count of taps or samples"};
        rest.remove_prefix(space + 1);
        const std::size_t end = std::min(rest.find(' '), rest.size());
        const std::string_view unit = rest.substr(0, end);
        if (unit != "taps" && unit != "samples")
            return base::Error{"expected taps or samples"};
        v.set(Part::Settings, unit == "taps" ? "glossyTaps" : "prefilterSamples", count);
        rest.remove_prefix(end);
    }
    return v;
}

// A declared field's column and value, read back through its declaration.
base::Result<Variation> declaredVariation(std::string_view column, std::string_view text) {
    for (Part part : kParts) {
        // A copy: the walk hands out each spec for the length of one visit.
        std::optional<render::FieldSpec> found;
        forEachPartField(part, [&](const render::FieldSpec& spec) {
            const bool swept =
                !spec.sweep.empty() || column == spec.sweepName ||
                std::find(kSettingNames.begin(), kSettingNames.end(), column) != kSettingNames.end();
            if (!found && swept && columnOf(spec) == column && spec.type != render::FieldType::Object)
                found = spec;
        });
        if (!found)
            continue;
        auto parsed = render::parseFieldValue(*found, text);
        if (const std::string* error = std::get_if<std::string>(&parsed))
            return base::Error{*error};
        const FieldValue& value = std::get<FieldValue>(parsed);
        if (auto problem = render::fieldProblem(*found, value))
            return base::Error{*problem};
        Variation v;
        return v.set(part, found->name, value);
    }
    return base::Error{"this version does not know the setting"};
}

// The text of a part's field over every component of the part: its value, or "mixed" where they differ,
// or nothing where the scene has no such component.
std::optional<std::string> partText(const render::FrameInput& frame, Part part,
                                    const render::FieldSpec& spec) {
    std::set<std::string> texts;
    const auto add = [&](const auto& component) {
        if (auto value = render::getField(component, spec.name))
            texts.insert(render::fieldValueText(spec, *value));
    };
    switch (part) {
    case Part::Settings:
        add(frame.settings);
        break;
    case Part::Mirrors:
        for (const render::Mirror& m : frame.mirrors)
            add(static_cast<const render::MirrorParams&>(m));
        break;
    case Part::Reflector:
        for (const render::Reflector& reflector : frame.reflectors)
            if (reflector.mesh)
                add(static_cast<const render::ReflectorParams&>(reflector));
        break;
    case Part::Shadows:
        for (const render::Light& light : frame.lights)
            if (light.shadows)
                add(*light.shadows);
        break;
    }
    if (texts.empty())
        return std::nullopt;
    return texts.size() == 1 ? *texts.begin() : std::string("mixed");
}

// Light by light, the kernels in use: "3/5" where lights differ.
std::optional<std::string> kernelsText(const render::FrameInput& frame) {
    std::set<int> kernels;
    for (const render::Light& light : frame.lights)
        if (light.shadows)
            kernels.insert(light.shadows->pcf);
    if (kernels.empty())
        return std::nullopt;
    std::string pcf;
    for (int k : kernels)
        pcf += (pcf.empty() ? "" : "/") + std::to_string(k);
    return pcf;
}

} // namespace

Variation& Variation::set(Part part, std::string_view field, const FieldValue& value) {
    for (FieldAssignment& a : fields)
        if (a.part == part && a.field == field) {
            a.value = value;
            return *this;
        }
    FieldAssignment& added = fields.emplace_back();
    added.part = part;
    added.field = std::string(field);
    added.value = value;
    return *this;
}

const FieldValue* Variation::find(Part part, std::string_view field) const {
    for (const FieldAssignment& a : fields)
        if (a.part == part && a.field == field)
            return &a.value;
    return nullptr;
}

void Variation::merge(const Variation& other) {
    for (const FieldAssignment& a : other.fields)
        set(a.part, a.field, a.value);
    parallax = other.parallax ? other.parallax : parallax;
    tessellation = other.tessellation ? other.tessellation : tessellation;
    roughness = other.roughness ? other.roughness : roughness;
}

std::string_view partName(Part part) {
    switch (part) {
    case Part::Settings:
        return "settings";
    case Part::Mirrors:
        return "mirror";
    case Part::Reflector:
        return "reflector";
    case Part::Shadows:
        return "shadows";
    }
    return "?";
}

std::string_view columnOf(const render::FieldSpec& spec) {
    return spec.sweepName.empty() ? spec.name : spec.sweepName;
}

const render::FieldSpec* partField(Part part, std::string_view field) {
    switch (part) {
    case Part::Settings:
        return render::findField<render::Settings>(field);
    case Part::Mirrors:
        return render::findField<render::MirrorParams>(field);
    case Part::Reflector:
        return render::findField<render::ReflectorParams>(field);
    case Part::Shadows:
        return render::findField<render::ShadowParams>(field);
    }
    return nullptr;
}

std::vector<std::pair<Part, const render::FieldSpec*>> declaredSweeps() {
    std::vector<std::pair<Part, const render::FieldSpec*>> out;
    for (Part part : kParts)
        forEachPartField(part, [&](const render::FieldSpec& spec) {
            if (!spec.sweep.empty())
                out.emplace_back(part, partField(part, spec.name));
        });
    return out;
}

std::optional<render::ParallaxParams> sceneProxy(const render::FrameInput& scene, int index) {
    if (index < 0)
        index = render::probeReflector(scene);
    if (index < 0 || static_cast<std::size_t>(index) >= scene.reflectors.size() ||
        !scene.reflectors[static_cast<std::size_t>(index)].mesh)
        return std::nullopt;
    const render::Reflector& reflector = scene.reflectors[static_cast<std::size_t>(index)];
    // A box around what the map sees, if that box encloses the reflector (a reflector outside the scene's
    // bounds has nothing around it for a box to stand for).
    render::FrameInput environment = scene;
    environment.reflectors.erase(environment.reflectors.begin() + index);
    const render::math::Box around = render::math::sceneBounds(environment);
    const render::math::Box own =
        render::math::worldBounds(render::computeBounds(*reflector.mesh), reflector.world);
    if (around.empty() || own.empty())
        return std::nullopt;
    const double tolerance = 1e-6 * std::max(1.0, glm::length(around.max - around.min));
    const bool encloses = glm::all(glm::lessThanEqual(around.min, own.min + tolerance)) &&
                          glm::all(glm::greaterThanEqual(around.max, own.max - tolerance));
    if (!encloses)
        return std::nullopt;
    const glm::dvec3 centre = render::envmapCapture(scene, index).centre;
    render::ParallaxParams proxy;
    proxy.shape = render::ParallaxShape::Box;
    proxy.min = around.min - centre;
    proxy.max = around.max - centre;
    return proxy;
}

render::FrameInput applyVariation(const render::FrameInput& scene, const Variation& v,
                                  const std::optional<render::ParallaxParams>& proxy,
                                  const TessellateTeapot& tessellate) {
    render::FrameInput out = scene;
    for (const FieldAssignment& a : v.fields)
        applyField(out, a);
    const int probe = render::probeReflector(scene);
    for (std::size_t i = 0; i < out.reflectors.size() && v.parallax; ++i) {
        render::Reflector& r = out.reflectors[i];
        // The first reflector's proxy is the one given; each other's is the box around it.
        const auto own = static_cast<int>(i) == probe ? proxy : sceneProxy(scene, static_cast<int>(i));
        r.parallax = *v.parallax ? r.parallax ? r.parallax : own : std::nullopt;
    }
    if (v.roughness) {
        for (render::Mirror& m : out.mirrors)
            if (m.roughness > 0.0)
                m.roughness = *v.roughness;
        for (render::Reflector& r : out.reflectors)
            if (r.roughness > 0.0)
                r.roughness = *v.roughness;
    }
    if (v.tessellation && tessellate) {
        for (render::DrawItem& item : out.items)
            item.mesh = tessellate(item.mesh, *v.tessellation);
        for (render::Reflector& r : out.reflectors)
            r.mesh = tessellate(r.mesh, *v.tessellation);
    }
    return out;
}

std::string glossyText(const render::Settings& settings, bool roughMirrors, bool roughReflector) {
    if (settings.glossyFilter == render::GlossyFilter::Mip)
        return "mip";
    if (settings.glossyFilter == render::GlossyFilter::Chain)
        return roughReflector ? "chain " + std::to_string(settings.prefilterSamples) + " samples" : "chain";
    std::string label;
    if (roughMirrors)
        label = std::to_string(settings.glossyTaps) + " taps";
    if (roughReflector)
        label += (label.empty() ? "" : " / ") + std::to_string(settings.prefilterSamples) + " samples";
    return "footprint " + label;
}

Settings effectiveSettings(const render::FrameInput& applied, const std::optional<int>& teapotTessellation,
                           bool simplifiableMeshes) {
    Settings s;
    const auto add = [&](Part part, std::string_view field) {
        if (auto text = partText(applied, part, *partField(part, field)))
            s.emplace_back(columnOf(*partField(part, field)), *text);
    };
    std::vector<const render::Reflector*> reflectors;
    for (const render::Reflector& r : applied.reflectors)
        if (r.mesh)
            reflectors.push_back(&r);
    const bool reflector = !reflectors.empty();
    const auto anyReflector = [&](auto&& test) {
        return std::any_of(reflectors.begin(), reflectors.end(), test);
    };
    if (reflector) {
        add(Part::Reflector, "map");
        add(Part::Reflector, "resolution");
        // The cube and the octahedron have no fill to choose.
        if (anyReflector([](const render::Reflector* r) { return render::warpable(r->map); }))
            add(Part::Reflector, "fill");
        s.emplace_back(
            "parallax",
            anyReflector([](const render::Reflector* r) { return r->parallax.has_value(); }) ? "on" : "off");
    }
    if (!applied.mirrors.empty()) {
        add(Part::Mirrors, "technique");
        add(Part::Settings, "mirrorDepth");
    }
    if (reflectors.size() >= 2) // reflectors that see each other
        add(Part::Settings, "reflectorBounces");
    if (reflector)
        add(Part::Reflector, "technique");
    const bool screenSpace = std::any_of(applied.mirrors.begin(), applied.mirrors.end(),
                                         [](const render::Mirror& m) {
                                             return m.technique == render::MirrorTechnique::ScreenSpace;
                                         }) ||
                             anyReflector([](const render::Reflector* r) {
                                 return r->technique == render::ReflectorTechnique::ScreenSpace;
                             });
    if (auto pcf = kernelsText(applied))
        s.emplace_back("pcf", *pcf);
    if (teapotTessellation)
        s.emplace_back("tessellation", std::to_string(*teapotTessellation));
    if (simplifiableMeshes)
        add(Part::Settings, "simplifyReflections");
    const bool roughMirrors = std::any_of(applied.mirrors.begin(), applied.mirrors.end(),
                                          [](const render::Mirror& m) { return m.roughness > 0.0; });
    const bool roughReflector = anyReflector([](const render::Reflector* r) { return r->roughness > 0.0; });
    if (roughMirrors || roughReflector) {
        double roughness = 0.0;
        for (const render::Reflector* r : reflectors)
            roughness = std::max(roughness, r->roughness);
        for (const render::Mirror& m : applied.mirrors)
            roughness = std::max(roughness, m.roughness);
        s.emplace_back("roughness", roughnessText(roughness));
        s.emplace_back("glossy", glossyText(applied.settings, roughMirrors, roughReflector));
    }
    if (screenSpace) { // the trace's own settings, where a mirror is traced
        add(Part::Settings, "screenSteps");
        add(Part::Settings, "screenThickness");
        add(Part::Settings, "screenResolution");
        if (reflector)
            add(Part::Settings, "screenFallback");
    }
    for (const auto& [part, spec] : declaredSweeps())
        if (auto text = partText(applied, part, *spec))
            s.emplace_back(columnOf(*spec), *text);
    return s;
}

base::Result<Variation> variationOf(std::string_view column, std::string_view value) {
    Variation v;
    if (column == "parallax") {
        if (value != "on" && value != "off")
            return base::Error{"expected on or off"};
        v.parallax = value == "on";
        return v;
    }
    if (column == "tessellation" || column == "roughness") {
        double number = 0.0;
        const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), number);
        const bool whole = error == std::errc() && end == value.data() + value.size();
        if (column == "tessellation") {
            if (!whole || number != int(number) || number < render::kMinTessellation ||
                number > render::kMaxTessellation)
                return base::Error{"not a tessellation in " + std::to_string(render::kMinTessellation) +
                                   ".." + std::to_string(render::kMaxTessellation)};
            v.tessellation = int(number);
            return v;
        }
        if (!whole || !(number > 0.0 && number <= 1.0))
            return base::Error{"not a roughness in (0, 1]"};
        v.roughness = number;
        return v;
    }
    if (column == "glossy")
        return glossyVariation(value);
    return declaredVariation(column, value);
}

} // namespace speculum::accuracy
