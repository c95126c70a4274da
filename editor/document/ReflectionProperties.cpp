#include "editor/document/NodeComponentGroups.hpp"
#include "editor/document/PropertyMakers.hpp"
#include "render/frame/SceneLimits.hpp"

#include <type_traits>
#include <utility>

namespace speculum::document::groups {

// The two reflecting components: the planar mirror and the curved reflector with its environment map.

using namespace makers;

ComponentInfo mirrorGroup() {
    ComponentInfo c;
    c.key = QStringLiteral("mirror");
    c.title = QStringLiteral("Planar mirror");
    c.present = [](const scene::NodeData& d) { return d.mirror.has_value(); };
    c.add = [](scene::NodeData& d) {
        d.mirror = scene::MirrorComponent{};
        return ok();
    };
    c.remove = [](scene::NodeData& d) {
        d.mirror.reset();
        return ok();
    };
    using Mi = scene::MirrorComponent;
    c.properties.push_back(vector<scene::NodeData, 2>(QStringLiteral("mirror.size"), QStringLiteral("Size"),
                                                      in(&scene::NodeData::mirror, &Mi::size), {},
                                                      QStringLiteral(" u"), positiveExtents));
    c.properties.back().info.tooltip = QStringLiteral("Extents along the node's local X and Z");
    c.properties.push_back(
        slider(number<scene::NodeData>(QStringLiteral("mirror.reflectivity"), QStringLiteral("Reflectivity"),
                                       in(&scene::NodeData::mirror, &Mi::reflectivity), {0.0, 1.0}, {},
                                       QStringLiteral("1 = perfect mirror")),
               0.0, 1.0));
    c.properties.push_back(namedField<scene::MirrorTechnique>(
        QStringLiteral("mirror.technique"), QStringLiteral("Technique"), render::names::kMirrorTechniques,
        in(&scene::NodeData::mirror, &Mi::technique)));
    c.properties.push_back(color<scene::NodeData>(QStringLiteral("mirror.tint"), QStringLiteral("Tint"),
                                                  in(&scene::NodeData::mirror, &Mi::tint)));
    c.properties.push_back(boolean<scene::NodeData>(
        QStringLiteral("mirror.fresnel"), QStringLiteral("Fresnel"),
        [](const scene::NodeData& d) { return d.mirror && d.mirror->fresnel; },
        [](scene::NodeData& d, bool on) -> base::Status {
            if (!d.mirror) {
                return base::Error{"Fresnel does not apply to this node"};
            }
            d.mirror->fresnel = on;
            return ok();
        }));
    c.properties.back().info.tooltip = QStringLiteral(
        "Schlick: the reflectivity applies at normal incidence and rises to 1 at grazing angles");
    c.properties.push_back(slider(
        number<scene::NodeData>(QStringLiteral("mirror.roughness"), QStringLiteral("Roughness"),
                                in(&scene::NodeData::mirror, &Mi::roughness), {0.0, 1.0}, {},
                                QStringLiteral("GGX microfacet roughness (α = roughness²): 0 is a perfect "
                                               "mirror; a rough mirror is drawn with the texture technique")),
        0.0, 1.0));
    return c;
}

namespace {

// The parallax proxy: off, a sphere or a box around the capture point, with the same rules as the project
// reader (a positive radius; a box that contains the capture point, min < 0 < max on every axis).
void addParallaxProperties(ComponentInfo& c) {
    using P = scene::ReflectorParallax;
    static const QStringList shapes{QStringLiteral("Off"), QStringLiteral("Sphere"), QStringLiteral("Box")};
    c.properties.push_back(enumeration<scene::NodeData>(
        QStringLiteral("reflector.parallax"), QStringLiteral("Parallax proxy"), shapes,
        [](const scene::NodeData& d) {
            if (!d.reflector) {
                return -1;
            }
            if (!d.reflector->parallax) {
                return 0;
            }
            return d.reflector->parallax->shape == scene::ParallaxShape::Sphere ? 1 : 2;
        },
        [](scene::NodeData& d, int i) -> base::Status {
            if (!d.reflector) {
                return base::Error{"Parallax proxy does not apply to this node"};
            }
            if (i == 0) {
                d.reflector->parallax.reset();
                return ok();
            }
            if (!d.reflector->parallax) {
                d.reflector->parallax = P{};
            }
            d.reflector->parallax->shape = i == 1 ? scene::ParallaxShape::Sphere : scene::ParallaxShape::Box;
            return ok();
        }));
    c.properties.back().info.tooltip = QStringLiteral(
        "Corrects the environment map's lookups for the distance to what it shows: each reflected ray is "
        "intersected with this sphere or box around the reflector's centre (world axes). Off treats "
        "everything as infinitely far away; a proxy that fits the room makes near walls reflect in the "
        "right place");
    const auto parallaxIs = [](scene::ParallaxShape shape) {
        return [shape](const scene::NodeData& d) {
            return d.reflector && d.reflector->parallax && d.reflector->parallax->shape == shape;
        };
    };
    const auto field = [](auto P::*member) {
        using V = std::remove_reference_t<decltype(std::declval<P&>().*member)>;
        return Access<scene::NodeData, V>([member](scene::NodeData& d) -> V* {
            return d.reflector && d.reflector->parallax ? &((*d.reflector->parallax).*member) : nullptr;
        });
    };
    c.properties.push_back(number<scene::NodeData>(
        QStringLiteral("reflector.parallax.radius"), QStringLiteral("Proxy radius"), field(&P::radius),
        {render::kMinScale, render::kMaxCoordinate}, QStringLiteral(" u"),
        QStringLiteral("Radius of the proxy sphere around the reflector's "
                       "centre")));
    c.properties.back().visible = parallaxIs(scene::ParallaxShape::Sphere);
    const auto faces = [](double sign) {
        return [sign](const glm::dvec3& v) -> QString {
            for (int i = 0; i < 3; ++i) {
                const double distance = sign * v[i];
                if (!(distance >= render::kMinScale && distance <= render::kMaxCoordinate)) {
                    return QStringLiteral("the box must contain the capture point (min < 0 < max on every "
                                          "axis, at most %1 away)")
                        .arg(formatNumber(render::kMaxCoordinate));
                }
            }
            return {};
        };
    };
    c.properties.push_back(vector<scene::NodeData, 3>(QStringLiteral("reflector.parallax.min"),
                                                      QStringLiteral("Proxy box min"), field(&P::min), {},
                                                      QStringLiteral(" u"), faces(-1.0)));
    c.properties.back().info.tooltip =
        QStringLiteral("The box's lower corner relative to the reflector's centre: every component below 0");
    c.properties.back().visible = parallaxIs(scene::ParallaxShape::Box);
    c.properties.push_back(vector<scene::NodeData, 3>(QStringLiteral("reflector.parallax.max"),
                                                      QStringLiteral("Proxy box max"), field(&P::max), {},
                                                      QStringLiteral(" u"), faces(1.0)));
    c.properties.back().info.tooltip =
        QStringLiteral("The box's upper corner relative to the reflector's centre: every component above 0");
    c.properties.back().visible = parallaxIs(scene::ParallaxShape::Box);
}

} // namespace

ComponentInfo reflectorGroup() {
    ComponentInfo c;
    c.key = QStringLiteral("reflector");
    c.title = QStringLiteral("Curved reflector");
    c.present = [](const scene::NodeData& d) { return d.reflector.has_value(); };
    c.add = [](scene::NodeData& d) {
        if (!d.mesh) {
            d.mesh = scene::MeshComponent::fromBuiltin(scene::BuiltinMesh::Sphere); // its surface
        }
        d.reflector = scene::ReflectorComponent{};
        return ok();
    };
    c.remove = [](scene::NodeData& d) {
        d.reflector.reset();
        return ok();
    };
    using R = scene::ReflectorComponent;
    c.properties.push_back(namedField<scene::ReflectorMap>(
        QStringLiteral("reflector.map"), QStringLiteral("Environment map"), render::names::kReflectorMaps,
        in(&scene::NodeData::reflector, &R::map)));
    c.properties.push_back(integer<scene::NodeData>(
        QStringLiteral("reflector.resolution"), QStringLiteral("Resolution"),
        in(&scene::NodeData::reflector, &R::resolution),
        {render::kMinEnvironmentMapSize, render::kMaxEnvironmentMapSize}, QStringLiteral(" px")));
    c.properties.back().info.step = 32;
    c.properties.push_back(slider(
        number<scene::NodeData>(QStringLiteral("reflector.reflectivity"), QStringLiteral("Reflectivity"),
                                in(&scene::NodeData::reflector, &R::reflectivity), {0.0, 1.0}),
        0.0, 1.0));
    c.properties.push_back(boolean<scene::NodeData>(
        QStringLiteral("reflector.fresnel"), QStringLiteral("Fresnel"),
        [](const scene::NodeData& d) { return d.reflector && d.reflector->fresnel; },
        [](scene::NodeData& d, bool on) -> base::Status {
            if (!d.reflector) {
                return base::Error{"Fresnel does not apply to this node"};
            }
            d.reflector->fresnel = on;
            return ok();
        }));
    c.properties.push_back(namedField<scene::ReflectorFill>(
        QStringLiteral("reflector.fill"), QStringLiteral("Fill"), render::names::kReflectorFills,
        in(&scene::NodeData::reflector, &R::fill)));
    c.properties.back().info.tooltip =
        QStringLiteral("How dual-paraboloid and tennis-ball maps are filled; the cube map ignores it");
    addParallaxProperties(c);
    c.properties.push_back(namedField<scene::ReflectorUpdate>(
        QStringLiteral("reflector.update"), QStringLiteral("Update"), render::names::kReflectorUpdates,
        in(&scene::NodeData::reflector, &R::update)));
    c.properties.push_back(integer<scene::NodeData>(
        QStringLiteral("reflector.mirrorDepth"), QStringLiteral("Mirror depth in the map"),
        in(&scene::NodeData::reflector, &R::mirrorDepth), {0, render::kMaxMirrorDepth}, {}, {},
        QStringLiteral(
            "How many levels of planar mirrors reflect inside the environment map, mirrors seen in "
            "mirrors included (every fill); 0 shows them with their own material")));
    c.properties.push_back(slider(
        number<scene::NodeData>(QStringLiteral("reflector.roughness"), QStringLiteral("Roughness"),
                                in(&scene::NodeData::reflector, &R::roughness), {0.0, 1.0}, {},
                                QStringLiteral("GGX microfacet roughness (α = roughness²): 0 is a perfect "
                                               "mirror; rougher looks up a pre-filtered level of the map")),
        0.0, 1.0));
    return c;
}

} // namespace speculum::document::groups
