#include "editor/document/NodeComponentGroups.hpp"
#include "editor/document/PropertyMakers.hpp"
#include "render/SceneLimits.hpp"

namespace speculum::document::groups {

// The two reflecting components: the planar mirror and the curved reflector with its environment map.

using namespace makers;

ComponentInfo mirrorGroup() {
    ComponentInfo c;
    c.key = QStringLiteral("mirror");
    c.title = QStringLiteral("Planar mirror");
    c.present = [](const NodeData& d) { return d.mirror.has_value(); };
    c.add = [](NodeData& d) {
        d.mirror = MirrorComponent{};
        return ok();
    };
    c.remove = [](NodeData& d) {
        d.mirror.reset();
        return ok();
    };
    using Mi = MirrorComponent;
    c.properties.push_back(vector<NodeData, 2>(QStringLiteral("mirror.size"), QStringLiteral("Size"),
                                               in(&NodeData::mirror, &Mi::size), {}, QStringLiteral(" u"),
                                               positiveExtents));
    c.properties.back().info.tooltip = QStringLiteral("Extents along the node's local X and Z");
    c.properties.push_back(
        slider(number<NodeData>(QStringLiteral("mirror.reflectivity"), QStringLiteral("Reflectivity"),
                                in(&NodeData::mirror, &Mi::reflectivity), {0.0, 1.0}, {},
                                QStringLiteral("1 = perfect mirror")),
               0.0, 1.0));
    c.properties.push_back(
        namedField<MirrorTechnique>(QStringLiteral("mirror.technique"), QStringLiteral("Technique"),
                                    render::names::kMirrorTechniques, in(&NodeData::mirror, &Mi::technique)));
    c.properties.push_back(color<NodeData>(QStringLiteral("mirror.tint"), QStringLiteral("Tint"),
                                           in(&NodeData::mirror, &Mi::tint)));
    c.properties.push_back(boolean<NodeData>(
        QStringLiteral("mirror.fresnel"), QStringLiteral("Fresnel"),
        [](const NodeData& d) { return d.mirror && d.mirror->fresnel; },
        [](NodeData& d, bool on) -> render::Status {
            if (!d.mirror) {
                return render::Error{"Fresnel does not apply to this node"};
            }
            d.mirror->fresnel = on;
            return ok();
        }));
    c.properties.back().info.tooltip = QStringLiteral(
        "Schlick: the reflectivity applies at normal incidence and rises to 1 at grazing angles");
    c.properties.push_back(
        slider(number<NodeData>(QStringLiteral("mirror.blur"), QStringLiteral("Blur"),
                                in(&NodeData::mirror, &Mi::blur), {0.0, 1.0}, {},
                                QStringLiteral("Roughness of the reflection (texture technique)")),
               0.0, 1.0));
    return c;
}

ComponentInfo reflectorGroup() {
    ComponentInfo c;
    c.key = QStringLiteral("reflector");
    c.title = QStringLiteral("Curved reflector");
    c.present = [](const NodeData& d) { return d.reflector.has_value(); };
    c.add = [](NodeData& d) {
        if (!d.mesh) {
            d.mesh = MeshComponent::fromBuiltin(BuiltinMesh::Sphere); // its surface
        }
        d.reflector = ReflectorComponent{};
        return ok();
    };
    c.remove = [](NodeData& d) {
        d.reflector.reset();
        return ok();
    };
    using R = ReflectorComponent;
    c.properties.push_back(
        namedField<ReflectorMap>(QStringLiteral("reflector.map"), QStringLiteral("Environment map"),
                                 render::names::kReflectorMaps, in(&NodeData::reflector, &R::map)));
    c.properties.push_back(integer<NodeData>(
        QStringLiteral("reflector.resolution"), QStringLiteral("Resolution"),
        in(&NodeData::reflector, &R::resolution),
        {render::kMinEnvironmentMapSize, render::kMaxEnvironmentMapSize}, QStringLiteral(" px")));
    c.properties.back().info.step = 32;
    c.properties.push_back(
        slider(number<NodeData>(QStringLiteral("reflector.reflectivity"), QStringLiteral("Reflectivity"),
                                in(&NodeData::reflector, &R::reflectivity), {0.0, 1.0}),
               0.0, 1.0));
    c.properties.push_back(boolean<NodeData>(
        QStringLiteral("reflector.fresnel"), QStringLiteral("Fresnel"),
        [](const NodeData& d) { return d.reflector && d.reflector->fresnel; },
        [](NodeData& d, bool on) -> render::Status {
            if (!d.reflector) {
                return render::Error{"Fresnel does not apply to this node"};
            }
            d.reflector->fresnel = on;
            return ok();
        }));
    c.properties.push_back(namedField<ReflectorFill>(QStringLiteral("reflector.fill"), QStringLiteral("Fill"),
                                                     render::names::kReflectorFills,
                                                     in(&NodeData::reflector, &R::fill)));
    c.properties.back().info.tooltip =
        QStringLiteral("How dual-paraboloid and tennis-ball maps are filled; the cube map ignores it");
    c.properties.push_back(
        namedField<ReflectorUpdate>(QStringLiteral("reflector.update"), QStringLiteral("Update"),
                                    render::names::kReflectorUpdates, in(&NodeData::reflector, &R::update)));
    c.properties.push_back(integer<NodeData>(
        QStringLiteral("reflector.mirrorDepth"), QStringLiteral("Mirror depth in the map"),
        in(&NodeData::reflector, &R::mirrorDepth), {0, render::kMaxMirrorDepth}, {}, {},
        QStringLiteral(
            "How many levels of planar mirrors reflect inside the environment map, mirrors seen in "
            "mirrors included (every fill); 0 shows them with their own material")));
    return c;
}

} // namespace speculum::document::groups
