#pragma once

#include "scene/model/SceneChecks.hpp"
#include "scene/model/SceneData.hpp"
#include "scene/project/JsonValues.hpp"

#include <QDir>
#include <string>
#include <type_traits>
#include <vector>

namespace speculum::scene::json {

// Reads any struct that declares its fields (render/frame/Field.hpp) from a JSON object: every declared
// field by its type, checked against its spec, the rules across fields of its struct (SceneChecks.hpp),
// and whatever keys are left kept as unknown fields. Relative paths are resolved against `baseDir`.
class FieldReader {
public:
    FieldReader(const QDir& baseDir, std::vector<std::string>& warnings)
        : m_baseDir(baseDir)
        , m_warnings(warnings) {}

    // Reads the object `json` at `path` into `value`; its unknown keys go to unknown[key], those of the
    // objects inside it to unknown["key.name"].
    template <typename T>
    void readObject(const QJsonValue& json, const std::string& path, T& value, UnknownFields& unknown,
                    const std::string& key) {
        ObjectReader o(json, path, m_warnings);
        readFields(o, value, unknown, key);
        finish(o, unknown, key);
    }

    // The declared fields of `value` from an object already open (its caller reads more keys of it).
    template <typename T>
    void readFields(ObjectReader& o, T& value, UnknownFields& unknown, const std::string& key) {
        beforeFields(o, value);
        render::forEachField<T>([&](const auto& f) { readField(o, f, value, unknown, key); });
        afterFields(o, value);
    }

    void finish(ObjectReader& o, UnknownFields& unknown, const std::string& key);

    std::string readPath(const QJsonValue& v, const std::string& path);

private:
    template <typename F, typename T>
    void readField(ObjectReader& o, const F& f, T& value, UnknownFields& unknown, const std::string& key) {
        using Owner = typename F::OwnerType;
        auto& member = static_cast<Owner&>(value).*f.member;
        std::string_view name = f.spec.name;
        if (!o.has(name) && !f.spec.formerName.empty() && o.has(f.spec.formerName))
            name = f.spec.formerName; // an older file's name for it
        else if (!f.spec.formerName.empty())
            o.get(f.spec.formerName); // superseded: not kept as an unknown field
        const QJsonValue v = o.get(name);
        if (v.isUndefined())
            return;
        const std::string childKey =
            key.empty() ? std::string(f.spec.name) : key + "." + std::string(f.spec.name);
        readMember(v, o.at(name), f.spec, member, unknown, childKey);
    }

    template <typename M>
    void readMember(const QJsonValue& v, const std::string& path, const render::FieldSpec& spec, M& member,
                    UnknownFields& unknown, const std::string& key) {
        if constexpr (render::IsOptional<M>::value) {
            typename render::IsOptional<M>::Value inner{};
            readMember(v, path, spec, inner, unknown, key);
            member = std::move(inner);
        } else if constexpr (render::HasFields<M>) {
            readObject(v, path, member, unknown, key);
        } else {
            member = readScalar<M>(v, path, spec);
            if constexpr (render::PlainFieldValue<M> || std::is_same_v<M, render::TextureSource>)
                if (auto problem = render::fieldProblem(spec, render::toFieldValue(member)))
                    fail(path, *problem);
        }
    }

    template <typename M>
    M readScalar(const QJsonValue& v, const std::string& path, const render::FieldSpec& spec) {
        if constexpr (std::is_enum_v<M>)
            return static_cast<M>(readChoice(v, path, spec));
        else if constexpr (std::is_same_v<M, bool>)
            return readBool(v, path);
        else if constexpr (std::is_same_v<M, int>)
            return readInt(v, path);
        else if constexpr (std::is_same_v<M, double>)
            return readNumber(v, path);
        else if constexpr (std::is_same_v<M, glm::dvec2>)
            return readVec2(v, path);
        else if constexpr (std::is_same_v<M, glm::dvec3>)
            return readVec3(v, path);
        else if constexpr (std::is_same_v<M, render::TextureSource>)
            return render::TextureSource{readPath(v, path), nullptr};
        else if constexpr (std::is_same_v<M, std::array<render::TextureWrap, 2>>)
            return readWrap(v, path, spec);
        else if (spec.type == render::FieldType::Path)
            return readPath(v, path);
        else
            return readString(v, path);
    }

    // The rules of a struct beyond its single fields; most have none.
    template <typename T>
    void beforeFields(ObjectReader&, T&) {}
    template <typename T>
    void afterFields(ObjectReader&, T&) {}
    void beforeFields(ObjectReader& o, MeshComponent& mesh);
    void afterFields(ObjectReader& o, MeshComponent& mesh);
    void beforeFields(ObjectReader& o, render::ParallaxParams& proxy);
    void afterFields(ObjectReader& o, render::ParallaxParams& proxy);
    void afterFields(ObjectReader& o, render::Camera& camera);
    void beforeFields(ObjectReader& o, EditorView& view);
    void afterFields(ObjectReader& o, EditorView& view);

    QDir m_baseDir;
    std::vector<std::string>& m_warnings;
};

} // namespace speculum::scene::json
