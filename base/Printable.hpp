#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace speculum::base {

// Text from a file or the command line, made safe to put inside a one-line message: control characters,
// escapes and invalid UTF-8 become visible escapes ("\n", "\x1b", "\xff"), so a node name can never end
// the line or forge a "speculum: error:" line of its own, and anything longer than maxChars keeps its
// beginning and end around an ellipsis. Valid UTF-8 letters are kept as they are.
std::string printable(std::string_view text, std::size_t maxChars = 200);

// printable() inside single quotes: the usual way to name a value in a message ("unknown command 'rendr'").
std::string quoted(std::string_view text, std::size_t maxChars = 200);

} // namespace speculum::base
