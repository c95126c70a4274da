#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace speculum::scene {

// QJsonDocument keeps only one value of a key that appears twice in an object, silently: a file with two
// "name"s (or two "transform"s, one of them hand-edited) would load with one of them thrown away, and
// saving would lose the other for good. This scanner goes over the raw bytes once, iteratively (no
// recursion, so nesting depth cannot overflow the stack), and finds the first object holding a key twice.
// Keys are compared as the parser sees them: escapes decoded ("\u0061" is "a", "\/" is "/"), compared as
// UTF-16 code units like QString.
//
// Meant for text the JSON parser accepted; on malformed input it stops quietly rather than failing (the
// parser reports syntax errors with line and column).
//
// The result is one line, "nodes[2]: duplicate key 'name'" (or "duplicate key 'format' at the top level"),
// keys shown through base::printable.
std::optional<std::string> findDuplicateKey(std::string_view json);

} // namespace speculum::scene
