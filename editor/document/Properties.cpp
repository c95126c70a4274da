#include "editor/document/Properties.hpp"

#include "editor/document/FieldProperties.hpp"
#include "editor/document/NodeComponentGroups.hpp"
#include "editor/document/PropertyMakers.hpp"
#include "render/frame/SceneLimits.hpp"
#include "render/frame/SceneNames.hpp"
#include "render/frame/Settings.hpp"
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

// The scene's settings and camera, from their declarations; the camera's rules across fields (a target
// away from the position, ...) are checked on the whole camera, as the project reader does.
template <typename T>
std::vector<Property<T>> declaredProperties(const QString& prefix) {
    std::vector<Property<T>> list;
    fieldprops::addProperties<T, T>(list, prefix, [](T& value) { return &value; }, {});
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
    static const auto list = declaredProperties<scene::SceneSettings>(QStringLiteral("settings"));
    return list;
}

const std::vector<Property<scene::CameraData>>& cameraProperties() {
    static const auto list = declaredProperties<scene::CameraData>(QStringLiteral("camera"));
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
