#include "editor/document/Properties.hpp"

#include <QFileInfo>
#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>

namespace speculum::document {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

render::Status fail(const PropertyInfo& info, const QString& why) {
    return render::Error{QStringLiteral("%1 %2").arg(info.label, why).toStdString()};
}

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

std::optional<double> toNumber(const QVariant& v) {
    bool ok = false;
    const double d = v.toDouble(&ok);
    if (!ok) {
        return std::nullopt;
    }
    return d;
}

template <int N>
std::optional<glm::vec<N, double>> toVector(const QVariant& v) {
    const QVariantList list = v.toList();
    if (list.size() != N) {
        return std::nullopt;
    }
    glm::vec<N, double> out;
    for (int i = 0; i < N; ++i) {
        auto d = toNumber(list[i]);
        if (!d) {
            return std::nullopt;
        }
        out[i] = *d;
    }
    return out;
}

template <int N>
QVariant fromVector(const glm::vec<N, double>& v) {
    QVariantList list;
    for (int i = 0; i < N; ++i) {
        list << v[i];
    }
    return list;
}

// ---- property makers. Accessors return a pointer into the value (nullptr when the component is absent).

template <typename T, typename V>
using Access = std::function<V*(T&)>;

template <typename T, typename V>
V* read(const Access<T, V>& access, const T& value) {
    return access(const_cast<T&>(value)); // only read through it
}

struct NumberRange {
    double minimum = -kInf;
    double maximum = kInf;
    bool minimumExclusive = false;
    bool maximumExclusive = false;
};

PropertyInfo numberInfo(QString key, QString label, PropertyKind kind, NumberRange range, QString unit,
                        QString tooltip) {
    PropertyInfo info;
    info.key = std::move(key);
    info.label = std::move(label);
    info.kind = kind;
    info.minimum = range.minimum;
    info.maximum = range.maximum;
    info.minimumExclusive = range.minimumExclusive;
    info.maximumExclusive = range.maximumExclusive;
    info.unit = std::move(unit);
    info.tooltip = std::move(tooltip);
    if (std::isfinite(range.minimum)) {
        info.softMinimum = range.minimum;
    }
    if (std::isfinite(range.maximum)) {
        info.softMaximum = range.maximum;
    }
    return info;
}

template <typename T>
Property<T> number(QString key, QString label, Access<T, double> access, NumberRange range, QString unit = {},
                   QString tooltip = {}) {
    Property<T> p;
    p.info = numberInfo(std::move(key), std::move(label), PropertyKind::Number, range, std::move(unit),
                        std::move(tooltip));
    p.get = [access](const T& v) {
        const double* d = read(access, v);
        return d ? QVariant(*d) : QVariant();
    };
    p.set = [access, info = p.info](T& v, const QVariant& value) -> render::Status {
        auto d = toNumber(value);
        if (!d) {
            return fail(info, QStringLiteral("expects a number"));
        }
        if (auto ok = checkRange(info, *d); !ok) {
            return ok;
        }
        double* field = access(v);
        if (!field) {
            return fail(info, QStringLiteral("does not apply to this node"));
        }
        *field = *d;
        return render::Done{};
    };
    return p;
}

template <typename T>
Property<T> slider(Property<T> p, double softMin, double softMax, int decimals = 3, double step = 0.05) {
    p.info.slider = true;
    p.info.softMinimum = softMin;
    p.info.softMaximum = softMax;
    p.info.decimals = decimals;
    p.info.step = step;
    return p;
}

template <typename T>
Property<T> integer(QString key, QString label, Access<T, int> access, NumberRange range, QString unit = {},
                    std::function<QString(int)> extraCheck = {}, QString tooltip = {}) {
    Property<T> p;
    p.info = numberInfo(std::move(key), std::move(label), PropertyKind::Integer, range, std::move(unit),
                        std::move(tooltip));
    p.info.decimals = 0;
    p.info.step = 1;
    p.get = [access](const T& v) {
        const int* i = read(access, v);
        return i ? QVariant(*i) : QVariant();
    };
    p.set = [access, info = p.info, extraCheck](T& v, const QVariant& value) -> render::Status {
        auto d = toNumber(value);
        if (!d || std::floor(*d) != *d) {
            return fail(info, QStringLiteral("expects a whole number"));
        }
        if (auto ok = checkRange(info, *d); !ok) {
            return ok;
        }
        const int i = static_cast<int>(*d);
        if (extraCheck) {
            if (const QString why = extraCheck(i); !why.isEmpty()) {
                return fail(info, why);
            }
        }
        int* field = access(v);
        if (!field) {
            return fail(info, QStringLiteral("does not apply to this node"));
        }
        *field = i;
        return render::Done{};
    };
    return p;
}

// Vectors: every component is checked against the range; `check` adds a rule over the whole vector.
template <typename T, int N>
Property<T> vector(QString key, QString label, Access<T, glm::vec<N, double>> access, NumberRange range,
                   QString unit = {}, std::function<QString(const glm::vec<N, double>&)> check = {},
                   PropertyKind kind = N == 2 ? PropertyKind::Vector2 : PropertyKind::Vector3) {
    Property<T> p;
    p.info = numberInfo(std::move(key), std::move(label), kind, range, std::move(unit), {});
    p.get = [access](const T& v) {
        const auto* x = read(access, v);
        return x ? fromVector<N>(*x) : QVariant();
    };
    p.set = [access, info = p.info, check](T& v, const QVariant& value) -> render::Status {
        auto x = toVector<N>(value);
        if (!x) {
            return fail(info, QStringLiteral("expects %1 numbers").arg(N));
        }
        for (int i = 0; i < N; ++i) {
            if (!std::isfinite((*x)[i])) {
                return fail(info, QStringLiteral("expects finite numbers"));
            }
            if (auto ok = checkRange(info, (*x)[i]); !ok) {
                return ok;
            }
        }
        if (check) {
            if (const QString why = check(*x); !why.isEmpty()) {
                return fail(info, why);
            }
        }
        auto* field = access(v);
        if (!field) {
            return fail(info, QStringLiteral("does not apply to this node"));
        }
        *field = *x;
        return render::Done{};
    };
    return p;
}

template <typename T>
Property<T> color(QString key, QString label, Access<T, glm::dvec3> access) {
    Property<T> p = vector<T, 3>(std::move(key), std::move(label), std::move(access), {0.0, 1.0}, {}, {},
                                 PropertyKind::Color);
    p.info.tooltip = QStringLiteral("Linear RGB, each component 0..1");
    p.info.step = 0.05;
    return p;
}

template <typename T>
Property<T> boolean(QString key, QString label, std::function<bool(const T&)> get,
                    std::function<render::Status(T&, bool)> set, QString tooltip = {}) {
    Property<T> p;
    p.info.key = std::move(key);
    p.info.label = std::move(label);
    p.info.kind = PropertyKind::Bool;
    p.info.tooltip = std::move(tooltip);
    p.get = [get](const T& v) { return QVariant(get(v)); };
    p.set = [set](T& v, const QVariant& value) { return set(v, value.toBool()); };
    return p;
}

template <typename T>
Property<T> enumeration(QString key, QString label, QStringList options, std::function<int(const T&)> get,
                        std::function<render::Status(T&, int)> set) {
    Property<T> p;
    p.info.key = std::move(key);
    p.info.label = std::move(label);
    p.info.kind = PropertyKind::Enum;
    p.info.options = std::move(options);
    p.get = [get](const T& v) {
        const int i = get(v);
        return i < 0 ? QVariant() : QVariant(i);
    };
    p.set = [set, info = p.info](T& v, const QVariant& value) -> render::Status {
        bool ok = false;
        const int i = value.toInt(&ok);
        if (!ok || i < 0 || i >= info.options.size()) {
            return fail(info,
                        QStringLiteral("expects one of: %1").arg(info.options.join(QStringLiteral(", "))));
        }
        return set(v, i);
    };
    return p;
}

// An enum property over a component field whose values are listed in option order.
template <typename E, std::size_t N>
Property<NodeData> enumField(QString key, QString label, QStringList options, std::array<E, N> values,
                             Access<NodeData, E> access) {
    return enumeration<NodeData>(
        std::move(key), std::move(label), std::move(options),
        [access, values](const NodeData& d) {
            const E* e = read(access, d);
            for (std::size_t i = 0; e && i < N; ++i) {
                if (values[i] == *e) {
                    return static_cast<int>(i);
                }
            }
            return -1;
        },
        [access, values](NodeData& d, int i) -> render::Status {
            E* e = access(d);
            if (!e) {
                return render::Error{"this property does not apply to this node"};
            }
            *e = values[static_cast<std::size_t>(i)];
            return render::Done{};
        });
}

Property<NodeData> filePath(QString key, QString label, Access<NodeData, std::string> access, QString filter,
                            bool allowEmpty) {
    Property<NodeData> p;
    p.info.key = std::move(key);
    p.info.label = std::move(label);
    p.info.kind = PropertyKind::FilePath;
    p.info.fileFilter = std::move(filter);
    p.get = [access](const NodeData& d) {
        const std::string* s = read(access, d);
        return s ? QVariant(QString::fromStdString(*s)) : QVariant();
    };
    p.set = [access, info = p.info, allowEmpty](NodeData& d, const QVariant& value) -> render::Status {
        const QString path = value.toString().trimmed();
        std::string* field = access(d);
        if (!field) {
            return fail(info, QStringLiteral("does not apply to this node"));
        }
        if (path.isEmpty()) {
            if (!allowEmpty) {
                return fail(info, QStringLiteral("needs a file"));
            }
            field->clear();
            return render::Done{};
        }
        const QFileInfo file(path);
        if (!file.isAbsolute()) {
            return fail(info, QStringLiteral("needs an absolute path, got \"%1\"").arg(path));
        }
        if (!file.isFile()) {
            return fail(info, QStringLiteral("file does not exist: %1").arg(path));
        }
        *field = file.absoluteFilePath().toStdString();
        return render::Done{};
    };
    return p;
}

// Accessor shorthands for optional components.
template <typename C, typename V>
Access<NodeData, V> in(std::optional<C> NodeData::*component, V C::*field) {
    return [component, field](NodeData& d) -> V* {
        auto& c = d.*component;
        return c ? &((*c).*field) : nullptr;
    };
}

QString nonZeroScale(const glm::dvec3& s) {
    for (int i = 0; i < 3; ++i) {
        if (s[i] == 0.0) {
            return QStringLiteral("components must be non-zero (a zero scale flattens the node)");
        }
    }
    return {};
}

QString positiveExtents(const glm::dvec2& s) {
    return s.x > 0.0 && s.y > 0.0 ? QString() : QStringLiteral("extents must be greater than 0");
}

render::Status ok() {
    return render::Done{};
}

ComponentInfo nodeGroup() {
    ComponentInfo c;
    c.key = QStringLiteral("node");
    c.title = QStringLiteral("Node");
    c.optional = false;
    c.present = [](const NodeData&) { return true; };
    Property<NodeData> name;
    name.info.key = QStringLiteral("node.name");
    name.info.label = QStringLiteral("Name");
    name.info.kind = PropertyKind::Text;
    name.get = [](const NodeData& d) { return QVariant(QString::fromStdString(d.name)); };
    name.set = [](NodeData& d, const QVariant& v) -> render::Status {
        const QString text = v.toString().trimmed();
        if (text.isEmpty()) {
            return render::Error{"Name must not be empty"};
        }
        d.name = text.toStdString();
        return render::Done{};
    };
    c.properties.push_back(name);
    return c;
}

ComponentInfo transformGroup() {
    ComponentInfo c;
    c.key = QStringLiteral("transform");
    c.title = QStringLiteral("Transform");
    c.optional = false;
    c.present = [](const NodeData&) { return true; };
    using V3 = Access<NodeData, glm::dvec3>;
    c.properties.push_back(vector<NodeData, 3>(
        QStringLiteral("transform.translate"), QStringLiteral("Translate"),
        V3([](NodeData& d) { return &d.transform.translate; }), {}, QStringLiteral(" u")));
    c.properties.push_back(vector<NodeData, 3>(QStringLiteral("transform.rotate"), QStringLiteral("Rotate"),
                                               V3([](NodeData& d) { return &d.transform.rotate; }), {},
                                               QStringLiteral("°")));
    c.properties.back().info.tooltip =
        QStringLiteral("XYZ Euler angles in degrees, applied X, then Y, then Z");
    c.properties.back().info.step = 5.0;
    c.properties.push_back(vector<NodeData, 3>(QStringLiteral("transform.scale"), QStringLiteral("Scale"),
                                               V3([](NodeData& d) { return &d.transform.scale; }), {}, {},
                                               nonZeroScale));
    return c;
}

ComponentInfo meshGroup() {
    ComponentInfo c;
    c.key = QStringLiteral("mesh");
    c.title = QStringLiteral("Mesh");
    c.present = [](const NodeData& d) { return d.mesh.has_value(); };
    c.add = [](NodeData& d) {
        d.mesh = MeshComponent::fromBuiltin(BuiltinMesh::Sphere);
        return ok();
    };
    c.remove = [](NodeData& d) -> render::Status {
        if (d.reflector) {
            return render::Error{"The reflector's surface is this mesh: remove the reflector first"};
        }
        d.mesh.reset();
        return ok();
    };
    static const std::array<BuiltinMesh, 4> kinds{BuiltinMesh::Teapot, BuiltinMesh::Sphere, BuiltinMesh::Box,
                                                  BuiltinMesh::Plane};
    c.properties.push_back(enumeration<NodeData>(
        QStringLiteral("mesh.source"), QStringLiteral("Shape"),
        {QStringLiteral("Teapot"), QStringLiteral("Sphere"), QStringLiteral("Box"), QStringLiteral("Plane"),
         QStringLiteral("Model file")},
        [](const NodeData& d) {
            if (!d.mesh) {
                return -1;
            }
            if (!d.mesh->builtin) {
                return 4;
            }
            return static_cast<int>(std::find(kinds.begin(), kinds.end(), *d.mesh->builtin) - kinds.begin());
        },
        [](NodeData& d, int i) -> render::Status {
            if (!d.mesh) {
                return render::Error{"Shape does not apply to this node"};
            }
            if (i == 4) {
                if (d.mesh->file.empty()) {
                    return render::Error{"Shape: choose the model file in the File field"};
                }
                d.mesh = MeshComponent::fromFile(d.mesh->file);
                return ok();
            }
            const BuiltinMesh kind = kinds[static_cast<std::size_t>(i)];
            if (d.mesh->builtin != kind) {
                d.mesh = MeshComponent::fromBuiltin(kind);
            }
            return ok();
        }));
    c.properties.push_back(integer<NodeData>(
        QStringLiteral("mesh.tessellation"), QStringLiteral("Tessellation"),
        in(&NodeData::mesh, &MeshComponent::tessellation), {1, 64}, {}, {},
        QStringLiteral("Subdivisions of the built-in shape (teapot: per patch edge, sphere: rings)")));
    c.properties.back().visible = [](const NodeData& d) { return d.mesh && d.mesh->builtin.has_value(); };
    Property<NodeData> file = filePath(QStringLiteral("mesh.file"), QStringLiteral("File"),
                                       in(&NodeData::mesh, &MeshComponent::file),
                                       QStringLiteral("3D models (*.obj *.gltf *.glb *.fbx *.dae *.ply *.stl "
                                                      "*.3ds *.blend *.off);;All files (*)"),
                                       false);
    // Choosing a file makes it the mesh's source.
    auto setFile = file.set;
    file.set = [setFile](NodeData& d, const QVariant& v) -> render::Status {
        NodeData copy = d;
        if (auto status = setFile(copy, v); !status) {
            return status;
        }
        copy.mesh = MeshComponent::fromFile(copy.mesh->file);
        d = std::move(copy);
        return ok();
    };
    c.properties.push_back(file);
    return c;
}

ComponentInfo materialGroup() {
    ComponentInfo c;
    c.key = QStringLiteral("material");
    c.title = QStringLiteral("Material");
    c.present = [](const NodeData& d) { return d.material.has_value(); };
    c.add = [](NodeData& d) {
        d.material = MaterialComponent{};
        return ok();
    };
    c.remove = [](NodeData& d) {
        d.material.reset();
        return ok();
    };
    using M = MaterialComponent;
    c.properties.push_back(color<NodeData>(QStringLiteral("material.color"), QStringLiteral("Colour"),
                                           in(&NodeData::material, &M::color)));
    c.properties.push_back(
        slider(number<NodeData>(QStringLiteral("material.ambient"), QStringLiteral("Ambient"),
                                in(&NodeData::material, &M::ambient), {0.0}),
               0.0, 2.0));
    c.properties.push_back(
        slider(number<NodeData>(QStringLiteral("material.diffuse"), QStringLiteral("Diffuse"),
                                in(&NodeData::material, &M::diffuse), {0.0}),
               0.0, 2.0));
    c.properties.push_back(
        slider(number<NodeData>(QStringLiteral("material.specular"), QStringLiteral("Specular"),
                                in(&NodeData::material, &M::specular), {0.0}),
               0.0, 2.0));
    c.properties.push_back(
        slider(number<NodeData>(QStringLiteral("material.shininess"), QStringLiteral("Shininess"),
                                in(&NodeData::material, &M::shininess), {0.0, 10000.0}),
               1.0, 256.0, 1, 1.0));
    c.properties.push_back(color<NodeData>(QStringLiteral("material.emission"), QStringLiteral("Emission"),
                                           in(&NodeData::material, &M::emission)));
    c.properties.push_back(filePath(
        QStringLiteral("material.texture"), QStringLiteral("Texture"), in(&NodeData::material, &M::texture),
        QStringLiteral("Images (*.png *.jpg *.jpeg *.tif *.tiff *.exr *.hdr);;All "
                       "files (*)"),
        true));
    c.properties.back().info.tooltip = QStringLiteral("Empty for none");
    return c;
}

ComponentInfo lightGroup() {
    ComponentInfo c;
    c.key = QStringLiteral("light");
    c.title = QStringLiteral("Light");
    c.present = [](const NodeData& d) { return d.light.has_value(); };
    c.add = [](NodeData& d) {
        d.light = LightComponent{};
        return ok();
    };
    c.remove = [](NodeData& d) {
        d.light.reset();
        return ok();
    };
    using L = LightComponent;
    c.properties.push_back(
        enumField(QStringLiteral("light.type"), QStringLiteral("Type"),
                  {QStringLiteral("Point"), QStringLiteral("Directional"), QStringLiteral("Spot")},
                  std::array{LightType::Point, LightType::Directional, LightType::Spot},
                  in(&NodeData::light, &L::type)));
    c.properties.push_back(color<NodeData>(QStringLiteral("light.color"), QStringLiteral("Colour"),
                                           in(&NodeData::light, &L::color)));
    c.properties.push_back(
        slider(number<NodeData>(QStringLiteral("light.intensity"), QStringLiteral("Intensity"),
                                in(&NodeData::light, &L::intensity), {0.0}),
               0.0, 5.0));
    const auto isSpot = [](const NodeData& d) { return d.light && d.light->type == LightType::Spot; };
    c.properties.push_back(
        slider(number<NodeData>(QStringLiteral("light.spotAngle"), QStringLiteral("Spot angle"),
                                in(&NodeData::light, &L::spotAngle), {0.0, 90.0, true, false},
                                QStringLiteral("°"), QStringLiteral("Outer half angle of the cone")),
               1.0, 90.0, 1, 1.0));
    c.properties.back().visible = isSpot;
    c.properties.push_back(
        slider(number<NodeData>(QStringLiteral("light.spotBlend"), QStringLiteral("Spot blend"),
                                in(&NodeData::light, &L::spotBlend), {0.0, 1.0}, {},
                                QStringLiteral("Fraction of the cone over which the edge fades")),
               0.0, 1.0));
    c.properties.back().visible = isSpot;
    c.properties.push_back(boolean<NodeData>(
        QStringLiteral("light.shadows"), QStringLiteral("Casts shadows"),
        [](const NodeData& d) { return d.light && d.light->shadows.has_value(); },
        [](NodeData& d, bool on) -> render::Status {
            if (!d.light) {
                return render::Error{"Casts shadows does not apply to this node"};
            }
            if (on && !d.light->shadows) {
                d.light->shadows = ShadowComponent{};
            } else if (!on) {
                d.light->shadows.reset();
            }
            return ok();
        }));
    const auto hasShadows = [](const NodeData& d) { return d.light && d.light->shadows; };
    const auto shadowField = [](int ShadowComponent::*field) -> Access<NodeData, int> {
        return [field](NodeData& d) -> int* {
            return d.light && d.light->shadows ? &((*d.light->shadows).*field) : nullptr;
        };
    };
    c.properties.push_back(integer<NodeData>(
        QStringLiteral("light.shadows.mapSize"), QStringLiteral("Shadow map size"),
        shadowField(&ShadowComponent::mapSize), {16, 16384}, QStringLiteral(" px"),
        [](int v) { return (v & (v - 1)) == 0 ? QString() : QStringLiteral("must be a power of two"); }));
    c.properties.back().visible = hasShadows;
    c.properties.push_back(integer<NodeData>(
        QStringLiteral("light.shadows.pcf"), QStringLiteral("Shadow softness (PCF)"),
        shadowField(&ShadowComponent::pcf), {1, 15}, QStringLiteral(" texels"),
        [](int v) { return v % 2 == 1 ? QString() : QStringLiteral("must be an odd kernel width"); },
        QStringLiteral("Odd filter width in shadow-map texels; 1 = hard shadows")));
    c.properties.back().info.step = 2;
    c.properties.back().visible = hasShadows;
    return c;
}

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
    c.properties.push_back(enumField(QStringLiteral("mirror.technique"), QStringLiteral("Technique"),
                                     {QStringLiteral("Stencil"), QStringLiteral("Texture")},
                                     std::array{MirrorTechnique::Stencil, MirrorTechnique::Texture},
                                     in(&NodeData::mirror, &Mi::technique)));
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
        enumField(QStringLiteral("reflector.map"), QStringLiteral("Environment map"),
                  {QStringLiteral("Cube"), QStringLiteral("Dual paraboloid"), QStringLiteral("Tennis ball")},
                  std::array{ReflectorMap::Cube, ReflectorMap::DualParaboloid, ReflectorMap::TennisBall},
                  in(&NodeData::reflector, &R::map)));
    c.properties.push_back(
        integer<NodeData>(QStringLiteral("reflector.resolution"), QStringLiteral("Resolution"),
                          in(&NodeData::reflector, &R::resolution), {8, 8192}, QStringLiteral(" px")));
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
    c.properties.push_back(enumField(
        QStringLiteral("reflector.fill"), QStringLiteral("Fill"),
        {QStringLiteral("Direct (vertex warp)"), QStringLiteral("Resampled cube")},
        std::array{ReflectorFill::Direct, ReflectorFill::Resampled}, in(&NodeData::reflector, &R::fill)));
    c.properties.back().info.tooltip =
        QStringLiteral("How dual-paraboloid and tennis-ball maps are filled; the cube map ignores it");
    c.properties.push_back(enumField(
        QStringLiteral("reflector.update"), QStringLiteral("Update"),
        {QStringLiteral("Always"), QStringLiteral("When something it sees changes"), QStringLiteral("Once")},
        std::array{ReflectorUpdate::Always, ReflectorUpdate::OnChange, ReflectorUpdate::Once},
        in(&NodeData::reflector, &R::update)));
    c.properties.push_back(integer<NodeData>(
        QStringLiteral("reflector.mirrorDepth"), QStringLiteral("Mirror depth in the map"),
        in(&NodeData::reflector, &R::mirrorDepth), {0, 16}, {}, {},
        QStringLiteral(
            "How many levels of planar mirrors reflect inside the environment map, mirrors seen in "
            "mirrors included (every fill); 0 shows them with their own material")));
    return c;
}

