#pragma once

#include <string>
#include <vector>

namespace speculum::scene {

// What a warning about the scene says, as data: code that acts on warnings (the editor puts right those
// about a model file it is still reading) selects them by code, node and file, never by their wording.
enum class WarningCode {
    MeshSkipped,          // a node's mesh is not drawn: its file is missing or unreadable, or lacks the part
    MeshLoading,          // a node's model file is still being read (the editor reads them on workers)
    ReflectorWithoutMesh, // a reflector whose node has no mesh that loads
    ModelFileNote,        // something a model file holds that speculum cannot show (a second uv set, ...)
};

struct Warning {
    WarningCode code = WarningCode::MeshSkipped;
    std::string node;    // the name of the node it is about; empty when none
    std::string file;    // the absolute path of the file it is about; empty when none
    std::string message; // the one line a user reads, formatted from the above

    bool operator==(const Warning&) const = default;
};

// The warnings, each with its message in the words the command line and the editor show.
// "node 'Statue': mesh skipped: <reason>" (the reason names the file).
Warning meshSkipped(const std::string& node, const std::string& file, const std::string& reason);
// "node 'Statue': mesh loading: 'statue.glb'..."
Warning meshLoading(const std::string& node, const std::string& file);
// "node 'Ball': reflector skipped: it needs a mesh on the same node"; `file` is the node's model file,
// whose failure may be the reason (empty when the node names none).
Warning reflectorWithoutMesh(const std::string& node, const std::string& file);
// A model reader's note on `file`, which already names the file ("chair.obj: ...").
Warning modelFileNote(const std::string& file, const std::string& note);

// The messages alone, in order.
std::vector<std::string> messages(const std::vector<Warning>& warnings);

} // namespace speculum::scene
