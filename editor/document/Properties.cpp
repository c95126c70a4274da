#include "editor/document/Properties.hpp"

#include "editor/document/NodeComponentGroups.hpp"
#include "editor/document/PropertyMakers.hpp"
#include "render/frame/GlossyLimits.hpp"
#include "render/frame/SceneLimits.hpp"
#include "render/frame/SceneNames.hpp"
#include "scene/model/SceneChecks.hpp"

#include <cmath>
#include <glm/geometric.hpp>
#include <map>

namespace speculum::document {

using namespace makers;

namespace {

QString rangeText(const PropertyInfo& info) {
    const bool hasMin = std::isfinite(info.minimum);
    const bool hasMax = std::isfinite(info.maximum);
    if (hasMin && hasMax) {
        return QStringLiteral("%1%2..%3%4")
            .arg(info.minimumExclusive ? QStringLiteral("(") : QString(), formatNumber(info.minimum),
                 formatNumber(info.maximum), info.maximumExclusive ? QStringLiteral(")") : QString());
    }
    if (hasMin) {
        return info.minimumExclusive ? QStringLiteral("greater than %1").arg(formatNumber(info.minimum))
                                     : QStringLiteral("at least %1").arg(formatNumber(info.minimum));
    }
    return QStringLiteral("at most %1").arg(formatNumber(info.maximum));
}

std::vector<Property<scene::SceneSettings>> makeSettingsProperties() {
    std::vector<Property<scene::SceneSettings>> list;
    list.push_back(color<scene::SceneSettings>(QStringLiteral("settings.background"),
                                               QStringLiteral("Background"),
                                               [](scene::SceneSettings& s) { return &s.background; }));
    list.push_back(integer<scene::SceneSettings>(
        QStringLiteral("settings.mirrorDepth"), QStringLiteral("Mirror depth"),
        [](scene::SceneSettings& s) { return &s.mirrorDepth; }, {0, render::kMaxMirrorDepth}, {}, {},
        QStringLiteral("How many reflections of reflections are drawn")));
    list.push_back(
        slider(number<scene::SceneSettings>(QStringLiteral("settings.ambient"), QStringLiteral("Ambient"),
                                            [](scene::SceneSettings& s) { return &s.ambient; }, {0.0, 1.0}),
               0.0, 1.0));
    list.push_back(boolean<scene::SceneSettings>(
        QStringLiteral("settings.simplifyReflections"), QStringLiteral("Simplify big meshes in reflections"),
        [](const scene::SceneSettings& s) { return s.simplifyReflections; },
        [](scene::SceneSettings& s, bool on) -> base::Status {
            s.simplifyReflections = on;
            return base::Done{};
        },
        QStringLiteral("Mirrors and the reflector's map draw meshes of more than 100 000 triangles at a "
                       "simplified level")));
    QStringList filters;
    for (const render::names::Name& n : render::names::kGlossyFilters)
        filters << QString::fromUtf8(n.label.data(), qsizetype(n.label.size()));
    list.push_back(enumeration<scene::SceneSettings>(
        QStringLiteral("settings.glossyFilter"), QStringLiteral("Rough reflections"), filters,
        [](const scene::SceneSettings& s) { return static_cast<int>(s.glossyFilter); },
        [](scene::SceneSettings& s, int i) -> base::Status {
            s.glossyFilter = static_cast<scene::GlossyFilter>(i);
            return base::Done{};
        }));
    list.back().info.tooltip =
        QStringLiteral("How rough mirrors and the rough reflector are approximated: one mip level chosen by "
                       "the roughness (cheap), or the GGX lobe's footprint on planar mirrors and a "
                       "pre-filtered map chain on the reflector");
    list.push_back(integer<scene::SceneSettings>(
        QStringLiteral("settings.glossyTaps"), QStringLiteral("Rough mirror taps"),
        [](scene::SceneSettings& s) { return &s.glossyTaps; },
        {render::kMinGlossyTaps, render::kMaxGlossyTaps}, {}, {},
        QStringLiteral("Samples of the GGX lobe per pixel of a rough planar mirror (lobe footprint)")));
    list.push_back(integer<scene::SceneSettings>(
        QStringLiteral("settings.prefilterSamples"), QStringLiteral("Pre-filter samples"),
        [](scene::SceneSettings& s) { return &s.prefilterSamples; },
        {render::kMinPrefilterSamples, render::kMaxPrefilterSamples}, {}, {},
        QStringLiteral("Samples of the GGX lobe per texel when the reflector's map is pre-filtered")));
    return list;
}

std::vector<Property<scene::CameraData>> makeCameraProperties() {
    std::vector<Property<scene::CameraData>> list;
    const NumberRange kCoordinate{-render::kMaxCoordinate, render::kMaxCoordinate};
    // Position and target must differ and up must not be parallel to the view: checked on the whole camera.
    const auto checkCamera = [](Property<scene::CameraData> p) {
        auto set = p.set;
        p.set = [set](scene::CameraData& c, const QVariant& v) -> base::Status {
            scene::CameraData copy = c;
            if (auto s = set(copy, v); !s) {
                return s;
            }
            // The project reader's rule for the whole camera (SceneChecks.hpp), word for word.
            if (const std::optional<scene::FieldProblem> problem = scene::cameraProblem(copy)) {
                static const std::map<std::string, std::string> labels{
                    {"position", "Position"},  {"target", "Target"}, {"up", "Up"},
                    {"fovY", "Field of view"}, {"near", "Near"},     {"far", "Far"}};
                const auto label = labels.find(problem->field);
                return base::Error{"Camera " + (label != labels.end() ? label->second : problem->field) +
                                   " " + problem->what};
            }
            c = std::move(copy);
            return base::Done{};
        };
        return p;
    };
    using V3 = Access<scene::CameraData, glm::dvec3>;
    list.push_back(checkCamera(vector<scene::CameraData, 3>(
        QStringLiteral("camera.position"), QStringLiteral("Position"),
        V3([](scene::CameraData& c) { return &c.position; }), kCoordinate, QStringLiteral(" u"))));
    list.push_back(checkCamera(vector<scene::CameraData, 3>(
        QStringLiteral("camera.target"), QStringLiteral("Target"),
        V3([](scene::CameraData& c) { return &c.target; }), kCoordinate, QStringLiteral(" u"))));
    list.push_back(checkCamera(vector<scene::CameraData, 3>(QStringLiteral("camera.up"), QStringLiteral("Up"),
                                                            V3([](scene::CameraData& c) { return &c.up; }),
                                                            kCoordinate)));
    list.push_back(
        checkCamera(slider(number<scene::CameraData>(
                               QStringLiteral("camera.fovY"), QStringLiteral("Field of view"),
                               [](scene::CameraData& c) { return &c.fovY; }, {0.0, 180.0, true, true},
                               QStringLiteral("°"), QStringLiteral("Vertical, in degrees")),
                           10.0, 120.0, 1, 1.0)));
    list.push_back(checkCamera(number<scene::CameraData>(
        QStringLiteral("camera.near"), QStringLiteral("Near"), [](scene::CameraData& c) { return &c.near; },
        {render::kMinNear, render::kMaxCoordinate}, QStringLiteral(" u"),
        QStringLiteral("At most %1 times nearer than Far (depth-buffer precision)")
            .arg(formatNumber(render::kMaxFarNearRatio)))));
    list.push_back(checkCamera(number<scene::CameraData>(
        QStringLiteral("camera.far"), QStringLiteral("Far"), [](scene::CameraData& c) { return &c.far; },
        {0.0, kInf, true}, QStringLiteral(" u"))));
    return list;
}

} // namespace

QString formatNumber(double value) {
    return QString::number(value, 'g', 10);
}

base::Status checkRange(const PropertyInfo& info, double value) {
    if (!std::isfinite(value)) {
        return fail(info, QStringLiteral("expects a finite number"));
    }
    const bool belowMin = info.minimumExclusive ? value <= info.minimum : value < info.minimum;
    const bool aboveMax = info.maximumExclusive ? value >= info.maximum : value > info.maximum;
    if (belowMin || aboveMax) {
        return fail(info, QStringLiteral("must be %1%2, got %3")
                              .arg(std::isfinite(info.minimum) && std::isfinite(info.maximum)
                                       ? QStringLiteral("in ")
                                       : QString(),
                                   rangeText(info), formatNumber(value)));
    }
    return base::Done{};
}

const std::vector<ComponentInfo>& nodeComponents() {
    static const std::vector<ComponentInfo> list{
        groups::nodeGroup(),  groups::transformGroup(), groups::meshGroup(),      groups::materialGroup(),
        groups::lightGroup(), groups::mirrorGroup(),    groups::reflectorGroup(), groups::animationGroup()};
    return list;
}

const ComponentInfo* findComponent(const QString& key) {
    for (const ComponentInfo& c : nodeComponents()) {
        if (c.key == key) {
            return &c;
        }
    }
    return nullptr;
}

const Property<scene::NodeData>* findNodeProperty(const QString& key) {
    for (const ComponentInfo& c : nodeComponents()) {
        for (const auto& p : c.properties) {
            if (p.info.key == key) {
                return &p;
            }
        }
    }
    return nullptr;
}

const std::vector<Property<scene::SceneSettings>>& settingsProperties() {
    static const auto list = makeSettingsProperties();
    return list;
}

const std::vector<Property<scene::CameraData>>& cameraProperties() {
    static const auto list = makeCameraProperties();
    return list;
}

const Property<scene::SceneSettings>* findSettingsProperty(const QString& key) {
    for (const auto& p : settingsProperties()) {
        if (p.info.key == key) {
            return &p;
        }
    }
    return nullptr;
}

const Property<scene::CameraData>* findCameraProperty(const QString& key) {
    for (const auto& p : cameraProperties()) {
        if (p.info.key == key) {
            return &p;
        }
    }
    return nullptr;
}

} // namespace speculum::document
