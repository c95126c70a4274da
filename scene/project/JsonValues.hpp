#pragma once

#include "render/frame/Field.hpp"
#include "render/frame/Material.hpp"

#include <QJsonObject>
#include <QJsonValue>
#include <QSet>
#include <QString>
#include <array>
#include <string>
#include <vector>

namespace speculum::scene::json {

// The project reader's building blocks: values read from JSON, each naming the JSON path in its error.
// Validation unwinds through many small readers; the ParseFailure thrown here is caught in parseProject
// and never leaves the reader.
struct ParseFailure {
    std::string message;
};

[[noreturn]] void fail(const std::string& path, const std::string& what);

// "path.key", with a key from the file shown escaped, never raw.
std::string join(const std::string& path, const QString& key);
std::string indexed(const std::string& path, qsizetype i);

double readNumber(const QJsonValue& v, const std::string& path);
int readInt(const QJsonValue& v, const std::string& path);
bool readBool(const QJsonValue& v, const std::string& path);
std::string readString(const QJsonValue& v, const std::string& path);
glm::dvec2 readVec2(const QJsonValue& v, const std::string& path);
glm::dvec3 readVec3(const QJsonValue& v, const std::string& path);
// A choice spelled as `spec.choices` says: its index. "unknown reflector map "x" (expected cube, ...)".
int readChoice(const QJsonValue& v, const std::string& path, const render::FieldSpec& spec);
// "repeat" | "clamp" | "mirror" for both directions, or [u, v].
std::array<render::TextureWrap, 2> readWrap(const QJsonValue& v, const std::string& path,
                                            const render::FieldSpec& spec);

// An object whose keys are read one by one; what is left is the file's unknown fields.
class ObjectReader {
public:
    ObjectReader(const QJsonValue& v, std::string path, std::vector<std::string>& warnings);

    const std::string& path() const { return m_path; }
    std::string at(std::string_view key) const;
    bool has(std::string_view key) const;
    // The value, or Undefined when absent; marks the key as known either way.
    QJsonValue get(std::string_view key);
    // Unknown keys: each warned about ("nodes[0].transfrom: unknown field, ignored") and returned.
    QJsonObject finish();

private:
    QJsonObject m_object;
    std::string m_path;
    std::vector<std::string>& m_warnings;
    QSet<QString> m_known;
};

} // namespace speculum::scene::json
