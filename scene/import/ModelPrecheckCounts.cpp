// ModelPrecheck of the OFF and PLY headers (ModelPrecheckFormats.hpp).
// OFF and PLY declare their element counts up front, and Assimp's readers reserve and loop over
// whatever the header says: invalid/OutOfMemory.off in Assimp's own test set declares 353535235358 faces
// and keeps the 5.2 reader busy for about a minute. Every element takes at least one byte, so a header
// that declares more elements than the file has bytes is refused.
#include "base/Printable.hpp"
#include "render/mesh/MeshRepair.hpp"
#include "scene/import/ModelPrecheckFormats.hpp"

#include <algorithm>
#include <cctype>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace speculum::scene::detail::precheck {

using base::Error;

namespace {

std::string headText(const char* bytes, std::size_t size) {
    return std::string(bytes, std::min<std::size_t>(size, 4096));
}

base::Status checkCounts(const std::vector<unsigned long long>& counts, std::size_t size) {
    for (unsigned long long count : counts) {
        if (count > size || count > 3ull * render::kMaxMeshTriangles) {
            return Error{"the header declares " + std::to_string(count) + " elements but the file has only " +
                         std::to_string(size) + " bytes"};
        }
    }
    return base::Done{};
}

bool parseCount(const std::string& token, std::vector<unsigned long long>& counts) {
    // Digits only; anything longer than 19 digits would not fit and is absurd anyway.
    if (token.empty() || token.size() > 19 || token.find_first_not_of("0123456789") != std::string::npos) {
        return false;
    }
    counts.push_back(std::stoull(token));
    return true;
}

// "property <type> <name>" or "property list <count type> <item type> <name>", PLY's types only.
bool plyPropertyKnown(std::istringstream& words) {
    static const std::set<std::string> kTypes = {"char",  "uchar",  "short",   "ushort", "int",   "uint",
                                                 "float", "double", "int8",    "uint8",  "int16", "uint16",
                                                 "int32", "uint32", "float32", "float64"};
    std::string type, item, name;
    if (!(words >> type)) {
        return false;
    }
    if (type == "list") {
        return words >> type >> item >> name && kTypes.count(type) != 0 && kTypes.count(item) != 0;
    }
    return words >> name && kTypes.count(type) != 0;
}

} // namespace

// The length of the [ST][C][N][4][n]OFF keyword the word starts with, 0 for none. Assimp's reader takes
// what follows it in the same word ("OFF8888...") as the first count.
std::size_t offKeywordLength(std::string word) {
    for (char& c : word) {
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
    const std::size_t off = word.find("OFF");
    if (off == std::string::npos || word.substr(0, off).find_first_not_of("STCN4") != std::string::npos) {
        return 0;
    }
    return off + 3;
}

// The first word of the file, '#' comments skipped.
std::string firstWord(const char* bytes, std::size_t size) {
    std::size_t i = 0;
    const std::size_t limit = std::min<std::size_t>(size, 4096);
    while (i < limit) {
        const auto c = static_cast<unsigned char>(bytes[i]);
        if (c == '#') {
            while (i < limit && bytes[i] != '\n') {
                ++i;
            }
        } else if (std::isspace(c)) {
            ++i;
        } else {
            break;
        }
    }
    std::size_t j = i;
    while (j < limit && !std::isspace(static_cast<unsigned char>(bytes[j])) && bytes[j] != '#') {
        ++j;
    }
    return std::string(bytes + i, j - i);
}

base::Status checkPly(const char* bytes, std::size_t size) {
    // Assimp 5.2's PLY reader loops for good on a header that never ends (found by fuzz_model_import).
    const std::string_view text(bytes, size);
    std::size_t end = text.find("end_header");
    while (end != std::string_view::npos && bytes[end - 1] != '\n' && bytes[end - 1] != '\r') {
        end = text.find("end_header", end + 1); // in a comment: not the end (end > 0: the file is "ply...")
    }
    if (end == std::string_view::npos) {
        return Error{"the PLY header has no end_header line"};
    }
    std::istringstream lines(std::string(bytes, end));
    std::string line;
    std::vector<unsigned long long> counts;
    int number = 0;
    bool sawElement = false;
    while (std::getline(lines, line)) {
        ++number;
        std::istringstream words(line);
        std::string keyword, name, count;
        // Assimp 5.2's PLY reader also loops for good on some malformed headers (fuzz_model_import): the
        // format must be one PLY defines and a property must follow an element. Other lines pass, as in
        // Assimp (Blender splits long comments into lines of their own).
        std::istringstream first(line);
        std::string word, version;
        first >> word;
        if (word == "element") {
            sawElement = true;
        }
        const bool known =
            number == 1 ? word == "ply"
            : word == "format"
                ? (first >> name >> version &&
                   (name == "ascii" || name == "binary_little_endian" || name == "binary_big_endian"))
                : word != "property" || (sawElement && plyPropertyKnown(first));
        if (!known) {
            return Error{"the PLY header line " + std::to_string(number) +
                         " is not understood: " + base::quoted(line)};
        }
        if (words >> keyword >> name >> count && keyword == "element" && !parseCount(count, counts)) {
            return Error{"invalid element count " + base::quoted(count) + " in the PLY header"};
        }
    }
    return checkCounts(counts, size);
}

base::Status checkOff(const char* bytes, std::size_t size) {
    std::istringstream lines(headText(bytes, size));
    std::string line, all;
    while (std::getline(lines, line)) {
        all += line.substr(0, line.find('#')) + ' ';
    }
    std::istringstream words(all);
    std::string keyword, token;
    words >> keyword;
    std::vector<std::string> tokens;
    const std::size_t length = offKeywordLength(keyword);
    if (length < keyword.size()) {
        tokens.push_back(keyword.substr(length));
    }
    while (tokens.size() < 3 && words >> token) {
        tokens.push_back(token);
    }
    if (keyword.substr(0, length).find('n') != std::string::npos && !tokens.empty()) {
        tokens.erase(tokens.begin()); // nOFF: the dimension comes first
    }
    std::vector<unsigned long long> counts;
    for (std::size_t i = 0; i < 2 && i < tokens.size(); ++i) {
        const std::string& token = tokens[i];
        if (!parseCount(token, counts)) {
            return Error{"invalid element count " + base::quoted(token) + " in the OFF header"};
        }
    }
    return checkCounts(counts, size);
}

} // namespace speculum::scene::detail::precheck
