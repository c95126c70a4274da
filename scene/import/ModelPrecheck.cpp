#include "scene/import/ModelPrecheck.hpp"

#include "base/FileKind.hpp"
#include "base/Printable.hpp"
#include "render/mesh/MeshRepair.hpp"

#include <QByteArray>
#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <QString>
#include <QXmlStreamReader>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace speculum::scene::detail {
namespace {

using base::Error;

std::string depthError(const char* what) {
    return std::string(what) + " nested deeper than " + std::to_string(kMaxNesting) + " levels";
}

// ---------------------------------------------------------------------------------------------------
// Node graphs (glTF nodes[].children, Collada <node>/<instance_node>, X3D DEF/USE): Assimp copies a
// node once per path that reaches it, so a DAG of 40 nodes each listing the next twice is 2^40 aiNodes.
// Counted here without unfolding: an explicit-stack depth-first walk, memoised per node.
struct NodeGraph {
    std::vector<std::vector<int>> children;
    std::vector<int> roots;                 // what the importer instantiates
    std::function<std::string(int)> nameOf; // "nodes[3]", "node 'n3'"
};

std::string formatWays(double ways) {
    if (ways < 1e6) {
        return std::to_string(static_cast<long long>(ways));
    }
    if (!std::isfinite(ways)) {
        return "more than 2^1023";
    }
    std::ostringstream out;
    out << "2^" << static_cast<long long>(std::floor(std::log2(ways)));
    return out.str();
}

base::Status checkNodeGraph(const NodeGraph& graph) {
    const int n = static_cast<int>(graph.children.size());
    std::vector<char> state(n, 0);         // 0 unvisited, 1 on the stack, 2 done
    std::vector<double> instances(n, 0.0); // nodes in the subtree once unfolded (itself included)
    std::vector<int> height(n, 0);         // levels below and including the node
    std::vector<int> postorder;
    postorder.reserve(n);
    struct Frame {
        int node;
        std::size_t next;
    };
    std::vector<Frame> stack;
    // Every node, roots first: a cycle or an absurd chain is broken even where no scene reaches it.
    std::vector<int> starts = graph.roots;
    for (int i = 0; i < n; ++i) {
        starts.push_back(i);
    }
    for (int start : starts) {
        if (start < 0 || start >= n || state[start] != 0) {
            continue;
        }
        state[start] = 1;
        stack.push_back({start, 0});
        while (!stack.empty()) {
            Frame& frame = stack.back();
            const std::vector<int>& kids = graph.children[frame.node];
            if (frame.next < kids.size()) {
                const int child = kids[frame.next++];
                if (child < 0 || child >= n) {
                    continue; // Assimp refuses a dangling index itself
                }
                if (state[child] == 1) {
                    return Error{"the node graph has a cycle (" + graph.nameOf(child) +
                                 " is its own descendant)"};
                }
                if (state[child] == 0) {
                    state[child] = 1;
                    stack.push_back({child, 0});
                }
                continue;
            }
            const int node = frame.node;
            double count = 1.0;
            int levels = 0;
            for (int child : kids) {
                if (child >= 0 && child < n) {
                    count += instances[child];
                    levels = std::max(levels, height[child]);
                }
            }
            instances[node] = count;
            height[node] = levels + 1;
            state[node] = 2;
            postorder.push_back(node);
            stack.pop_back();
            if (height[node] > kMaxNodeDepth) {
                return Error{"the node hierarchy is deeper than " + std::to_string(kMaxNodeDepth) +
                             " levels (below " + graph.nameOf(node) + ")"};
            }
        }
    }
    double total = 0.0;
    for (int root : graph.roots) {
        if (root >= 0 && root < n) {
            total += instances[root];
        }
    }
    if (total <= kMaxNodeInstances) {
        return base::Done{};
    }
    // Name the node reached the most ways: the ways to reach a node, summed over its parents in
    // topological order (reverse postorder).
    std::vector<double> ways(n, 0.0);
    for (int root : graph.roots) {
        if (root >= 0 && root < n) {
            ways[root] += 1.0;
        }
    }
    int most = graph.roots.empty() ? 0 : graph.roots.front();
    for (auto it = postorder.rbegin(); it != postorder.rend(); ++it) {
        for (int child : graph.children[*it]) {
            if (child >= 0 && child < n) {
                ways[child] += ways[*it];
            }
        }
        if (ways[*it] > ways[most]) {
            most = *it;
        }
    }
    return Error{"the node graph unfolds into more than " +
                 std::to_string(static_cast<long long>(kMaxNodeInstances)) + " node instances (" +
                 graph.nameOf(most) + " is reached " + formatWays(ways[most]) + " ways)"};
}

// ---------------------------------------------------------------------------------------------------
// Duplicate keys: QJsonObject keeps the last of them, Assimp's rapidjson finds the first, so a glTF with a
// benign "nodes" after a hostile one would be checked on one graph and read with the other. JSON names
// should be unique (RFC 8259) and no exporter repeats one: refused. Run after QJsonDocument accepted the
// text, so it is valid JSON nested at most 1024 deep. Keys are compared decoded (\u0065 is 'e').
base::Status checkDuplicateKeys(const char* bytes, std::size_t size) {
    struct Container {
        bool object;
        bool expectKey;
        std::set<std::string> keys;
    };
    std::vector<Container> stack;
    for (std::size_t i = 0; i < size; ++i) {
        const char c = bytes[i];
        if (c == '{' || c == '[') {
            stack.push_back({c == '{', c == '{', {}});
        } else if (c == '}' || c == ']') {
            if (!stack.empty()) {
                stack.pop_back();
            }
        } else if (c == ',') {
            if (!stack.empty() && stack.back().object) {
                stack.back().expectKey = true;
            }
        } else if (c == '"') {
            const bool isKey = !stack.empty() && stack.back().object && stack.back().expectKey;
            std::string key;
            for (++i; i < size && bytes[i] != '"'; ++i) {
                if (bytes[i] != '\\' || i + 1 >= size) {
                    if (isKey) {
                        key += bytes[i];
                    }
                    continue;
                }
                const char escaped = bytes[++i];
                if (escaped == 'u' && i + 4 < size) {
                    const unsigned long unit =
                        std::strtoul(std::string(bytes + i + 1, 4).c_str(), nullptr, 16);
                    i += 4;
                    if (isKey) {
                        key += unit < 0x80 ? std::string(1, static_cast<char>(unit))
                                           : "\\u" + std::to_string(unit); // not ASCII: kept distinct
                    }
                } else if (isKey) {
                    key += escaped;
                }
            }
            if (isKey) {
                stack.back().expectKey = false;
                if (!stack.back().keys.insert(key).second) {
                    return Error{"the glTF JSON has the key " + base::quoted(key) + " twice in one object"};
                }
            }
        }
    }
    return base::Done{};
}

// ---------------------------------------------------------------------------------------------------
// glTF 1 and 2 (JSON; .glb holds the same JSON in its first chunk).
base::Status checkGltfJson(const QByteArray& json) {
    QJsonParseError parseError{};
    // QJsonDocument parses iteratively and refuses nesting deeper than 1024 levels itself.
    const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
    if (document.isNull()) {
        return Error{"the glTF JSON is invalid: " + parseError.errorString().toStdString() + " at offset " +
                     std::to_string(parseError.offset)};
    }
    if (const base::Status unique = checkDuplicateKeys(json.constData(), std::size_t(json.size())); !unique) {
        return unique;
    }
    const QJsonObject top = document.object();
    NodeGraph graph;
    const QJsonValue nodes = top.value(QStringLiteral("nodes"));
    std::vector<QJsonValue> nodeValues;
    QHash<QString, int> idOf; // glTF 1 names nodes by string id
    std::vector<std::string> ids;
    if (nodes.isArray()) {
        for (const QJsonValue& node : nodes.toArray()) {
            nodeValues.push_back(node);
        }
    } else if (nodes.isObject()) {
        const QJsonObject byId = nodes.toObject();
        for (auto it = byId.begin(); it != byId.end(); ++it) {
            idOf.insert(it.key(), static_cast<int>(nodeValues.size()));
            ids.push_back(it.key().toStdString());
            nodeValues.push_back(it.value());
        }
    }
    const auto indexOf = [&](const QJsonValue& ref) {
        if (ref.isDouble()) {
            const double d = ref.toDouble();
            return d >= 0 && d < static_cast<double>(nodeValues.size()) ? static_cast<int>(d) : -1;
        }
        return ref.isString() ? idOf.value(ref.toString(), -1) : -1;
    };
    graph.children.resize(nodeValues.size());
    for (std::size_t i = 0; i < nodeValues.size(); ++i) {
        for (const QJsonValue& child : nodeValues[i].toObject().value(QStringLiteral("children")).toArray()) {
            graph.children[i].push_back(indexOf(child));
        }
    }
    const auto addSceneRoots = [&](const QJsonValue& scene) {
        for (const QJsonValue& root : scene.toObject().value(QStringLiteral("nodes")).toArray()) {
            graph.roots.push_back(indexOf(root));
        }
    };
    const QJsonValue scenes = top.value(QStringLiteral("scenes"));
    if (scenes.isArray()) {
        for (const QJsonValue& scene : scenes.toArray()) {
            addSceneRoots(scene);
        }
    } else if (scenes.isObject()) {
        for (const QJsonValue& scene : scenes.toObject()) {
            addSceneRoots(scene);
        }
    }
    if (graph.roots.empty()) {
        // No scene: count every node that is nobody's child as a root, the most an importer may take.
        std::vector<char> isChild(nodeValues.size(), 0);
        for (const auto& kids : graph.children) {
            for (int child : kids) {
                if (child >= 0) {
                    isChild[child] = 1;
                }
            }
        }
        for (std::size_t i = 0; i < nodeValues.size(); ++i) {
            if (!isChild[i]) {
                graph.roots.push_back(static_cast<int>(i));
            }
        }
    }
    graph.nameOf = [&](int i) {
        return ids.empty() ? "nodes[" + std::to_string(i) + "]" : "node " + base::quoted(ids[i]);
    };
    return checkNodeGraph(graph);
}

std::uint32_t readU32(const char* p) {
    std::uint32_t v;
    std::memcpy(&v, p, 4); // little-endian on every platform speculum builds for
    return v;
}

std::uint64_t readU64(const char* p) {
    std::uint64_t v;
    std::memcpy(&v, p, 8);
    return v;
}

base::Status checkGlb(const char* bytes, std::size_t size) {
    if (size < 20) {
        return base::Done{}; // Assimp refuses a truncated header itself
    }
    const std::uint32_t version = readU32(bytes + 4);
    std::size_t offset = 0, length = 0;
    if (version == 1) {
        offset = 20; // magic, version, length, contentLength, contentFormat
        length = readU32(bytes + 12);
    } else {
        offset = 20; // magic, version, length, then chunk length and type
        length = readU32(bytes + 12);
        if (readU32(bytes + 16) != 0x4E4F534Au) { // "JSON"
            return Error{"the first chunk of the .glb file is not its JSON"};
        }
    }
    if (length > size - offset) {
        return Error{"the .glb JSON chunk runs past the end of the file"};
    }
    return checkGltfJson(QByteArray::fromRawData(bytes + offset, static_cast<qsizetype>(length)));
}

// ---------------------------------------------------------------------------------------------------
// XML (Collada, X3D, AMF, XGL, Ogre XML, Irrlicht, ...): element depth, and Collada/X3D node instances.
base::Status checkXml(const char* bytes, std::size_t size) {
    QXmlStreamReader reader(QByteArray::fromRawData(bytes, static_cast<qsizetype>(size)));
    reader.setNamespaceProcessing(false); // an undeclared prefix is no reason to refuse
    NodeGraph graph;
    std::vector<std::string> names; // per graph node, for messages
    std::vector<char> inLibrary;    // defined inside <library_nodes>: instantiated only when referenced
    std::vector<int> parentOf;      // nearest graph node above, -1 for none
    QHash<QString, int> byId;       // Collada node ids, X3D DEF names
    struct Reference {
        int from;
        QString id;
    };
    std::vector<Reference> references; // instance_node url="#id", USE="id"
    struct Open {
        int graphNode; // the graph node this element is, or -1
        bool library;
    };
    std::vector<Open> open;
    std::vector<int> trackedStack; // graph nodes among the open elements
    const auto currentGraphNode = [&] { return trackedStack.empty() ? -1 : trackedStack.back(); };
    while (!reader.atEnd()) {
        const QXmlStreamReader::TokenType token = reader.readNext();
        if (token == QXmlStreamReader::StartElement) {
            if (open.size() >= static_cast<std::size_t>(kMaxNesting)) {
                return Error{depthError("XML elements")};
            }
            const QStringView name = reader.name();
            const QXmlStreamAttributes attributes = reader.attributes();
            const bool library = (!open.empty() && open.back().library) || name == u"library_nodes";
            int self = -1;
            const QStringView def = attributes.value(QStringLiteral("DEF"));
            if (name == u"node" || !def.isEmpty()) {
                self = static_cast<int>(graph.children.size());
                graph.children.emplace_back();
                const int parent = currentGraphNode();
                parentOf.push_back(parent);
                inLibrary.push_back(library ? 1 : 0);
                const QStringView id = def.isEmpty() ? attributes.value(QStringLiteral("id")) : def;
                names.push_back(id.isEmpty() ? std::string() : id.toString().toStdString());
                if (!id.isEmpty()) {
                    byId.insert(id.toString(), self);
                }
                if (parent >= 0) {
                    graph.children[parent].push_back(self);
                }
            }
            QStringView reference;
            if (name == u"instance_node") {
                reference = attributes.value(QStringLiteral("url"));
                if (reference.startsWith(u'#')) {
                    reference = reference.mid(1);
                }
            } else {
                reference = attributes.value(QStringLiteral("USE"));
            }
            if (!reference.isEmpty()) {
                const int from = self >= 0 ? self : currentGraphNode();
                if (from >= 0) {
                    references.push_back({from, reference.toString()});
                }
            }
            open.push_back({self, library});
            if (self >= 0) {
                trackedStack.push_back(self);
            }
        } else if (token == QXmlStreamReader::EndElement) {
            if (!open.empty()) {
                if (open.back().graphNode >= 0) {
                    trackedStack.pop_back();
                }
                open.pop_back();
            }
        }
    }
    if (reader.hasError() && reader.error() != QXmlStreamReader::PrematureEndOfDocumentError) {
        // Assimp's XML parser (pugixml) is more lenient than Qt's, so a file Qt cannot read past some
        // point could still hold anything after it: refuse rather than pass it unchecked.
        return Error{"the XML is not well-formed: " + reader.errorString().toStdString() + " (line " +
                     std::to_string(reader.lineNumber()) + ")"};
    }
    for (const Reference& reference : references) {
        if (const auto it = byId.constFind(reference.id); it != byId.constEnd()) {
            graph.children[reference.from].push_back(it.value());
        }
    }
    for (std::size_t i = 0; i < parentOf.size(); ++i) {
        if (parentOf[i] < 0 && !inLibrary[i]) {
            graph.roots.push_back(static_cast<int>(i));
        }
    }
    graph.nameOf = [&](int i) {
        return names[i].empty() ? "node " + std::to_string(i) : "node " + base::quoted(names[i]);
    };
    return checkNodeGraph(graph);
}

// ---------------------------------------------------------------------------------------------------
// Text formats nested with braces, brackets or parentheses (ASCII FBX, text .x, OpenGEX, ASE, MD5,
// IFC/STEP, ...): their parsers recurse once per level. A NUL byte means a binary file: not checked.
base::Status checkTextNesting(const char* bytes, std::size_t size) {
    int depth = 0;
    bool quoted = false;
    for (std::size_t i = 0; i < size; ++i) {
        const char c = bytes[i];
        switch (c) {
        case '\0':
            return base::Done{};
        case '\n':
            quoted = false; // an unterminated string does not hide the rest of the file
            break;
        case '"':
            quoted = !quoted;
            break;
        case '{':
        case '[':
        case '(':
            if (!quoted && ++depth > kMaxNesting) {
                return Error{depthError("braces, brackets or parentheses")};
            }
            break;
        case '}':
        case ']':
        case ')':
            if (!quoted && depth > 0) {
                --depth;
            }
            break;
        default:
            break;
        }
    }
    return base::Done{};
}

// Binary FBX: records (end offset, property count and length, name) holding nested records up to their
// end offset. Walked with a stack of open end offsets; a corrupt record stops the walk (Assimp refuses it).
base::Status checkFbxBinary(const char* bytes, std::size_t size) {
    if (size < 27) {
        return base::Done{};
    }
    const bool wide = readU32(bytes + 23) >= 7500; // 64-bit offsets from FBX 7.5
    const std::size_t header = wide ? 25 : 13;
    std::vector<std::uint64_t> ends;
    std::uint64_t pos = 27;
    while (true) {
        while (!ends.empty() && pos >= ends.back()) {
            pos = ends.back();
            ends.pop_back();
        }
        if (pos + header > size) {
            return base::Done{};
        }
        const char* p = bytes + pos;
        const std::uint64_t end = wide ? readU64(p) : readU32(p);
        const std::uint64_t propertyBytes = wide ? readU64(p + 16) : readU32(p + 8);
        const auto nameLength = static_cast<unsigned char>(p[header - 1]);
        if (end == 0) { // the null record that closes a list
            if (ends.empty()) {
                return base::Done{};
            }
            pos += header;
            continue;
        }
        if (end <= pos || end > size || (!ends.empty() && end > ends.back()) || propertyBytes > size) {
            return base::Done{};
        }
        const std::uint64_t childStart = pos + header + nameLength + propertyBytes;
        if (childStart < end) {
            ends.push_back(end);
            if (ends.size() > static_cast<std::size_t>(kMaxNesting)) {
                return Error{depthError("FBX records")};
            }
            pos = childStart;
        } else {
            pos = end;
        }
    }
}

// ---------------------------------------------------------------------------------------------------
// OFF and PLY declare their element counts up front, and Assimp's readers reserve and loop over
// whatever the header says: invalid/OutOfMemory.off in Assimp's own test set declares 353535235358 faces
// and keeps the 5.2 reader busy for about a minute. Every element takes at least one byte, so a header
// that declares more elements than the file has bytes is refused.
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

std::string headText(const char* bytes, std::size_t size) {
    return std::string(bytes, std::min<std::size_t>(size, 4096));
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

bool startsWith(const char* bytes, std::size_t size, const char* prefix) {
    const std::size_t n = std::strlen(prefix);
    return size >= n && std::memcmp(bytes, prefix, n) == 0;
}

} // namespace

ModelContent identifyModelContent(const char* bytes, std::size_t size) {
    if (startsWith(bytes, size, "glTF")) {
        return ModelContent::Glb;
    }
    if (startsWith(bytes, size, "Kaydara FBX Binary")) {
        return ModelContent::FbxBinary;
    }
    if (startsWith(bytes, size, "ply")) {
        return ModelContent::Ply;
    }
    std::size_t i = startsWith(bytes, size, "\xEF\xBB\xBF") ? 3 : 0;
    while (i < size && i < 4096 && std::isspace(static_cast<unsigned char>(bytes[i]))) {
        ++i;
    }
    if (i < size && bytes[i] == '{') {
        return ModelContent::GltfJson;
    }
    if (i < size && bytes[i] == '<') {
        return ModelContent::Xml;
    }
    if (offKeywordLength(firstWord(bytes, size)) > 0) {
        return ModelContent::Off;
    }
    if (std::memchr(bytes, '\0', std::min<std::size_t>(size, 65536)) == nullptr) {
        return ModelContent::Text;
    }
    return ModelContent::Unknown;
}

base::Status precheckModelBytes(const char* bytes, std::size_t size) {
    switch (identifyModelContent(bytes, size)) {
    case ModelContent::Glb:
        return checkGlb(bytes, size);
    case ModelContent::GltfJson: {
        // A JSON file is glTF for Assimp; anything else starting with '{' is checked as nested text.
        const base::Status nesting = checkTextNesting(bytes, size);
        if (!nesting) {
            return nesting;
        }
        return checkGltfJson(QByteArray::fromRawData(bytes, static_cast<qsizetype>(size)));
    }
    case ModelContent::Xml:
        return checkXml(bytes, size);
    case ModelContent::FbxBinary:
        return checkFbxBinary(bytes, size);
    case ModelContent::Ply:
        return checkPly(bytes, size);
    case ModelContent::Off:
        return checkOff(bytes, size);
    case ModelContent::Text:
        return checkTextNesting(bytes, size);
    case ModelContent::Unknown:
        break;
    }
    return base::Done{};
}

base::Status precheckModel(const std::filesystem::path& file) {
    // O_NONBLOCK and fstat on the opened descriptor: a FIFO swapped in after the caller's check still
    // cannot block here.
    const int fd = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        return base::requireRegularFile(file);
    }
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};
    struct stat info {};
    if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
        return Error{"it is not a regular file"};
    }
    const auto size = static_cast<std::size_t>(info.st_size);
    if (size == 0) {
        return base::Done{};
    }
    // Mapped, not read: a large binary model costs no copy, and the whole-file scans read it once.
    void* mapped = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
    if (mapped == MAP_FAILED) {
        return Error{std::string("cannot map the file: ") + std::strerror(errno)};
    }
    const base::Status status = precheckModelBytes(static_cast<const char*>(mapped), size);
    ::munmap(mapped, size);
    return status;
}

} // namespace speculum::scene::detail
