#include "scene/project/JsonValues.hpp"

#include "base/Printable.hpp"

#include <QJsonArray>
#include <cmath>

namespace speculum::scene::json {

namespace {

template <int N>
glm::vec<N, double> readVec(const QJsonValue& v, const std::string& path) {
    const std::string what = "expected " + std::to_string(N) + " numbers";
    if (!v.isArray() || v.toArray().size() != N)
        fail(path, what);
    const QJsonArray a = v.toArray();
    glm::vec<N, double> out(0.0);
    for (int i = 0; i < N; ++i) {
        if (!a[i].isDouble() || !std::isfinite(a[i].toDouble()))
            fail(path, what);
        out[i] = a[i].toDouble();
    }
    return out;
}

QString latin1(std::string_view key) {
    return QString::fromLatin1(key.data(), static_cast<qsizetype>(key.size()));
}

} // namespace

void fail(const std::string& path, const std::string& what) {
    throw ParseFailure{path.empty() ? what : path + ": " + what};
}

std::string join(const std::string& path, const QString& key) {
    const std::string shown = base::printable(key.toStdString(), 40);
    return path.empty() ? shown : path + "." + shown;
}

std::string indexed(const std::string& path, qsizetype i) {
    return path + "[" + std::to_string(i) + "]";
}

double readNumber(const QJsonValue& v, const std::string& path) {
    if (!v.isDouble())
        fail(path, "expected a number");
    const double d = v.toDouble();
    if (!std::isfinite(d))
        fail(path, "expected a finite number");
    return d;
}

int readInt(const QJsonValue& v, const std::string& path) {
    const double d = v.isDouble() ? v.toDouble() : NAN;
    if (!std::isfinite(d) || d != std::floor(d) || std::abs(d) > 1e9)
        fail(path, "expected an integer");
    return static_cast<int>(d);
}

bool readBool(const QJsonValue& v, const std::string& path) {
    if (!v.isBool())
        fail(path, "expected true or false");
    return v.toBool();
}

std::string readString(const QJsonValue& v, const std::string& path) {
    if (!v.isString())
        fail(path, "expected a string");
    return v.toString().toStdString();
}

glm::dvec2 readVec2(const QJsonValue& v, const std::string& path) {
    return readVec<2>(v, path);
}

glm::dvec3 readVec3(const QJsonValue& v, const std::string& path) {
    return readVec<3>(v, path);
}

int readChoice(const QJsonValue& v, const std::string& path, const render::FieldSpec& spec) {
    const std::string s = readString(v, path);
    const std::optional<int> index = render::names::fromFileName<int>(spec.choices, s);
    if (!index)
        fail(path, "unknown " + std::string(spec.noun) + " \"" + base::printable(s, 40) + "\" (expected " +
                       render::names::choices(spec.choices) + ")");
    return *index;
}

std::array<render::TextureWrap, 2> readWrap(const QJsonValue& v, const std::string& path,
                                            const render::FieldSpec& spec) {
    const auto one = [&](const QJsonValue& value, const std::string& at) {
        return static_cast<render::TextureWrap>(readChoice(value, at, spec));
    };
    if (v.isString()) {
        const render::TextureWrap both = one(v, path);
        return {both, both};
    }
    if (!v.isArray() || v.toArray().size() != 2)
        fail(path, "expected a wrap mode or [u, v] wrap modes");
    const QJsonArray a = v.toArray();
    return {one(a[0], indexed(path, 0)), one(a[1], indexed(path, 1))};
}

ObjectReader::ObjectReader(const QJsonValue& v, std::string path, std::vector<std::string>& warnings)
    : m_path(std::move(path))
    , m_warnings(warnings) {
    if (!v.isObject())
        fail(m_path, "expected an object");
    m_object = v.toObject();
}

std::string ObjectReader::at(std::string_view key) const {
    return join(m_path, latin1(key));
}

bool ObjectReader::has(std::string_view key) const {
    return m_object.contains(latin1(key));
}

QJsonValue ObjectReader::get(std::string_view key) {
    m_known.insert(latin1(key));
    return m_object.value(latin1(key));
}

QJsonObject ObjectReader::finish() {
    QJsonObject extra;
    for (auto it = m_object.begin(); it != m_object.end(); ++it) {
        if (!m_known.contains(it.key())) {
            m_warnings.push_back(join(m_path, it.key()) + ": unknown field, ignored");
            extra.insert(it.key(), it.value());
        }
    }
    return extra;
}

} // namespace speculum::scene::json
