#pragma once

#include <QByteArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QStringList>
#include <string_view>
#include <vector>

namespace speculum::scene {

// Streams JSON with keys in the order they are written (QJsonDocument sorts them), 2-space indentation,
// arrays of numbers on one line, and numbers in their shortest round-trip form (integers without ".0").
// The output is a pure function of the calls, which is what makes saving byte-for-byte reproducible.
class JsonWriter {
public:
    // The keys of an object in code-unit order. QJsonObject's own iteration order is not a dependable
    // sort (a key whose raw U+FEFF the parser dropped keeps its old place), so files are written by this.
    static QStringList sortedKeys(const QJsonObject& object);

    void beginObject();
    void endObject();
    void beginArray();
    void endArray();
    void key(std::string_view name); // inside an object, before each value

    void value(double number);
    void value(int number);
    void value(std::string_view text);
    void value(const char* text) { value(std::string_view(text)); }
    void numbers(const double* values, int count); // [a, b, c] on one line
    void value(const QJsonValue& any);             // unknown fields kept from a file; objects sorted by key

    // The document, ending with a newline. The writer must be back at the top level.
    QByteArray finish();

    static QByteArray formatNumber(double number);

private:
    void beforeValue();
    void newline();
    void writeString(std::string_view text);
    void raw(std::string_view text) { m_out.append(text.data(), static_cast<qsizetype>(text.size())); }

    struct Level {
        bool isArray = false;
        int count = 0;
    };
    QByteArray m_out;
    std::vector<Level> m_levels;
    bool m_afterKey = false;
};

} // namespace speculum::scene
