#pragma once

#include "editor/document/Properties.hpp"
#include "render/frame/SceneNames.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <utility>

namespace speculum::document::makers {

// The building blocks of the property lists (NodeProperties.cpp, ReflectionProperties.cpp, Properties.cpp):
// one maker per kind of property, each producing a Property whose setter validates before it writes.
// Internal to the document library; the inspector sees only Properties.hpp.

inline constexpr double kInf = std::numeric_limits<double>::infinity();

// "<label> <why>" as an error for the user.
base::Status fail(const PropertyInfo& info, const QString& why);

std::optional<double> toNumber(const QVariant& v);

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
                        QString tooltip);

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
    p.set = [access, info = p.info](T& v, const QVariant& value) -> base::Status {
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
        return base::Done{};
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
    p.set = [access, info = p.info, extraCheck](T& v, const QVariant& value) -> base::Status {
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
        return base::Done{};
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
    p.set = [access, info = p.info, check](T& v, const QVariant& value) -> base::Status {
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
        return base::Done{};
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
                    std::function<base::Status(T&, bool)> set, QString tooltip = {}) {
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
                        std::function<base::Status(T&, int)> set) {
    Property<T> p;
    p.info.key = std::move(key);
    p.info.label = std::move(label);
    p.info.kind = PropertyKind::Enum;
    p.info.options = std::move(options);
    p.get = [get](const T& v) {
        const int i = get(v);
        return i < 0 ? QVariant() : QVariant(i);
    };
    p.set = [set, info = p.info](T& v, const QVariant& value) -> base::Status {
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
Property<scene::NodeData> enumField(QString key, QString label, QStringList options, std::array<E, N> values,
                                    Access<scene::NodeData, E> access) {
    return enumeration<scene::NodeData>(
        std::move(key), std::move(label), std::move(options),
        [access, values](const scene::NodeData& d) {
            const E* e = read(access, d);
            for (std::size_t i = 0; e && i < N; ++i) {
                if (values[i] == *e) {
                    return static_cast<int>(i);
                }
            }
            return -1;
        },
        [access, values](scene::NodeData& d, int i) -> base::Status {
            E* e = access(d);
            if (!e) {
                return base::Error{"this property does not apply to this node"};
            }
            *e = values[static_cast<std::size_t>(i)];
            return base::Done{};
        });
}

// An enum property whose options are the labels of a render/frame/SceneNames.hpp table, in enum order.
template <typename E, std::size_t N>
Property<scene::NodeData> namedField(QString key, QString label,
                                     const std::array<render::names::Name, N>& names,
                                     Access<scene::NodeData, E> access) {
    QStringList options;
    std::array<E, N> values{};
    for (std::size_t i = 0; i < N; ++i) {
        options << QString::fromUtf8(names[i].label.data(), qsizetype(names[i].label.size()));
        values[i] = static_cast<E>(i);
    }
    return enumField(std::move(key), std::move(label), std::move(options), values, std::move(access));
}

// A path to an existing file, stored absolute; allowEmpty accepts "" for none.
Property<scene::NodeData> filePath(QString key, QString label, Access<scene::NodeData, std::string> access,
                                   QString filter, bool allowEmpty);

// Accessor shorthands for optional components.
template <typename C, typename V>
Access<scene::NodeData, V> in(std::optional<C> scene::NodeData::*component, V C::*field) {
    return [component, field](scene::NodeData& d) -> V* {
        auto& c = d.*component;
        return c ? &((*c).*field) : nullptr;
    };
}

// Whole-vector checks for vector(): an empty message accepts the value.
QString nonZeroScale(const glm::dvec3& s);
QString positiveExtents(const glm::dvec2& s);

base::Status ok();

} // namespace speculum::document::makers
