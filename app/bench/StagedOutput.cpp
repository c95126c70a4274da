#include "app/bench/StagedOutput.hpp"

#include <system_error>
#include <unistd.h>
#include <vector>

namespace speculum::app::bench {

namespace fs = std::filesystem;

render::Result<StagedOutput> StagedOutput::begin(const fs::path& folder) {
    std::error_code ec;
    const fs::path absolute = fs::absolute(folder, ec).lexically_normal();
    if (ec)
        return render::Error{folder.string() + ": " + ec.message()};
    if (fs::exists(absolute, ec) && !fs::is_directory(absolute, ec))
        return render::Error{folder.string() + ": exists and is not a folder"};
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
        return render::Error{folder.string() + ": cannot create the folder (" + ec.message() + ")"};
    }
    out.m_staging = absolute / (".speculum-bench-" + std::to_string(::getpid()) + ".partial");
    fs::remove_all(out.m_staging, ec);
    if (!fs::create_directory(out.m_staging, ec) || ec) {
        out.discard();
        return render::Error{folder.string() + ": cannot write into the folder (" +
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

render::Status StagedOutput::commit(const std::function<bool(const std::string&)>& earlierOutput) {
    std::error_code ec;
    std::vector<fs::path> written; // listed first: the loop below adds to the staging folder
    for (const fs::directory_entry& entry : fs::directory_iterator(m_staging, ec))
        written.push_back(entry.path());
    if (ec)
        return render::Error{m_staging.string() + ": " + ec.message()};
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
                return render::Error{target.string() + ": cannot replace (" + ec.message() + ")"};
        }
        fs::rename(path, target, ec);
        if (ec)
            return render::Error{target.string() + ": cannot write (" + ec.message() + ")"};
    }
    fs::remove_all(m_staging, ec);
    m_done = true;
    return render::Done{};
}

} // namespace speculum::app::bench
