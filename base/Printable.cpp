#include "base/Printable.hpp"

#include <algorithm>
#include <cstdio>
#include <deque>
#include <vector>

namespace speculum::base {
namespace {

// The valid UTF-8 sequence at text[i]: its length and code point, or length 0 when it is not one
// (overlong forms and surrogates count as invalid: a terminal may still act on them).
struct Sequence {
    std::size_t length = 0;
    char32_t code = 0;
};

Sequence utf8Sequence(std::string_view text, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char lead = byte(i);
    std::size_t length = 0;
    char32_t minimum = 0, code = 0;
    if (lead >= 0xC2 && lead <= 0xDF) {
        length = 2, minimum = 0x80, code = lead & 0x1F;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
        length = 3, minimum = 0x800, code = lead & 0x0F;
    } else if (lead >= 0xF0 && lead <= 0xF4) {
        length = 4, minimum = 0x10000, code = lead & 0x07;
    } else {
        return {};
    }
    if (i + length > text.size()) {
        return {};
    }
    for (std::size_t k = 1; k < length; ++k) {
        if ((byte(i + k) & 0xC0) != 0x80) {
            return {};
        }
        code = (code << 6) | (byte(i + k) & 0x3F);
    }
    if (code < minimum || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) {
        return {};
    }
    return {length, code};
}

// Valid characters that still must not reach a terminal or a log as they are: C1 controls (U+0080..U+009F,
// U+009B is a CSI), the line and paragraph separators (a line break to some viewers), the bidirectional
// marks, embeddings, overrides and isolates (they reorder what is shown), and the invisible zero-width
// characters and byte order mark (they hide differences between names).
bool mustEscape(char32_t code) {
    return (code >= 0x80 && code <= 0x9F) || code == 0x061C || (code >= 0x200B && code <= 0x200F) ||
           (code >= 0x2028 && code <= 0x202E) || (code >= 0x2060 && code <= 0x2069) || code == 0xFEFF ||
           (code >= 0xFFF9 && code <= 0xFFFB);
}

// Calls emit(unit) for each visible unit of text in order (a character, a UTF-8 sequence or an escape), so
// that shortening never cuts an escape or a multi-byte character in half.
template <typename Emit>
void forEachUnit(std::string_view text, Emit&& emit) {
    char buffer[16];
    for (std::size_t i = 0; i < text.size();) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c >= 0x20 && c < 0x7F) {
            emit(c == '\\' ? std::string_view("\\\\") : text.substr(i, 1));
            ++i;
            continue;
        }
        if (c >= 0x80) {
            if (const Sequence s = utf8Sequence(text, i); s.length > 0) {
                if (mustEscape(s.code)) {
                    std::snprintf(buffer, sizeof buffer, "\\u%04x", static_cast<unsigned>(s.code));
                    emit(std::string_view(buffer));
                } else {
                    emit(text.substr(i, s.length));
                }
                i += s.length;
                continue;
            }
        }
        switch (c) {
        case '\n':
            emit(std::string_view("\\n"));
            break;
        case '\r':
            emit(std::string_view("\\r"));
            break;
        case '\t':
            emit(std::string_view("\\t"));
            break;
        default:
            std::snprintf(buffer, sizeof buffer, "\\x%02x", c);
            emit(std::string_view(buffer));
        }
        ++i;
    }
}

} // namespace

std::string printable(std::string_view text, std::size_t maxChars) {
    maxChars = std::max<std::size_t>(maxChars, 8);
    const std::size_t keep = (maxChars - 3) / 2;
    // One pass, memory bounded by maxChars whatever the size of text: everything while it still fits, then
    // the first `keep` units and a window over the last `keep`.
    std::vector<std::string> head;
    std::deque<std::string> tail;
    std::size_t count = 0;
    forEachUnit(text, [&](std::string_view unit) {
        ++count;
        if (head.size() < maxChars) {
            head.emplace_back(unit);
            return;
        }
        tail.emplace_back(unit);
        if (tail.size() > keep) {
            tail.pop_front();
        }
    });
    std::string out;
    if (count <= maxChars) {
        for (const std::string& unit : head) {
            out += unit;
        }
        return out;
    }
    // The last `keep` units overall: the tail window, topped up from the end of head when short.
    std::vector<std::string> last(head.end() - static_cast<std::ptrdiff_t>(keep - tail.size()), head.end());
    last.insert(last.end(), tail.begin(), tail.end());
    for (std::size_t i = 0; i < keep; ++i) {
        out += head[i];
    }
    out += "...";
    for (const std::string& unit : last) {
        out += unit;
    }
    return out;
}

std::string quoted(std::string_view text, std::size_t maxChars) {
    return "'" + printable(text, maxChars) + "'";
}

} // namespace speculum::base