ComponentInfo animationGroup() {
    ComponentInfo c;
    c.key = QStringLiteral("animation");
    c.title = QStringLiteral("Animation");
    c.present = [](const NodeData& d) { return d.animation.has_value(); };
    c.add = [](NodeData& d) {
        d.animation = AnimationComponent{};
        d.animation->bounce = BounceAnimation{};
        return ok();
    };
    c.remove = [](NodeData& d) {
        d.animation.reset();
        return ok();
    };
    c.properties.push_back(boolean<NodeData>(
        QStringLiteral("animation.bounce"), QStringLiteral("Bounce"),
        [](const NodeData& d) { return d.animation && d.animation->bounce.has_value(); },
        [](NodeData& d, bool on) -> render::Status {
            if (!d.animation) {
                return render::Error{"Bounce does not apply to this node"};
            }
            if (on && !d.animation->bounce) {
                d.animation->bounce = BounceAnimation{};
            } else if (!on) {
                d.animation->bounce.reset();
            }
            return ok();
        }));
    const auto bounce = [](double BounceAnimation::*f) -> Access<NodeData, double> {
        return [f](NodeData& d) -> double* {
            return d.animation && d.animation->bounce ? &((*d.animation->bounce).*f) : nullptr;
        };
    };
    const auto orbit = [](auto OrbitAnimation::*f) {
        using V = std::remove_reference_t<decltype(std::declval<OrbitAnimation&>().*f)>;
        return Access<NodeData, V>([f](NodeData& d) -> V* {
            return d.animation && d.animation->orbit ? &((*d.animation->orbit).*f) : nullptr;
        });
    };
    const auto hasBounce = [](const NodeData& d) { return d.animation && d.animation->bounce; };
    const auto hasOrbit = [](const NodeData& d) { return d.animation && d.animation->orbit; };
    c.properties.push_back(number<NodeData>(QStringLiteral("animation.bounce.height"),
                                            QStringLiteral("Bounce height"), bounce(&BounceAnimation::height),
                                            {}, QStringLiteral(" u")));
    c.properties.back().visible = hasBounce;
    c.properties.push_back(number<NodeData>(QStringLiteral("animation.bounce.period"),
                                            QStringLiteral("Bounce period"), bounce(&BounceAnimation::period),
                                            {0.0, kInf, true}, QStringLiteral(" s")));
    c.properties.back().visible = hasBounce;
    c.properties.push_back(boolean<NodeData>(
        QStringLiteral("animation.orbit"), QStringLiteral("Orbit"),
        [](const NodeData& d) { return d.animation && d.animation->orbit.has_value(); },
        [](NodeData& d, bool on) -> render::Status {
            if (!d.animation) {
                return render::Error{"Orbit does not apply to this node"};
            }
            if (on && !d.animation->orbit) {
                OrbitAnimation o;
                o.center = d.transform.translate; // orbit around where the node stands
                d.animation->orbit = o;
            } else if (!on) {
                d.animation->orbit.reset();
            }
            return ok();
        }));
    c.properties.push_back(vector<NodeData, 3>(QStringLiteral("animation.orbit.center"),
                                               QStringLiteral("Orbit centre"), orbit(&OrbitAnimation::center),
                                               {}, QStringLiteral(" u")));
    c.properties.back().visible = hasOrbit;
    c.properties.push_back(number<NodeData>(QStringLiteral("animation.orbit.radius"),
                                            QStringLiteral("Orbit radius"), orbit(&OrbitAnimation::radius),
                                            {}, QStringLiteral(" u")));
    c.properties.back().visible = hasOrbit;
    c.properties.push_back(number<NodeData>(QStringLiteral("animation.orbit.period"),
                                            QStringLiteral("Orbit period"), orbit(&OrbitAnimation::period),
                                            {0.0, kInf, true}, QStringLiteral(" s")));
    c.properties.back().visible = hasOrbit;
    return c;
}

