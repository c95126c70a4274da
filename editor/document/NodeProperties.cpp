#include "editor/document/NodeComponentGroups.hpp"
#include "editor/document/PropertyMakers.hpp"
#include "render/frame/SceneLimits.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace speculum::document::groups {

// What a node is and where: its name, transform, shape, surface, light and motion. The reflecting
// components are in ReflectionProperties.cpp.

using namespace makers;

// The project reader's limits (render/frame/SceneLimits.hpp), so an edit never makes a file that does not
// load.
namespace {
const NumberRange kCoordinate{-render::kMaxCoordinate, render::kMaxCoordinate};
const NumberRange kLength{0.0, render::kMaxCoordinate};
const NumberRange kIntensity{0.0, render::kMaxIntensity};
const NumberRange kPeriod{render::kMinPeriod, render::kMaxPeriod};
} // namespace

ComponentInfo nodeGroup() {
    ComponentInfo c;
    c.key = QStringLiteral("node");
    c.title = QStringLiteral("Node");
    c.optional = false;
    c.present = [](const scene::NodeData&) { return true; };
    Property<scene::NodeData> name;
    name.info.key = QStringLiteral("node.name");
    name.info.label = QStringLiteral("Name");
    name.info.kind = PropertyKind::Text;
    name.get = [](const scene::NodeData& d) { return QVariant(QString::fromStdString(d.name)); };
    name.set = [](scene::NodeData& d, const QVariant& v) -> base::Status {
        const QString text = v.toString().trimmed();
        if (text.isEmpty()) {
            return base::Error{"Name must not be empty"};
        }
        d.name = text.toStdString();
        return base::Done{};
    };
    c.properties.push_back(name);
    return c;
}

ComponentInfo transformGroup() {
    ComponentInfo c;
    c.key = QStringLiteral("transform");
    c.title = QStringLiteral("Transform");
    c.optional = false;
    c.present = [](const scene::NodeData&) { return true; };
    using V3 = Access<scene::NodeData, glm::dvec3>;
    c.properties.push_back(vector<scene::NodeData, 3>(
        QStringLiteral("transform.translate"), QStringLiteral("Translate"),
        V3([](scene::NodeData& d) { return &d.transform.translate; }), kCoordinate, QStringLiteral(" u")));
    c.properties.push_back(vector<scene::NodeData, 3>(
        QStringLiteral("transform.rotate"), QStringLiteral("Rotate"),
        V3([](scene::NodeData& d) { return &d.transform.rotate; }), {}, QStringLiteral("°")));
    c.properties.back().info.tooltip =
        QStringLiteral("XYZ Euler angles in degrees, applied X, then Y, then Z");
    c.properties.back().info.step = 5.0;
    c.properties.push_back(vector<scene::NodeData, 3>(
        QStringLiteral("transform.scale"), QStringLiteral("Scale"),
        V3([](scene::NodeData& d) { return &d.transform.scale; }), {}, {}, nonZeroScale));
    return c;
}

