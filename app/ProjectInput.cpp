#include "app/ProjectInput.hpp"

#include "base/FileKind.hpp"
#include "base/Printable.hpp"
#include "render/imageio/TextureLoader.hpp"
#include "render/renderer/Renderer.hpp"
#include "scene/evaluate/Snapshot.hpp"
#include "scene/project/ProjectFile.hpp"

#include <QFileInfo>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <iostream>
#include <set>
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

// Keeps a decoder's own output off standard error while it is alive: libpng prints "libpng error: ..." by
// itself before OpenImageIO reports the same failure, which the command's one error line then carries.
class QuietStandardError {
public:
    QuietStandardError() {
        std::fflush(stderr);
        m_saved = ::dup(STDERR_FILENO);
        const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
        if (m_saved >= 0 && null >= 0)
            ::dup2(null, STDERR_FILENO);
        if (null >= 0)
            ::close(null);
    }
    ~QuietStandardError() {
        if (m_saved < 0)
            return;
        std::fflush(stderr);
        ::dup2(m_saved, STDERR_FILENO);
        ::close(m_saved);
    }
    QuietStandardError(const QuietStandardError&) = delete;
    QuietStandardError& operator=(const QuietStandardError&) = delete;

private:
    int m_saved = -1;
};

// Why the texture file `path` cannot be used, or empty when it decodes; its image (and a note when it was
// read smaller than the file) go into `files`. Decoded here, once: a file that exists but is corrupt,
// truncated or not an image at all is found before the command writes anything.
std::string textureProblem(const std::string& path, ProjectFiles& files) {
    if (const std::string why = unreadable(path); !why.empty())
        return "texture " + base::quoted(path) + ": " + why;
    std::string reduced;
    base::Result<render::TextureImage> image = base::Error{""};
    {
        const QuietStandardError quiet;
        image = render::loadTexture(path, {}, &reduced);
    }
    if (!image)
        return image.error();
    if (!reduced.empty())
        files.textureNotes.push_back(std::move(reduced));
    files.textures.decoded.emplace(path, std::make_shared<const render::TextureImage>(std::move(*image)));
    return {};
}

// The material's texture sources, for changing each in place.
std::array<render::TextureSource*, 3> textureSources(render::Material& m) {
    return {&m.texture, &m.emissionTexture, &m.normalTexture};
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
    // Once each: a warning printed as the frame was planned is not repeated after it was drawn.
    static std::set<std::string> printed;
    for (const std::string& w : warnings)
        if (printed.insert(w).second)
            std::cerr << "speculum: warning: " << oneLine(w) << "\n";
}

void warnAsPlanned(render::Renderer& renderer) {
    renderer.setPlanObserver([](const render::FramePlan& plan) { printWarnings(plan.warnings); });
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
        if (std::string problem = textureProblem(path, files); !problem.empty()) {
            files.problems.push_back("node " + base::quoted(node) + ": " + problem);
            files.textureProblems.push_back(files.problems.back());
            files.textures.bad.insert(path);
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

void useCheckedTextures(render::FrameInput& frame, const CheckedTextures& textures) {
    const auto use = [&](render::Material& m) {
        for (render::TextureSource* source : textureSources(m)) {
            if (source->image)
                continue;
            if (auto found = textures.decoded.find(source->path); found != textures.decoded.end())
                source->image = found->second;
            else if (textures.dropBad && textures.bad.count(source->path))
                *source = render::TextureSource{};
        }
    };
    for (render::DrawItem& item : frame.items)
        use(item.material);
    for (render::Mirror& mirror : frame.mirrors)
        use(mirror.material);
    for (render::Reflector& reflector : frame.reflectors)
        use(reflector.material);
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
    frame.textures = files.textures;
    frame.textures.dropBad = policy == MissingFiles::KeepGoing;
    frame.input = scene::snapshot(scene, time, *frame.meshes, warnings);
    useCheckedTextures(frame.input, frame.textures);
    printWarnings(warnings);
    printWarnings(files.textureNotes);
    scene.forEachNode([&](const scene::Node& node) {
        const auto& mesh = node.data().mesh;
        if (mesh && mesh->builtin == scene::BuiltinMesh::Teapot)
            frame.teapotTessellations.insert(mesh->tessellation);
    });
    frame.scene = std::move(owned);
    return frame;
}

} // namespace speculum::app
