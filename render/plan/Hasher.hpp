#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace speculum::render {

// FNV-1a over raw bytes: deterministic and cheap; the planner's signatures hash plain doubles, ints and
// pointers (never structs with padding or strings by value).
struct Hasher {
    std::uint64_t value = 1469598103934665603ull;
    void bytes(const void* data, std::size_t size) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i) {
            value ^= p[i];
            value *= 1099511628211ull;
        }
    }
    template <typename T>
    void add(const T& v) {
        bytes(&v, sizeof(v));
    }
    void add(std::string_view text) {
        add(text.size());
        bytes(text.data(), text.size());
    }
};

} // namespace speculum::render