ComponentInfo meshGroup() {
    ComponentInfo c;
    c.key = QStringLiteral("mesh");
    c.title = QStringLiteral("Mesh");
    c.present = [](const scene::NodeData& d) { return d.mesh.has_value(); };
    c.add = [](scene::NodeData& d) {
        d.mesh = scene::MeshComponent::fromBuiltin(scene::BuiltinMesh::Sphere);
        return ok();
    };
    c.remove = [](scene::NodeData& d) -> base::Status {
        if (d.reflector) {
            return base::Error{"The reflector's surface is this mesh: remove the reflector first"};
        }
        d.mesh.reset();
        return ok();
    };
    static const std::array<scene::BuiltinMesh, 4> kinds{scene::BuiltinMesh::Teapot,
                                                         scene::BuiltinMesh::Sphere, scene::BuiltinMesh::Box,
                                                         scene::BuiltinMesh::Plane};
    c.properties.push_back(enumeration<scene::NodeData>(
        QStringLiteral("mesh.source"), QStringLiteral("Shape"),
        {QStringLiteral("Teapot"), QStringLiteral("Sphere"), QStringLiteral("Box"), QStringLiteral("Plane"),
         QStringLiteral("Model file")},
        [](const scene::NodeData& d) {
            if (!d.mesh) {
                return -1;
            }
            if (!d.mesh->builtin) {
                return 4;
            }
            return static_cast<int>(std::find(kinds.begin(), kinds.end(), *d.mesh->builtin) - kinds.begin());
        },
        [](scene::NodeData& d, int i) -> base::Status {
            if (!d.mesh) {
                return base::Error{"Shape does not apply to this node"};
            }
            if (i == 4) {
                if (d.mesh->file.empty()) {
                    return base::Error{"Shape: choose the model file in the File field"};
                }
                d.mesh = scene::MeshComponent::fromFile(d.mesh->file);
                return ok();
            }
            const scene::BuiltinMesh kind = kinds[static_cast<std::size_t>(i)];
            if (d.mesh->builtin != kind) {
                d.mesh = scene::MeshComponent::fromBuiltin(kind);
            }
            return ok();
        }));
    c.properties.push_back(integer<scene::NodeData>(
        QStringLiteral("mesh.tessellation"), QStringLiteral("Tessellation"),
        in(&scene::NodeData::mesh, &scene::MeshComponent::tessellation),
        {render::kMinTessellation, render::kMaxTessellation}, {}, {},
        QStringLiteral("Subdivisions of the built-in shape (teapot: per patch edge, sphere: rings)")));
    c.properties.back().visible = [](const scene::NodeData& d) {
        return d.mesh && d.mesh->builtin.has_value();
    };
    Property<scene::NodeData> file =
        filePath(QStringLiteral("mesh.file"), QStringLiteral("File"),
                 in(&scene::NodeData::mesh, &scene::MeshComponent::file),
                 QStringLiteral("3D models (*.obj *.gltf *.glb *.fbx *.dae *.ply *.stl "
                                "*.3ds *.blend *.off);;All files (*)"),
                 false);
    // Choosing a file makes it the mesh's source.
    auto setFile = file.set;
    file.set = [setFile](scene::NodeData& d, const QVariant& v) -> base::Status {
        scene::NodeData copy = d;
        if (auto status = setFile(copy, v); !status) {
            return status;
        }
        copy.mesh = scene::MeshComponent::fromFile(copy.mesh->file);
        d = std::move(copy);
        return ok();
    };
    c.properties.push_back(file);
    // One part of the model file (Assimp's scene order), or -1 for the whole file.
    Property<scene::NodeData> part = integer<scene::NodeData>(
        QStringLiteral("mesh.part"), QStringLiteral("Part"), [](scene::NodeData&) -> int* { return nullptr; },
        {-1, 1e9}, {}, {},
        QStringLiteral("Which mesh of the file this node draws, in its own coordinates; -1 for all of it"));
    part.get = [](const scene::NodeData& d) {
        return d.mesh && !d.mesh->builtin ? QVariant(d.mesh->part.value_or(-1)) : QVariant();
    };
    part.set = [](scene::NodeData& d, const QVariant& v) -> base::Status {
        if (!d.mesh || d.mesh->builtin) {
            return base::Error{"Part: only model files have parts"};
        }
        bool parsed = false;
        const double x = v.toDouble(&parsed);
        if (!parsed || !std::isfinite(x) || x != std::floor(x) || x < -1.0 || x > 1e9) {
            return base::Error{"Part expects a whole number, -1 (the whole file) or more"};
        }
        if (x < 0.0) {
            d.mesh->part.reset();
        } else {
            d.mesh->part = static_cast<int>(x);
        }
        return ok();
    };
    part.visible = [](const scene::NodeData& d) { return d.mesh && !d.mesh->builtin.has_value(); };
    c.properties.push_back(part);
    return c;
}

