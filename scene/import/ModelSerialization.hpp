#pragma once

#include "scene/import/ModelImport.hpp"
#include "scene/import/ModelMaterials.hpp"

#include <algorithm>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace speculum::scene::detail {

// What the import child (ModelImportProcess) hands back to the editor process: the model, or the reason
// it was refused, and the notes either way. Compressed embedded textures travel as their file bytes and
// are decoded by the receiver (decodeEmbeddedTextures).
struct ChildImport {
    bool ok = false;
    std::string error;
    ImportedModel model;
    std::map<std::string, EmbeddedBytes> compressedTextures;
    std::vector<std::string> notes;
};

// A flat byte stream of little-endian integers, doubles and length-prefixed strings and arrays.
class ByteWriter {
public:
    void u64(std::uint64_t value) { raw(&value, sizeof value); }
    void i64(std::int64_t value) { raw(&value, sizeof value); }
    void f64(double value) { raw(&value, sizeof value); }
    void string(std::string_view text) {
        u64(text.size());
        raw(text.data(), text.size());
    }
    template <typename T>
    void array(const std::vector<T>& values) {
        static_assert(std::is_standard_layout_v<T>); // glm vectors: plain floats, copied as bytes
        u64(values.size());
        raw(values.data(), values.size() * sizeof(T));
    }
    void raw(const void* data, std::size_t size) { out.append(static_cast<const char*>(data), size); }
    std::string out;
};

// Reads what ByteWriter wrote; every read checks the bytes left, so a stream cut short (a child killed
// mid-write) or a length gone wrong turns into `failed()`, never into a read past the end or an absurd
// allocation.
class ByteReader {
public:
    explicit ByteReader(std::string_view bytes)
        : m_bytes(bytes) {}
    bool failed() const { return m_failed; }
    bool atEnd() const { return m_offset == m_bytes.size(); }
    std::uint64_t u64() {
        std::uint64_t value = 0;
        raw(&value, sizeof value);
        return value;
    }
    std::int64_t i64() {
        std::int64_t value = 0;
        raw(&value, sizeof value);
        return value;
    }
    double f64() {
        double value = 0;
        raw(&value, sizeof value);
        return value;
    }
    std::string string() {
        const std::uint64_t size = u64();
        if (!fits(size, 1)) {
            return {};
        }
        std::string text(m_bytes.substr(m_offset, size));
        m_offset += size;
        return text;
    }
    template <typename T>
    std::vector<T> array() {
        static_assert(std::is_standard_layout_v<T>); // glm vectors: plain floats, copied as bytes
        const std::uint64_t count = u64();
        std::vector<T> values;
        if (fits(count, sizeof(T))) {
            values.resize(count);
            raw(values.data(), count * sizeof(T));
        }
        return values;
    }
    // A count of items each at least `minBytes` long: larger than the bytes left is a failure.
    std::uint64_t count(std::size_t minBytes) {
        const std::uint64_t value = u64();
        return fits(value, minBytes) ? value : 0;
    }
    void fail() { m_failed = true; }
    void raw(void* data, std::size_t size) {
        if (!fits(size, 1)) {
            return;
        }
        std::copy_n(m_bytes.data() + m_offset, size, static_cast<char*>(data));
        m_offset += size;
    }

private:
    bool fits(std::uint64_t count, std::size_t size) {
        if (m_failed || (size != 0 && count > (m_bytes.size() - m_offset) / size)) {
            m_failed = true;
            return false;
        }
        return true;
    }
    std::string_view m_bytes;
    std::size_t m_offset = 0;
    bool m_failed = false;
};

void writeMaterial(ByteWriter& out, const MaterialComponent& material);
bool readMaterial(ByteReader& in, MaterialComponent& material);

std::string serializeChildImport(const ChildImport& result);
// Every length, count and index is checked: a truncated or inconsistent stream is an error.
base::Result<ChildImport> deserializeChildImport(std::string_view bytes);

} // namespace speculum::scene::detail
