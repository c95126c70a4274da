#include "scene/project/JsonDuplicateKeys.hpp"

#include "base/Printable.hpp"

#include <set>
#include <vector>

namespace speculum::scene {

namespace {

// One open object or array, with what its current child is called (for the JSON path of a message).
struct Frame {
    bool object = false;
    bool expectKey = false;        // objects: the next string is a key
    std::set<std::u16string> keys; // objects: keys seen so far, decoded
    std::string key;               // objects: the current key, decoded to UTF-8, for paths
    std::size_t index = 0;         // arrays: the current element
};

void appendUtf8(std::string& out, char32_t c) {
    if (c < 0x80) {
        out += static_cast<char>(c);
    } else if (c < 0x800) {
        out += static_cast<char>(0xC0 | (c >> 6));
        out += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
        out += static_cast<char>(0xE0 | (c >> 12));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (c >> 18));
        out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    }
}

void appendUtf16(std::u16string& out, char32_t c) {
    if (c >= 0x10000) {
        c -= 0x10000;
        out += static_cast<char16_t>(0xD800 + (c >> 10));
        out += static_cast<char16_t>(0xDC00 + (c & 0x3FF));
    } else {
        out += static_cast<char16_t>(c);
    }
}

int hexValue(char c) {
    if (c >= '0' && c <= '9') {
        return c - '0';
    }
    if (c >= 'a' && c <= 'f') {
        return c - 'a' + 10;
    }
    if (c >= 'A' && c <= 'F') {
        return c - 'A' + 10;
    }
    return -1;
}

struct DecodedString {
    std::u16string units; // what QString holds: compared for duplicates
    std::string shown;    // UTF-8 for messages (lone surrogates come out as invalid bytes, shown escaped)
};

// The string starting at json[i] == '"'; i ends after the closing quote (or at the end of malformed text).
DecodedString readString(std::string_view json, std::size_t& i) {
    DecodedString s;
    ++i; // opening quote
    while (i < json.size()) {
        const unsigned char c = static_cast<unsigned char>(json[i]);
        if (c == '"') {
            ++i;
            return s;
        }
        if (c == '\\' && i + 1 < json.size()) {
            const char e = json[i + 1];
            i += 2;
            char32_t code = 0;
            switch (e) {
            case 'b':
                code = '\b';
                break;
            case 'f':
                code = '\f';
                break;
            case 'n':
                code = '\n';
                break;
            case 'r':
                code = '\r';
                break;
            case 't':
                code = '\t';
                break;
            case 'u': {
                for (int k = 0; k < 4 && i < json.size(); ++k, ++i) {
                    const int h = hexValue(json[i]);
                    code = (code << 4) | static_cast<char32_t>(h < 0 ? 0 : h);
                }
                // A \u escape is one UTF-16 unit: a pair of them spells a character outside the BMP, and
                // QString compares them as units, so units are what is compared here too.
                s.units += static_cast<char16_t>(code);
                appendUtf8(s.shown, code);
                continue;
            }
            default:
                code = static_cast<unsigned char>(e); // \" \\ \/ and anything else as itself
            }
            s.units += static_cast<char16_t>(code);
            appendUtf8(s.shown, code);
            continue;
        }
        // Raw UTF-8 (the parser accepted it, so it is well formed); anything odd counts byte by byte.
        std::size_t length = c < 0x80 ? 1 : c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC0 ? 2 : 1;
        if (i + length > json.size()) {
            length = 1;
        }
        char32_t code = length == 1 ? c : length == 2 ? (c & 0x1F) : length == 3 ? (c & 0x0F) : (c & 0x07);
        for (std::size_t k = 1; k < length; ++k) {
            code = (code << 6) | (static_cast<unsigned char>(json[i + k]) & 0x3F);
        }
        appendUtf16(s.units, code);
        s.shown.append(json.substr(i, length));
        i += length;
    }
    return s;
}

std::string pathOf(const std::vector<Frame>& stack) {
    std::string path;
    // Every frame but the innermost names its current child.
    for (std::size_t f = 0; f + 1 < stack.size(); ++f) {
        if (stack[f].object) {
            path += (path.empty() ? "" : ".") + base::printable(stack[f].key, 40);
        } else {
            path += "[" + std::to_string(stack[f].index) + "]";
        }
    }
    return path;
}

} // namespace

std::optional<std::string> findDuplicateKey(std::string_view json) {
    std::vector<Frame> stack;
    std::size_t i = 0;
    while (i < json.size()) {
        const char c = json[i];
        switch (c) {
        case '{':
            stack.push_back(Frame{true, true, {}, {}, 0});
            ++i;
            break;
        case '[':
            stack.push_back(Frame{false, false, {}, {}, 0});
            ++i;
            break;
        case '}':
        case ']':
            if (!stack.empty()) {
                stack.pop_back();
            }
            ++i;
            break;
        case ',':
            if (!stack.empty()) {
                stack.back().object ? void(stack.back().expectKey = true) : void(++stack.back().index);
            }
            ++i;
            break;
        case ':':
            if (!stack.empty()) {
                stack.back().expectKey = false;
            }
            ++i;
            break;
        case '"': {
            DecodedString s = readString(json, i);
            if (!stack.empty() && stack.back().object && stack.back().expectKey) {
                Frame& frame = stack.back();
                if (!frame.keys.insert(std::move(s.units)).second) {
                    const std::string path = pathOf(stack);
                    const std::string what = "duplicate key " + base::quoted(s.shown, 60);
                    return path.empty() ? what + " at the top level" : path + ": " + what;
                }
                frame.key = std::move(s.shown);
                frame.expectKey = false;
            }
            break;
        }
        default:
            ++i; // whitespace, numbers, true/false/null
        }
    }
    return std::nullopt;
}

} // namespace speculum::scene