std::vector<Property<SceneSettings>> makeSettingsProperties() {
    std::vector<Property<SceneSettings>> list;
    list.push_back(color<SceneSettings>(QStringLiteral("settings.background"), QStringLiteral("Background"),
                                        [](SceneSettings& s) { return &s.background; }));
    list.push_back(integer<SceneSettings>(
        QStringLiteral("settings.mirrorDepth"), QStringLiteral("Mirror depth"),
        [](SceneSettings& s) { return &s.mirrorDepth; }, {0, 16}, {}, {},
        QStringLiteral("How many reflections of reflections are drawn")));
    list.push_back(slider(number<SceneSettings>(QStringLiteral("settings.ambient"), QStringLiteral("Ambient"),
                                                [](SceneSettings& s) { return &s.ambient; }, {0.0, 1.0}),
                          0.0, 1.0));
    return list;
}

std::vector<Property<CameraData>> makeCameraProperties() {
    std::vector<Property<CameraData>> list;
    // Position and target must differ and up must not be parallel to the view: checked on the whole camera.
    const auto checkCamera = [](Property<CameraData> p) {
        auto set = p.set;
        p.set = [set](CameraData& c, const QVariant& v) -> render::Status {
            CameraData copy = c;
            if (auto s = set(copy, v); !s) {
                return s;
            }
            const glm::dvec3 view = copy.target - copy.position;
            if (glm::length(view) == 0.0) {
                return render::Error{"The camera target must differ from its position"};
            }
            const glm::dvec3 side = glm::cross(view, copy.up);
            if (glm::length(copy.up) == 0.0 ||
                glm::length(side) <= 1e-12 * glm::length(view) * glm::length(copy.up)) {
                return render::Error{
                    "The camera's up must be non-zero and not parallel to the view direction"};
            }
            if (!(copy.far > copy.near)) {
                return render::Error{QStringLiteral("Far must be greater than near (%1), got %2")
                                         .arg(formatNumber(copy.near), formatNumber(copy.far))
                                         .toStdString()};
            }
            c = std::move(copy);
            return render::Done{};
        };
        return p;
    };
    using V3 = Access<CameraData, glm::dvec3>;
    list.push_back(checkCamera(
        vector<CameraData, 3>(QStringLiteral("camera.position"), QStringLiteral("Position"),
                              V3([](CameraData& c) { return &c.position; }), {}, QStringLiteral(" u"))));
    list.push_back(checkCamera(
        vector<CameraData, 3>(QStringLiteral("camera.target"), QStringLiteral("Target"),
                              V3([](CameraData& c) { return &c.target; }), {}, QStringLiteral(" u"))));
    list.push_back(checkCamera(vector<CameraData, 3>(QStringLiteral("camera.up"), QStringLiteral("Up"),
                                                     V3([](CameraData& c) { return &c.up; }), {})));
    list.push_back(checkCamera(slider(number<CameraData>(
                                          QStringLiteral("camera.fovY"), QStringLiteral("Field of view"),
                                          [](CameraData& c) { return &c.fovY; }, {0.0, 180.0, true, true},
                                          QStringLiteral("°"), QStringLiteral("Vertical, in degrees")),
                                      10.0, 120.0, 1, 1.0)));
    list.push_back(checkCamera(number<CameraData>(
        QStringLiteral("camera.near"), QStringLiteral("Near"), [](CameraData& c) { return &c.near; },
        {0.0, kInf, true}, QStringLiteral(" u"))));
    list.push_back(checkCamera(number<CameraData>(
        QStringLiteral("camera.far"), QStringLiteral("Far"), [](CameraData& c) { return &c.far; },
        {0.0, kInf, true}, QStringLiteral(" u"))));
    return list;
}

} // namespace

