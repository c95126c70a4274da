#pragma once

#include "render/frame/SceneNames.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

namespace speculum::render {

// Every setting a scene holds is declared once, beside the struct that holds it: its name (as project
// files, bench results and the inspector's keys spell it), its type, its range, its default (the member's
// initializer) and what it means. The project reader and writer, the inspector, the planner's signatures,
// the model import's child process and the accuracy sweep all walk these declarations, so a new setting is
// its member, its declaration and the code that uses it, nothing else.
//
// A struct declares its fields in file order with a static member template that hands each one to a
// visitor:
//
//     template <typename Visit>
//     static void fields(Visit&& visit) {
//         visit(field(&MirrorParams::reflectivity, {.name = "reflectivity", .label = "Reflectivity", ...}));
//     }
//
// A walker is a visitor taking `const auto& field` (a Field<Owner, Member> below).

enum class FieldType {
    Bool,
    Integer,
    Number,
    Vector2, // each component within the range
    Vector3,
    Color,    // linear RGB, each component in 0..1
    Choice,   // an enumeration, spelled as `choices` says
    WrapPair, // texture wrap modes [u, v], one name when both agree
    Path,     // a file: absolute in memory, relative to the project file in files
    Text,     // any string (a node's name)
    Object,   // a group with fields of its own: a struct with fields(), or a std::optional of one
};

enum class FieldRule {
    None,
    PowerOfTwo, // integers: 1, 2, 4, ...
    Odd,        // integers
    Magnitude,  // numbers and vector components: the range bounds |x| and 0 is refused (a scale's sign
                // mirrors)
};

// Whether the writer may leave a field out.
enum class FieldWrite {
    // Written whenever it applies to its object; where it does not apply (a point light's cone), written
    // only when it differs from its default, so that switching back loses nothing.
    Always,
    UnlessDefault, // left out at its default, so files that never set it are written as they were
    WhenApplies,   // written only where it applies (a built-in mesh's tessellation)
    Everywhere,    // written wherever its object is, applying or not (files have always had it)
};

struct FieldSpec {
    std::string_view name;    // in files, bench results and inspector keys: "reflectivity"
    std::string_view label;   // for people: "Reflectivity"
    std::string_view meaning; // a sentence: the inspector's tooltip and the file format's specification
    FieldType type = FieldType::Number;
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool minOpen = false; // the range excludes its minimum: (0, 90]
    bool maxOpen = false; // the range excludes its maximum: (0, 180)
    FieldRule rule = FieldRule::None;
    std::string_view unit; // after a value in the inspector: "°", " s", " px", " u"
    std::string_view noun; // in messages: "reflector map" (Choice), "extents" (vectors)
    std::span<const names::Name> choices;
    FieldWrite write = FieldWrite::Always;
    std::string_view formerName; // an older file's name, read when `name` is absent ("blur")
    // The inspector's editor: a slider over [softMin, softMax]; the spin box takes the whole range.
    bool slider = false;
    double softMin = 0.0;
    double softMax = 1.0;
    int decimals = 3;
    double step = 0.1;
    // False for a setting that only the camera's own view reads (a mirror's technique, its roughness):
    // changing it leaves the environment map's signature, and so the map, alone.
    bool drawnInMaps = true;
    // Values the accuracy sweep tries for it (around the scene's own), for a setting no family of the
    // sweep's own varies. Empty: not swept on its own.
    std::span<const double> sweep;
    // Its column in bench results, where that is not its name ("reflectedDetail").
    std::string_view sweepName;
};

// One declared field: where it is in its struct, its spec, and whether it means something for a given
// value of the struct (a spot's cone; a sphere proxy's radius). A field that does not apply is kept, and
// written only when it differs from its default, so switching back loses nothing.
template <typename Owner, typename Member>
struct Field {
    using OwnerType = Owner;
    using MemberType = Member;
    Member Owner::*member;
    FieldSpec spec;
    bool (*applies)(const Owner&) = nullptr;