ComponentInfo materialGroup() {
    ComponentInfo c;
    c.key = QStringLiteral("material");
    c.title = QStringLiteral("Material");
    c.present = [](const scene::NodeData& d) { return d.material.has_value(); };
    c.add = [](scene::NodeData& d) {
        d.material = scene::MaterialComponent{};
        return ok();
    };
    c.remove = [](scene::NodeData& d) {
        d.material.reset();
        return ok();
    };
    using M = scene::MaterialComponent;
    c.properties.push_back(color<scene::NodeData>(QStringLiteral("material.color"), QStringLiteral("Colour"),
                                                  in(&scene::NodeData::material, &M::color)));
    c.properties.push_back(
        slider(number<scene::NodeData>(QStringLiteral("material.ambient"), QStringLiteral("Ambient"),
                                       in(&scene::NodeData::material, &M::ambient), kIntensity),
               0.0, 2.0));
    c.properties.push_back(
        slider(number<scene::NodeData>(QStringLiteral("material.diffuse"), QStringLiteral("Diffuse"),
                                       in(&scene::NodeData::material, &M::diffuse), kIntensity),
               0.0, 2.0));
    c.properties.push_back(
        slider(number<scene::NodeData>(QStringLiteral("material.specular"), QStringLiteral("Specular"),
                                       in(&scene::NodeData::material, &M::specular), kIntensity),
               0.0, 2.0));
    c.properties.push_back(slider(
        number<scene::NodeData>(QStringLiteral("material.shininess"), QStringLiteral("Shininess"),
                                in(&scene::NodeData::material, &M::shininess), {0.0, render::kMaxShininess}),
        1.0, 256.0, 1, 1.0));
    c.properties.push_back(color<scene::NodeData>(QStringLiteral("material.emission"),
                                                  QStringLiteral("Emission"),
                                                  in(&scene::NodeData::material, &M::emission)));
    c.properties.push_back(
        filePath(QStringLiteral("material.texture"), QStringLiteral("Texture"),
                 in(&scene::NodeData::material, &M::texture),
                 QStringLiteral("Images (*.png *.jpg *.jpeg *.tif *.tiff *.exr *.hdr);;All "
                                "files (*)"),
                 true));
    c.properties.back().info.tooltip = QStringLiteral("Empty for none");
    // What imported models bring (glTF, OBJ, FBX, Collada materials).
    c.properties.push_back(color<scene::NodeData>(QStringLiteral("material.specularColor"),
                                                  QStringLiteral("Highlight colour"),
                                                  in(&scene::NodeData::material, &M::specularColor)));
    const QString images =
        QStringLiteral("Images (*.png *.jpg *.jpeg *.tif *.tiff *.exr *.hdr);;All files (*)");
    c.properties.push_back(filePath(QStringLiteral("material.emissionTexture"),
                                    QStringLiteral("Emission texture"),
                                    in(&scene::NodeData::material, &M::emissionTexture), images, true));
    c.properties.back().info.tooltip = QStringLiteral("Multiplies the emission; empty for none");
    c.properties.push_back(filePath(QStringLiteral("material.normalTexture"), QStringLiteral("Normal map"),
                                    in(&scene::NodeData::material, &M::normalTexture), images, true));
    c.properties.back().info.tooltip = QStringLiteral("Tangent-space normal map; empty for none");
    c.properties.push_back(slider(
        number<scene::NodeData>(QStringLiteral("material.normalScale"), QStringLiteral("Normal strength"),
                                in(&scene::NodeData::material, &M::normalScale),
                                {-render::kMaxNormalScale, render::kMaxNormalScale}),
        0.0, 2.0));
    static const std::array<scene::TextureWrap, 3> wraps{
        scene::TextureWrap::Repeat, scene::TextureWrap::Clamp, scene::TextureWrap::Mirror};
    const QStringList wrapNames{QStringLiteral("Repeat"), QStringLiteral("Clamp"), QStringLiteral("Mirror")};
    for (int axis = 0; axis < 2; ++axis) {
        c.properties.push_back(enumField<scene::TextureWrap, 3>(
            axis == 0 ? QStringLiteral("material.wrapU") : QStringLiteral("material.wrapV"),
            axis == 0 ? QStringLiteral("Wrap u") : QStringLiteral("Wrap v"), wrapNames, wraps,
            [axis](scene::NodeData& d) -> scene::TextureWrap* {
                return d.material ? &d.material->wrap[axis] : nullptr;
            }));
    }
    c.properties.push_back(
        slider(number<scene::NodeData>(QStringLiteral("material.opacity"), QStringLiteral("Opacity"),
                                       in(&scene::NodeData::material, &M::opacity), {0.0, 1.0}),
               0.0, 1.0));
    c.properties.push_back(enumField<scene::AlphaMode, 3>(
        QStringLiteral("material.alphaMode"), QStringLiteral("Alpha"),
        {QStringLiteral("Opaque"), QStringLiteral("Mask"), QStringLiteral("Blend (drawn as mask)")},
        {scene::AlphaMode::Opaque, scene::AlphaMode::Mask, scene::AlphaMode::Blend},
        in(&scene::NodeData::material, &M::alphaMode)));
    c.properties.push_back(
        slider(number<scene::NodeData>(QStringLiteral("material.alphaCutoff"), QStringLiteral("Alpha cutoff"),
                                       in(&scene::NodeData::material, &M::alphaCutoff), {0.0, 1.0}),
               0.0, 1.0));
    return c;
}

