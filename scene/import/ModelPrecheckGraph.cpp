// ModelPrecheck for the formats whose node graph Assimp unfolds: glTF (JSON and .glb) and XML (Collada,
// X3D, ...), with glTF's duplicate keys (ModelPrecheckFormats.hpp).
#include "base/Printable.hpp"
#include "scene/import/ModelPrecheckFormats.hpp"

#include <QByteArray>
#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <QString>
#include <QXmlStreamReader>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace speculum::scene::detail::precheck {

using base::Error;

namespace {

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

} // namespace

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

} // namespace speculum::scene::detail::precheck
