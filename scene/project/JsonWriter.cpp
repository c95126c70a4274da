#include "scene/project/JsonWriter.hpp"

#include <QJsonArray>
#include <QJsonObject>
#include <QLocale>
#include <QString>
#include <QVariant>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>

namespace speculum::scene {

QByteArray JsonWriter::formatNumber(double number) {
    assert(std::isfinite(number) && "JsonWriter::formatNumber(): JSON has no NaN or infinity");
    // Whole numbers of a sane size print as integers: "1024", not "1024.0" or "1.024e+03".
    if (number == std::floor(number) && std::abs(number) < 1e15) {
        return QByteArray::number(static_cast<qint64>(number));
    }
    return QString::number(number, 'g', QLocale::FloatingPointShortest).toLatin1();
}

void JsonWriter::newline() {
    m_out.append('\n');
    m_out.append(QByteArray(static_cast<qsizetype>(m_levels.size()) * 2, ' '));
}

void JsonWriter::beforeValue() {
    if (m_afterKey) {
        m_afterKey = false;
        return;
    }
    if (m_levels.empty()) {
        assert(m_out.isEmpty() && "JsonWriter: only one top-level value");
        return;
    }
    Level& level = m_levels.back();
    assert(level.isArray && "JsonWriter: a value in an object needs a key first");
    if (level.count++ > 0) {
        m_out.append(',');
    }
    newline();
}

void JsonWriter::key(std::string_view name) {
    assert(!m_levels.empty() && !m_levels.back().isArray && !m_afterKey &&
           "JsonWriter::key(): not in an object");
    Level& level = m_levels.back();
    if (level.count++ > 0) {
        m_out.append(',');
    }
    newline();
    writeString(name);
    raw(": ");
    m_afterKey = true;
}

void JsonWriter::beginObject() {
    beforeValue();
    m_out.append('{');
    m_levels.push_back({false, 0});
}

void JsonWriter::endObject() {
    assert(!m_levels.empty() && !m_levels.back().isArray && "JsonWriter::endObject(): not in an object");
    const bool empty = m_levels.back().count == 0;
    m_levels.pop_back();
    if (!empty) {
        newline();
    }
    m_out.append('}');
}

void JsonWriter::beginArray() {
    beforeValue();
    m_out.append('[');
    m_levels.push_back({true, 0});
}

void JsonWriter::endArray() {
    assert(!m_levels.empty() && m_levels.back().isArray && "JsonWriter::endArray(): not in an array");
    const bool empty = m_levels.back().count == 0;
    m_levels.pop_back();
    if (!empty) {
        newline();
    }
    m_out.append(']');
}

void JsonWriter::value(double number) {
    beforeValue();
    m_out.append(formatNumber(number));
}

void JsonWriter::value(int number) {
    beforeValue();
    m_out.append(QByteArray::number(number));
}

void JsonWriter::value(std::string_view text) {
    beforeValue();
    writeString(text);
}

void JsonWriter::writeString(std::string_view text) {
    m_out.append('"');
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        // U+FEFF (a byte-order mark) is dropped by Qt's parser when it appears raw inside a string, so a
        // key or value holding one would change between a save and the next load: write it escaped.
        if (text.compare(i, 3, "\xEF\xBB\xBF") == 0) {
            raw("\\ufeff");
            i += 2;
            continue;
        }
        switch (c) {
        case '"':
            raw("\\\"");
            break;
        case '\\':
            raw("\\\\");
            break;
        case '\n':
            raw("\\n");
            break;
        case '\r':
            raw("\\r");
            break;
        case '\t':
            raw("\\t");
            break;
        case '\b':
            raw("\\b");
            break;
        case '\f':
            raw("\\f");
            break;
        default:
            if (static_cast<unsigned char>(c) < 0x20) {
                char buffer[8];
                std::snprintf(buffer, sizeof buffer, "\\u%04x", static_cast<unsigned>(c));
                raw(buffer);
            } else {
                m_out.append(c); // UTF-8 passes through unchanged
            }
        }
    }
    m_out.append('"');
}

void JsonWriter::numbers(const double* values, int count) {
    beforeValue();
    m_out.append('[');
    for (int i = 0; i < count; ++i) {
        if (i > 0) {
            raw(", ");
        }
        m_out.append(formatNumber(values[i]));
    }
    m_out.append(']');
}

void JsonWriter::value(const QJsonValue& any) {
    switch (any.type()) {
    case QJsonValue::Null:
    case QJsonValue::Undefined:
        beforeValue();
        raw("null");
        break;
    case QJsonValue::Bool:
        beforeValue();
        raw(any.toBool() ? "true" : "false");
        break;
    case QJsonValue::Double: {
        const QVariant v = any.toVariant();
        if (v.typeId() == QMetaType::LongLong) {
            beforeValue(); // integers beyond 2^53 stay exact
            m_out.append(QByteArray::number(v.toLongLong()));
        } else {
            value(any.toDouble());
        }
        break;
    }
    case QJsonValue::String:
        value(any.toString().toStdString());
        break;
    case QJsonValue::Array: {
        const QJsonArray array = any.toArray();
        const bool allNumbers =
            !array.isEmpty() &&
            std::all_of(array.begin(), array.end(), [](const QJsonValue& e) { return e.isDouble(); });
        if (allNumbers) {
            std::vector<double> values;
            for (const QJsonValue& e : array) {
                values.push_back(e.toDouble());
            }
            numbers(values.data(), static_cast<int>(values.size()));
        } else {
            beginArray();
            for (const QJsonValue& e : array) {
                value(e);
            }
            endArray();
        }
        break;
    }
    case QJsonValue::Object: {
        const QJsonObject object = any.toObject();
        beginObject();
        for (const QString& name : sortedKeys(object)) {
            key(name.toStdString());
            value(object.value(name));
        }
        endObject();
        break;
    }
    }
}

QStringList JsonWriter::sortedKeys(const QJsonObject& object) {
    QStringList keys = object.keys();
    std::sort(keys.begin(), keys.end(), [](const QString& a, const QString& b) { return a.compare(b) < 0; });
    return keys;
}

QByteArray JsonWriter::finish() {
    assert(m_levels.empty() && !m_afterKey && "JsonWriter::finish(): unclosed object or array");
    QByteArray out = std::move(m_out);
    out.append('\n');
    m_out.clear();
    return out;
}

} // namespace speculum::scene