    bool appliesTo(const Owner& owner) const { return !applies || applies(owner); }
};

template <typename Owner, typename Member>
constexpr Field<Owner, Member> field(Member Owner::*member, FieldSpec spec,
                                     std::type_identity_t<bool (*)(const Owner&)> applies = nullptr) {
    return {member, spec, applies};
}

template <typename T>
concept HasFields = requires {
    T::fields([](const auto&) {});
};

template <typename T>
struct IsOptional : std::false_type {};
template <typename T>
struct IsOptional<std::optional<T>> : std::true_type {
    using Value = T;
};

// An optional group of fields (std::optional of a struct with fields()), as opposed to an optional value.
template <typename M>
constexpr bool isOptionalGroup() {
    if constexpr (IsOptional<M>::value)
        return HasFields<typename IsOptional<M>::Value>;
    else
        return false;
}

// Calls visit(field) for every field T declares, in file order.
template <typename T, typename Visit>
void forEachField(Visit&& visit) {
    T::fields(visit);
}

// A field's value without its C++ type: what the inspector edits, the sweep varies and bench results
// record. Enumerations are their index in `choices`; paths are strings.
using FieldValue = std::variant<bool, int, double, glm::dvec2, glm::dvec3, std::string>;

// A member's value as a FieldValue, and back (false when the value has another type). Enumerations are
// their index; other member types (TextureSource) add overloads beside their own definition.
template <typename M>
concept PlainFieldValue =
    std::is_enum_v<M> || std::is_same_v<M, bool> || std::is_same_v<M, int> || std::is_same_v<M, double> ||
    std::is_same_v<M, glm::dvec2> || std::is_same_v<M, glm::dvec3> || std::is_same_v<M, std::string>;

template <PlainFieldValue M>
FieldValue toFieldValue(const M& value) {
    if constexpr (std::is_enum_v<M>) {
        return static_cast<int>(value);
    } else {
        return FieldValue(value);
    }
}

template <PlainFieldValue M>
bool fromFieldValue(const FieldValue& value, M& out) {
    if constexpr (std::is_enum_v<M>) {
        const int* index = std::get_if<int>(&value);
        return index && (out = static_cast<M>(*index), true);
    } else if constexpr (std::is_same_v<M, double>) {
        // An integer where a number is expected is that number (a bench record's "1").
        if (const int* i = std::get_if<int>(&value)) {
            out = *i;
            return true;
        }
        const double* d = std::get_if<double>(&value);
        return d && (out = *d, true);
    } else {
        const M* v = std::get_if<M>(&value);
        return v && (out = *v, true);
    }
}

// A value's field of `value` by name, type-erased: nothing for an unknown name or a field no FieldValue
// holds (an optional group, the wrap pair).
template <typename T>
std::optional<FieldValue> getField(const T& value, std::string_view name) {
    std::optional<FieldValue> out;
    forEachField<T>([&](const auto& f) {
        using Owner = typename std::decay_t<decltype(f)>::OwnerType;
        using Member = typename std::decay_t<decltype(f)>::MemberType;
        if constexpr (requires(const Member& m) { toFieldValue(m); })
            if (f.spec.name == name)
                out = toFieldValue(static_cast<const Owner&>(value).*f.member);
    });
    return out;
}

// The spec of T's field `name`, or null.
template <typename T>
const FieldSpec* findField(std::string_view name) {
    static const auto all = [] {
        std::vector<FieldSpec> specs;
        forEachField<T>([&](const auto& f) { specs.push_back(f.spec); });
        return specs;
    }();
    for (const FieldSpec& spec : all)
        if (spec.name == name)
            return &spec;
    return nullptr;
}

// What is wrong with a value for this field, or nothing: "must be in 0..1, got 2". Callers put the place
// in front: the JSON path ("nodes[2].mirror.reflectivity: ...") or the label ("Reflectivity ...").
std::optional<std::string> fieldProblem(const FieldSpec& spec, const FieldValue& value);

// Sets T's field `name` of `value` to `v` after checking it against the field's spec; on any problem
// (an unknown name, a value of another type, out of range) `value` is unchanged and the problem returned
// ("must be in 0..1, got 2").
template <typename T>
std::optional<std::string> setField(T& value, std::string_view name, const FieldValue& v) {
    std::optional<std::string> problem = "no such setting";
    forEachField<T>([&](const auto& f) {
        using Owner = typename std::decay_t<decltype(f)>::OwnerType;
        using Member = typename std::decay_t<decltype(f)>::MemberType;
        if (f.spec.name != name)
            return;
        if constexpr (requires(Member & m) { fromFieldValue(v, m); }) {
            problem = fieldProblem(f.spec, v);
            Member converted{};
            if (!problem && !fromFieldValue(v, converted))
                problem = "has another type";
            if (!problem)
                static_cast<Owner&>(value).*f.member = converted;
        } else {
            problem = "cannot be set on its own";
        }
    });
    return problem;
}

// The range as messages say it: "0..1", "(0, 90]", "±1e+12".
std::string rangeText(const FieldSpec& spec);

// A number as people read it: the shortest form that reads back exactly ("0.1", "1e+12", "16").
std::string shortestNumber(double value);

// "cube", "dual-paraboloid": a choice's value as files spell it; "true"/"false"; numbers shortest.
std::string fieldValueText(const FieldSpec& spec, const FieldValue& value);
// The value `text` spells for this field (the reverse of fieldValueText), or an error message.
std::variant<FieldValue, std::string> parseFieldValue(const FieldSpec& spec, std::string_view text);

} // namespace speculum::render
