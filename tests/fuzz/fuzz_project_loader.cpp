// libFuzzer target for the project loader: any bytes must give either a scene or an error message —
// never a crash, a hang or a sanitizer report — and whatever loads must save and load back to the same
// bytes (so a file speculum accepted is never damaged by saving it).
#include "scene/project/ProjectFile.hpp"

#include <QByteArray>
#include <QDir>
#include <cstdint>
#include <cstdlib>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace speculum::scene;
    const QByteArray json(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    const QDir base(QStringLiteral("/nonexistent/project"));
    std::vector<std::string> warnings;
    auto scene = speculum::scene::parseProject(json, base, warnings);
    if (!scene.ok()) {
        if (scene.error().empty())
            std::abort(); // every failure must say what is wrong
        return 0;
    }
    const QByteArray saved = speculum::scene::serializeProject(*scene, base);
    std::vector<std::string> again;
    auto reloaded = speculum::scene::parseProject(saved, base, again);
    if (!reloaded.ok() || speculum::scene::serializeProject(*reloaded, base) != saved)
        std::abort();
    return 0;
}
