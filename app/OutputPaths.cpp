#include "app/OutputPaths.hpp"

#include "base/Printable.hpp"

#include <climits>
#include <filesystem>
#include <system_error>

namespace speculum::app {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kNameMax = NAME_MAX; // bytes per path component (255 on Linux file systems)
constexpr std::size_t kPathMax = PATH_MAX;

base::Status checkNameLengths(const std::string& path) {
    if (path.size() >= kPathMax)
        return base::Error{base::quoted(path) + ": the path is longer than " + std::to_string(kPathMax - 1) +
                           " bytes"};
    for (const fs::path& part : fs::path(path))
        if (part.native().size() > kNameMax)
            return base::Error{base::quoted(path) + ": the name " + base::quoted(part.native(), 40) +
                               " is longer than " + std::to_string(kNameMax) + " bytes"};
    return base::Done{};
}

// The absolute form of `path` with symlinks resolved as far as it exists; empty on an error.
fs::path resolved(const std::string& path) {
    std::error_code ec;
    const fs::path absolute = fs::absolute(path, ec);
    if (ec)
        return {};
    const fs::path canonical = fs::weakly_canonical(absolute, ec);
    return ec ? absolute.lexically_normal() : canonical;
}

// Whether a and b are the same file (through symlinks and hard links); false when either does not exist.
bool sameFile(const fs::path& a, const fs::path& b) {
    std::error_code ec;
    const bool same = fs::equivalent(a, b, ec);
    return !ec && same;
}

} // namespace

base::Status checkOutputFile(const std::string& output) {
    if (base::Status lengths = checkNameLengths(output); !lengths)
        return lengths;
    std::error_code ec;
    const fs::path absolute = fs::absolute(output, ec);
    if (ec)
        return base::Error{base::quoted(output) + ": " + ec.message()};
    const fs::path folder = absolute.parent_path();
    const fs::file_status status = fs::status(folder, ec);
    if (ec && ec != std::errc::no_such_file_or_directory)
        return base::Error{base::quoted(output) + ": folder " + base::quoted(folder.string()) + ": " +
                           ec.message()};
    if (!fs::exists(status))
        return base::Error{base::quoted(output) + ": folder " + base::quoted(folder.string()) +
                           " does not exist"};
    if (!fs::is_directory(status))
        return base::Error{base::quoted(output) + ": " + base::quoted(folder.string()) + " is not a folder"};
    const fs::file_status target = fs::status(absolute, ec);
    if (ec && ec != std::errc::no_such_file_or_directory)
        return base::Error{base::quoted(output) + ": " + ec.message()};
    if (fs::is_directory(target))
        return base::Error{base::quoted(output) + ": is a folder"};
    return base::Done{};
}

base::Status checkNotAnInput(const std::string& output, const std::vector<std::string>& inputs,
                             const std::vector<std::string>& companions) {
    const fs::path out = resolved(output);
    for (const std::string& input : inputs) {
        const fs::path in = resolved(input);
        if (sameFile(output, input) || (!out.empty() && out == in))
            return base::Error{base::quoted(output) + " is " + base::quoted(input) +
                               ", which this command reads: choose another output"};
        for (const std::string& companion : companions) {
            const fs::path name = fs::path(companion).filename();
            const fs::path folder = fs::path(companion).parent_path();
            if (!sameFile(folder.empty() ? fs::path(".") : folder, in.parent_path()))
                continue;
            const std::string inName = in.filename().string();
            const std::string want = name.string();
            const bool prefix = !want.empty() && want.back() == '_';
            if (prefix ? inName.rfind(want, 0) == 0 : inName == want)
                return base::Error{base::quoted(output) + " would write " +
                                   base::quoted((folder / inName).string()) + " beside it, which is " +
                                   base::quoted(input) + ", read by this command: choose another output"};
        }
    }
    return base::Done{};
}

base::Status checkOutputFolder(const std::string& folder, const std::vector<std::string>& inputs) {
    if (base::Status lengths = checkNameLengths(folder); !lengths)
        return lengths;
    std::error_code ec;
    const fs::file_status status = fs::status(folder, ec);
    if (ec && ec != std::errc::no_such_file_or_directory)
        return base::Error{base::quoted(folder) + ": " + ec.message()};
    if (!fs::exists(status))
        return base::Done{}; // created by the command; it holds nothing yet
    if (!fs::is_directory(status))
        return base::Error{base::quoted(folder) + ": exists and is not a folder"};
    for (const std::string& input : inputs) {
        // Walk up from the input: is DIR one of the folders it lies in?
        fs::path p = resolved(input);
        while (!p.empty()) {
            if (sameFile(p, folder))
                return base::Error{base::quoted(folder) + " holds " + base::quoted(input) +
                                   ", which this command reads, and bench replaces files in it: choose "
                                   "another folder"};
            if (p == p.parent_path())
                break;
            p = p.parent_path();
        }
    }
    return base::Done{};
}

} // namespace speculum::app
