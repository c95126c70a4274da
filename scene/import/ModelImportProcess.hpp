#pragma once

#include "scene/import/ModelImport.hpp"

#include <functional>
#include <string>

namespace speculum::scene::detail {

// Sends one progress step from the import child to the editor process.
using ChildProgress = std::function<void(double fraction, const char* phase)>;

// How a run of an import child ended.
struct ChildRun {
    enum class Outcome {
        Answered,   // `answer` holds what the child's body returned
        NotStarted, // no child process could be made (fork failed): the caller may read in-process
        Cancelled,  // control.cancel was set: the child was killed
        Failed,     // crashed, ran out of CPU time or memory, or ended without an answer: `error` says which
    };
    Outcome outcome = Outcome::Failed;
    std::string answer;
    std::string error; // without the file name: "the model reader crashed on this file (SIGSEGV); ..."
};

// Runs `body` in a forked child process (no exec) and returns the bytes it produced. The child limits its
// own CPU time to `cpuSeconds` (and, without AddressSanitizer, its address space to what the machine has),
// offers itself to the OOM killer first, and restores default signal handlers, so that whatever goes
// wrong inside it — a crash, a hang, a memory blow-up in the model reader — ends only the child. Progress
// the body reports arrives here through a pipe and is passed to control.progress on the calling thread;
// control.cancel is polled every 50 ms and kills the child, as does a wall-clock limit of
// 2 * cpuSeconds + 5 s (a child stuck on a lock it inherited spends no CPU). The child is always reaped.
// `body` runs in the child and must touch nothing that another thread of the parent may have held locked
// at the fork (Qt's event system, logging, OpenImageIO): Assimp, the mesh code and malloc are fine.
ChildRun runInChildProcess(const std::function<std::string(const ChildProgress&)>& body,
                           const ImportControl& control, int cpuSeconds);

// Test hook: an action the child runs before its body (a loop that spins or sleeps stands for a reader
// that hangs or is slow). nullptr, the default, for none.
void setImportChildTestAction(void (*action)());

// The import as it ran before the child process: in this process, textures decoded here. What
// importModelFile falls back to when no child can be made; tests compare the two.
base::Result<ImportedModel> importModelFileInProcess(const std::string& path,
                                                     std::vector<std::string>& warnings,
                                                     const ImportControl& control = {});

} // namespace speculum::scene::detail
