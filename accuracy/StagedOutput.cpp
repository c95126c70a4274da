#include "accuracy/StagedOutput.hpp"

#include <cerrno>
#include <csignal>
#include <string_view>
#include <system_error>
#include <unistd.h>
#include <vector>

namespace speculum::accuracy {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kStagingPrefix = ".speculum-bench-";
constexpr std::string_view kStagingSuffix = ".partial";

// The process id in a staging folder's name, or 0 when the name is not one of ours.
pid_t stagingOwner(const std::string& name) {
    if (name.size() <= kStagingPrefix.size() + kStagingSuffix.size() || name.rfind(kStagingPrefix, 0) != 0 ||
        name.compare(name.size() - kStagingSuffix.size(), kStagingSuffix.size(), kStagingSuffix) != 0)
        return 0;
    const std::string digits =
        name.substr(kStagingPrefix.size(), name.size() - kStagingPrefix.size() - kStagingSuffix.size());
    if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos)
        return 0;
    return static_cast<pid_t>(std::stol(digits));
}

// A run that was killed (Ctrl-C, a crash) could not remove its staging folder; the next run into the
// same folder does, once no process of that id is running. A folder of a live process is left alone: it
// may be another run writing into the same folder right now.
void removeAbandonedStaging(const fs::path& folder) {
    std::error_code ec;
    std::vector<fs::path> abandoned;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder, ec)) {
        const pid_t owner = stagingOwner(entry.path().filename().string());
        if (owner > 0 && entry.is_directory(ec) && ::kill(owner, 0) != 0 && errno == ESRCH)
            abandoned.push_back(entry.path());
    }
    for (const fs::path& path : abandoned)
        fs::remove_all(path, ec);
}

} // namespace

base::Result<StagedOutput> StagedOutput::begin(const fs::path& folder) {
    std::error_code ec;
    const fs::path absolute = fs::absolute(folder, ec).lexically_normal();
    if (ec)
        return base::Error{folder.string() + ": " + ec.message()};
    if (fs::exists(absolute, ec) && !fs::is_directory(absolute, ec))
        return base::Error{folder.string() + ": exists and is not a folder"};
    StagedOutput out;
    out.m_folder = absolute;
    // Remember the outermost folder that does not exist yet: removing it undoes create_directories.
    for (fs::path p = absolute; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
        out.m_created = p;
        if (p == p.parent_path())
            break;
    }
    fs::create_directories(absolute, ec);
    if (ec) {
        out.discard();
        return base::Error{folder.string() + ": cannot create the folder (" + ec.message() + ")"};
    }
    removeAbandonedStaging(absolute);
    out.m_staging =
        absolute / (std::string(kStagingPrefix) + std::to_string(::getpid()) + std::string(kStagingSuffix));
    fs::remove_all(out.m_staging, ec);
    if (!fs::create_directory(out.m_staging, ec) || ec) {
        out.discard();
        return base::Error{folder.string() + ": cannot write into the folder (" +
                           (ec ? ec.message() : std::string("staging folder exists")) + ")"};
    }
    return out;
}

StagedOutput::StagedOutput(StagedOutput&& other) noexcept
    : m_folder(std::move(other.m_folder))
    , m_staging(std::move(other.m_staging))
    , m_created(std::move(other.m_created))
    , m_done(other.m_done) {
    other.m_done = true;
}

StagedOutput::~StagedOutput() {
    if (!m_done)
        discard();
}

void StagedOutput::discard() {
    std::error_code ec;
    if (!m_staging.empty())
        fs::remove_all(m_staging, ec);
    if (m_created)
        fs::remove_all(*m_created, ec); // holds nothing but what begin() made
    m_done = true;
}

base::Status StagedOutput::commit(const std::function<bool(const std::string&)>& earlierOutput) {
    std::error_code ec;
    std::vector<fs::path> written; // listed first: the loop below adds to the staging folder
    for (const fs::directory_entry& entry : fs::directory_iterator(m_staging, ec))
        written.push_back(entry.path());
    if (ec)
        return base::Error{m_staging.string() + ": " + ec.message()};
    if (earlierOutput) {
        std::vector<fs::path> stale;
        for (const fs::directory_entry& entry : fs::directory_iterator(m_folder, ec)) {
            const std::string name = entry.path().filename().string();
            if (entry.is_regular_file() && earlierOutput(name) && !fs::exists(m_staging / name))
                stale.push_back(entry.path());
        }
        for (const fs::path& path : stale)
            fs::remove(path, ec);
    }
    for (const fs::path& path : written) {
        const fs::path target = m_folder / path.filename();
        if (fs::is_directory(path) && fs::exists(target)) {
            // rename() cannot replace a non-empty folder: move the old one aside first.
            fs::rename(target, m_staging / (".old-" + path.filename().string()), ec);
            if (ec)
                return base::Error{target.string() + ": cannot replace (" + ec.message() + ")"};
        }
        fs::rename(path, target, ec);
        if (ec)
            return base::Error{target.string() + ": cannot write (" + ec.message() + ")"};
    }
    fs::remove_all(m_staging, ec);
    m_done = true;
    return base::Done{};
}

} // namespace speculum::accuracy
