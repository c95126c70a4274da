#pragma once

#include "base/Result.hpp"

#include <filesystem>
#include <functional>
#include <optional>

namespace speculum::accuracy {

// The output folder, written all at once: files are written into a hidden staging folder inside it and
// moved into place by commit(), replacing only the files of the same names (a previous run's results),
// never anything else in the folder. Without commit() (an error, an exception), the staging folder and
// any folder begin() created are removed again, so a failed run leaves the disk as it found it. A run that
// was killed before it could clean up leaves its staging folder behind; the next run into the folder
// removes it.
class StagedOutput {
public:
    // Creates the folder (and missing parents) if needed. Errors: the path names a file, or a folder
    // cannot be created.
    static base::Result<StagedOutput> begin(const std::filesystem::path& folder);

    StagedOutput(StagedOutput&& other) noexcept;
    StagedOutput& operator=(StagedOutput&&) = delete;
    StagedOutput(const StagedOutput&) = delete;
    ~StagedOutput();

    // Where to write: a fresh, empty folder.
    const std::filesystem::path& staging() const { return m_staging; }
    const std::filesystem::path& folder() const { return m_folder; }

    // Moves everything written into the folder. Sub-folders (such as errors/) replace the old ones whole,
    // so no stale file of an earlier run survives among the new ones; files of the folder that this run
    // did not write and `earlierOutput` claims (a plot of a family this scene lacks) are removed too.
    base::Status commit(const std::function<bool(const std::string& fileName)>& earlierOutput = {});

private:
    StagedOutput() = default;
    void discard();

    std::filesystem::path m_folder;
    std::filesystem::path m_staging;
    std::optional<std::filesystem::path> m_created; // the outermost folder begin() created
    bool m_done = false;
};

} // namespace speculum::accuracy