QString formatNumber(double value) {
    return QString::number(value, 'g', 10);
}

render::Status checkRange(const PropertyInfo& info, double value) {
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
    return render::Done{};
}

const std::vector<ComponentInfo>& nodeComponents() {
    static const std::vector<ComponentInfo> list{nodeGroup(),      transformGroup(), meshGroup(),
                                                 materialGroup(),  lightGroup(),     mirrorGroup(),
                                                 reflectorGroup(), animationGroup()};
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

const Property<NodeData>* findNodeProperty(const QString& key) {
    for (const ComponentInfo& c : nodeComponents()) {
        for (const auto& p : c.properties) {
            if (p.info.key == key) {
                return &p;
            }
        }
    }
    return nullptr;
}

const std::vector<Property<SceneSettings>>& settingsProperties() {
    static const auto list = makeSettingsProperties();
    return list;
}

const std::vector<Property<CameraData>>& cameraProperties() {
    static const auto list = makeCameraProperties();
    return list;
}

const Property<SceneSettings>* findSettingsProperty(const QString& key) {
    for (const auto& p : settingsProperties()) {
        if (p.info.key == key) {
            return &p;
        }
    }
    return nullptr;
}

const Property<CameraData>* findCameraProperty(const QString& key) {
    for (const auto& p : cameraProperties()) {
        if (p.info.key == key) {
            return &p;
        }
    }
    return nullptr;
}

} // namespace speculum::document
