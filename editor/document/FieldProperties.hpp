#pragma once

#include "editor/document/PropertyMakers.hpp"
#include "render/frame/Field.hpp"
#include "scene/model/SceneChecks.hpp"

#include <QString>
#include <QStringList>
#include <functional>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace speculum::document::fieldprops {

// The inspector's properties made from the declarations (render/frame/Field.hpp): one property per
// declared field, with its label, type, range, unit, slider and meaning as its declaration says, its key
// "<prefix>.<name>", shown only where the field applies, and a setter that refuses what the project
// reader would refuse (the same spec, the same rules across fields), so an edit never makes a file that
// does not load. An optional group becomes a check box that adds or removes it, its fields under it.

// Where a struct is inside the value the properties edit (a node, the settings): null where it is absent.
template <typename Root, typename T>
using Reach = std::function<T*(Root&)>;
template <typename Root>
using Shown = std::function<bool(const Root&)>;

// The rules across a struct's fields, in the inspector's words ("Camera Up must not be parallel ...").
template <typename T>
std::optional<std::string> wholeProblem(const T&) {
    return std::nullopt;
}
std::optional<std::string> wholeProblem(const render::Camera& camera);
std::optional<std::string> wholeProblem(const render::ParallaxParams& proxy);

// A property's description from a field's spec.
PropertyInfo infoOf(const render::FieldSpec& spec, const QString& key);
QStringList choiceLabels(const render::FieldSpec& spec);
// The property's message for a value the spec refuses: "Reflectivity must be in 0..1, got 2".
base::Status refuse(const render::FieldSpec& spec, const std::string& problem);
// A QVariant as the field's value: a number, a whole number, an index, a list of numbers.
std::optional<render::FieldValue> toFieldValue(const render::FieldSpec& spec, const QVariant& value);
QVariant toVariant(const render::FieldValue& value);
// A path from the inspector, checked as Property kind FilePath expects; the empty string where allowed.
base::Result<std::string> checkedPath(const render::FieldSpec& spec, const QString& text, bool allowEmpty);

template <typename Root>
bool shown(const Shown<Root>& visible, const Root& root) {
    return !visible || visible(root);
}

// Sets one field of the struct `reach` finds, on a copy checked by the struct's whole rules first.
template <typename Root, typename T, typename F, typename Set>
base::Status editCopy(Root& root, const Reach<Root, T>& reach, const F& f, Set&& set) {
    T* target = reach(root);
    if (!target)
        return base::Error{std::string(f.spec.label) + " does not apply to this node"};
    T copy = *target;
    if (base::Status status = set(copy); !status)
        return status;
    if (auto problem = wholeProblem(static_cast<const T&>(copy)))
        return base::Error{*problem};
    *target = std::move(copy);
    return base::Done{};
}

template <typename Root, typename T>
void addProperties(std::vector<Property<Root>>& out, const QString& prefix, Reach<Root, T> reach,
                   Shown<Root> visible);
template <typename Root, typename T, typename F>
Property<Root> valueProperty(const QString& key, const Reach<Root, T>& reach, const Shown<Root>& applies,
                             const F& f);
template <typename Root, typename T, typename F>
void addWrapProperties(std::vector<Property<Root>>& out, const QString& prefix, const Reach<Root, T>& reach,
                       const Shown<Root>& visible, const F& f);

// One declared field of T as properties of Root.
template <typename Root, typename T, typename F>
void addField(std::vector<Property<Root>>& out, const QString& prefix, const Reach<Root, T>& reach,
              const Shown<Root>& visible, const F& f) {
    using Member = typename F::MemberType;
    const QString key =
        prefix + QLatin1Char('.') + QString::fromUtf8(f.spec.name.data(), qsizetype(f.spec.name.size()));
    const auto member = [reach, f](Root& root) -> Member* {
        T* t = reach(root);
        return t ? &(static_cast<typename F::OwnerType&>(*t).*f.member) : nullptr;
    };
    const Shown<Root> applies = [reach, visible, f](const Root& root) {
        const T* t = reach(const_cast<Root&>(root));
        return shown(visible, root) && t && f.appliesTo(*t);
    };
    if constexpr (render::IsOptional<Member>::value) {
        using Inner = typename render::IsOptional<Member>::Value;
        if constexpr (render::HasFields<Inner>) {
            Property<Root> toggle;
            toggle.info = infoOf(f.spec, key);
            toggle.info.kind = PropertyKind::Bool;
            toggle.get = [member](const Root& root) {
                const Member* m = member(const_cast<Root&>(root));
                return m ? QVariant(m->has_value()) : QVariant();
            };
            toggle.set = [reach, f](Root& root, const QVariant& value) {
                return editCopy(root, reach, f, [&](T& t) -> base::Status {
                    Member& m = static_cast<typename F::OwnerType&>(t).*f.member;
                    if (value.toBool() && !m)
                        m = Inner{};
                    else if (!value.toBool())
                        m.reset();
                    return base::Done{};
                });
            };
            toggle.visible = applies;
            out.push_back(std::move(toggle));
            const Reach<Root, Inner> inner = [member](Root& root) -> Inner* {
                Member* m = member(root);
                return m && *m ? &**m : nullptr;
            };
            const Shown<Root> present = [applies, member](const Root& root) {
                const Member* m = member(const_cast<Root&>(root));
                return applies(root) && m && m->has_value();
            };
            addProperties<Root, Inner>(out, key, inner, present);
        }
    } else if constexpr (render::HasFields<Member>) {
        addProperties<Root, Member>(out, key, Reach<Root, Member>(member), applies);
    } else {
        out.push_back(valueProperty<Root, T>(key, reach, applies, f));
    }
}

