#include "editor/document/FieldProperties.hpp"
#include "editor/document/NodeComponentGroups.hpp"
#include "editor/document/PropertyMakers.hpp"

#include <algorithm>
#include <cmath>

namespace speculum::document::groups {

// The node's groups: one per component of NodeData, each made from the component's declared fields
// (FieldProperties.hpp). What is said here is only what a declaration cannot say: how a component is added
// and removed, the mesh's source, and the parallax proxy shown as one choice.

using namespace makers;
using scene::NodeData;

namespace {

template <typename C>
ComponentInfo component(std::optional<C> NodeData::*member, std::string_view key) {
    const render::FieldSpec& spec = *render::findField<NodeData>(key);
    ComponentInfo c;
    c.key = QString::fromUtf8(key.data(), qsizetype(key.size()));
    c.title = QString::fromUtf8(spec.label.data(), qsizetype(spec.label.size()));
    c.present = [member](const NodeData& d) { return (d.*member).has_value(); };
    c.add = [member](NodeData& d) {
        d.*member = C{};
        return ok();
    };
    c.remove = [member, key](NodeData& d) {
        d.*member = std::nullopt;
        d.unknown.erase(std::string(key)); // the file's unknown fields of the component go with it
        return ok();
    };
    fieldprops::addProperties<NodeData, C>(c.properties, c.key,
                                           [member](NodeData& d) -> C* {
                                               auto& m = d.*member;
                                               return m ? &*m : nullptr;
                                           },
                                           {});
    return c;
}

Property<NodeData>* find(ComponentInfo& c, const char* key) {
    const auto it = std::find_if(c.properties.begin(), c.properties.end(), [&](const Property<NodeData>& p) {
        return p.info.key == QLatin1String(key);
    });
    return it == c.properties.end() ? nullptr : &*it;
}

void erase(ComponentInfo& c, const char* key) {
    std::erase_if(c.properties,
                  [&](const Property<NodeData>& p) { return p.info.key == QLatin1String(key); });
}

// The mesh's source as one choice: a built-in shape, or the model file.
Property<NodeData> meshSource() {
    static const std::array<scene::BuiltinMesh, 4> kinds{scene::BuiltinMesh::Teapot,
                                                         scene::BuiltinMesh::Sphere, scene::BuiltinMesh::Box,
                                                         scene::BuiltinMesh::Plane};
    QStringList options;
    for (const render::names::Name& n : scene::kBuiltinMeshNames)
        options << QString::fromUtf8(n.label.data(), qsizetype(n.label.size()));
    options << QStringLiteral("Model file");
    return enumeration<NodeData>(
        QStringLiteral("mesh.source"), QStringLiteral("Shape"), options,
        [](const NodeData& d) {
            if (!d.mesh)
                return -1;
            return d.mesh->builtin ? static_cast<int>(*d.mesh->builtin) : 4;
        },
        [](NodeData& d, int i) -> base::Status {
            if (!d.mesh)
                return base::Error{"Shape does not apply to this node"};
            if (i == 4) {
                if (d.mesh->file.empty())
                    return base::Error{"Shape: choose the model file in the File field"};
                d.mesh = scene::MeshComponent::fromFile(d.mesh->file);
                return ok();
            }
            const scene::BuiltinMesh kind = kinds[static_cast<std::size_t>(i)];
            if (d.mesh->builtin != kind)
                d.mesh = scene::MeshComponent::fromBuiltin(kind);
            return ok();
        });
}

// One part of the model file (Assimp's scene order), or -1 for the whole file.
Property<NodeData> meshPart() {
    const render::FieldSpec& spec = *render::findField<scene::MeshComponent>("part");
    Property<NodeData> part;
    part.info = fieldprops::infoOf(spec, QStringLiteral("mesh.part"));
    part.info.minimum = -1;
    part.info.tooltip += QStringLiteral("; -1 for all of it");
    part.get = [](const NodeData& d) {
        return d.mesh && !d.mesh->builtin ? QVariant(d.mesh->part.value_or(-1)) : QVariant();
    };
    part.set = [](NodeData& d, const QVariant& v) -> base::Status {
        if (!d.mesh || d.mesh->builtin)
            return base::Error{"Part: only model files have parts"};
        bool parsed = false;
        const double x = v.toDouble(&parsed);
        if (!parsed || !std::isfinite(x) || x != std::floor(x) || x < -1.0 || x > 1e9)
            return base::Error{"Part expects a whole number, -1 (the whole file) or more"};
        d.mesh->part = x < 0.0 ? std::nullopt : std::optional<int>(static_cast<int>(x));
        return ok();
    };
    part.visible = [](const NodeData& d) { return d.mesh && !d.mesh->builtin.has_value(); };
    return part;
}

} // namespace

ComponentInfo nodeGroup() {
    ComponentInfo c;
    c.key = QStringLiteral("node");
    c.title = QStringLiteral("Node");
    c.optional = false;
    c.present = [](const NodeData&) { return true; };
    Property<NodeData> name;
    name.info = fieldprops::infoOf(*render::findField<NodeData>("name"), QStringLiteral("node.name"));
    name.get = [](const NodeData& d) { return QVariant(QString::fromStdString(d.name)); };
    name.set = [](NodeData& d, const QVariant& v) -> base::Status {
        const QString text = v.toString().trimmed();
        if (text.isEmpty())
            return base::Error{"Name must not be empty"};
        d.name = text.toStdString();
        return base::Done{};
    };
    c.properties.push_back(name);
    Property<NodeData> hidden;
    hidden.info = fieldprops::infoOf(*render::findField<NodeData>("hidden"), QStringLiteral("node.hidden"));
    hidden.get = [](const NodeData& d) { return QVariant(d.hidden); };
    hidden.set = [](NodeData& d, const QVariant& v) -> base::Status {
        d.hidden = v.toBool();
        return base::Done{};
    };
    c.properties.push_back(hidden);
    return c;
}

ComponentInfo transformGroup() {
    ComponentInfo c;
    c.key = QStringLiteral("transform");
    c.title = QStringLiteral("Transform");
    c.optional = false;
    c.present = [](const NodeData&) { return true; };
    fieldprops::addProperties<NodeData, scene::Transform>(c.properties, c.key,
                                                          [](NodeData& d) { return &d.transform; }, {});
    return c;
}

ComponentInfo meshGroup() {
    ComponentInfo c = component(&NodeData::mesh, "mesh");
    c.add = [](NodeData& d) {
        d.mesh = scene::MeshComponent::fromBuiltin(scene::BuiltinMesh::Sphere);
        return ok();
    };
    const auto remove = c.remove;
    c.remove = [remove](NodeData& d) -> base::Status {
        if (d.reflector)
            return base::Error{"The reflector's surface is this mesh: remove the reflector first"};
        return remove(d);
    };
    // The source is one choice (built-in shapes or the file); choosing a file makes it the source.
    c.properties.insert(c.properties.begin(), meshSource());
    if (Property<NodeData>* file = find(c, "mesh.file")) {
        auto setFile = file->set;
        file->set = [setFile](NodeData& d, const QVariant& v) -> base::Status {
            NodeData copy = d;
            if (auto status = setFile(copy, v); !status)
                return status;
            copy.mesh = scene::MeshComponent::fromFile(copy.mesh->file);
            d = std::move(copy);
            return ok();
        };
        file->visible = {}; // shown for built-ins too: picking a file is how a node gets one
    }
    c.properties.push_back(meshPart());
    return c;
}

ComponentInfo materialGroup() {
    return component(&NodeData::material, "material");
}

ComponentInfo lightGroup() {
    return component(&NodeData::light, "light");
}

ComponentInfo mirrorGroup() {
    ComponentInfo c = component(&NodeData::mirror, "mirror");
    // The planner draws a rough mirror into a texture whatever its technique says (the stencil technique
    // leaves no image of the reflection to blur): the field says so rather than show a technique that is
    // not the one drawn.
    if (Property<NodeData>* technique = find(c, "mirror.technique")) {
        technique->note = [](const NodeData& d) {
            return d.mirror && d.mirror->roughness > 0.0 &&
                           d.mirror->technique == render::MirrorTechnique::Stencil
                       ? QObject::tr("Drawn with the texture technique while rough: the stencil technique "
                                     "leaves no image of the reflection to blur.")
                       : QString();
        };
    }
    return c;
}

ComponentInfo animationGroup() {
    ComponentInfo c = component(&NodeData::animation, "animation");
    c.add = [](NodeData& d) {
        d.animation = scene::AnimationComponent{};
        d.animation->bounce = scene::BounceAnimation{};
        return ok();
    };
    // A new orbit goes around where the node stands.
    Property<NodeData>* orbit = find(c, "animation.orbit");
    auto set = orbit->set;
    orbit->set = [set](NodeData& d, const QVariant& v) -> base::Status {
        const bool adds = v.toBool() && d.animation && !d.animation->orbit;
        if (base::Status status = set(d, v); !status || !adds)
            return status;
        d.animation->orbit->center = d.transform.translate;
        return ok();
    };
    return c;
}

ComponentInfo reflectorGroup() {
    ComponentInfo c = component(&NodeData::reflector, "reflector");
    c.add = [](NodeData& d) {
        if (!d.mesh)
            d.mesh = scene::MeshComponent::fromBuiltin(scene::BuiltinMesh::Sphere); // its surface
        d.reflector = scene::ReflectorComponent{};
        return ok();
    };
    // The proxy and its shape are one choice: off, a sphere or a box.
    erase(c, "reflector.parallax.shape");
    Property<NodeData>* parallax = find(c, "reflector.parallax");
    parallax->info.kind = PropertyKind::Enum;
    parallax->info.options = QStringList{QStringLiteral("Off")} +
                             fieldprops::choiceLabels(*render::findField<render::ParallaxParams>("shape"));
    parallax->get = [](const NodeData& d) -> QVariant {
        if (!d.reflector)
            return {};
        return d.reflector->parallax ? static_cast<int>(d.reflector->parallax->shape) + 1 : 0;
    };
    parallax->set = [](NodeData& d, const QVariant& v) -> base::Status {
        bool parsed = false;
        const int i = v.toInt(&parsed);
        if (!d.reflector)
            return base::Error{"Parallax proxy does not apply to this node"};
        if (!parsed || i < 0 || i > 2)
            return base::Error{"Parallax proxy expects off, sphere or box"};
        if (i == 0) {
            d.reflector->parallax.reset();
            return ok();
        }
        if (!d.reflector->parallax)
            d.reflector->parallax = scene::ReflectorParallax{};
        d.reflector->parallax->shape = static_cast<scene::ParallaxShape>(i - 1);
        return ok();
    };
    return c;
}

} // namespace speculum::document::groups