ComponentInfo lightGroup() {
    ComponentInfo c;
    c.key = QStringLiteral("light");
    c.title = QStringLiteral("Light");
    c.present = [](const scene::NodeData& d) { return d.light.has_value(); };
    c.add = [](scene::NodeData& d) {
        d.light = scene::LightComponent{};
        return ok();
    };
    c.remove = [](scene::NodeData& d) {
        d.light.reset();
        return ok();
    };
    using L = scene::LightComponent;
    c.properties.push_back(namedField<scene::LightType>(QStringLiteral("light.type"), QStringLiteral("Type"),
                                                        render::names::kLightTypes,
                                                        in(&scene::NodeData::light, &L::type)));
    c.properties.push_back(color<scene::NodeData>(QStringLiteral("light.color"), QStringLiteral("Colour"),
                                                  in(&scene::NodeData::light, &L::color)));
    c.properties.push_back(
        slider(number<scene::NodeData>(QStringLiteral("light.intensity"), QStringLiteral("Intensity"),
                                       in(&scene::NodeData::light, &L::intensity), kIntensity),
               0.0, 5.0));
    const auto isSpot = [](const scene::NodeData& d) {
        return d.light && d.light->type == scene::LightType::Spot;
    };
    c.properties.push_back(
        slider(number<scene::NodeData>(QStringLiteral("light.spotAngle"), QStringLiteral("Spot angle"),
                                       in(&scene::NodeData::light, &L::spotAngle), {0.0, 90.0, true, false},
                                       QStringLiteral("°"), QStringLiteral("Outer half angle of the cone")),
               1.0, 90.0, 1, 1.0));
    c.properties.back().visible = isSpot;
    c.properties.push_back(
        slider(number<scene::NodeData>(QStringLiteral("light.spotBlend"), QStringLiteral("Spot blend"),
                                       in(&scene::NodeData::light, &L::spotBlend), {0.0, 1.0}, {},
                                       QStringLiteral("Fraction of the cone over which the edge fades")),
               0.0, 1.0));
    c.properties.back().visible = isSpot;
    c.properties.push_back(boolean<scene::NodeData>(
        QStringLiteral("light.shadows"), QStringLiteral("Casts shadows"),
        [](const scene::NodeData& d) { return d.light && d.light->shadows.has_value(); },
        [](scene::NodeData& d, bool on) -> base::Status {
            if (!d.light) {
                return base::Error{"Casts shadows does not apply to this node"};
            }
            if (on && !d.light->shadows) {
                d.light->shadows = scene::ShadowComponent{};
            } else if (!on) {
                d.light->shadows.reset();
            }
            return ok();
        }));
    const auto hasShadows = [](const scene::NodeData& d) { return d.light && d.light->shadows; };
    const auto shadowField = [](int scene::ShadowComponent::*field) -> Access<scene::NodeData, int> {
        return [field](scene::NodeData& d) -> int* {
            return d.light && d.light->shadows ? &((*d.light->shadows).*field) : nullptr;
        };
    };
    c.properties.push_back(integer<scene::NodeData>(
        QStringLiteral("light.shadows.mapSize"), QStringLiteral("Shadow map size"),
        shadowField(&scene::ShadowComponent::mapSize), {render::kMinShadowMapSize, render::kMaxShadowMapSize},
        QStringLiteral(" px"), [](int v) {
            return render::isPowerOfTwo(v) ? QString() : QStringLiteral("must be a power of two");
        }));
    c.properties.back().visible = hasShadows;
    c.properties.push_back(integer<scene::NodeData>(
        QStringLiteral("light.shadows.pcf"), QStringLiteral("Shadow softness (PCF)"),
        shadowField(&scene::ShadowComponent::pcf), {render::kMinPcfWidth, render::kMaxPcfWidth},
        QStringLiteral(" texels"),
        [](int v) { return v % 2 == 1 ? QString() : QStringLiteral("must be an odd kernel width"); },
        QStringLiteral("Odd filter width in shadow-map texels; 1 = hard shadows")));
    c.properties.back().info.step = 2;
    c.properties.back().visible = hasShadows;
    return c;
}