// A property over one plain value: a number, a vector, a choice, a switch, a path, the wrap modes.
template <typename Root, typename T, typename F>
Property<Root> valueProperty(const QString& key, const Reach<Root, T>& reach, const Shown<Root>& applies,
                             const F& f) {
    using Member = typename F::MemberType;
    using Owner = typename F::OwnerType;
    Property<Root> p;
    p.info = infoOf(f.spec, key);
    p.visible = applies;
    p.get = [reach, f](const Root& root) -> QVariant {
        const T* t = reach(const_cast<Root&>(root));
        if (!t)
            return {};
        const Member& m = static_cast<const Owner&>(*t).*f.member;
        if constexpr (std::is_same_v<Member, render::TextureSource>)
            return QString::fromStdString(m.path);
        else
            return toVariant(render::toFieldValue(m));
    };
    p.set = [reach, f](Root& root, const QVariant& value) -> base::Status {
        return editCopy(root, reach, f, [&](T& t) -> base::Status {
            Member& m = static_cast<Owner&>(t).*f.member;
            if constexpr (std::is_same_v<Member, render::TextureSource> ||
                          std::is_same_v<Member, std::string>) {
                if constexpr (std::is_same_v<Member, std::string>) {
                    if (f.spec.type == render::FieldType::Text) {
                        m = value.toString().toStdString();
                        return base::Done{};
                    }
                }
                auto path =
                    checkedPath(f.spec, value.toString(), std::is_same_v<Member, render::TextureSource>);
                if (!path)
                    return base::Error{path.error()};
                if constexpr (std::is_same_v<Member, render::TextureSource>)
                    m = render::TextureSource{*path, nullptr};
                else
                    m = *path;
                return base::Done{};
            } else {
                const std::optional<render::FieldValue> v = toFieldValue(f.spec, value);
                if (!v)
                    return refuse(f.spec, "expects " + std::string(f.spec.type == render::FieldType::Integer
                                                                       ? "a whole number"
                                                                       : "a value of its kind"));
                if (auto problem = render::fieldProblem(f.spec, *v))
                    return refuse(f.spec, *problem);
                return render::fromFieldValue(*v, m) ? base::Status(base::Done{})
                                                     : refuse(f.spec, "has another type");
            }
        });
    };
    return p;
}

template <typename Root, typename T>
void addProperties(std::vector<Property<Root>>& out, const QString& prefix, Reach<Root, T> reach,
                   Shown<Root> visible) {
    render::forEachField<T>([&](const auto& f) {
        using Member = typename std::decay_t<decltype(f)>::MemberType;
        if constexpr (std::is_same_v<Member, std::array<render::TextureWrap, 2>>)
            addWrapProperties(out, prefix, reach, visible, f);
        else if constexpr (!render::IsOptional<Member>::value || render::isOptionalGroup<Member>())
            addField(out, prefix, reach, visible, f);
    });
}

// The wrap modes [u, v] as two choices, "<prefix>.wrapU" and "<prefix>.wrapV".
template <typename Root, typename T, typename F>
void addWrapProperties(std::vector<Property<Root>>& out, const QString& prefix, const Reach<Root, T>& reach,
                       const Shown<Root>& visible, const F& f) {
    for (int axis = 0; axis < 2; ++axis) {
        Property<Root> p;
        p.info = infoOf(f.spec, prefix + (axis == 0 ? QStringLiteral(".wrapU") : QStringLiteral(".wrapV")));
        p.info.kind = PropertyKind::Enum;
        p.info.label += axis == 0 ? QStringLiteral(" u") : QStringLiteral(" v");
        p.visible = visible;
        p.get = [reach, f, axis](const Root& root) -> QVariant {
            const T* t = reach(const_cast<Root&>(root));
            return t ? QVariant(static_cast<int>((t->*f.member)[axis])) : QVariant();
        };
        p.set = [reach, f, axis](Root& root, const QVariant& value) -> base::Status {
            return editCopy(root, reach, f, [&](T& t) -> base::Status {
                bool ok = false;
                const int i = value.toInt(&ok);
                if (!ok || i < 0 || std::size_t(i) >= f.spec.choices.size())
                    return refuse(f.spec, "expects one of: " + render::names::choices(f.spec.choices));
                (t.*f.member)[axis] = static_cast<render::TextureWrap>(i);
                return base::Done{};
            });
        };
        out.push_back(std::move(p));
    }
}

} // namespace speculum::document::fieldprops
