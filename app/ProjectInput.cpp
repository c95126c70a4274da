#include "app/ProjectInput.hpp"

#include "base/FileKind.hpp"
#include "base/Printable.hpp"
#include "scene/evaluate/Snapshot.hpp"
#include "scene/project/ProjectFile.hpp"

#include <QFileInfo>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <iostream>
#include <unistd.h>

namespace speculum::app {

namespace {

// Why `path` cannot be read as a texture, or empty when it can: a regular file that opens for reading.
// O_NONBLOCK: a path swapped for a FIFO after the check still cannot block the open.
std::string unreadable(const std::string& path) {
    if (base::Status regular = base::requireRegularFile(path); !regular)
        return regular.error();
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        return std::string("cannot be read: ") + std::strerror(errno);
    ::close(fd);
    return {};
}

// Each texture in `frame` whose file is in `bad` is cleared, so the renderer draws without it (the
// warning was already given) instead of reporting it a second time.
void dropTextures(render::FrameInput& frame, const std::set<std::string>& bad) {
    const auto drop = [&](render::Material& m) {
        for (render::TextureSource* source : {&m.texture, &m.emissionTexture, &m.normalTexture})
            if (!source->image && bad.count(source->path))
                *source = render::TextureSource{};
    };
    for (render::DrawItem& item : frame.items)
        drop(item.material);
    for (render::Mirror& mirror : frame.mirrors)
        drop(mirror.material);
    if (frame.reflector)
        drop(frame.reflector->material);
}

} // namespace

std::string oneLine(std::string_view message) {
    std::string out;
    out.reserve(message.size());
    for (const char ch : message) {
        const auto c = static_cast<unsigned char>(ch);
        if (c >= 0x20 && c != 0x7F) {
            out += ch;
        } else if (c == '\n') {
            out += "\\n";
        } else if (c == '\r') {
            out += "\\r";
        } else if (c == '\t') {
            out += "\\t";
        } else {
            char hex[5];
            std::snprintf(hex, sizeof hex, "\\x%02x", c);
            out += hex;
        }
    }
    return out;
}

void printWarnings(const std::vector<std::string>& warnings) {
    for (const std::string& w : warnings)
        std::cerr << "speculum: warning: " << oneLine(w) << "\n";
}

void printWarnings(const std::vector<scene::Warning>& warnings) {
    printWarnings(scene::messages(warnings));
}

void printError(const std::string& message) {
    std::cerr << "speculum: error: " << oneLine(message) << "\n";
}

base::Status loadProjectScene(const std::string& project, scene::Scene& scene) {
    const QString path = QString::fromStdString(project);
    // Only a regular file is read: a FIFO or /dev/stdin would block the command for good.
    if (const base::Status regular = base::requireRegularFile(project); !regular)
        return base::Error{base::quoted(project) + ": " + regular.error()};
    std::vector<std::string> warnings;
    if (base::Status opened = scene::openProject(scene, path, warnings); !opened)
        return base::Error{base::quoted(project) + ": " + opened.error()};
    printWarnings(warnings);
    return base::Done{};
}

ProjectFiles checkProjectFiles(const std::string& project, const scene::Scene& scene,
                               scene::MeshLibrary& meshes, std::vector<scene::Warning>& warnings) {
    ProjectFiles files;
    files.inputs.push_back(project);
    std::set<std::string> checked;
    const auto texture = [&](const std::string& node, const std::string& path) {
        if (path.empty() || !checked.insert(path).second)
            return;
        // An embedded texture ("/abs/model.glb#*0") is read with its model, which was checked already.
        if (path.find('#') != std::string::npos && meshes.embeddedTexture(path, warnings))
            return;
        files.inputs.push_back(path);
        if (const std::string why = unreadable(path); !why.empty()) {
            files.problems.push_back("node " + base::quoted(node) + ": texture " + base::quoted(path) + ": " +
                                     why);
            files.textureProblems.push_back(files.problems.back());
            files.badTextures.insert(path);
        }
    };
    const auto textures = [&](const std::string& node, const scene::MaterialComponent& m) {
        texture(node, m.texture.path);
        texture(node, m.emissionTexture.path);
        texture(node, m.normalTexture.path);
    };
    scene.forEachNode([&](const scene::Node& node) {
        const scene::NodeData& d = node.data();
        if (d.material)
            textures(d.name, *d.material);
        if (!d.mesh || d.mesh->builtin)
            return;
        files.inputs.push_back(d.mesh->file);
        // The same calls the snapshot makes, so each import is cached and not repeated: a whole model on a
        // plain node draws its parts with the file's own materials; anything else draws one mesh.
        const bool parts = !d.mesh->part && !d.material && !d.reflector && !d.mirror;
        if (parts) {
            auto model = meshes.model(d.mesh->file, warnings);
            if (!model) {
                files.problems.push_back("node " + base::quoted(d.name) + ": model " + model.error());
                return;
            }
            for (const scene::MaterialComponent& m : (*model)->materials)
                textures(d.name, m);
        } else if (auto mesh = meshes.get(*d.mesh, warnings); !mesh) {
            files.problems.push_back("node " + base::quoted(d.name) + ": model " + mesh.error());
        }
    });
    return files;
}

base::Status applyMissingFiles(const ProjectFiles& files, MissingFiles policy) {
    if (files.problems.empty() || policy == MissingFiles::Report)
        return base::Done{};
    if (policy == MissingFiles::KeepGoing) {
        // Models that failed are skipped by the snapshot, which warns of each ("mesh skipped: ...").
        printWarnings(files.textureProblems);
        return base::Done{};
    }
    std::string message = files.problems.front();
    if (files.problems.size() > 1)
        message += " (and " + std::to_string(files.problems.size() - 1) + " more)";
    return base::Error{message + "; --keep-going goes on without it"};
}

base::Result<ProjectFrame> loadProjectFrame(const std::string& project, double time, MissingFiles policy) {
    auto owned = std::make_unique<scene::Scene>();
    scene::Scene& scene = *owned;
    if (base::Status opened = loadProjectScene(project, scene); !opened)
        return base::Error{opened.error()};
    ProjectFrame frame;
    frame.meshes = std::make_unique<scene::MeshLibrary>();
    std::vector<scene::Warning> warnings;
    const ProjectFiles files = checkProjectFiles(project, scene, *frame.meshes, warnings);
    if (base::Status missing = applyMissingFiles(files, policy); !missing)
        return base::Error{missing.error()};
    frame.inputs = files.inputs;
    frame.input = scene::snapshot(scene, time, *frame.meshes, warnings);
    if (policy == MissingFiles::KeepGoing)
        dropTextures(frame.input, files.badTextures);
    printWarnings(warnings);
    scene.forEachNode([&](const scene::Node& node) {
        const auto& mesh = node.data().mesh;
        if (mesh && mesh->builtin == scene::BuiltinMesh::Teapot)
            frame.teapotTessellations.insert(mesh->tessellation);
    });
    frame.scene = std::move(owned);
    return frame;
}

} // namespace speculum::app