ComponentInfo animationGroup() {
    ComponentInfo c;
    c.key = QStringLiteral("animation");
    c.title = QStringLiteral("Animation");
    c.present = [](const scene::NodeData& d) { return d.animation.has_value(); };
    c.add = [](scene::NodeData& d) {
        d.animation = scene::AnimationComponent{};
        d.animation->bounce = scene::BounceAnimation{};
        return ok();
    };
    c.remove = [](scene::NodeData& d) {
        d.animation.reset();
        return ok();
    };
    c.properties.push_back(boolean<scene::NodeData>(
        QStringLiteral("animation.bounce"), QStringLiteral("Bounce"),
        [](const scene::NodeData& d) { return d.animation && d.animation->bounce.has_value(); },
        [](scene::NodeData& d, bool on) -> base::Status {
            if (!d.animation) {
                return base::Error{"Bounce does not apply to this node"};
            }
            if (on && !d.animation->bounce) {
                d.animation->bounce = scene::BounceAnimation{};
            } else if (!on) {
                d.animation->bounce.reset();
            }
            return ok();
        }));
    const auto bounce = [](double scene::BounceAnimation::*f) -> Access<scene::NodeData, double> {
        return [f](scene::NodeData& d) -> double* {
            return d.animation && d.animation->bounce ? &((*d.animation->bounce).*f) : nullptr;
        };
    };
    const auto orbit = [](auto scene::OrbitAnimation::*f) {
        using V = std::remove_reference_t<decltype(std::declval<scene::OrbitAnimation&>().*f)>;
        return Access<scene::NodeData, V>([f](scene::NodeData& d) -> V* {
            return d.animation && d.animation->orbit ? &((*d.animation->orbit).*f) : nullptr;
        });
    };
    const auto hasBounce = [](const scene::NodeData& d) { return d.animation && d.animation->bounce; };
    const auto hasOrbit = [](const scene::NodeData& d) { return d.animation && d.animation->orbit; };
    c.properties.push_back(
        number<scene::NodeData>(QStringLiteral("animation.bounce.height"), QStringLiteral("Bounce height"),
                                bounce(&scene::BounceAnimation::height), kCoordinate, QStringLiteral(" u")));
    c.properties.back().visible = hasBounce;
    c.properties.push_back(
        number<scene::NodeData>(QStringLiteral("animation.bounce.period"), QStringLiteral("Bounce period"),
                                bounce(&scene::BounceAnimation::period), kPeriod, QStringLiteral(" s")));
    c.properties.back().visible = hasBounce;
    c.properties.push_back(boolean<scene::NodeData>(
        QStringLiteral("animation.orbit"), QStringLiteral("Orbit"),
        [](const scene::NodeData& d) { return d.animation && d.animation->orbit.has_value(); },
        [](scene::NodeData& d, bool on) -> base::Status {
            if (!d.animation) {
                return base::Error{"Orbit does not apply to this node"};
            }
            if (on && !d.animation->orbit) {
                scene::OrbitAnimation o;
                o.center = d.transform.translate; // orbit around where the node stands
                d.animation->orbit = o;
            } else if (!on) {
                d.animation->orbit.reset();
            }
            return ok();
        }));
    c.properties.push_back(
        vector<scene::NodeData, 3>(QStringLiteral("animation.orbit.center"), QStringLiteral("Orbit centre"),
                                   orbit(&scene::OrbitAnimation::center), kCoordinate, QStringLiteral(" u")));
    c.properties.back().visible = hasOrbit;
    c.properties.push_back(
        number<scene::NodeData>(QStringLiteral("animation.orbit.radius"), QStringLiteral("Orbit radius"),
                                orbit(&scene::OrbitAnimation::radius), kLength, QStringLiteral(" u")));
    c.properties.back().visible = hasOrbit;
    c.properties.push_back(
        number<scene::NodeData>(QStringLiteral("animation.orbit.period"), QStringLiteral("Orbit period"),
                                orbit(&scene::OrbitAnimation::period), kPeriod, QStringLiteral(" s")));
    c.properties.back().visible = hasOrbit;
    return c;
}

} // namespace speculum::document::groups
